// Everything derived within one force evaluation, preallocated so a warm step does not
// allocate (tests/core/allocation_test.cpp): geometry poses, contact points and records,
// force buffers split by source, the resulting accelerations, and the constraint
// quantities. Each field names the stage of Dynamics::evaluate (core/dynamics.hpp) that
// writes it; read by the integrators, outputs and tests. Not restart state (core/state.hpp).
#pragma once

#include <vector>

#include "contact/contact_point.hpp"
#include "core/contact_pair.hpp"
#include "core/joint_actuator.hpp"
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
  // updatePoses, per body: rotation (body to world) and, for dynamic bodies, the inverse
  // world inertia R I^-1 R^T (zero for kinematic bodies); per geometry, its world pose.
  std::vector<Mat3> rotation;
  std::vector<Mat3> inv_inertia_world;
  std::vector<Eigen::Isometry3d> geometry_poses;  // world
  // detect: the contact points, grouped by pair (and `contacts` sized to match).
  std::vector<contact::ContactPoint> contact_points;
  // One per contact point: contactKinematics (point, depth rate, slip), normalForces
  // (normal_force), friction (friction_force, mu).
  std::vector<contact::ContactRecord> contacts;
  std::vector<ContactPair> contact_pair;  // contact_points[i]'s pair (geometries, material)
  // friction, dynamic laws: dz/dt for State::friction_values (zero where no contact point
  // uses the record in this evaluation), expressed against each record's stored normal; and
  // per record of State::friction_states the contact point that used it (-1: none).
  std::vector<double> friction_state_rate;
  std::vector<int> friction_state_contact;
  // assemble, per body, by source (gravity is m g, not stored). spring_wrench: the force
  // elements (spring-dampers, bushings, torsional springs). joint_wrench: joint limits,
  // springs, dampers, efforts, constant-load friction; solveConstraints adds the friction
  // under reaction load. Each but contact_wrench is empty when the model has none of its
  // source (no force element, no joint, no constraint row, no load): a reader takes zero.
  std::vector<Wrench> contact_wrench;
  std::vector<Wrench> spring_wrench;
  std::vector<Wrench> joint_wrench;
  std::vector<Wrench> constraint_wrench;  // solveConstraints: J^T lambda
  // assemble: per body, the applied loads (core/applied_load.hpp); per model load, its world
  // force F at this evaluation's time.
  std::vector<Wrench> load_wrench;
  std::vector<Vec3> load_force;
  // Per body, world: unconstrainedAccelerations, then solveConstraints adds the constraint
  // forces' part; the result of the evaluation (zero for kinematic bodies).
  std::vector<Vec3> linear_acceleration;
  std::vector<Vec3> angular_acceleration;
  // Constraint measures at the evaluated state (solveConstraints).
  double max_constraint_error = 0.0;       // max |Phi| [m or -]
  double max_constraint_rate_error = 0.0;  // max |J v|
  int max_constraint_joint = -1;           // the joint of the row with max |Phi| (-1: none)
  double max_penetration = 0.0;            // contactKinematics: deepest contact [m]
  // contactKinematics, when the friction is formed in its pass (core/dynamics.cpp): every
  // point's normal and friction force is finite, so Simulator::check need not read them
  // again. False when they were not screened (or some force is not finite).
  bool forces_finite = false;
  // contactKinematics, when the friction is formed in its pass and the evaluation was asked
  // for the points' energy (Dynamics::evaluate): each point's elastic energy U(d), in contact
  // order, formed while its record is in cache (the energy guard's contact terms,
  // core/energy.cpp). Empty when not formed.
  std::vector<double> point_elastic;
  // solveConstraints: joint friction under reaction load (core/joint_forces.hpp): false when
  // its fixed-point iteration stopped at the cap before the friction torques settled.
  bool joint_friction_converged = true;
  // JointForces at fixed steps: the largest change the I_q |q'| / (2 h) rule made to a joint's
  // damping or friction torque at this evaluation, |law's - applied| [N m or N], and that
  // joint (-1: the rule did not engage).
  double joint_held_change = 0.0;
  int joint_held = -1;
  // Per model joint: the friction force [N] or torque [N m] on its coordinate at this
  // evaluation (joint friction of any law and load; 0 for joints without friction).
  std::vector<double> joint_friction;
  // Per model joint: its actuator's target, effort and saturation at this evaluation
  // (core/joint_actuator.hpp; zero for joints without one).
  std::vector<ActuatorOutput> actuator_output;
  // Per body: its surface velocity at this evaluation's time, body's geometry frames
  // (Body::surfaceVelocityAt; zero for bodies without one). Empty when no body has one.
  std::vector<Vec3> surface_velocity;
};

}  // namespace tribo
