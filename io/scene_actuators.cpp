// Scene reader (io/scene_reader.hpp): joint actuators (core/joint_actuator.hpp), on scene
// joints and on robots' joints by name, each with a target signal (io/scene_signal.hpp).
#include <string>
#include <utility>

#include "io/scene_keys.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_signal.hpp"

namespace tribo::io::scene_detail {

void Loader::readActuator(const Value& v) {
  const Map m(v, scene_keys::kActuator);
  JointActuator a;
  a.name = m.required("name").text();
  const Value joint_value = m.required("joint");
  const auto joint = builder_.findJoint(joint_value.text());
  if (!joint) {
    Keys known;
    for (const Joint& j : builder_.joints())
      if (hasScalarCoordinate(j.type)) known.push_back(j.name);
    joint_value.fail("unknown joint '" + joint_value.text() +
                     "' (revolute and prismatic joints: " + joined(known) + ")");
  }
  static const ActuatorKind kKinds[] = {ActuatorKind::kMotor, ActuatorKind::kPositionServo,
                                        ActuatorKind::kVelocityServo};
  a.kind = kKinds[m.required("type").choice(scene_keys::kActuatorTypes)];
  a.target = readSignal(m.required("target"));
  if (auto x = m.get("kp")) a.kp = x->nonNegative();
  if (auto x = m.get("kd")) a.kd = x->nonNegative();
  if (auto x = m.get("effort_limit")) a.max_effort = x->positive();
  if (auto x = m.get("velocity_limit")) a.max_velocity = x->positive();
  guarded(v, [&] { builder_.setJointActuator(*joint, std::move(a)); });
}

}  // namespace tribo::io::scene_detail
