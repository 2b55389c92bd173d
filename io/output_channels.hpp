// The channels a run records (`output.channels` in a scene): groups of columns chosen by
// name, so that a large scene pays only for what is asked. Column names, in this order:
//   t
//   per body, for the groups asked:
//     position          NAME.x NAME.y NAME.z            body origin, world [m]
//     orientation       NAME.qw NAME.qx NAME.qy NAME.qz body to world, unit quaternion
//     rpy               NAME.roll NAME.pitch NAME.yaw   R = Rz(yaw) Ry(pitch) Rx(roll) [rad]
//     velocity          NAME.vx NAME.vy NAME.vz         body origin, world [m/s]
//     angular_velocity  NAME.wx NAME.wy NAME.wz         world [rad/s]
//     contact           NAME.slip NAME.normal_force     largest slip speed of its contacts
//                                                       [m/s], sum of their normal forces [N]
//     friction          NAME.friction_force             |sum of its contacts' friction| [N]
//   joints              JOINT.q JOINT.rate              each revolute and prismatic joint's
//                                                       coordinate [rad or m] and rate
//   energy              energy.kinetic energy.gravity energy.elastic energy.input_power
//                                                       (core/energy.hpp) [J, W]
// Default: position, velocity, contact (what trajectory.csv always held).
// Not here: recording (study/trajectory_recorder.hpp), per-contact-point columns (points
// come and go), the internal states of dynamic friction laws (records come and go).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model.hpp"

namespace tribo::io {

// Every group name, in column order.
const std::vector<std::string>& knownChannelGroups();
// The default groups.
const std::vector<std::string>& defaultChannelGroups();

// The column names of `groups` (known names, any order, no repeats) for `model`.
std::vector<std::string> channelColumns(const Model& model, const std::vector<std::string>& groups);

// True when `groups` holds `group`.
bool hasGroup(const std::vector<std::string>& groups, std::string_view group);

}  // namespace tribo::io
