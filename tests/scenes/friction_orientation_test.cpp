// Friction does not depend on how a body is turned about the contact normal: a box resting
// at its static depth on the ground and sliding at speed v in direction beta, turned by
// 0, 15, 30, 45 and 60 degrees about the vertical, gets the same tangential contact force
// (magnitude to 1e-12 relative, direction exactly against the slip) from an isotropic law,
// memoryless or with internal state. A law that snaps to axes (a pyramid cone, or friction
// applied per axis) would differ by up to sqrt(2) at 45 degrees.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string scene(const std::string& law, double yaw, double beta, double speed) {
  return "simulation: {duration: 1, time_step: 0.001, gravity: [0, 0, -9.81]}\n"
         "bodies:\n"
         "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
         "  - name: block\n    mass: 1.5\n    position: [0, 0, " +
         number(0.05 - 1.5 * 9.81 / 4e5) + "]\n    rpy: [0, 0, " + number(yaw) +
         "]\n    velocity: [" + number(speed * std::cos(beta)) + ", " +
         number(speed * std::sin(beta)) +
         ", 0]\n    geometry: [{name: box, shape: box, size: [0.3, 0.2, 0.1]}]\n"
         "friction_laws:\n  coulomb: {mu: 0.3, regularization: tanh, v_eps: 0.01}\n"
         "  stribeck: {mu_s: 0.35, mu_k: 0.3, v_st: 0.15, v_eps: 0.01}\n"
         "  lugre: {sigma0: 1.0e4, sigma1: 10, sigma2: 0.4, mu_c: 0.3, mu_s: 0.35, v_s: 0.001}\n"
         "materials:\n  - {name: m, normal: {law: linear, stiffness: 1.0e5, damping: 0}, "
         "friction: " +
         law + "}\ncontacts:\n  - {a: floor, b: box, material: m}\n";
}

TEST(FrictionOrientation, AnIsotropicLawGivesTheSameForceHoweverTheBodyIsTurned) {
  for (const char* law : {"coulomb", "stribeck", "lugre"}) {
    for (double beta : {0.0, 0.4, 2.0}) {
      for (double speed : {0.003, 0.05}) {
        double reference = -1.0;
        for (double degrees : {0.0, 15.0, 30.0, 45.0, 60.0}) {
          SCOPED_TRACE(std::string(law) + " beta " + number(beta) + " v " + number(speed) +
                       " yaw " + number(degrees));
          const io::Scene s =
              io::loadSceneFromString(scene(law, degrees * kPi / 180, beta, speed), "turned.yaml");
          Simulator sim(s.model);
          const std::size_t block = static_cast<std::size_t>(s.model->findBody("block")->value);
          const Vec3 f = sim.current().contact_wrench[block].force;
          const Vec3 tangential(f.x(), f.y(), 0.0);
          const double magnitude = tangential.norm();
          ASSERT_GT(magnitude, 0.0);
          // Against the slip: the slip direction is (cos beta, sin beta).
          const Vec3 slip(std::cos(beta), std::sin(beta), 0.0);
          EXPECT_LT((tangential / magnitude + slip).norm(), 1e-12);
          if (reference < 0.0) reference = magnitude;
          EXPECT_NEAR(magnitude, reference, 1e-12 * reference);
        }
      }
    }
  }
}

}  // namespace
}  // namespace tribo
