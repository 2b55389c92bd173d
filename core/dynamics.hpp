// One force evaluation: state in, forces and constrained accelerations out. The fixed
// pipeline of every evaluation:
//   kinematics (rotations, world inertias) -> geometry poses -> collision -> contact kinematics, normal force, friction law ->
//   spring-dampers -> gravity and gyroscopic terms -> constraint solve (Lagrange
//   multipliers) -> accelerations
// Results land in the Workspace, split by source. Not here: time stepping
// (core/integrator.hpp), run control and divergence checks (core/simulator.hpp).
#pragma once

#include <memory>

#include "contact/collision_detector.hpp"
#include "core/constraint_solver.hpp"
#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo {

class Dynamics {
 public:
  explicit Dynamics(std::shared_ptr<const Model> model);

  const Model& model() const { return *model_; }
  // The state a model starts from (its bodies' initial poses and velocities, t = 0).
  State initialState() const;
  // Evaluates forces and accelerations at `state`; the workspace stays valid until the
  // next call.
  const Workspace& evaluate(const State& state);
  const Workspace& workspace() const { return ws_; }

 private:
  void computeKinematics(const State& state);
  void accumulateContacts(const State& state);
  void accumulateSprings(const State& state);

  std::shared_ptr<const Model> model_;
  contact::CollisionDetector detector_;
  ConstraintSolver solver_;
  Workspace ws_;
  std::vector<Mat3> inv_inertia_body_;  // per body, zero for kinematic bodies
};

}  // namespace tribo
