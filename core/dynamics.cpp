#include "core/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "contact/parallel_range.hpp"
#include "core/model_detector.hpp"
#include "core/prescribed_motion.hpp"
#include "core/stage_threads.hpp"

namespace tribo {

using contact::parallelFor;

namespace {

// Motion of geometry g, on body `body` (-1: the world): its body's, with the geometry's
// surface velocity (world). The geometry's record is read only when some body has a surface
// velocity (ws.surface_velocity not empty).
contact::GeometryMotion motionOf(const Model& model, const State& state, const Workspace& ws, int g,
                                 int body) {
  contact::GeometryMotion m;
  if (body < 0) return m;
  const BodyState& s = state.bodies[static_cast<std::size_t>(body)];
  m.origin = s.position;
  m.velocity = s.velocity;
  m.angular_velocity = s.angular_velocity;
  if (!ws.surface_velocity.empty())
    m.surface_velocity = surfaceVelocityOf(model, ws.rotation, ws.surface_velocity, g);
  return m;
}

inline void applyAt(Wrench& w, const Vec3& origin, const Vec3& point, const Vec3& force) {
  w.force += force;
  w.torque += (point - origin).cross(force);
}

}  // namespace

int autoThreads() {
  // OMP_NUM_THREADS's first number, read from the environment rather than from OpenMP's
  // current setting: a library in the same process may change that (LAMMPS sets one thread
  // when it opens). Else one per core this process may run on.
  if (const char* env = std::getenv("OMP_NUM_THREADS"); env != nullptr) {
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);
    if (end != env && n >= 1) return static_cast<int>(std::min(n, 4096L));
  }
  return omp_get_num_procs();
}

int resolveThreads(int requested) {
  int n = requested == kAutoThreads ? autoThreads() : requested;
  if (const int limit = ScopedThreadLimit::limit(); limit > 0) n = std::min(n, limit);
  return std::max(1, n);
}

Dynamics::Dynamics(std::shared_ptr<const Model> model)
    : model_(std::move(model)),
      detector_(makeModelDetector(model_)),
      solver_(*model_),
      joint_forces_(*model_),
      loads_(*model_),
      projection_(*model_),
      friction_(*model_, joint_forces_) {
  const Model& m = *model_;
  const std::size_t nb = m.bodies.size(), ng = m.geometries.size();
  inv_inertia_body_.reserve(nb);
  isotropic_inverse_.reserve(nb);
  dynamic_mass_.reserve(nb);
  for (const Body& b : m.bodies) {
    const bool dynamic = b.kind == BodyKind::kDynamic;
    inv_inertia_body_.push_back(dynamic ? Mat3(b.inertia.inverse()) : Mat3::Zero());
    const double s = dynamic ? isotropicMoment(b.inertia) : 0.0;
    isotropic_inverse_.push_back(s > 0.0 ? 1.0 / s : 0.0);
    dynamic_mass_.push_back(b.dynamicMass());
  }
  ws_.geometry_poses.assign(ng, Eigen::Isometry3d::Identity());
  geometry_motion_.resize(ng);
  prescribed_bodies_ = tribo::prescribedBodies(m.bodies);
  geometry_body_.reserve(ng);
  origin_geometry_.assign(nb, -1);
  for (std::size_t g = 0; g < ng; ++g) {
    const Geometry& geo = m.geometries[g];
    geometry_body_.push_back(geo.body.isWorld() ? -1 : static_cast<int>(geo.body.value));
    const bool at_origin = geo.local_pose.matrix() == Eigen::Matrix4d::Identity();
    if (at_origin && !geo.body.isWorld() && origin_geometry_[geo.body.value] < 0)
      origin_geometry_[geo.body.value] = static_cast<int>(g);
    else
      geometry_elsewhere_.push_back({static_cast<int>(g), at_origin});
  }
  // The wrenches a body by source, each made only where the model has that source (empty
  // otherwise, read as zero: four of them were 192 bytes a body of a scene of free boxes).
  const bool force_elements =
      !m.springs.empty() || !m.bushings.empty() || !m.torsional_springs.empty();
  ws_.contact_wrench.assign(nb, {});
  ws_.spring_wrench.assign(force_elements ? nb : 0, {});
  ws_.joint_wrench.assign(m.joints.empty() ? 0 : nb, {});
  ws_.constraint_wrench.assign(solver_.equationCount() > 0 ? nb : 0, {});
  ws_.load_wrench.assign(m.loads.empty() ? 0 : nb, {});
  ws_.joint_friction.assign(m.joints.size(), 0.0);
  ws_.actuator_output.assign(m.joints.size(), {});
  // Surface velocities a body only where some body has one (else empty: zero everywhere).
  const bool surfaces = std::any_of(m.bodies.begin(), m.bodies.end(), [](const Body& b) {
    return b.surface_velocity_signal || b.surface_velocity.squaredNorm() != 0.0;
  });
  ws_.surface_velocity.clear();
  ws_.surface_velocity.reserve(surfaces ? nb : 0);
  for (std::size_t b = 0; surfaces && b < nb; ++b) {
    ws_.surface_velocity.push_back(m.bodies[b].surface_velocity);
    if (m.bodies[b].surface_velocity_signal)
      varying_surfaces_.emplace_back(b, SignalVectorMemo(*m.bodies[b].surface_velocity_signal));
  }
  ws_.load_force.assign(m.loads.size(), Vec3::Zero());
  ws_.rotation.assign(nb, Mat3::Identity());
  ws_.inv_inertia_world.assign(nb, Mat3::Zero());
  for (std::size_t b = 0; b < nb; ++b)  // an isotropic body's, for good (updatePoses)
    if (isotropic_inverse_[b] > 0.0)
      ws_.inv_inertia_world[b] = isotropic_inverse_[b] * Mat3::Identity();
  ws_.linear_acceleration.assign(nb, Vec3::Zero());
  ws_.angular_acceleration.assign(nb, Vec3::Zero());
  // Automatic contacts list every pair that may touch; reserve for the few that do: four
  // points a geometry (a box resting on a face) or eight a listed pair. Reserved, not used,
  // this is most of what a large scene holds (eight points a geometry were 1.8 kB a box of a
  // 20 000-box grid's 4.7); a scene with more points grows the lists once, in its first steps.
  const std::size_t expected =
      model_->automatic_contacts ? 4 * model_->geometries.size() : 8 * model_->contact_pairs.size();
  ws_.contact_points.reserve(expected);
  ws_.contacts.reserve(expected);
  // One thread for a scene whose every stage is too small to share (no helper asked then).
  // Automatic contacts have no pair list: about three pairs a geometry (a densely packed
  // body's six neighbours, each pair counted once).
  const std::size_t most_items =
      std::max({model_->bodies.size(), model_->geometries.size(),
                static_cast<std::size_t>(model_->options.collision.max_points_per_pair) *
                    (model_->automatic_contacts ? 3 * model_->geometries.size()
                                                : model_->contact_pairs.size())});
  most_threads_ = stageThreads(most_items, resolveThreads(model_->options.threads));
  useThreads(most_threads_);
}

void Dynamics::useThreads(int threads) {
  threads_ = std::clamp(threads, 1, most_threads_);
  detector_.setThreads(threads_);
}

State Dynamics::initialState() const {
  State s;
  s.time = 0.0;
  s.bodies.reserve(model_->bodies.size());
  for (const Body& b : model_->bodies)
    s.bodies.push_back({b.position, b.orientation, b.velocity, b.angular_velocity});
  const ConstraintOptions& c = model_->options.constraints;
  if (c.project_initial) projection_.project(s, c.projection_tolerance, c.projection_iterations);
  friction_.initial(s, joint_forces_);
  return s;
}

void Dynamics::projectConstraints(State& state) {
  const ConstraintOptions& c = model_->options.constraints;
  if (c.projection) projection_.project(state, c.projection_tolerance, c.projection_iterations);
}

void Dynamics::setProfiling(bool on) {
  if (on && !profiling_) {
    profile_ = {};
    fcl_offset_ = detector_.fclSeconds();
  }
  profiling_ = on;
  detector_.setTiming(on);
}

namespace {

// Body b's acceleration from its wrenches, gravity and gyroscopic terms (a kinematic body's
// from its prescribed motion). Only the sources the model has (Dynamics::Dynamics): a wrench
// of a source it has not is zero, and a sum of contact forces starting from +0 is never -0,
// so leaving it out adds nothing a bit would show. `mass`: the body's if it is dynamic, 0 if
// it is kinematic (Dynamics::dynamic_mass_); `isotropic_inverse`: 1 / I for a body whose
// inertia is I times the identity (Dynamics::isotropic_inverse_), else 0.
void unconstrainedAcceleration(const Model& m, const State& state, Workspace& ws, std::size_t b,
                               double mass, double isotropic_inverse) {
  if (mass == 0.0) {  // a kinematic body
    const Body& body = m.bodies[b];
    if (body.motion) {  // core/prescribed_motion.hpp: the signals' derivatives
      ws.linear_acceleration[b] = body.motion->linearAcceleration(state.time);
      ws.angular_acceleration[b] = body.motion->angularAcceleration(state.time);
    } else {
      ws.linear_acceleration[b].setZero();
      ws.angular_acceleration[b].setZero();
    }
    return;
  }
  const BodyState& s = state.bodies[b];
  Vec3 force = ws.contact_wrench[b].force;
  Vec3 torque = ws.contact_wrench[b].torque;
  if (!ws.spring_wrench.empty()) {
    force += ws.spring_wrench[b].force;
    torque += ws.spring_wrench[b].torque;
  }
  if (!ws.joint_wrench.empty()) {
    force += ws.joint_wrench[b].force;
    torque += ws.joint_wrench[b].torque;
  }
  if (!m.loads.empty()) {  // else nothing added: a scene without loads computes as before
    force += ws.load_wrench[b].force;
    torque += ws.load_wrench[b].torque;
  }
  ws.linear_acceleration[b] = force / mass + m.options.gravity;
  if (isotropic_inverse > 0.0) {  // I w is parallel to w: no gyroscopic term
    ws.angular_acceleration[b] = isotropic_inverse * torque;
    return;
  }
  const Mat3& r = ws.rotation[b];
  const Vec3 gyro =
      s.angular_velocity.cross(r * (m.bodies[b].inertia * (r.transpose() * s.angular_velocity)));
  ws.angular_acceleration[b] = ws.inv_inertia_world[b] * (torque - gyro);
}

// Whether the accelerations are formed in assemble's pass over the bodies, right after each
// body's contact sum (its wrench, rotation and state then in cache): when the contacts are
// the only source of force (no force elements, joints or loads, whose wrenches are summed
// after the contacts') and the stages are not being timed apart.
bool accelerationsWithContactSums(bool profiling, const Model& m, const Workspace& ws) {
  return !profiling && ws.spring_wrench.empty() && ws.joint_wrench.empty() && m.loads.empty();
}

}  // namespace

const Workspace& Dynamics::evaluate(const State& state, bool point_energy) {
  StageClock clock(profiling_ ? &profile_ : nullptr);
  updatePoses(state);
  clock.lap(Stage::kPoses);
  detect();
  clock.lap(Stage::kDetect);
  // Off the stage clock, with each point's normal force (and friction, and elastic energy).
  contactKinematics(state, point_energy);
  clock.lap(Stage::kContactKinematics);
  if (profiling_) normalForces();
  clock.lap(Stage::kNormalForce);
  friction(state);
  clock.lap(Stage::kFriction);
  assemble(state);  // off the stage clock, with the accelerations of bodies moved by contacts alone
  clock.lap(Stage::kAssemble);
  unconstrainedAccelerations(state);
  clock.lap(Stage::kAccelerations);
  solveConstraints(state);
  clock.lap(Stage::kConstraints);
  if (profiling_) {
    ++profile_.evaluations;
    profile_.fcl = detector_.fclSeconds() - fcl_offset_;
  }
  return ws_;
}

void Dynamics::updatePoses(const State& state) {
  const Model& m = *model_;
  for (auto& [b, memo] : varying_surfaces_) ws_.surface_velocity[b] = memo.at(state.time);
  // Inlined in parallelFor's loops: a call a body cost the 200-sphere pile 2 % of its step.
  auto body_pose = [&](std::size_t b) __attribute__((always_inline)) {
    const BodyState& s = state.bodies[b];
    const Mat3 r = s.orientation.toRotationMatrix();
    ws_.rotation[b] = r;
    if (isotropic_inverse_[b] == 0.0 && dynamic_mass_[b] > 0.0)
      ws_.inv_inertia_world[b] = rotatedTensor(r, inv_inertia_body_[b]);
    if (const int g = origin_geometry_[b]; g >= 0) {  // the body's own frame
      Eigen::Isometry3d& pose = ws_.geometry_poses[static_cast<std::size_t>(g)];
      pose.linear() = r;
      pose.translation() = s.position;
    }
  };
  parallelFor(m.bodies.size(), stageThreads(m.bodies.size(), threads_), body_pose);
  const std::size_t ne = geometry_elsewhere_.size();
  parallelFor(ne, stageThreads(ne, threads_), [&](std::size_t e) {
    const auto g = static_cast<std::size_t>(geometry_elsewhere_[e].geometry);
    const Geometry& geo = m.geometries[g];
    if (geo.body.isWorld()) {
      ws_.geometry_poses[g] = geo.local_pose;
    } else {
      const BodyState& s = state.bodies[geo.body.value];
      Eigen::Isometry3d& pose = ws_.geometry_poses[g];
      pose.linear() = ws_.rotation[geo.body.value];
      pose.translation() = s.position;
      if (!geometry_elsewhere_[e].at_body_origin) pose = pose * geo.local_pose;
    }
  });
}

void Dynamics::detect() {
  detector_.detect(ws_.geometry_poses, ws_.contact_points);
  ws_.contacts.resize(ws_.contact_points.size());
  // Each point's pair (with automatic contacts it is derived from the id: a division and a
  // material lookup, 63 instructions), once per run of points of one pair (a manifold's
  // points are adjacent), and taken from the last detection's pairs when that one had the id:
  // the pairs come in ascending id (the skin list's and the grid's order), so one walk along
  // the last detection's list finds them. A pair is a function of its id in the immutable
  // model, so the memo gives the same pair; ids out of order only miss it.
  const std::size_t n = ws_.contact_points.size();
  ws_.contact_pair.resize(n);
  pair_memo_next_.resize(n);  // at most a pair a point
  const std::pair<int, ContactPair>* memo = pair_memo_.data();
  const std::size_t memo_size = pair_memo_.size();
  std::size_t k = 0, pairs = 0;
  int last_id = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const int id = ws_.contact_points[i].pair;
    if (id == last_id) {
      ws_.contact_pair[i] = ws_.contact_pair[i - 1];
      continue;
    }
    last_id = id;
    while (k < memo_size && memo[k].first < id) ++k;
    const ContactPair pair =
        k < memo_size && memo[k].first == id ? memo[k].second : model_->contactPair(id);
    ws_.contact_pair[i] = pair;
    pair_memo_next_[pairs++] = {id, pair};
  }
  pair_memo_next_.resize(pairs);
  std::swap(pair_memo_, pair_memo_next_);
}

void Dynamics::contactKinematics(const State& state, bool point_energy) {
  const Model& m = *model_;
  ws_.max_penetration = 0.0;
  ws_.forces_finite = false;
  ws_.point_elastic.clear();
  if (ws_.contact_points.empty()) return;
  // Each geometry's motion once per evaluation, not once per contact point and side.
  const std::size_t geometries = m.geometries.size();
  parallelFor(geometries, stageThreads(geometries, threads_), [&](std::size_t g) {
    geometry_motion_[g] = motionOf(m, state, ws_, static_cast<int>(g), geometry_body_[g]);
  });
  // Unless the stages are being timed apart, each point's normal force is formed in the same
  // pass, while its record is in cache: on 20 000 boxes the normal-force stage's own pass over
  // the records cost 3.6 times as much a point as on 100 (docs/performance.md). The same
  // arithmetic either way, so the same bits.
  const bool with_normal_force = !profiling_;
  const std::size_t n = ws_.contact_points.size();
  auto kinematics = [&](std::size_t i) {
    const contact::ContactPoint& cp = ws_.contact_points[i];
    const ContactPair& pair = ws_.contact_pair[i];
    contact::ContactRecord& rec = ws_.contacts[i];
    contact::contactKinematics(cp, geometry_motion_[static_cast<std::size_t>(pair.geometry_a)],
                               geometry_motion_[static_cast<std::size_t>(pair.geometry_b)], rec);
    if (with_normal_force) contact::normalForce(m.materials[pair.material], rec);
  };
  // And while no dynamic law is in play, the points go in the friction stage's chunks: each
  // chunk's kinematics and normal forces, then its friction (FrictionStates::evaluateChunk),
  // its deepest point and whether its forces are finite, while its 256 records (40 kB) are in
  // cache; the friction stage's and the check's passes over all records are then not needed.
  // Each point's arithmetic is the stages' own, and a maximum does not depend on its order:
  // the same bits.
  if (!frictionInPointsPass()) {
    parallelFor(n, stageThreads(n, threads_), kinematics);
    for (const contact::ContactPoint& cp : ws_.contact_points)
      ws_.max_penetration = std::max(ws_.max_penetration, cp.depth);
    return;
  }
  constexpr std::size_t kChunk = FrictionStates::kChunk;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  chunk_summary_.resize(chunks);
  // Asked for, each point's elastic energy too: the energy guard's term, the same function of
  // the same depth as its own pass over the records would form (core/energy.cpp).
  if (point_energy) ws_.point_elastic.resize(n);
  parallelFor(chunks, stageThreads(n, threads_), [&](std::size_t c) {
    const std::size_t end = std::min(n, (c + 1) * kChunk);
    ChunkSummary summary;
    for (std::size_t i = c * kChunk; i < end; ++i) {
      kinematics(i);
      const double depth = ws_.contact_points[i].depth;
      summary.deepest = std::max(summary.deepest, depth);
      if (point_energy)
        ws_.point_elastic[i] = m.materials[ws_.contact_pair[i].material].normal.energy(depth);
    }
    friction_.evaluateChunk(state, ws_, c);
    for (std::size_t i = c * kChunk; i < end; ++i) {
      const contact::ContactRecord& rec = ws_.contacts[i];
      summary.finite =
          summary.finite && std::isfinite(rec.normal_force) && rec.friction_force.allFinite();
    }
    chunk_summary_[c] = summary;
  });
  bool finite = true;
  for (const ChunkSummary& summary : chunk_summary_) {
    ws_.max_penetration = std::max(ws_.max_penetration, summary.deepest);
    finite = finite && summary.finite;
  }
  ws_.forces_finite = finite;
}

void Dynamics::normalForces() {
  const Model& m = *model_;
  const std::size_t n = ws_.contacts.size();
  parallelFor(n, stageThreads(n, threads_), [&](std::size_t i) {
    contact::ContactRecord& rec = ws_.contacts[i];
    contact::normalForce(m.materials[ws_.contact_pair[i].material], rec);
  });
}

void Dynamics::friction(const State& state) {
  if (frictionInPointsPass()) return;  // formed in the points' pass (contactKinematics)
  friction_.evaluate(state, ws_, stageThreads(ws_.contacts.size(), threads_));
}

void Dynamics::assemble(const State& state) {
  const Model& m = *model_;
  for (Wrench& w : ws_.spring_wrench) w.setZero();
  const std::size_t n = ws_.contacts.size(), nb = m.bodies.size();
  const bool with_accelerations = accelerationsWithContactSums(profiling_, m, ws_);
  if (stageThreads(std::max(2 * n, with_accelerations ? nb : 0), threads_) == 1) {
    // One thread (2 n bounds the entries listed below): the points walked once in contact
    // order, each adding to its B's sum, then its A's, gives each body's sum the additions
    // of the listing below in the same order, without the listing.
    for (Wrench& w : ws_.contact_wrench) w.setZero();
    Vec3 force, torque;
    for (std::size_t i = 0; i < n; ++i) {
      const ContactPair& pair = ws_.contact_pair[i];
      for (const auto& [g, is_b] : {std::pair{pair.geometry_b, true}, {pair.geometry_a, false}}) {
        const int body = geometry_body_[static_cast<std::size_t>(g)];
        if (body < 0) continue;  // the world
        const auto b = static_cast<std::size_t>(body);
        contact::contactWrench(ws_.contacts[i], state.bodies[b].position, is_b, force, torque);
        ws_.contact_wrench[b].force += force;
        ws_.contact_wrench[b].torque += torque;
      }
    }
    if (with_accelerations)
      for (std::size_t b = 0; b < nb; ++b)
        unconstrainedAcceleration(m, state, ws_, b, dynamic_mass_[b], isotropic_inverse_[b]);
  } else {
    listedContactSums(state, with_accelerations);
  }
  accumulateSprings(state);
  accumulateBushingsAndTorsion(state);
  if (!loads_.empty()) loads_.accumulate(state, ws_);  // core/applied_loads.hpp
  joint_forces_.accumulate(state, ws_);
}

void Dynamics::listedContactSums(const State& state, bool with_accelerations) {
  const Model& m = *model_;
  const std::size_t n = ws_.contacts.size(), nb = m.bodies.size();
  // Each point's bodies in parallel; then each body's points listed in contact order (B's
  // entry before A's within a point); then each body's sum of its points' forces and moments
  // in parallel, in that order: the additions of the one-thread loop over the points.
  point_bodies_.resize(n);
  parallelFor(n, stageThreads(n, threads_), [&](std::size_t i) {
    const ContactPair& pair = ws_.contact_pair[i];
    point_bodies_[i] = {BodyIndex{geometry_body_[static_cast<std::size_t>(pair.geometry_a)]},
                        BodyIndex{geometry_body_[static_cast<std::size_t>(pair.geometry_b)]}};
  });
  body_point_start_.assign(nb + 1, 0);
  int* const start = body_point_start_.data();  // in locals: a store through them reloads nothing
  for (const auto& [a, b] : point_bodies_) {
    if (!b.isWorld()) ++start[b.value + 1];
    if (!a.isWorld()) ++start[a.value + 1];
  }
  for (std::size_t b = 0; b < nb; ++b) start[b + 1] += start[b];
  body_points_.resize(static_cast<std::size_t>(start[nb]));
  int* const entries = body_points_.data();
  for (std::size_t i = 0; i < n; ++i) {  // start[b] runs to start[b + 1], then shifted back
    const auto [a, b] = point_bodies_[i];
    if (!b.isWorld()) entries[start[b.value]++] = static_cast<int>(2 * i + 1);
    if (!a.isWorld()) entries[start[a.value]++] = static_cast<int>(2 * i);
  }
  for (std::size_t b = nb; b > 0; --b) start[b] = start[b - 1];
  start[0] = 0;
  const std::size_t items = std::max<std::size_t>(start[nb], with_accelerations ? nb : 0);
  parallelFor(nb, stageThreads(items, threads_), [&](std::size_t b) {
    const Vec3& origin = state.bodies[b].position;
    Vec3 sum_force = Vec3::Zero(), sum_torque = Vec3::Zero(), force, torque;
    for (int k = start[b]; k < start[b + 1]; ++k) {
      const auto e = static_cast<std::size_t>(entries[k]);
      contact::contactWrench(ws_.contacts[e / 2], origin, e % 2 == 1, force, torque);
      sum_force += force;
      sum_torque += torque;
    }
    ws_.contact_wrench[b] = {sum_force, sum_torque};
    if (with_accelerations)
      unconstrainedAcceleration(m, state, ws_, b, dynamic_mass_[b], isotropic_inverse_[b]);
  });
}

void Dynamics::accumulateSprings(const State& state) {
  for (const SpringDamper& s : model_->springs) {
    auto end = [&](BodyIndex b, const Vec3& local, Vec3& p, Vec3& v) {
      if (b.isWorld()) {
        p = local;
        v.setZero();
        return;
      }
      const BodyState& bs = state.bodies[b.value];
      const Vec3 r = ws_.rotation[b.value] * local;
      p = bs.position + r;
      v = bs.velocity + bs.angular_velocity.cross(r);
    };
    Vec3 pa, va, pb, vb;
    end(s.body_a, s.point_a, pa, va);
    end(s.body_b, s.point_b, pb, vb);
    const Vec3 d = pb - pa;
    const double length = d.norm();
    if (length < 1e-12) continue;  // direction undefined; zero-length springs carry no force
    const Vec3 e = d / length;
    const double tension = s.stiffness * (length - s.rest_length) + s.damping * e.dot(vb - va);
    const Vec3 f_b = -tension * e;
    if (!s.body_b.isWorld())
      applyAt(ws_.spring_wrench[s.body_b.value], state.bodies[s.body_b.value].position, pb, f_b);
    if (!s.body_a.isWorld())
      applyAt(ws_.spring_wrench[s.body_a.value], state.bodies[s.body_a.value].position, pa, -f_b);
  }
}

void Dynamics::accumulateBushingsAndTorsion(const State& state) {
  auto apply = [&](BodyIndex body, const Vec3& point, const Vec3& force, const Vec3& torque) {
    if (body.isWorld()) return;
    Wrench& w = ws_.spring_wrench[body.value];
    applyAt(w, state.bodies[body.value].position, point, force);
    w.torque += torque;
  };
  for (const Bushing& bushing : model_->bushings) {
    const BushingDeflection d =
        bushingDeflection(bushing, bodyKinematics(state, ws_.rotation, bushing.body_a),
                          bodyKinematics(state, ws_.rotation, bushing.body_b));
    const PairWrench w = bushingWrench(bushing, d);
    apply(bushing.body_b, w.point, w.force, w.torque);
    apply(bushing.body_a, w.point, -w.force, -w.torque);  // the same point: no net moment
  }
  for (const TorsionalSpring& spring : model_->torsional_springs) {
    const TorsionalDeflection d =
        torsionalDeflection(spring, bodyKinematics(state, ws_.rotation, spring.body_a),
                            bodyKinematics(state, ws_.rotation, spring.body_b));
    const Vec3 torque = torsionalTorque(spring, d);
    if (!spring.body_b.isWorld()) ws_.spring_wrench[spring.body_b.value].torque += torque;
    if (!spring.body_a.isWorld()) ws_.spring_wrench[spring.body_a.value].torque -= torque;
  }
}

void Dynamics::unconstrainedAccelerations(const State& state) {
  if (accelerationsWithContactSums(profiling_, *model_, ws_)) return;  // made in assemble
  const Model& m = *model_;
  parallelFor(m.bodies.size(), stageThreads(m.bodies.size(), threads_), [&](std::size_t b) {
    unconstrainedAcceleration(m, state, ws_, b, dynamic_mass_[b], isotropic_inverse_[b]);
  });
}

void Dynamics::solveConstraints(const State& state) {
  solver_.solve(state, ws_);
  joint_forces_.applyReactionFriction(solver_, ws_);
}

bool Dynamics::beforeStep(State& state) {
  if (!friction_.dynamic()) return false;
  StageClock clock(profiling_ ? &profile_ : nullptr);
  const bool changed = friction_.beforeStep(state, ws_);
  clock.lap(Stage::kFrictionStates);
  return changed;
}

bool Dynamics::afterStep(State& state) {
  if (!friction_.stateful()) return false;
  StageClock clock(profiling_ ? &profile_ : nullptr);
  const bool changed = friction_.afterStep(state, ws_);
  clock.lap(Stage::kFrictionStates);
  return changed;
}

void Dynamics::stepFrictionMemory(State& state, double h) const {
  friction_.stepStable(state, ws_, joint_forces_, h);
}

}  // namespace tribo
