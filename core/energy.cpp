#include "core/energy.hpp"

#include <algorithm>
#include <cmath>

#include "core/prescribed_motion.hpp"

namespace tribo {

namespace {

constexpr double kFloor = 1e-9;  // [J] below this a rise is rounding noise

}  // namespace

EnergyAccount measureEnergy(const Model& model, const State& state, const Workspace& ws,
                            std::vector<double>* body_energy) {
  EnergyAccount a;
  const Vec3& g = model.options.gravity;
  if (body_energy) body_energy->assign(model.bodies.size(), 0.0);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const BodyState& s = state.bodies[b];
    if (body.kind == BodyKind::kKinematic) {
      const Wrench& c = ws.contact_wrench[b];
      const Wrench& k = ws.spring_wrench[b];
      a.input_power -=
          (c.force + k.force).dot(s.velocity) + (c.torque + k.torque).dot(s.angular_velocity);
      continue;
    }
    const Mat3& r = ws.rotation[b];
    const Vec3 w_body = r.transpose() * s.angular_velocity;
    const double kinetic =
        0.5 * body.mass * s.velocity.squaredNorm() + 0.5 * w_body.dot(body.inertia * w_body);
    const double gravity = -body.mass * g.dot(s.position);
    a.kinetic += kinetic;
    a.gravity += gravity;
    if (body_energy) (*body_energy)[b] = kinetic + gravity;
    // Joint constraint forces and joint elements (limits, springs, dampers, friction,
    // drives) count as sources: their work enters or leaves through the joints.
    for (const Wrench* j : {&ws.constraint_wrench[b], &ws.joint_wrench[b]})
      a.input_power += j->force.dot(s.velocity) + j->torque.dot(s.angular_velocity);
    // Applied loads too (core/applied_load.hpp): F . v + T . w, T about the origin.
    if (!model.loads.empty()) {
      const Wrench& l = ws.load_wrench[b];
      a.input_power += l.force.dot(s.velocity) + l.torque.dot(s.angular_velocity);
    }
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
  for (std::size_t i = 0; i < ws.contacts.size(); ++i) {
    const contact::ContactRecord& c = ws.contacts[i];
    const ContactPair& pair = ws.contact_pair[i];
    a.elastic += model.materials[pair.material].normal.energy(c.point.depth);
    const Vec3 f = c.force();  // on B; A gets -f
    const std::pair<int, double> sides[2] = {{pair.geometry_b, 1.0}, {pair.geometry_a, -1.0}};
    for (const auto& [geometry, sign] : sides) {
      const Vec3 surface = surfaceVelocityOf(model, ws.rotation, ws.surface_velocity, geometry);
      if (surface.squaredNorm() == 0.0) continue;
      a.input_power -= sign * f.dot(surface);
    }
  }
  return a;
}

EnergyGuard::EnergyGuard(const Model& model, double modified_step)
    : model_(&model), floor_(kFloor), modified_step_(modified_step) {
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
  const double g = model.options.gravity.norm();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind != BodyKind::kDynamic) continue;
    // A turning source drives a body at up to spin |x_b - x_K| through whatever links them.
    double reach = 0.0;
    for (const Body& k : model.bodies)
      if (k.kind == BodyKind::kKinematic)
        reach = std::max(reach, (k.motion ? k.motion->spinBound(model.options.duration)
                                          : k.angular_velocity.norm()) *
                                    (body.position - k.position).norm());
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

double EnergyGuard::modification(const State& state, const Workspace& ws) const {
  if (modified_step_ <= 0.0) return 0.0;
  double rate = 0.0;  // d(kinetic energy)/dt at the state
  for (std::size_t b = 0; b < model_->bodies.size(); ++b) {
    const Body& body = model_->bodies[b];
    if (body.kind != BodyKind::kDynamic) continue;
    const BodyState& s = state.bodies[b];
    const Mat3& r = ws.rotation[b];
    const Vec3 w_body = r.transpose() * s.angular_velocity;
    const Vec3 alpha_body = r.transpose() * ws.angular_acceleration[b];
    rate += body.mass * ws.linear_acceleration[b].dot(s.velocity) +
            w_body.dot(body.inertia * alpha_body);
  }
  return 0.5 * modified_step_ * rate;
}

void EnergyGuard::reset(const State& state, const Workspace& ws) {
  EnergyAccount a = measureEnergy(*model_, state, ws, &body_energy_);
  a.kinetic += modification(state, ws);
  started_ = true;
  t_ = state.time;
  power_ = a.input_power;
  work_ = abs_work_ = 0.0;
  markMinimum(state.time, a.total(), a);
}

EnergyVerdict EnergyGuard::update(const State& state, const Workspace& ws) {
  EnergyAccount a = measureEnergy(*model_, state, ws, &body_energy_);
  a.kinetic += modification(state, ws);
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
