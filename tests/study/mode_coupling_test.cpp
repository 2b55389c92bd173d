// The mode-coupling scene (scenes/mode_coupling.yaml) against its 2 x 2 theory, derived here
// from the scene's numbers alone. The box (mass m) moves in x (along the belt, which slides
// at +v_b) and z; its contact is 4 corners of k_n (K_n = 4 k_n) and damping c_n (C_n = 4 c_n)
// under the half-height h/2, and friction is mu N along +x (coulomb, tanh(v_b / 1e-4) = 1).
// Steady state p = (x, z): the root of
//   sum_i -k_i (l_i - L) u_i + (mu N, N - m g) = 0,   N = K_n (h/2 - z),  u_i = (p - A_i)/l_i,
// found by Newton below. About it, m p'' + C p' + K p = 0 with
//   K = sum_i [k_i u_i u_i^T + (T_i / l_i)(I - u_i u_i^T)] + [[0, mu K_n], [0, K_n]]
//   C = [[0, mu C_n], [0, C_n]]        (T_i = k_i (l_i - L): the tension's transverse stiffness)
// Undamped (C_n = 0): the eigenvalues w^2 of K / m coalesce, then turn complex (flutter), when
//   (k11 - k22)^2 + 4 k12 k21 = 0.                                                     (1)
// With C_n > 0 the characteristic polynomial is
//   m^2 s^4 + m C_n s^3 + m (k11 + k22) s^2 + C_n (k11 - mu k21) s + det K,
// and Routh-Hurwitz's last condition a3 a2 a1 > a4 a1^2 + a3^2 a0 reduces (divide by
// m^2 C_n^2, p = k11 - mu k21) to  k12 k21 - (p - k11)(p - k22) > 0, i.e. stability while
//   k21 (mu (k11 - k22 - mu k21) + k12) > 0                                            (2)
// independent of C_n and m: damping of the normal coordinate alone moves the boundary by a
// finite step however small it is (the destabilization paradox of non-conservative systems;
// Hoffmann & Gaul 2003, ZAMM 83:524-534). Both boundaries are found here by bisection on mu
// of (1) and (2) (K depends on mu through the steady state), then compared with
// `findBoundary` on the scene within 1e-6.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>

#include "study/modes/stability_boundary.hpp"

namespace tribo::study {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/mode_coupling.yaml";
// The scene's numbers.
constexpr double kM = 1.0, kG = 9.81, kHalf = 0.05, kKn = 4 * 2.5e3, kL = 10.0;
const Eigen::Vector2d kStart(0.0, 0.049);
struct Spring {
  double k;
  Eigen::Vector2d anchor;
};
const Spring kSprings[] = {{1e4, {-8.660254037844386, 5.049}}, {2e3, {-5.0, -8.611254037844386}}};

// Steady state and K at friction coefficient mu.
Eigen::Matrix2d stiffness(double mu) {
  Eigen::Vector2d p = kStart;
  Eigen::Matrix2d k;
  for (int it = 0; it < 50; ++it) {
    Eigen::Vector2d force(0.0, -kM * kG);
    k.setZero();
    for (const Spring& s : kSprings) {
      const Eigen::Vector2d d = p - s.anchor;
      const double l = d.norm();
      const Eigen::Vector2d u = d / l;
      const double tension = s.k * (l - kL);
      force -= tension * u;
      k +=
          s.k * u * u.transpose() + tension / l * (Eigen::Matrix2d::Identity() - u * u.transpose());
    }
    const double n = kKn * (kHalf - p.y());
    force += Eigen::Vector2d(mu * n, n);
    k(0, 1) += mu * kKn;
    k(1, 1) += kKn;
    if (force.norm() < 1e-13) break;
    p += k.lu().solve(force);
  }
  return k;
}

double flutter(double mu) {  // (1): < 0 beyond the boundary
  const Eigen::Matrix2d k = stiffness(mu);
  return (k(0, 0) - k(1, 1)) * (k(0, 0) - k(1, 1)) + 4 * k(0, 1) * k(1, 0);
}

double hurwitz(double mu) {  // (2): < 0 beyond the boundary
  const Eigen::Matrix2d k = stiffness(mu);
  return k(1, 0) * (mu * (k(0, 0) - k(1, 1) - mu * k(1, 0)) + k(0, 1));
}

double root(const std::function<double(double)>& f, double lo, double hi) {
  EXPECT_GT(f(lo), 0);
  EXPECT_LT(f(hi), 0);
  while (hi - lo > 1e-13) (f(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

BoundarySpec spec(std::vector<std::string> overrides) {
  BoundarySpec s;
  s.scene_path = kScene;
  s.overrides = std::move(overrides);
  s.parameter = "mu";
  s.lo = 0.4;
  s.hi = 0.8;
  s.tolerance = 1e-9;
  return s;
}

TEST(ModeCoupling, CriticalMuIsWhereTheTwoModesCoalesce) {
  const double mu_c = root(flutter, 0.4, 0.8);
  // Without the springs' tilt and tension (anchors at infinity) (1) is closed-form in the
  // spring matrix S = sum k_i e_i e_i^T:  mu_c = -((S11 - S22 - K_n)^2 + 4 S12^2) / (4 S12 K_n).
  const double s11 = 1e4 * 0.75 + 2e3 * 0.25, s22 = 1e4 * 0.25 + 2e3 * 0.75;
  const double s12 = -1e4 * std::sqrt(3.0) / 4 + 2e3 * std::sqrt(3.0) / 4;
  const double mu_far = -((s11 - s22 - kKn) * (s11 - s22 - kKn) + 4 * s12 * s12) / (4 * s12 * kKn);
  EXPECT_NEAR(mu_c, mu_far, 1e-3);  // the 10 m anchors move it by 1e-4
  const BoundaryResult found = findBoundary(spec({}));
  std::printf(
      "mode coupling: critical mu %.9f (theory), %.9f (found), %.6f (anchors at infinity)\n", mu_c,
      found.critical, mu_far);
  EXPECT_TRUE(found.unstable_above);
  EXPECT_NEAR(found.critical, mu_c, 1e-6);
  // Either side: stable (purely imaginary pairs) and one growing pair.
  const ModesResult below = analyzeScene(kScene, {"mu=0.58"}, {});
  EXPECT_EQ(below.unstable_count, 0);
  EXPECT_NEAR(below.leading().growth_rate, 0.0, 1e-6);
  const ModesResult above = analyzeScene(kScene, {"mu=0.63"}, {});
  EXPECT_EQ(above.unstable_count, 1);
  // Above: the pair's eigenvalues s with s^2 the eigenvalues of -K/m.
  const Eigen::Matrix2d k = stiffness(0.63);
  const Eigen::Vector2cd s2 = (-k / kM).eigenvalues();
  const std::complex<double> s = std::sqrt(s2(0));
  EXPECT_NEAR(above.leading().growth_rate, std::abs(s.real()), 1e-6 * std::abs(s));
  EXPECT_NEAR(above.leading().frequency, std::abs(s.imag()) / (2 * std::numbers::pi),
              1e-6 * std::abs(s));
}

TEST(ModeCoupling, NormalDampingAloneLowersTheCriticalMuWhateverItsSize) {
  const double mu_d = root(hurwitz, 0.4, 0.8);
  EXPECT_LT(mu_d, root(flutter, 0.4, 0.8) - 0.02);
  for (const char* c : {"contact_damping=0.5", "contact_damping=5"}) {
    const BoundaryResult found = findBoundary(spec({c}));
    std::printf("mode coupling, %s: critical mu %.9f (theory), %.9f (found)\n", c, mu_d,
                found.critical);
    EXPECT_TRUE(found.unstable_above);
    EXPECT_NEAR(found.critical, mu_d, 1e-6) << c;
  }
}

}  // namespace
}  // namespace tribo::study
