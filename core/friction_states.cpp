#include "core/friction_states.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "contact/contact_force.hpp"
#include "contact/dynamic_friction.hpp"
#include "contact/parallel_range.hpp"

namespace tribo {

namespace {

// The pair of ws.contacts[i], for a record of ws.contacts.
const ContactPair& pairOf(const Workspace& ws, const contact::ContactRecord& rec) {
  return ws.contact_pair[static_cast<std::size_t>(&rec - ws.contacts.data())];
}

contact::AnchorFrames anchorFrames(const Model& model, const Workspace& ws,
                                   const ContactPair& pair) {
  return {&ws.geometry_poses[pair.geometry_a], &ws.geometry_poses[pair.geometry_b],
          surfaceVelocityOf(model, ws.rotation, ws.surface_velocity, pair.geometry_a),
          surfaceVelocityOf(model, ws.rotation, ws.surface_velocity, pair.geometry_b)};
}

std::string bodyOfPair(const Model& m, int pair_id) {
  const Geometry& g = m.geometries[m.contactPair(pair_id).geometry_b];
  return g.body.isWorld() ? "world" : m.bodies[g.body.value].name;
}

}  // namespace

FrictionStates::FrictionStates(const Model& model, const JointForces& joints)
    : model_(&model), joint_values_(joints.jointStateSize()) {
  for (const auto& material : model.materials) {
    stateful_material_.push_back(material.friction->stateful() ? 1 : 0);
    any_stateful_ = any_stateful_ || material.friction->stateful();
    dynamic_law_.push_back(material.friction->dynamic());
    any_dynamic_ = any_dynamic_ || material.friction->dynamic() != nullptr;
  }
  any_dynamic_ = any_dynamic_ || joint_values_ > 0;
}

void FrictionStates::initial(State& state, const JointForces& joints) const {
  state.stick_anchors.clear();
  state.friction_states.clear();
  state.friction_values.assign(static_cast<std::size_t>(joint_values_), 0.0);
  joints.initialJointStates(state.friction_values.data());
}

void FrictionStates::evaluate(const State& state, Workspace& ws, int threads) const {
  const Model& m = *model_;
  if (any_dynamic_) {  // the joints' rates, first, are the joint stage's (assemble)
    ws.friction_state_rate.resize(state.friction_values.size());
    std::fill(ws.friction_state_rate.begin() + joint_values_, ws.friction_state_rate.end(), 0.0);
    ws.friction_state_contact.assign(state.friction_states.size(), -1);
  }
  // Memoryless and stateful laws: each point on its own (stateful ones only read the
  // anchors), so in parallel when no dynamic law is in play.
  auto independent = [&](contact::ContactRecord& rec) {
    const ContactPair& pair = pairOf(ws, rec);
    const contact::Material& material = m.materials[pair.material];
    if (!stateful_material_[pair.material]) {
      contact::frictionForce(material, rec);
      return;
    }
    const contact::StickAnchor* anchor =
        contact::findAnchor(state.stick_anchors, rec.point, m.options.collision.match_radius);
    const friction::StickView view =
        contact::stickView(anchor, rec.point, anchorFrames(m, ws, pair), state.time);
    contact::frictionForce(material, view, rec);
  };
  if (!any_dynamic_ || steady_) {
    contact::parallelFor(ws.contacts.size(), threads,
                         [&](std::size_t i) { independent(ws.contacts[i]); });
    return;
  }
  // Dynamic laws: the first point using a record drives it, so in contact order.
  const std::span<const contact::FrictionStateRecord> records(state.friction_states);
  std::array<double, contact::kMaxFrictionState> z, zdot, back;
  for (std::size_t i = 0; i < ws.contacts.size(); ++i) {
    contact::ContactRecord& rec = ws.contacts[i];
    const friction::DynamicFrictionLaw* law = dynamic_law_[pairOf(ws, rec).material];
    if (law == nullptr) {
      independent(rec);
      continue;
    }
    const contact::FrictionStateRecord* record =
        contact::findRecord(records, rec.point, m.options.collision.match_radius);
    if (record == nullptr) {
      law->initialState(z.data());  // a contact new within the step: not integrated yet
      contact::dynamicFrictionForce(*law, z.data(), rec, zdot.data());
      continue;
    }
    contact::transportState(*law, &state.friction_values[record->state], record->normal,
                            rec.point.normal, z.data());
    contact::dynamicFrictionForce(*law, z.data(), rec, zdot.data());
    const auto r = static_cast<std::size_t>(record - records.data());
    if (ws.friction_state_contact[r] >= 0) continue;  // the first point using it drives it
    ws.friction_state_contact[r] = static_cast<int>(i);
    contact::transportState(*law, zdot.data(), record->normal, rec.point.normal, back.data(), true);
    std::copy_n(back.data(), record->state_size, &ws.friction_state_rate[record->state]);
  }
}

bool FrictionStates::beforeStep(State& state, Workspace& ws) {
  if (!any_dynamic_) return false;
  const Model& m = *model_;
  const double cos_rebase = std::cos(kRebaseAngle);
  const std::span<const contact::FrictionStateRecord> records(state.friction_states);
  bool forces_changed = false;
  state_book_.begin(records);
  // Joints' states first, as they are; the contacts' records after them.
  next_values_.assign(state.friction_values.begin(), state.friction_values.begin() + joint_values_);
  for (const contact::ContactRecord& rec : ws.contacts) {
    const friction::DynamicFrictionLaw* law = dynamic_law_[pairOf(ws, rec).material];
    if (law == nullptr) continue;
    const contact::FrictionStateRecord* old =
        contact::findRecord(records, rec.point, m.options.collision.match_radius);
    contact::FrictionStateRecord next;
    next.key = state_book_.claim(rec.point, old);
    next.position = rec.point.position;
    next.state = static_cast<int>(next_values_.size());
    next.state_size = law->stateSize();
    next_values_.resize(next_values_.size() + static_cast<std::size_t>(next.state_size));
    double* z = &next_values_[static_cast<std::size_t>(next.state)];
    if (old != nullptr && old->key == next.key) {
      const double* stored = &state.friction_values[static_cast<std::size_t>(old->state)];
      if (old->normal.dot(rec.point.normal) < cos_rebase) {
        contact::transportState(*law, stored, old->normal, rec.point.normal, z);
        next.normal = rec.point.normal;
        forces_changed = forces_changed || law->tangentVectors() > 0;
      } else {
        std::copy_n(stored, next.state_size, z);
        next.normal = old->normal;
      }
    } else {
      law->initialState(z);
      next.normal = rec.point.normal;
      // The evaluation gave this point the state of a record another point continues.
      forces_changed = forces_changed || old != nullptr;
    }
    state_book_.add(next);
  }
  state_book_.finish(state.friction_states);
  state.friction_values.swap(next_values_);
  // Same forces: the rates for the new records (the stage's order does not need threads).
  if (!forces_changed) evaluate(state, ws, 1);
  return forces_changed;
}

bool FrictionStates::afterStep(State& state, const Workspace& ws) {
  if (!any_stateful_) return false;
  const Model& m = *model_;
  anchor_book_.begin(state.stick_anchors);
  for (const contact::ContactRecord& rec : ws.contacts) {
    const ContactPair& pair = pairOf(ws, rec);
    if (!stateful_material_[pair.material]) continue;
    const contact::AnchorFrames frames = anchorFrames(m, ws, pair);
    const contact::StickAnchor* old =
        contact::findAnchor(state.stick_anchors, rec.point, m.options.collision.match_radius);
    const friction::StickView view = contact::stickView(old, rec.point, frames, state.time);
    const friction::StickUpdate update =
        m.materials[pair.material].friction->advance(rec.slip, rec.normal_force, view);
    anchor_book_.add(contact::anchorAt(anchor_book_.claim(rec.point, old), rec.point, frames,
                                       state.time, update));
  }
  return anchor_book_.finish(state.stick_anchors);
}

void FrictionStates::stepStable(State& state, const Workspace& ws, const JointForces& joints,
                                double h) const {
  joints.stepStates(state, h);
  std::array<double, contact::kMaxFrictionState> z, back;
  for (std::size_t r = 0; r < state.friction_states.size(); ++r) {
    if (r >= ws.friction_state_contact.size() || ws.friction_state_contact[r] < 0) continue;
    const contact::ContactRecord& rec =
        ws.contacts[static_cast<std::size_t>(ws.friction_state_contact[r])];
    const friction::DynamicFrictionLaw& law = *dynamic_law_[pairOf(ws, rec).material];
    const contact::FrictionStateRecord& record = state.friction_states[r];
    double* stored = &state.friction_values[static_cast<std::size_t>(record.state)];
    contact::transportState(law, stored, record.normal, rec.point.normal, z.data());
    law.stableStep(z.data(), rec.slip, rec.normal_force, h);
    contact::transportState(law, z.data(), record.normal, rec.point.normal, back.data(), true);
    std::copy_n(back.data(), record.state_size, stored);
  }
}

std::string FrictionStates::nonFinite(const State& state, std::string& body) const {
  const Model& m = *model_;
  body.clear();
  auto finite = [](double x) { return std::isfinite(x); };
  const auto joints_end =
      state.friction_values.begin() +
      std::min<std::ptrdiff_t>(joint_values_, std::ssize(state.friction_values));
  if (!std::all_of(state.friction_values.begin(), joints_end, finite))
    return "the internal state of a joint's friction law is not finite";
  for (const contact::FrictionStateRecord& record : state.friction_states) {
    const double* z = &state.friction_values[static_cast<std::size_t>(record.state)];
    if (std::all_of(z, z + record.state_size, finite)) continue;
    const int pair = contact::keyPair(record.key);
    body = bodyOfPair(m, pair);
    return "the internal state of friction law '" +
           std::string(m.materials[m.contactPair(pair).material].friction->name()) +
           "' at a contact of body '" + body + "' is not finite";
  }
  return {};
}

void addRates(const State& from, std::span<const double> rate, double dt, State& to) {
  for (std::size_t i = 0; i < from.friction_values.size(); ++i)
    to.friction_values[i] = from.friction_values[i] + dt * rate[i];
}

}  // namespace tribo
