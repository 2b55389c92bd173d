#include "core/sundials_system.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/prescribed_motion.hpp"

namespace tribo {

namespace {

constexpr int kP = 0, kQ = 3, kV = 7, kW = 10;  // offsets within a body's block
// Added to the signed slip so that a contact sticking exactly (slip 0.0, e.g. a box set on a
// belt at belt speed) does not make an event function vanish identically, which root
// finding cannot handle; a reversal is then located at s.d = -1e-12 m/s.
constexpr double kSignedOffset = 1e-12;  // [m/s]

}  // namespace

OdeSystem::OdeSystem(const Model& model, bool events)
    : model_(model), events_(events), slots_(events ? PairSlots(model) : PairSlots()) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].kind == BodyKind::kDynamic) dynamic_.push_back(static_cast<int>(b));
  base_.bodies.resize(model.bodies.size());
  scratch_.bodies.resize(model.bodies.size());
  for (const ContactPair& pair : slots_.pairs()) {
    const friction::FrictionLaw& law = *model.materials[pair.material].friction;
    PairEvents e;
    std::vector<double> speeds = law.breakpoints();
    speeds.push_back(law.stickSpeed());
    std::sort(speeds.begin(), speeds.end());
    for (double s : speeds)
      if (std::isfinite(s) && s > 0.0 && (e.speeds.empty() || s > e.speeds.back() * (1 + 1e-12)))
        e.speeds.push_back(s);
    event_count_ += static_cast<int>(e.speeds.size()) + 1;
    pairs_.push_back(e);
  }
  cached_g_.resize(event_count_);
  cached_y_.resize(size());
  max_slip_.resize(pairs_.size());
  signed_slip_.resize(pairs_.size());
  points_.resize(pairs_.size());
}

void OdeSystem::begin(const State& state, const Workspace& ws, double* y) {
  base_ = state;
  scratch_.stick_anchors = state.stick_anchors;  // stateful friction: fixed over a segment
  scratch_.friction_states = state.friction_states;
  values_ = static_cast<int>(state.friction_values.size());
  cached_y_.resize(static_cast<std::size_t>(size()));
  std::copy(state.friction_values.begin(), state.friction_values.end(),
            y + kPerBody * dynamic_.size());
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const BodyState& s = state.bodies[dynamic_[i]];
    double* block = y + kPerBody * i;
    for (int k = 0; k < 3; ++k) {
      block[kP + k] = s.position[k];
      block[kV + k] = s.velocity[k];
      block[kW + k] = s.angular_velocity[k];
    }
    for (int k = 0; k < 4; ++k) block[kQ + k] = s.orientation.coeffs()[k];
  }
  // Reference directions: the largest slip of each pair that has none yet.
  std::vector<double> best(pairs_.size(), 0.0);
  for (const auto& c : ws.contacts) {
    if (pairs_.empty()) break;  // no events
    const auto p = static_cast<std::size_t>(slots_.slot(c.point.pair));
    PairEvents& e = pairs_[p];
    const double s = c.slip.norm();
    if (e.direction_known || !(s > best[p])) continue;
    best[p] = s;
    e.direction = c.slip / s;
  }
  for (std::size_t p = 0; p < pairs_.size(); ++p)
    if (best[p] > 0.0) pairs_[p].direction_known = true;
  cache_valid_ = false;
}

void OdeSystem::unpack(double t, const double* y, State& out) const {
  out.time = t;
  const double dt = t - base_.time;
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const Body& body = model_.bodies[b];
    if (body.kind == BodyKind::kDynamic) continue;
    BodyState& s = out.bodies[b];
    if (body.motion) {  // along signals: exact at t (core/prescribed_motion.hpp)
      s = body.motion->at(body, t);
      continue;
    }
    const BodyState& s0 = base_.bodies[b];
    s.position = s0.position + dt * s0.velocity;
    s.orientation = rotateBy(s0.angular_velocity, dt, s0.orientation);
    s.velocity = s0.velocity;
    s.angular_velocity = s0.angular_velocity;
  }
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const double* block = y + kPerBody * i;
    BodyState& s = out.bodies[dynamic_[i]];
    s.position = Vec3(block[kP], block[kP + 1], block[kP + 2]);
    s.orientation.coeffs() =
        Eigen::Vector4d(block[kQ], block[kQ + 1], block[kQ + 2], block[kQ + 3]);
    s.orientation.normalize();
    s.velocity = Vec3(block[kV], block[kV + 1], block[kV + 2]);
    s.angular_velocity = Vec3(block[kW], block[kW + 1], block[kW + 2]);
  }
  const double* z = y + kPerBody * dynamic_.size();
  out.friction_values.assign(z, z + values_);
}

bool OdeSystem::rhs(double t, const double* y, double* ydot) {
  unpack(t, y, scratch_);
  const Workspace& ws = dynamics_->evaluate(scratch_);
  ++evaluations_;
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const int b = dynamic_[i];
    const double* block = y + kPerBody * i;
    double* d = ydot + kPerBody * i;
    const Vec3 w(block[kW], block[kW + 1], block[kW + 2]);
    Quat q;
    q.coeffs() = Eigen::Vector4d(block[kQ], block[kQ + 1], block[kQ + 2], block[kQ + 3]);
    const Eigen::Vector4d dq = quaternionRate(w, q);
    for (int k = 0; k < 3; ++k) {
      d[kP + k] = block[kV + k];
      d[kV + k] = ws.linear_acceleration[b][k];
      d[kW + k] = ws.angular_acceleration[b][k];
    }
    for (int k = 0; k < 4; ++k) d[kQ + k] = dq[k];
  }
  std::copy_n(ws.friction_state_rate.begin(), values_, ydot + kPerBody * dynamic_.size());
  bad_component_ = -1;
  for (int k = 0; k < size(); ++k) {
    if (!std::isfinite(ydot[k])) {
      bad_component_ = k;
      cache_valid_ = false;
      return false;
    }
  }
  if (events_ && event_count_ > 0) {
    eventValues(ws, cached_g_.data());
    std::memcpy(cached_y_.data(), y, sizeof(double) * size());
    cached_t_ = t;
    cache_valid_ = true;
  }
  return true;
}

void OdeSystem::events(double t, const double* y, double* g) {
  if (suspended_) {
    std::fill(g, g + event_count_, 1.0);
    return;
  }
  if (!(cache_valid_ && t == cached_t_ &&
        std::memcmp(cached_y_.data(), y, sizeof(double) * size()) == 0)) {
    unpack(t, y, scratch_);
    const Workspace& ws = dynamics_->evaluate(scratch_);
    ++evaluations_;
    eventValues(ws, cached_g_.data());
    std::memcpy(cached_y_.data(), y, sizeof(double) * size());
    cached_t_ = t;
    cache_valid_ = true;
  }
  std::copy(cached_g_.begin(), cached_g_.end(), g);
}

void OdeSystem::eventValues(const Workspace& ws, double* g) {
  std::fill(max_slip_.begin(), max_slip_.end(), 0.0);
  std::fill(signed_slip_.begin(), signed_slip_.end(), 0.0);
  std::fill(points_.begin(), points_.end(), 0);
  for (const auto& c : ws.contacts) {
    const auto p = static_cast<std::size_t>(slots_.slot(c.point.pair));
    max_slip_[p] = std::max(max_slip_[p], c.slip.norm());
    signed_slip_[p] += c.slip.dot(pairs_[p].direction);
    ++points_[p];
  }
  int k = 0;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    for (double s : pairs_[p].speeds) g[k++] = max_slip_[p] - s;
    g[k++] = points_[p] > 0 ? signed_slip_[p] / points_[p] + kSignedOffset : 1.0;
  }
}

double OdeSystem::quaternionDrift(const double* y) const {
  double drift = 0.0;
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const double* q = y + kPerBody * i + kQ;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    drift = std::max(drift, std::abs(norm - 1.0));
  }
  return drift;
}

void OdeSystem::normalizeQuaternions(double* y) const {
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    double* q = y + kPerBody * i + kQ;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (norm > 0.0)
      for (int k = 0; k < 4; ++k) q[k] /= norm;
  }
}

std::pair<std::string, std::string> OdeSystem::componentName(int i) const {
  if (i < 0 || i >= size()) return {"", ""};
  const int bodies = kPerBody * static_cast<int>(dynamic_.size());
  if (i >= bodies) {  // an internal friction state: the body B of its contact
    for (const contact::FrictionStateRecord& r : scratch_.friction_states) {
      if (i - bodies < r.state || i - bodies >= r.state + r.state_size) continue;
      const ContactPair pair = model_.contactPair(contact::keyPair(r.key));
      const BodyIndex b = model_.geometries[pair.geometry_b].body;
      return {b.isWorld() ? "world" : model_.bodies[b.value].name, "friction_state"};
    }
    return {"", "friction_state"};
  }
  static const char* kNames[kPerBody] = {
      "position.x",        "position.y",    "position.z",         "orientation.x",
      "orientation.y",     "orientation.z", "orientation.w",      "velocity.x",
      "velocity.y",        "velocity.z",    "angular_velocity.x", "angular_velocity.y",
      "angular_velocity.z"};
  return {model_.bodies[dynamic_[i / kPerBody]].name, kNames[i % kPerBody]};
}

}  // namespace tribo
