// One force evaluation: state in, forces and constrained accelerations out, as a fixed
// pipeline of named stages (each a member function below, run in this order by evaluate):
//   updatePoses        kinematics (rotations, world inertias) and geometry poses
//   detect             collision detection (contact/collision_detector.hpp)
//   contactKinematics  per contact point: depth rate, slip (contact/contact_force.hpp)
//   normalForces       per contact point: penalty normal force (in the kinematics' pass over
//                      the points unless profiling, so that each record is read once)
//   friction           per contact point: the pair's friction law, with the memory of
//                      stateful and dynamic laws (core/friction_states.hpp); unless
//                      profiling, while no dynamic law is in play, in the kinematics' pass
//                      too, chunk by chunk (each chunk's kinematics, normal forces, then its
//                      friction, its deepest point and whether its forces are finite; for
//                      the evaluation the energy guard reads, each point's elastic energy)
//   assemble           wrenches by source: contacts, force elements (spring-dampers,
//                      bushings, torsional springs), applied loads at the state's time
//                      (core/applied_load.hpp), joint forces (core/joint_forces.hpp)
//   unconstrainedAccelerations  forces, gravity and gyroscopic terms -> accelerations (in
//                      assemble's pass over the bodies, unless profiling, when contacts are
//                      the only source of force)
//   solveConstraints   Lagrange multipliers (core/constraint_solver.hpp), then joint
//                      friction under reaction load
// Results land in the Workspace, split by source. With profiling on, each stage's wall time
// is added to a StageProfile (core/stage_profile.hpp); off, no clock is read. Before and
// after a step, the friction memory is brought up to date (beforeStep, afterStep).
// Collision detection is set up by core/model_detector.hpp (with its query watchdog).
// Not here: time stepping (core/integrator.hpp), run control and divergence checks
// (core/simulator.hpp).
#pragma once

#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "contact/collision_detector.hpp"
#include "contact/contact_force.hpp"
#include "core/applied_loads.hpp"
#include "core/constraint_projection.hpp"
#include "core/constraint_solver.hpp"
#include "core/friction_states.hpp"
#include "core/joint_forces.hpp"
#include "core/model.hpp"
#include "core/model_detector.hpp"
#include "core/stage_profile.hpp"
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
  // next call. With `point_energy`, each contact point's elastic energy too, where it can be
  // formed in the points' pass (Workspace::point_elastic): for the evaluation the energy
  // guard reads.
  const Workspace& evaluate(const State& state, bool point_energy = false);
  const Workspace& workspace() const { return ws_; }
  // The joint solve of the last evaluation (its multipliers, the path it took).
  const ConstraintSolver& constraintSolver() const { return solver_; }
  // Added to load i's force and torque (in its frame) from now on: the input matrix's
  // perturbation (study/modes/input_matrix.hpp); zero offsets restore the load.
  void setLoadOffset(std::size_t load, const Vec3& force, const Vec3& torque) {
    loads_.setOffset(load, force, torque);
  }
  // Load i held at these values in place of its signals (AppliedLoads::setCommand).
  void setLoadCommand(std::size_t load, const std::optional<Vec3>& force,
                      const std::optional<Vec3>& torque) {
    loads_.setCommand(load, force, torque);
  }
  // A command for a joint's actuator from outside (JointForces::setActuatorCommand).
  bool setActuatorCommand(int joint, double command) {
    return joint_forces_.setActuatorCommand(joint, command);
  }
  // Drift control after a step (ConstraintOptions::projection): moves `state` back onto the
  // joint constraints (core/constraint_projection.hpp); does nothing unless enabled.
  void projectConstraints(State& state);

  // Friction memory (core/friction_states.hpp): which kinds the model has, and its layout.
  const FrictionStates& frictionMemory() const { return friction_; }
  // Before a step, with the workspace evaluated at `state`: the records of dynamic laws;
  // true when the caller must evaluate again (FrictionStates::beforeStep).
  bool beforeStep(State& state);
  // After a step, with the workspace evaluated at `state`: stateful laws move their anchors;
  // true when they changed (FrictionStates::afterStep).
  bool afterStep(State& state);
  // Semi-implicit Euler's bounded update of the internal states over h at the slip and load
  // of the workspace's evaluation (FrictionStates::stepStable).
  void stepFrictionMemory(State& state, double h) const;
  // Quasi-steady friction: with it on, dynamic laws act through their steady-state curve (as
  // memoryless laws, for the steady-state search of `tribo modes`); off by default.
  void setSteadyFriction(bool on) { friction_.setSteady(on); }

  // Time per stage (core/stage_profile.hpp). Switching profiling on starts the profile from
  // zero; switching it off keeps the totals. Off by default.
  void setProfiling(bool on);
  bool profiling() const { return profiling_; }
  const StageProfile& profile() const { return profile_; }
  // The threads an evaluation uses now: mostThreads() unless useThreads chose fewer.
  int threads() const { return threads_; }
  // The threads an evaluation may use (SimulationOptions::threads resolved, under the
  // constructing thread's ScopedThreadLimit): 1 for a scene too small to gain from more.
  int mostThreads() const { return most_threads_; }
  // From the next evaluation on, `threads` threads (within 1 and mostThreads()); the results
  // are the same bit for bit (core/thread_choice.hpp chooses it for `threads: auto`).
  void useThreads(int threads);
  // The model's bodies with a prescribed motion (core/prescribed_motion.hpp), in index order.
  const std::vector<std::size_t>& prescribedBodies() const { return prescribed_bodies_; }

 private:
  // The stages of evaluate, in order.
  void updatePoses(const State& state);
  void detect();
  void contactKinematics(const State& state, bool point_energy);
  void normalForces();
  void friction(const State& state);
  void assemble(const State& state);
  void listedContactSums(const State& state, bool with_accelerations);  // assemble's, split
  void unconstrainedAccelerations(const State& state);
  void solveConstraints(const State& state);

  void accumulateSprings(const State& state);
  void accumulateBushingsAndTorsion(const State& state);  // core/bushing.hpp, torsional_spring.hpp

  std::shared_ptr<const Model> model_;
  contact::CollisionDetector detector_;
  ConstraintSolver solver_;
  JointForces joint_forces_;
  AppliedLoads loads_;
  mutable ConstraintProjection projection_;  // scratch only; initialState() uses it
  Workspace ws_;
  std::vector<Mat3> inv_inertia_body_;  // per body, zero for kinematic bodies
  // Per body: 1 / I for a dynamic body whose body-frame inertia is exactly I times the
  // identity (a sphere, a cube): its world inertia is I in every orientation (R I R^T = I),
  // so updatePoses leaves its inverse as the constructor set it, and its gyroscopic term
  // w x (I w) is zero; 0 for every other body, which takes the general formulas.
  std::vector<double> isotropic_inverse_;
  // Per body, Body::dynamicMass (0: kinematic): the passes over bodies read it rather than
  // the model's body record (288 bytes): on the 32 000 spheres of the chute that record's
  // cache miss was three quarters of the accelerations' time (perf, docs/performance.md).
  std::vector<double> dynamic_mass_;
  std::vector<contact::GeometryMotion> geometry_motion_;  // per geometry, contactKinematics
  // Per geometry, its body's index (-1 on the world): the passes over geometries read it
  // rather than the model's geometry record (a few hundred bytes, one cache line each).
  std::vector<int> geometry_body_;
  // Per body, one geometry whose local pose is the identity (-1 when none): updatePoses
  // writes its pose (the body's own) in the pass over bodies, while the rotation is in
  // registers; the pass over geometries takes the others (geometry_elsewhere_), so in a scene
  // of one-geometry bodies (a pile, a chute) that pass is the world's geometries alone.
  std::vector<int> origin_geometry_;
  struct GeometryElsewhere {
    int geometry;
    bool at_body_origin;  // its local pose is the identity (a body's second such geometry)
  };
  std::vector<GeometryElsewhere> geometry_elsewhere_;
  std::vector<std::size_t> prescribed_bodies_;
  // Bodies whose surface velocity is a signal, each with its memo (core/signal_memo.hpp).
  std::vector<std::pair<std::size_t, SignalVectorMemo>> varying_surfaces_;
  FrictionStates friction_;
  bool profiling_ = false;
  StageProfile profile_;
  double fcl_offset_ = 0.0;  // detector's FCL seconds when profiling was switched on
  int threads_ = 1, most_threads_ = 1;
  // assemble on more than one thread: per contact point its two bodies (A, B); per body the
  // entries of its points in contact order, 2 i + 1 where it is point i's B and 2 i where A
  // (body_points_, from body_point_start_[b] to body_point_start_[b + 1]): each body's sum
  // then runs on its own thread in the one-thread order, without a copy of each point's wrench.
  std::vector<std::pair<BodyIndex, BodyIndex>> point_bodies_;
  std::vector<int> body_point_start_, body_points_;
  // contactKinematics with the friction in its pass: each chunk of points' deepest depth and
  // whether its forces are all finite.
  struct ChunkSummary {
    double deepest = 0.0;
    bool finite = true;
  };
  std::vector<ChunkSummary> chunk_summary_;
  // detect: the last detection's pairs by id (each pair id once, in the points' order), and
  // the list being written.
  std::vector<std::pair<int, ContactPair>> pair_memo_, pair_memo_next_;
  // The friction is formed in contactKinematics' pass (the friction stage has nothing left to
  // do): the stages are not timed apart and no dynamic law is in play.
  bool frictionInPointsPass() const { return !profiling_ && friction_.pointwise(); }
};

}  // namespace tribo
