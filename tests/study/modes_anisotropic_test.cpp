// tribo modes on a steady-sliding anisotropic contact (contact/anisotropy.hpp): a box held by
// a bushing (k_x, k_y) on a belt sliding at V along x, its grain turned by psi from x, a
// falling Stribeck law. The friction's Jacobian is derived here by hand from
//   F(s) = -N mu(rho) R w / rho,   w = R s,  rho = |w|
//   dF/ds = -N R [mu'(rho) w w^T / rho^2 + mu(rho) (I / rho - w w^T / rho^3)] R,
// so the box obeys m q'' + D q' + K q = 0 with D = -dF/ds at s = (-V, 0) and K = diag(k_x,
// k_y); its four eigenvalues (a 4 x 4 companion matrix, Eigen) and the steady deflection
// K q = F(s) must be what the engine's finite-difference linearization finds. Along the grain
// the damping is N r^2 mu'(r V) (negative on the falling branch: it squeals); across it,
// N mu(r V) r_2^2 / (r V), positive: a soft lateral direction damps faster.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"

namespace tribo::study {
namespace {

constexpr double kMass = 2.0, kG = 9.81, kKx = 300.0, kKy = 500.0, kContact = 1e5;

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string scene(double v, double psi, double forward, double backward, double across) {
  const std::string z0 = number(0.05 - kMass * kG / (4 * kContact));
  return "simulation: {duration: 1, time_step: 0.0005, gravity: [0, 0, -9.81]}\n"
         "bodies:\n"
         "  - {name: belt, kind: kinematic, surface_velocity: [" +
         number(v) +
         ", 0, 0], geometry: [{name: belt_surface, shape: halfspace}]}\n"
         "  - {name: box, mass: " +
         number(kMass) + ", position: [0, 0, " + z0 +
         "], geometry: [{name: box_shape, shape: box, size: [0.2, 0.2, 0.1]}]}\n"
         "joints:\n"
         "  - {name: slide, type: planar_translation, parent: world, child: box, anchor: [0, 0, " +
         z0 +
         "], axis: [0, 0, 1]}\n"
         "bushings:\n"
         "  - {name: hold, a: world, b: box, frame_a: {position: [0, 0, " +
         z0 + "]}, stiffness: [" + number(kKx) + ", " + number(kKy) +
         ", 0]}\n"
         "friction_laws:\n"
         "  stribeck: {mu_s: 0.35, mu_k: 0.3, v_st: 0.15, v_eps: 0.01}\n"
         "materials:\n"
         "  - {name: grained, normal: {law: linear, stiffness: " +
         number(kContact) +
         ", damping: 0}, friction: stribeck,\n"
         "     anisotropy: {frame: b, axis: [" +
         number(std::cos(psi)) + ", " + number(std::sin(psi)) + ", 0], ratio: [" + number(forward) +
         ", " + number(across) + "], backward: [" + number(backward) + ", " + number(across) +
         "]}}\n"
         "contacts:\n  - {a: belt_surface, b: box_shape, material: grained}\n";
}

TEST(AnisotropicModes, EigenvaluesAndDeflectionAreTheHandLinearization) {
  const auto law = friction::makeFrictionLaw(
      {"stribeck", {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_st", 0.15}, {"v_eps", 0.01}}, {}});
  const double n = kMass * kG;
  for (double psi : {0.0, 0.5, 1.2}) {
    for (double v : {0.05, 0.4}) {
      SCOPED_TRACE("psi " + number(psi) + " V " + number(v));
      const double forward = 0.6, backward = 1.4, across = 2.0;
      const ModesResult r = analyzeModes(
          io::loadSceneFromString(scene(v, psi, forward, backward, across), "grained_belt.yaml"));
      ASSERT_EQ(r.coordinates, 2);
      // The box barely moves while it slides: its slip is -V along x. Its grain's axes (t1
      // along psi) and the ratios for that slip (the box moves against +x of the belt).
      const Eigen::Vector2d t1(std::cos(psi), std::sin(psi)), t2(-std::sin(psi), std::cos(psi));
      const Eigen::Vector2d s(-v, 0.0);
      const double c1 = t1.dot(s);
      const double r1 = c1 >= 0 ? forward : backward, r2 = across;
      Eigen::Matrix2d axes;
      axes.col(0) = t1;
      axes.col(1) = t2;
      const Eigen::Matrix2d R = axes * Eigen::Vector2d(r1, r2).asDiagonal() * axes.transpose();
      const Eigen::Vector2d w = R * s;
      const double rho = w.norm();
      const Eigen::Vector2d f = -n * law->coefficient(rho) * R * w / rho;
      const Eigen::Matrix2d dfds =
          -n * R *
          (law->slope(rho) * w * w.transpose() / (rho * rho) +
           law->coefficient(rho) *
               (Eigen::Matrix2d::Identity() / rho - w * w.transpose() / (rho * rho * rho))) *
          R;
      // Steady deflection K q = F.
      const Vec3& p = r.steady.state.bodies[1].position;
      EXPECT_NEAR(p.x(), f.x() / kKx, 1e-9);
      EXPECT_NEAR(p.y(), f.y() / kKy, 1e-9);
      // Companion matrix of m q'' = -K q + dF/ds q'.
      Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
      a.topRightCorner<2, 2>().setIdentity();
      a.bottomLeftCorner<2, 2>() = -Eigen::Vector2d(kKx, kKy).asDiagonal().toDenseMatrix() / kMass;
      a.bottomRightCorner<2, 2>() = dfds / kMass;
      const Eigen::Vector4cd expected = a.eigenvalues();
      // Every expected eigenvalue is a mode's (a complex pair is listed once) and every mode
      // an expected one.
      for (const Mode& m : r.modes) {
        double nearest = INFINITY;
        for (int i = 0; i < 4; ++i)
          nearest = std::min(nearest, std::abs(m.eigenvalue - expected[i]));
        EXPECT_LT(nearest, 1e-6 * std::abs(m.eigenvalue));
      }
      for (int i = 0; i < 4; ++i) {
        double nearest = INFINITY;
        for (const Mode& m : r.modes)
          nearest = std::min({nearest, std::abs(m.eigenvalue - expected[i]),
                              std::abs(std::conj(m.eigenvalue) - expected[i])});
        std::printf("psi %.1f V %.2f: expected %+.9f %+.9fi, nearest mode at %.2e\n", psi, v,
                    expected[i].real(), expected[i].imag(), nearest);
        EXPECT_LT(nearest, 1e-6 * std::abs(expected[i]));
      }
    }
  }
}

}  // namespace
}  // namespace tribo::study
