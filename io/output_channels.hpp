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
//     resistance        NAME.resisting_moment           |sum of its contacts' rolling and
//                                                       spinning resistance moments| [N m]
//   pairs               A/B.normal_force A/B.friction_force A/B.slip
//                                                       per contact pair (geometry names A, B;
//                                                       forces on B): the sum of its points'
//                                                       normal forces [N], |sum of their
//                                                       friction forces| [N], their largest
//                                                       slip speed [m/s]; 0 out of contact
//   pair_resistance     A/B.mu_slip A/B.resisting_moment
//                                                       per contact pair: the effective
//                                                       friction coefficient in the slip
//                                                       direction, sum(-F_i . s_i / |s_i|) /
//                                                       sum(F_n,i) over its slipping points
//                                                       (mu(|s|) for an isotropic law, mu(|R s|)
//                                                       |R s| / |s| for an anisotropic one,
//                                                       contact/anisotropy.hpp: the power
//                                                       dissipated per unit load and slip
//                                                       speed; 0 with none; the largest double
//                                                       for a finite force on a vanishing
//                                                       load), and |sum of its points'
//                                                       rolling and spinning moments on B|
//                                                       [N m]
//   joints              JOINT.q JOINT.rate JOINT.friction
//                                                       each revolute and prismatic joint's
//                                                       coordinate [rad or m], its rate (the
//                                                       joint's slip) and its friction force
//                                                       or torque on the coordinate [N, N m]
//   friction_states     JOINT.S, A/B.S                  the internal state of dynamic friction
//                                                       laws (friction/dynamic_law.hpp), S its
//                                                       names (z.x, theta, z1.x ...): a joint's
//                                                       own; a pair's mean over its points in
//                                                       contact (0 out of contact)
//   energy              energy.kinetic energy.gravity energy.elastic energy.input_power
//                                                       (core/energy.hpp) [J, W]
//   loads               LOAD.fx LOAD.fy LOAD.fz         each applied load's force, world [N]
//                                                       (core/applied_load.hpp)
//   actuators           ACT.target ACT.effort ACT.saturated  each joint actuator's command,
//                                                       its effort after saturation [N m or
//                                                       N] and 1 while saturated, else 0
//                                                       (core/joint_actuator.hpp)
// Default: position, velocity, contact (what trajectory.csv always held).
// A scene with automatic contacts has a pair for every two geometries that may touch: `pairs`
// then writes three columns for each, and listing them costs time and memory quadratic in
// the geometries (choose per-body `contact` and `friction` there).
// Not here: recording (study/trajectory_recorder.hpp), per-contact-point columns (points
// come and go, and with them their states).
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

// "A/B": the name of contact pair `pair` in column names.
std::string pairName(const Model& model, const ContactPair& pair);

// The unit of column `column` of `model`'s recording ("m", "rad/s", "N m", ...), from the
// table above; "" for a unitless column (quaternion parts, t is "s") and for a friction
// state (each law's own) or a name no group makes.
std::string channelUnit(const Model& model, std::string_view column);

// True when `groups` holds `group`.
bool hasGroup(const std::vector<std::string>& groups, std::string_view group);

}  // namespace tribo::io
