#include "core/friction_states.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "contact/contact_force.hpp"
#include "contact/dynamic_friction.hpp"
#include "contact/parallel_range.hpp"
#include "friction/tangential_batch.hpp"

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

// The principal axes at a contact of an anisotropic material (contact/anisotropy.hpp).
contact::SlipAxes slipAxesOf(const Workspace& ws, const ContactPair& pair,
                             const contact::Anisotropy& an, const contact::ContactRecord& rec) {
  const int g = an.frame_is_b ? pair.geometry_b : pair.geometry_a;
  return contact::slipAxes(an, ws.geometry_poses[static_cast<std::size_t>(g)].linear(),
                           rec.point.normal);
}

// The friction stage of one point in its law's scaled plane when the material is anisotropic
// (contact/anisotropy.hpp): the constructor moves rec.slip into it, leave() moves the force
// and slip back; for an isotropic material both do nothing.
class LawPlane {
 public:
  LawPlane(const Workspace& ws, const ContactPair& pair, const contact::Anisotropy& an,
           contact::ContactRecord& rec)
      : an_(an) {
    if (!an.active) return;
    axes_ = slipAxesOf(ws, pair, an, rec);
    slip_ = contact::enterLawPlane(an, axes_, rec);
  }
  // A vector of the slip's kind (a stick spring's elongation) in the plane.
  Eigen::Vector3d in(const Eigen::Vector3d& v) const {
    return an_.active ? contact::toLawPlane(an_, axes_, v) : v;
  }
  void leave(contact::ContactRecord& rec) const {
    if (an_.active) contact::leaveLawPlane(an_, axes_, slip_, rec);
  }
  // The frame geometry's axes at this point; null for an isotropic material.
  const contact::SlipAxes* axes() const { return an_.active ? &axes_ : nullptr; }

 private:
  const contact::Anisotropy& an_;
  contact::SlipAxes axes_;
  Eigen::Vector3d slip_ = Eigen::Vector3d::Zero();
};

// A record's state z carried into the point's current frame (or back, `inverse`): against
// the normal only, or with the anisotropy's axis when `axes` is given
// (contact/dynamic_friction.hpp).
void transport(const friction::DynamicFrictionLaw& law, const double* z,
               const contact::FrictionStateRecord& record, const contact::ContactRecord& rec,
               const contact::SlipAxes* axes, double* out, bool inverse = false) {
  if (axes != nullptr)
    contact::transportStateWithAxis(law, z, record.normal, record.axis, rec.point.normal, axes->t1,
                                    out, inverse);
  else
    contact::transportState(law, z, record.normal, rec.point.normal, out, inverse);
}

// A geometry's angular velocity (its body's; zero on the world).
Vec3 angularVelocityOf(const Model& m, const State& state, int geometry) {
  const BodyIndex b = m.geometries[static_cast<std::size_t>(geometry)].body;
  return b.isWorld() ? Vec3::Zero() : state.bodies[b.value].angular_velocity;
}

// Rolling and spinning resistance (contact/rolling_resistance.hpp): rec.moment from the
// pair's relative angular velocity and the point's angular anchor (none: just anchored).
void resistingMoment(const Model& m, const State& state, const Workspace& ws,
                     const ContactPair& pair, const contact::StickAnchor* anchor,
                     contact::ContactRecord& rec) {
  const contact::RollingResistance& r = m.materials[pair.material].resistance;
  const Eigen::Matrix3d rot_a = ws.geometry_poses[pair.geometry_a].linear();
  const Eigen::Matrix3d rot_b = ws.geometry_poses[pair.geometry_b].linear();
  const contact::AngularAnchor none;
  const contact::AngularAnchor& angular = anchor ? anchor->angular : none;
  const Vec3 theta = anchor ? contact::angularElongation(angular, rot_a, rot_b) : Vec3::Zero();
  const Vec3 w =
      angularVelocityOf(m, state, pair.geometry_b) - angularVelocityOf(m, state, pair.geometry_a);
  rec.moment = contact::resistingMoment(r, rec.point.normal, w, rec.normal_force, anchor != nullptr,
                                        angular, theta);
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
    anchored_material_.push_back(material.friction->stateful() || material.resistance.active());
    batched_material_.push_back(!anchored_material_.back() && !material.anisotropy.active);
    any_stateful_ = any_stateful_ || anchored_material_.back();
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

void FrictionStates::evaluatePoint(const State& state, Workspace& ws,
                                   contact::ContactRecord& rec) const {
  const Model& m = *model_;
  const ContactPair& pair = pairOf(ws, rec);
  const contact::Material& material = m.materials[pair.material];
  const LawPlane plane(ws, pair, material.anisotropy, rec);
  const contact::StickAnchor* anchor =
      anchored_material_[pair.material]
          ? contact::findAnchor(state.stick_anchors, rec.point, m.options.collision.match_radius)
          : nullptr;
  if (!stateful_material_[pair.material]) {
    contact::frictionForce(material, rec);
  } else {
    friction::StickView view =
        contact::stickView(anchor, rec.point, anchorFrames(m, ws, pair), state.time);
    view.elongation = plane.in(view.elongation);
    contact::frictionForce(material, view, rec);
  }
  plane.leave(rec);
  if (material.resistance.active()) resistingMoment(m, state, ws, pair, anchor, rec);
}

// Each run of points of one plain material through its law as a batch; the others one by one
// (stateful laws only read the anchors, so every point on its own). The batches are the
// point-by-point arithmetic: the same bits for any split.
void FrictionStates::evaluateChunk(const State& state, Workspace& ws, std::size_t chunk) const {
  const Model& m = *model_;
  const std::size_t end = std::min(ws.contacts.size(), (chunk + 1) * kChunk);
  friction::TangentialBatch batch;
  for (std::size_t i = chunk * kChunk; i < end;) {
    const int material = ws.contact_pair[i].material;
    if (!batched_material_[material]) {
      evaluatePoint(state, ws, ws.contacts[i++]);
      continue;
    }
    const std::size_t first = i;
    const friction::FrictionLaw& law = *m.materials[material].friction;
    for (batch.clear(); i < end && ws.contact_pair[i].material == material; ++i)
      batch.add(ws.contacts[i].slip);
    batch.evaluate(law);
    for (std::size_t k = 0; k < batch.size; ++k) {
      contact::ContactRecord& rec = ws.contacts[first + k];
      rec.friction_force = batch.force(k, rec.slip, rec.normal_force, &rec.mu);
    }
  }
}

void FrictionStates::evaluate(const State& state, Workspace& ws, int threads) const {
  const Model& m = *model_;
  if (any_dynamic_) {  // the joints' rates, first, are the joint stage's (assemble)
    ws.friction_state_rate.resize(state.friction_values.size());
    std::fill(ws.friction_state_rate.begin() + joint_values_, ws.friction_state_rate.end(), 0.0);
    ws.friction_state_contact.assign(state.friction_states.size(), -1);
  }
  if (!any_dynamic_ || steady_) {
    // Each chunk of points on its own: the same bits for any split.
    const std::size_t n = ws.contacts.size();
    contact::parallelFor((n + kChunk - 1) / kChunk, threads,
                         [&](std::size_t chunk) { evaluateChunk(state, ws, chunk); });
    return;
  }
  // Dynamic laws: the first point using a record drives it, so in contact order.
  auto resistance = [&](contact::ContactRecord& rec, const ContactPair& pair) {
    if (!m.materials[pair.material].resistance.active()) return;
    resistingMoment(
        m, state, ws, pair,
        contact::findAnchor(state.stick_anchors, rec.point, m.options.collision.match_radius), rec);
  };
  const std::span<const contact::FrictionStateRecord> records(state.friction_states);
  std::array<double, contact::kMaxFrictionState> z, zdot, back;
  for (std::size_t i = 0; i < ws.contacts.size(); ++i) {
    contact::ContactRecord& rec = ws.contacts[i];
    const ContactPair& pair = pairOf(ws, rec);
    const friction::DynamicFrictionLaw* law = dynamic_law_[pair.material];
    if (law == nullptr) {
      evaluatePoint(state, ws, rec);
      continue;
    }
    const LawPlane plane(ws, pair, m.materials[pair.material].anisotropy, rec);
    const contact::FrictionStateRecord* record =
        contact::findRecord(records, rec.point, m.options.collision.match_radius);
    if (record == nullptr) {
      law->initialState(z.data());  // a contact new within the step: not integrated yet
      contact::dynamicFrictionForce(*law, z.data(), rec, zdot.data());
      plane.leave(rec);
      resistance(rec, pair);
      continue;
    }
    transport(*law, &state.friction_values[record->state], *record, rec, plane.axes(), z.data());
    contact::dynamicFrictionForce(*law, z.data(), rec, zdot.data());
    plane.leave(rec);
    resistance(rec, pair);
    const auto r = static_cast<std::size_t>(record - records.data());
    if (ws.friction_state_contact[r] >= 0) continue;  // the first point using it drives it
    ws.friction_state_contact[r] = static_cast<int>(i);
    transport(*law, zdot.data(), *record, rec, plane.axes(), back.data(), true);
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
    const ContactPair& pair = pairOf(ws, rec);
    const friction::DynamicFrictionLaw* law = dynamic_law_[pair.material];
    if (law == nullptr) continue;
    // An anisotropic material's state is kept against its axes too (contact/
    // dynamic_friction.hpp): re-set when the normal or the axis turned past the angle.
    const contact::Anisotropy& an = m.materials[pair.material].anisotropy;
    const contact::SlipAxes axes = an.active ? slipAxesOf(ws, pair, an, rec) : contact::SlipAxes{};
    const contact::SlipAxes* turning = an.active ? &axes : nullptr;
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
      if (old->normal.dot(rec.point.normal) < cos_rebase ||
          (turning != nullptr && old->axis.dot(axes.t1) < cos_rebase)) {
        transport(*law, stored, *old, rec, turning, z);
        next.normal = rec.point.normal;
        next.axis = axes.t1;
        forces_changed = forces_changed || law->tangentVectors() > 0;
      } else {
        std::copy_n(stored, next.state_size, z);
        next.normal = old->normal;
        next.axis = old->axis;
      }
    } else {
      law->initialState(z);
      next.normal = rec.point.normal;
      next.axis = axes.t1;
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
    if (!anchored_material_[pair.material]) continue;
    const contact::AnchorFrames frames = anchorFrames(m, ws, pair);
    const contact::StickAnchor* old =
        contact::findAnchor(state.stick_anchors, rec.point, m.options.collision.match_radius);
    const contact::Material& material = m.materials[pair.material];
    const contact::Anisotropy& an = material.anisotropy;
    friction::StickUpdate update;  // a memoryless or dynamic law: only the angular anchor
    if (stateful_material_[pair.material]) {
      friction::StickView view = contact::stickView(old, rec.point, frames, state.time);
      if (an.active) {  // the law decides in its scaled plane (contact/anisotropy.hpp)
        const contact::SlipAxes axes = slipAxesOf(ws, pair, an, rec);
        view.elongation = contact::toLawPlane(an, axes, view.elongation);
        update = material.friction->advance(contact::toLawPlane(an, axes, rec.slip),
                                            rec.normal_force, view);
        update.elongation = contact::fromLawPlane(an, axes, update.elongation);
      } else {
        update = material.friction->advance(rec.slip, rec.normal_force, view);
      }
    }
    contact::StickAnchor next = contact::anchorAt(anchor_book_.claim(rec.point, old), rec.point,
                                                  frames, state.time, update);
    if (const contact::RollingResistance& r = material.resistance; r.active()) {
      const Eigen::Matrix3d rot_a = frames.pose_a->linear(), rot_b = frames.pose_b->linear();
      const contact::AngularAnchor none;
      const contact::AngularAnchor& angular = old ? old->angular : none;
      const Vec3 theta = old ? contact::angularElongation(angular, rot_a, rot_b) : Vec3::Zero();
      const Vec3 w = angularVelocityOf(m, state, pair.geometry_b) -
                     angularVelocityOf(m, state, pair.geometry_a);
      next.angular = contact::advanceAngular(r, rec.point.normal, w, rec.normal_force,
                                             old != nullptr, angular, theta, rot_a, rot_b);
    }
    anchor_book_.add(next);
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
    const ContactPair& pair = pairOf(ws, rec);
    const friction::DynamicFrictionLaw& law = *dynamic_law_[pair.material];
    const contact::Anisotropy& an = model_->materials[pair.material].anisotropy;
    const contact::FrictionStateRecord& record = state.friction_states[r];
    double* stored = &state.friction_values[static_cast<std::size_t>(record.state)];
    const contact::SlipAxes axes = an.active ? slipAxesOf(ws, pair, an, rec) : contact::SlipAxes{};
    const contact::SlipAxes* turning = an.active ? &axes : nullptr;
    transport(law, stored, record, rec, turning, z.data());
    const Eigen::Vector3d slip = an.active ? contact::toLawPlane(an, axes, rec.slip) : rec.slip;
    law.stableStep(z.data(), slip, rec.normal_force, h);
    transport(law, z.data(), record, rec, turning, back.data(), true);
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
    return "the friction state (the internal state of a joint's friction law) is not finite";
  for (const contact::FrictionStateRecord& record : state.friction_states) {
    const double* z = &state.friction_values[static_cast<std::size_t>(record.state)];
    if (std::all_of(z, z + record.state_size, finite)) continue;
    const int pair = contact::keyPair(record.key);
    body = bodyOfPair(m, pair);
    return "the friction state (the internal state of friction law '" +
           std::string(m.materials[m.contactPair(pair).material].friction->name()) +
           "') at a contact of body '" + body + "' is not finite";
  }
  return {};
}

void addRates(const State& from, std::span<const double> rate, double dt, State& to) {
  for (std::size_t i = 0; i < from.friction_values.size(); ++i)
    to.friction_values[i] = from.friction_values[i] + dt * rate[i];
}

}  // namespace tribo
