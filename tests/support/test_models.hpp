// Small models built directly with ModelBuilder for the core tests: each has a closed-form
// answer (free fall, oscillator, pendulum, box at rest, sliding box).
#pragma once

#include <memory>
#include <string>

#include "core/model_builder.hpp"
#include "friction/friction_law.hpp"

namespace tribo::test {

inline Mat3 boxInertia(double m, const Vec3& size) {
  const Vec3 s2 = size.cwiseProduct(size);
  return (m / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y())).asDiagonal();
}

inline contact::Material coulombMaterial(double mu, double stiffness, double damping,
                                         double v_eps = 1e-4) {
  friction::LawSpec spec{"coulomb", {{"mu", mu}, {"v_eps", v_eps}}, {{"regularization", "tanh"}}};
  contact::Material material;
  material.normal.stiffness = stiffness;
  material.normal.damping = damping;
  material.friction = friction::makeFrictionLaw(spec);
  return material;
}

// A box (m, edge lengths `size`) on the ground plane z = 0, moving in the x-z plane without
// rotating (planar_translation joint), starting at its static depth with velocity (vx, 0, vz).
inline ModelBuilder boxOnGround(double m, const Vec3& size, double vx, double mu, double k,
                                double c, IntegratorType integrator, double dt, double vz = 0) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  Body box;
  box.name = "box";
  box.mass = m;
  box.inertia = boxInertia(m, size);
  box.position = Vec3(0, 0, size.z() / 2 - m * 9.81 / (4 * k));
  box.velocity = Vec3(vx, 0, vz);
  const BodyIndex ib = b.addBody(box);
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(size / 2));
  b.addContactPair(ground, shape, b.addMaterial(coulombMaterial(mu, k, c)));
  b.addJoint("slide", JointType::kPlanarTranslation, BodyIndex::world(), ib, box.position,
             Vec3::UnitY());
  return b;
}

// The ModelError message of f(), "" when it throws none.
template <typename F>
std::string modelErrorOf(F&& f) {
  try {
    f();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

}  // namespace tribo::test
