// Adds a URDF robot to a ModelBuilder: one body per group of links joined by fixed joints
// (io/urdf_assembly.hpp), Tribo joints for the movable URDF joints (revolute and continuous
// -> revolute, prismatic, planar; floating -> a free body), limits, <dynamics> damping and
// friction, mimic couplings, and collision geometry (one surface material per link, so the
// caller can give each link its contact material, e.g. from its Gazebo tags).
// Joints whose range excludes 0 start at the nearest end of their range (said in a note).
// What it does to data a simulation cannot use, each said in the returned notes:
//   - a root group without mass, or base = kFixed: the root is welded to the world;
//   - a movable group without mass (chains of massless "dummy" links between joints): it
//     gets 1e-3 of the robot's mean link mass and the inertia of a 5 cm solid sphere;
//   - an inertia that is not positive definite or breaks the triangle inequality: its
//     principal moments are raised to at least half the largest (and a floor), which keeps
//     the axes and changes the dynamics of that link only.
// Not here: reading the file (io/urdf_reader.hpp), the ground or other scene content.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/model_builder.hpp"
#include "io/urdf_robot.hpp"

namespace tribo::io {

struct UrdfPlacement {
  std::string prefix;  // prepended to every body, joint and geometry name
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();  // root link frame in the world
  enum class Base { kAuto, kFixed, kFloating } base_mode = Base::kAuto;  // auto: fixed if massless
  std::map<std::string, double> joint_positions;   // by URDF joint name [rad or m]
  std::map<std::string, double> joint_velocities;  // [rad/s or m/s]
  // Collision filter bit of this robot: its links do not collide with each other (nor with
  // other geometry carrying the same bit); everything else they touch.
  std::uint32_t collision_group = 0x2;
};

struct UrdfModelResult {
  std::vector<std::string> notes;  // what was changed to make the robot simulable
  std::vector<int> geometries;     // geometry indices added
  double lowest_point = 0.0;       // smallest world z of the collision geometry [m]
  // One surface per link with collision geometry (name = prefix + link name), with the mass
  // of the body carrying it (0 when welded to the world) and its Gazebo contact tags: the
  // caller gives each its contact materials.
  struct Surface {
    std::string name;
    double body_mass = 0.0;
    GazeboContact contact;
  };
  std::vector<Surface> surfaces;
};

// Coulomb friction at mu, tanh-regularized at 0.01 m/s: what a URDF friction coefficient
// (Gazebo's mu1, `tribo run ROBOT.urdf --set mu=`) becomes.
std::shared_ptr<const friction::FrictionLaw> urdfCoulomb(double mu);

// The contact material a link's Gazebo tags make of `base`: mu1 -> urdfCoulomb(mu1); kp or kd
// -> a linear normal law of stiffness kp (else base's) and damping kd (else, with kp given,
// critical for `body_mass` on 4 points when `critical_without_kd`, or base's). mu2 is not
// used (isotropic friction). Without tags: `base`.
contact::Material withGazeboTags(contact::Material base, const GazeboContact& tags,
                                 double body_mass, bool critical_without_kd = true);

// Throws ModelError (from the builder) or std::invalid_argument naming the link or joint.
UrdfModelResult addUrdfRobot(ModelBuilder& builder, const UrdfRobot& robot,
                             const UrdfPlacement& placement);

}  // namespace tribo::io
