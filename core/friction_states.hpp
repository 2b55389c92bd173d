// Friction memory: the one owner of what friction laws remember from step to step, and of
// the friction stage of a force evaluation.
//
// Two kinds of memory, both per contact point and both found again by contact identity
// (contact/contact_identity.hpp):
//   anchors   stateful laws (elastic_stick): State::stick_anchors, one StickAnchor per point
//             (contact/stick_anchor.hpp), re-set after every step at the slip and load the
//             law decides (afterStep);
//   states    dynamic laws (LuGre, Dahl, elasto-plastic, GMS, rate-and-state; on contacts
//             and on joints): an internal state z integrated with the bodies, dz/dt = g(z, v,
//             N) (friction/dynamic_law.hpp). State::friction_values holds every z: first
//             each joint's fixed slice in joint order (core/joint_forces.hpp), then one slice
//             per contact record of State::friction_states (contact/dynamic_friction.hpp).
// Around one step:
//   beforeStep  every contact point of the evaluation at the step's start gets its record
//               (continuing the one it matched, a new one from the law's initial state,
//               ended contacts forgotten); stored tangent vectors are turned to the current
//               normal (and, anisotropic, the current axis: they turn with the grain) once
//               either has turned by more than kRebaseAngle;
//   evaluate    the friction stage: each point's friction force (the points of a plain
//               material in batches, friction/tangential_batch.hpp); for dynamic laws also dz/dt
//               into Workspace::friction_state_rate. When two points continue one record,
//               the first in contact order drives it (its rate is the record's);
//   the integrator advances z with the bodies: semi-implicit Euler through stepStable (the
//               law's bounded update), RK4 through addRates (z + dt dz/dt), SUNDIALS as part
//               of its vector y;
//   afterStep   stateful laws and rolling and spinning resistance (contact/
//               rolling_resistance.hpp: an angular anchor) move their anchors.
// Quasi-steady friction (setSteady): dynamic laws act through their steady-state curve, as
// memoryless laws (the steady-state search of `tribo modes`).
// Not here: the laws (friction/), contact identity (contact/), the step (core/simulator.hpp).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "contact/stick_anchor.hpp"
#include "core/joint_forces.hpp"
#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"
#include "friction/dynamic_law.hpp"
#include "friction/tangential_batch.hpp"

namespace tribo {

class FrictionStates {
 public:
  // `joints`: the model's joint elements (their dynamic laws' slices come first).
  FrictionStates(const Model& model, const JointForces& joints);

  // Some material's law keeps anchors / some material's or joint's law has an internal state.
  bool stateful() const { return any_stateful_; }
  bool dynamic() const { return any_dynamic_; }
  // The joints' slices' total: the contact records' states start here.
  int jointValues() const { return joint_values_; }
  void setSteady(bool on) { steady_ = on; }

  // The memory a run starts with: no anchors or records, the joints' initial states.
  void initial(State& state, const JointForces& joints) const;

  // The friction stage of an evaluation at `state` (contact points, their pairs and normal
  // forces in `ws`), on up to `threads` threads when no dynamic law is in play.
  void evaluate(const State& state, Workspace& ws, int threads) const;
  // The same stage one chunk at a time, for the points' pass of core/dynamics.cpp, which forms
  // each chunk's kinematics and normal forces and then its friction while its records are in
  // cache: points [kChunk c, kChunk (c + 1)) of ws.contacts (fewer in the last chunk). Only
  // while no dynamic law is in play (pointwise()): then each point's force depends on its own
  // record alone, and evaluate is these chunks in any order, the same bits.
  static constexpr std::size_t kChunk = friction::TangentialBatch::kCapacity;
  bool pointwise() const { return !any_dynamic_; }
  void evaluateChunk(const State& state, Workspace& ws, std::size_t chunk) const;
  // Before a step, with `ws` evaluated at `state`: the records of dynamic laws (above).
  // Returns true when a force of the evaluation may have changed (a state was turned or a
  // record shared by two points was split), so the caller must evaluate again; otherwise it
  // refreshes ws's state rates for the new records itself.
  bool beforeStep(State& state, Workspace& ws);
  // After a step, with `ws` evaluated at `state`: stateful laws decide their contacts' mode
  // and elongation and re-set their anchors; returns true when they changed.
  bool afterStep(State& state, const Workspace& ws);
  // Semi-implicit Euler's update of every internal state over h at the slip and load of
  // `ws` (DynamicFrictionLaw::stableStep): bounded for stiff bristles.
  void stepStable(State& state, const Workspace& ws, const JointForces& joints, double h) const;

  // The first internal state that is not finite, as a message naming the law and the body
  // (`body` set to its name, or empty for a joint's); empty when all are finite.
  std::string nonFinite(const State& state, std::string& body) const;

  static constexpr double kRebaseAngle = 1e-3;  // [rad]

 private:
  // A point whose material is not batched: memoryless or stateful law, in its law's plane,
  // with its rolling and spinning moment.
  void evaluatePoint(const State& state, Workspace& ws, contact::ContactRecord& rec) const;

  const Model* model_;
  int joint_values_ = 0;
  std::vector<char> stateful_material_;  // per material
  std::vector<char> anchored_material_;  // per material: stateful, or rolling resistance
  // Per material: a law without anchors, isotropic, without rolling resistance, whose points
  // go through the law in batches (friction/tangential_batch.hpp) while no dynamic law is in
  // play (or all act through their steady curve).
  std::vector<char> batched_material_;
  std::vector<const friction::DynamicFrictionLaw*> dynamic_law_;  // per material, or nullptr
  bool any_stateful_ = false;
  bool any_dynamic_ = false;
  bool steady_ = false;
  contact::AnchorBook anchor_book_;
  contact::RecordBook<contact::FrictionStateRecord> state_book_;
  std::vector<double> next_values_;
};

// The explicit integrators' update of the internal states: to.friction_values = from's +
// dt * rate (rate: Workspace::friction_state_rate, or a weighted sum of them). `to` may be
// `from`.
void addRates(const State& from, std::span<const double> rate, double dt, State& to);

}  // namespace tribo
