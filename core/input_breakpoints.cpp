#include "core/input_breakpoints.hpp"

#include <algorithm>

#include "core/prescribed_motion.hpp"

namespace tribo {

std::vector<double> inputBreakpoints(const Model& model) {
  std::vector<double> times;
  auto add = [&](const Signal& s) {
    const std::vector<double> b = s.breakpoints();
    times.insert(times.end(), b.begin(), b.end());
  };
  for (const AppliedLoad& load : model.loads) {
    for (const Signal& s : load.force) add(s);
    for (const Signal& s : load.torque) add(s);
  }
  for (const Joint& joint : model.joints) {
    if (joint.elements.actuator) add(joint.elements.actuator->target);
    if (joint.elements.drive && joint.elements.drive->signal) add(*joint.elements.drive->signal);
  }
  for (const Body& body : model.bodies) {
    if (body.surface_velocity_signal)
      for (const Signal& s : *body.surface_velocity_signal) add(s);
    if (body.motion) {
      const std::vector<double> b = body.motion->breakpoints();
      times.insert(times.end(), b.begin(), b.end());
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace tribo
