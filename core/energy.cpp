#include "core/energy.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/prescribed_motion.hpp"
#include "core/stage_threads.hpp"

namespace tribo {

namespace {

constexpr double kFloor = 1e-9;  // [J] below this a rise is rounding noise

}  // namespace

namespace {

// The terms of body b (EnergyTerms::Body); the kinetic rate only when `rate` is asked.
// `isotropic` and `mass`: the body's EnergyTerms::isotropic and ::mass (0: kinematic). The
// model's body record is read only for a dynamic body's inertia when it is not isotropic.
inline __attribute__((always_inline)) EnergyTerms::Body bodyTerms(const Model& model,
                                                                  const State& state,
                                                                  const Workspace& ws,
                                                                  std::size_t b, bool rate,
                                                                  double isotropic, double mass) {
  EnergyTerms::Body t;
  const BodyState& s = state.bodies[b];
  if (mass == 0.0) {  // a kinematic body
    // A model without force elements has no spring wrenches (core/workspace.hpp): zero.
    const Wrench& c = ws.contact_wrench[b];
    const Wrench k = ws.spring_wrench.empty() ? Wrench{} : ws.spring_wrench[b];
    t.power[0] =
        (c.force + k.force).dot(s.velocity) + (c.torque + k.torque).dot(s.angular_velocity);
    return t;
  }
  // A sphere's or a cube's rotational terms without turning w into the body frame.
  const Mat3& r = ws.rotation[b];
  const Vec3 w_body = isotropic > 0.0 ? Vec3::Zero() : Vec3(r.transpose() * s.angular_velocity);
  t.kinetic = 0.5 * mass * s.velocity.squaredNorm() +
              0.5 * (isotropic > 0.0 ? isotropic * s.angular_velocity.squaredNorm()
                                     : w_body.dot(model.bodies[b].inertia * w_body));
  t.gravity = -mass * model.options.gravity.dot(s.position);
  // Joint constraint forces and joint elements (limits, springs, dampers, friction,
  // drives) count as sources: their work enters or leaves through the joints. A model
  // without constraint rows or joints has no such wrenches (core/workspace.hpp): power 0.
  int k = 0;
  for (const std::vector<Wrench>* j : {&ws.constraint_wrench, &ws.joint_wrench}) {
    if (!j->empty())
      t.power[k] = (*j)[b].force.dot(s.velocity) + (*j)[b].torque.dot(s.angular_velocity);
    ++k;
  }
  // Applied loads too (core/applied_load.hpp): F . v + T . w, T about the origin.
  if (!model.loads.empty()) {
    const Wrench& l = ws.load_wrench[b];
    t.power[2] = l.force.dot(s.velocity) + l.torque.dot(s.angular_velocity);
  }
  if (rate) {  // d(kinetic energy)/dt
    const double spin_rate =
        isotropic > 0.0
            ? isotropic * s.angular_velocity.dot(ws.angular_acceleration[b])
            : w_body.dot(model.bodies[b].inertia * (r.transpose() * ws.angular_acceleration[b]));
    t.kinetic_rate = mass * ws.linear_acceleration[b].dot(s.velocity) + spin_rate;
  }
  return t;
}

// The terms of contact point i (EnergyTerms::Point); `surfaces`: some body has a surface
// velocity at this evaluation (else both powers are +0 without looking).
inline __attribute__((always_inline)) EnergyTerms::Point pointTerms(const Model& model,
                                                                    const Workspace& ws,
                                                                    std::size_t i, bool surfaces) {
  EnergyTerms::Point t;
  const contact::ContactRecord& c = ws.contacts[i];
  const ContactPair& pair = ws.contact_pair[i];
  t.elastic = model.materials[pair.material].normal.energy(c.point.depth);
  if (!surfaces) return t;
  const Vec3 f = c.force();  // on B; A gets -f
  const std::pair<int, double> sides[2] = {{pair.geometry_b, 1.0}, {pair.geometry_a, -1.0}};
  double* power[2] = {&t.power_b, &t.power_a};
  for (int k = 0; k < 2; ++k) {
    const auto& [geometry, sign] = sides[k];
    const Vec3 surface = surfaceVelocityOf(model, ws.rotation, ws.surface_velocity, geometry);
    if (surface.squaredNorm() != 0.0) *power[k] = sign * f.dot(surface);
  }
  return t;
}

// Sums the terms in index order. Where the items pay for threads, `terms` is filled in
// parallel first; on one thread each term is summed as it is formed (the same additions).
// With `kinetic_rate`, also the sum over dynamic bodies of d(kinetic energy)/dt.
EnergyAccount account(const Model& model, const State& state, const Workspace& ws,
                      std::vector<double>* body_energy, int threads, EnergyTerms& terms,
                      double* kinetic_rate) {
  const bool rate = kinetic_rate != nullptr;
  const std::size_t nb = model.bodies.size(), np = ws.contacts.size();
  const bool surfaces = std::any_of(ws.surface_velocity.begin(), ws.surface_velocity.end(),
                                    [](const Vec3& v) { return v.squaredNorm() != 0.0; });
  // No surface moving, the points' terms are their elastic energies alone (both powers +0),
  // and the evaluation may have formed them in its pass over the points
  // (Workspace::point_elastic: the same function of the same depth): then they are summed
  // from that list, in the same order, instead of from the records.
  const bool elastic_listed = !surfaces && ws.point_elastic.size() == np;
  const int body_threads = stageThreads(nb, threads);
  const int point_threads = elastic_listed ? 1 : stageThreads(np, threads);
  if (body_threads > 1) {
    terms.bodies.resize(nb);
    contact::parallelFor(nb, body_threads, [&](std::size_t b) {
      terms.bodies[b] = bodyTerms(model, state, ws, b, rate, terms.isotropic[b], terms.mass[b]);
    });
  }
  if (point_threads > 1) {
    terms.points.resize(np);
    contact::parallelFor(np, point_threads, [&](std::size_t i) {
      terms.points[i] = pointTerms(model, ws, i, surfaces);
    });
  }
  EnergyAccount a;
  if (body_energy) body_energy->assign(nb, 0.0);
  if (rate) *kinetic_rate = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    const EnergyTerms::Body t =
        body_threads > 1 ? terms.bodies[b]
                         : bodyTerms(model, state, ws, b, rate, terms.isotropic[b], terms.mass[b]);
    if (terms.mass[b] == 0.0) {  // a kinematic body
      a.input_power -= t.power[0];
      continue;
    }
    a.kinetic += t.kinetic;
    a.gravity += t.gravity;
    if (rate) *kinetic_rate += t.kinetic_rate;
    if (body_energy) (*body_energy)[b] = t.kinetic + t.gravity;
    a.input_power += t.power[0];
    a.input_power += t.power[1];
    if (!model.loads.empty()) a.input_power += t.power[2];
  }
  for (const SpringDamper& sp : model.springs) {
    auto end = [&](BodyIndex b, const Vec3& local) {
      return b.isWorld() ? local
                         : Vec3(state.bodies[b.value].position + ws.rotation[b.value] * local);
    };
    const double stretch =
        (end(sp.body_b, sp.point_b) - end(sp.body_a, sp.point_a)).norm() - sp.rest_length;
    a.elastic += 0.5 * sp.stiffness * stretch * stretch;
  }
  for (const Bushing& bushing : model.bushings)
    a.elastic += bushingEnergy(
        bushing, bushingDeflection(bushing, bodyKinematics(state, ws.rotation, bushing.body_a),
                                   bodyKinematics(state, ws.rotation, bushing.body_b)));
  for (const TorsionalSpring& spring : model.torsional_springs)
    a.elastic += torsionalEnergy(
        spring, torsionalDeflection(spring, bodyKinematics(state, ws.rotation, spring.body_a),
                                    bodyKinematics(state, ws.rotation, spring.body_b)));
  // A side without a surface speed holds +0, and x - (+0) is x bit for bit: the listed terms
  // subtract nothing.
  if (elastic_listed) {
    for (const double e : ws.point_elastic) a.elastic += e;
    return a;
  }
  for (std::size_t i = 0; i < np; ++i) {
    const EnergyTerms::Point t =
        point_threads > 1 ? terms.points[i] : pointTerms(model, ws, i, surfaces);
    a.elastic += t.elastic;
    a.input_power -= t.power_b;
    a.input_power -= t.power_a;
  }
  return a;
}

}  // namespace

void EnergyTerms::listBodies(const Model& model) {
  isotropic.resize(model.bodies.size());
  mass.resize(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    isotropic[b] = isotropicMoment(model.bodies[b].inertia);
    mass[b] = model.bodies[b].dynamicMass();
  }
}

EnergyAccount measureEnergy(const Model& model, const State& state, const Workspace& ws,
                            std::vector<double>* body_energy, int threads) {
  EnergyTerms terms;
  terms.listBodies(model);
  return account(model, state, ws, body_energy, threads, terms, nullptr);
}

EnergyGuard::EnergyGuard(const Model& model, double modified_step, int threads)
    : model_(&model), floor_(kFloor), modified_step_(modified_step), threads_(threads) {
  terms_.listBodies(model);
  // The motion sources impose: the fastest kinematic body or surface (linear), the fastest
  // turning kinematic body and velocity of a joint drive (angular; drives of a prismatic
  // joint count as linear).
  double speed = 0.0, spin = 0.0;
  for (const Body& b : model.bodies) {
    if (b.kind == BodyKind::kKinematic) {
      speed = std::max({speed, b.velocity.norm(), b.surfaceSpeedBound(model.options.duration)});
      spin = std::max(spin, b.angular_velocity.norm());
      if (b.motion) {  // along signals: their largest over the run
        speed = std::max(speed, b.motion->speedBound(model.options.duration));
        spin = std::max(spin, b.motion->spinBound(model.options.duration));
      }
    } else {
      speed = std::max(speed, b.surfaceSpeedBound(model.options.duration));
    }
  }
  for (const Joint& j : model.joints) {
    if (!j.elements.drive) continue;
    const double rate = j.elements.drive->speedBound(model.options.duration);
    (j.type == JointType::kPrismatic ? speed : spin) =
        std::max(j.type == JointType::kPrismatic ? speed : spin, rate);
  }
  std::vector<double> size(model.bodies.size(), 0.0);
  for (const Geometry& g : model.geometries) {
    const double half = g.shape.size();
    if (g.body.isWorld() || !std::isfinite(half)) continue;
    double& s = size[g.body.value];
    s = s > 0.0 ? std::min(s, half) : half;
  }
  // The turning sources: each kinematic body's position and largest spin (listed once, so
  // that the floor costs bodies x sources, not bodies^2).
  std::vector<std::pair<Vec3, double>> turning;
  for (const Body& k : model.bodies)
    if (k.kind == BodyKind::kKinematic)
      turning.emplace_back(k.position, k.motion ? k.motion->spinBound(model.options.duration)
                                                : k.angular_velocity.norm());
  const double g = model.options.gravity.norm();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind != BodyKind::kDynamic) continue;
    // A turning source drives a body at up to spin |x_b - x_K| through whatever links them.
    double reach = 0.0;
    for (const auto& [position, source_spin] : turning)
      reach = std::max(reach, source_spin * (body.position - position).norm());
    const double v = speed + reach;
    floor_ += body.mass * (g * size[b] + 0.5 * v * v) +
              0.5 * body.inertia.diagonal().maxCoeff() * spin * spin;
  }
}

void EnergyGuard::markMinimum(double t, double net, const EnergyAccount& a) {
  min_time_ = t;
  min_net_ = net;
  min_kinetic_elastic_ = a.kinetic + a.elastic;
  min_gravity_ = a.gravity;
  lowest_gravity_ = a.gravity;
  min_abs_work_ = abs_work_;
  min_body_energy_ = body_energy_;
}

EnergyAccount EnergyGuard::measure(const State& state, const Workspace& ws) {
  if (modified_step_ <= 0.0)
    return account(*model_, state, ws, &body_energy_, threads_, terms_, nullptr);
  double rate = 0.0;  // d(kinetic energy)/dt at the state
  EnergyAccount a = account(*model_, state, ws, &body_energy_, threads_, terms_, &rate);
  a.kinetic += 0.5 * modified_step_ * rate;
  return a;
}

void EnergyGuard::reset(const State& state, const Workspace& ws) {
  const EnergyAccount a = measure(state, ws);
  started_ = true;
  t_ = state.time;
  power_ = a.input_power;
  work_ = abs_work_ = 0.0;
  markMinimum(state.time, a.total(), a);
}

EnergyVerdict EnergyGuard::update(const State& state, const Workspace& ws) {
  const EnergyAccount a = measure(state, ws);
  const double dt = state.time - t_;
  work_ += 0.5 * (power_ + a.input_power) * dt;
  // The allowance |P| integrated: by the trapezoid, or for semi-implicit Euler by the larger
  // end's |P| over the whole step. That method applies the step's starting force F0 over the
  // whole step, so from rest it gives the kinetic energy h F0 v1 / 2, above the trapezoid
  // h F1 v1 / 2 when the force falls within the step (a servo or a spring pulling a body
  // from rest, with no other energy to hide it); the larger end covers it while F1 >= F0 / 2.
  abs_work_ += (modified_step_ > 0.0 ? std::max(std::abs(power_), std::abs(a.input_power))
                                     : 0.5 * (std::abs(power_) + std::abs(a.input_power))) *
               dt;
  t_ = state.time;
  power_ = a.input_power;
  const double net = a.total() - work_;
  lowest_gravity_ = std::min(lowest_gravity_, a.gravity);
  if (net < min_net_) {
    markMinimum(state.time, net, a);
    return {};
  }
  EnergyVerdict v;
  v.rise = net - min_net_;
  v.available = min_kinetic_elastic_ + (min_gravity_ - lowest_gravity_) +
                (abs_work_ - min_abs_work_) + floor_;
  v.since = min_time_;
  if (v.rise <= v.available) return v;
  v.ok = false;
  double largest = -1.0;
  for (std::size_t b = 0; b < body_energy_.size(); ++b) {
    const double gain = body_energy_[b] - min_body_energy_[b];
    if (model_->bodies[b].kind == BodyKind::kDynamic && gain > largest) {
      largest = gain;
      v.body = model_->bodies[b].name;
    }
  }
  return v;
}

}  // namespace tribo
