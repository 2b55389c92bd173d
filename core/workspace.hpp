// Everything derived within one force evaluation, preallocated so a warm step does not
// allocate: geometry poses, contact points and records, force buffers split by source, the
// resulting accelerations, and the constraint quantities. Written by Dynamics::evaluate;
// read by the integrators, outputs and tests. Not restart state (core/state.hpp).
#pragma once

#include <vector>

#include "contact/contact_point.hpp"
#include "core/math.hpp"

namespace tribo {

struct Wrench {
  Vec3 force = Vec3::Zero();   // at the body origin, world [N]
  Vec3 torque = Vec3::Zero();  // about the body origin, world [N m]
  void setZero() {
    force.setZero();
    torque.setZero();
  }
};

struct Workspace {
  // Kinematics stage, per body: rotation (body to world) and, for dynamic bodies, the
  // inverse world inertia R I^-1 R^T (zero for kinematic bodies).
  std::vector<Mat3> rotation;
  std::vector<Mat3> inv_inertia_world;
  std::vector<Eigen::Isometry3d> geometry_poses;  // world
  std::vector<contact::ContactPoint> contact_points;
  std::vector<contact::ContactRecord> contacts;  // one per contact point
  // Per body, by source (gravity is m g, not stored).
  std::vector<Wrench> contact_wrench;
  std::vector<Wrench> spring_wrench;
  std::vector<Wrench> joint_wrench;       // joint limits, springs, dampers, friction
  std::vector<Wrench> constraint_wrench;  // J^T lambda
  // Per body, world: the result of the evaluation (zero for kinematic bodies).
  std::vector<Vec3> linear_acceleration;
  std::vector<Vec3> angular_acceleration;
  // Constraint measures at the evaluated state.
  double max_constraint_error = 0.0;       // max |Phi| [m or -]
  double max_constraint_rate_error = 0.0;  // max |J v|
  double max_penetration = 0.0;            // [m]
  // Joint friction under reaction load (core/joint_forces.hpp): false when its fixed-point
  // iteration stopped at the cap before the friction torques settled.
  bool joint_friction_converged = true;
};

}  // namespace tribo
