// Mechanisms built directly with ModelBuilder for the joint tests and the chain bench, and
// the closed forms they are checked against: a chain of revolute links, energy of a model
// (kinetic + gravity + springs), the complete elliptic integral K(k) by the arithmetic-
// geometric mean (Abramowitz & Stegun 17.6), and an angle unwrapper.
#pragma once

#include <cmath>
#include <memory>
#include <numbers>

#include "core/model_builder.hpp"
#include "core/state.hpp"

namespace tribo::test {

inline Mat3 rodInertia(double m, double length, double thickness) {
  const double a = m / 12.0 * (length * length + thickness * thickness);
  const double b = m / 12.0 * 2.0 * thickness * thickness;
  return Vec3(b, a, a).asDiagonal();  // rod along its x axis
}

// N links of `length` [m] and `mass` [kg] in a horizontal line along +x from the origin,
// each turning about y on a revolute joint at its left end (the first one to the world).
inline ModelBuilder revoluteChain(int n, IntegratorType integrator, double dt,
                                  ConstraintSolverKind solver = ConstraintSolverKind::kAuto,
                                  double length = 0.1, double mass = 0.1) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  b.options().constraints.solver = solver;
  BodyIndex previous = BodyIndex::world();
  for (int i = 0; i < n; ++i) {
    Body link;
    link.name = "link" + std::to_string(i);
    link.mass = mass;
    link.inertia = rodInertia(mass, length, 0.01);
    link.position = Vec3((i + 0.5) * length, 0.0, 0.0);
    const BodyIndex index = b.addBody(link);
    b.addJoint("pin" + std::to_string(i), JointType::kRevolute, previous, index,
               Vec3(i * length, 0.0, 0.0), Vec3::UnitY());
    previous = index;
  }
  return b;
}

// Kinetic + gravitational energy of the dynamic bodies plus the model's spring-dampers'
// elastic energy [J].
inline double mechanicalEnergy(const Model& model, const State& s) {
  double e = 0.0;
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& body = model.bodies[i];
    if (body.kind != BodyKind::kDynamic) continue;
    const BodyState& bs = s.bodies[i];
    const Vec3 w_body = bs.orientation.conjugate() * bs.angular_velocity;
    e += 0.5 * body.mass * bs.velocity.squaredNorm() + 0.5 * w_body.dot(body.inertia * w_body) -
         body.mass * model.options.gravity.dot(bs.position);
  }
  for (const SpringDamper& sp : model.springs) {
    auto point = [&](BodyIndex b, const Vec3& local) {
      return b.isWorld() ? local
                         : Vec3(s.bodies[b.value].position + s.bodies[b.value].orientation * local);
    };
    const double stretch =
        (point(sp.body_b, sp.point_b) - point(sp.body_a, sp.point_a)).norm() - sp.rest_length;
    e += 0.5 * sp.stiffness * stretch * stretch;
  }
  return e;
}

// Complete elliptic integral of the first kind K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
inline double ellipticK(double k) {
  double a = 1.0, g = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40 && std::abs(a - g) > 1e-16 * a; ++i) {
    const double next = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = next;
  }
  return std::numbers::pi / (2.0 * a);
}

// Follows an angle through +-pi wraps.
class Unwrapper {
 public:
  double operator()(double wrapped) {
    if (started_) {
      double d = wrapped - last_;
      d -= 2.0 * std::numbers::pi * std::round(d / (2.0 * std::numbers::pi));
      value_ += d;
    } else {
      value_ = wrapped;
      started_ = true;
    }
    last_ = wrapped;
    return value_;
  }

 private:
  bool started_ = false;
  double last_ = 0.0, value_ = 0.0;
};

}  // namespace tribo::test
