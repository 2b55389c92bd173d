// The joint-force stage: generalized forces tau on the scalar coordinates of revolute and
// prismatic joints (limits, springs, dampers, efforts, friction; core/joint_elements.hpp),
// applied to the two bodies as J_q^T tau with J_q the coordinate's Jacobian, so the power
// they deliver is exactly tau q'. Results go to Workspace::joint_wrench.
//
// Friction uses the friction-law strategy (friction/friction_law.hpp) on a one-dimensional
// slip: tau = -mu(v) N r sign(v), v = r q' (revolute; r = pin radius) or q' (prismatic,
// r = 1). With a constant load N it is an ordinary force. With the reaction load N depends
// on the multipliers, which depend on the friction: the stage iterates
//   N_k = |reaction(lambda_k)|,  tau_k = friction(N_k),  lambda_k+1 = solve with tau_k
// re-using the factorization of J M^-1 J^T (ConstraintSolver::addForcesAndResolve) until
// the torques change by less than 1e-12 relative, at most 20 times (a step whose state
// hit the cap is counted in StepStats and warned about after the run). Measured: 1 iteration when
// the load does not depend on the friction (a slider pushed through its centre), 4-6 for a
// pendulum's pin with mu r <= 0.015 m, 13 at mu r = 0.06 m; the map contracts by about mu r m d /
// I_pivot. Reaction load: revolute |F| (radial and axial; moments are not turned into load);
// prismatic |F - (F.z) z| (the part normal to the slide).
// Not here: the drive constraints (core/constraint_rows.hpp), contact friction.
#pragma once

#include <vector>

#include "core/constraint_rows.hpp"
#include "core/constraint_solver.hpp"
#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo {

class JointForces {
 public:
  explicit JointForces(const Model& model);

  bool empty() const { return entries_.empty(); }
  // Limits, springs, dampers, efforts and constant-load friction at `state` (whose rotations
  // are in ws.rotation) into ws.joint_wrench, which it zeroes first (a model without joint
  // forces never writes it).
  void accumulate(const State& state, Workspace& ws);
  // Reaction-load friction, after solver.solve(state, ws): adds it to ws.joint_wrench and
  // updates the constrained accelerations. Returns the iterations used (0: none needed).
  int applyReactionFriction(ConstraintSolver& solver, Workspace& ws);

 private:
  struct Entry {
    int joint = -1;
    JointCoordinate coordinate;
    const JointElements* elements = nullptr;
    CoordinateValue value;         // at the last accumulate()
    Vec3 axis = Vec3::UnitZ();     // world joint axis at the last accumulate()
    double reaction_torque = 0.0;  // friction with the reaction load, last applied
  };
  void addGeneralized(const Entry& e, double tau, std::vector<Wrench>& out) const;
  double frictionTorque(const Entry& e, double load) const;

  const Model& model_;
  std::vector<Entry> entries_;
  std::vector<int> reaction_;  // entries with reaction-load friction
  std::vector<Wrench> delta_;  // per body
};

}  // namespace tribo
