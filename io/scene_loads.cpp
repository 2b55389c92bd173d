// Scene reader (io/scene_reader.hpp): applied loads (core/applied_load.hpp), each component
// a signal (io/scene_signal.hpp).
#include <array>
#include <string>

#include "io/scene_keys.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_signal.hpp"

namespace tribo::io::scene_detail {

void Loader::readLoad(const Value& v) {
  const Map m(v, scene_keys::kLoad);
  AppliedLoad load;
  load.name = m.required("name").text();
  load.body = body(m.required("body"));
  const auto force = m.get("force");
  const auto torque = m.get("torque");
  if (!force && !torque) v.fail("load '" + load.name + "' needs a force, a torque or both");
  if (force) load.force = readSignals3(*force);
  if (torque) load.torque = readSignals3(*torque);
  if (auto frame = m.get("frame"))
    load.frame = frame->choice(scene_keys::kLoadFrames) == 0 ? LoadFrame::kWorld : LoadFrame::kBody;
  load.point = m.vec3("point", Vec3::Zero());
  guarded(v, [&] { builder_.addLoad(load); });
}

}  // namespace tribo::io::scene_detail
