// study/modes with a law that has internal state: the belt scene (scenes/belt.yaml) under
// LuGre. Reduced by hand to (x, x', dz) about steady sliding at slip s0 = -v_b (the box at
// rest, the belt under it at v_b), with g(v) = mu_k + (mu_s - mu_k) exp(-(v/v_s)^2),
// phi(s) = sigma0 |s| / g(|s|), N = m g, and the steady bristle z0 = -g(v_b) / sigma0:
//   z'  = s - phi(s) z           ->  dz' = a dx' + b dz,
//         a = 1 - phi'(s0) z0 = v_b g'(v_b) / g(v_b),   b = -sigma0 v_b / g(v_b)
//   m x'' = -k x - N (sigma0 z + sigma1 z' + sigma2 s)  (about the steady state)
//   A = [[0, 1, 0], [-k/m, -N (sigma2 + sigma1 a)/m, -N (sigma0 + sigma1 b)/m], [0, a, b]]
// The four corners carry N/4 each with equal states, so the lumped system's complex pair is
// the engine's in-plane pair. As sigma0 grows, the pair tends to the memoryless answer
// sigma = -N (g'(v_b) + sigma2) / (2 m) of the steady-state curve (tests/study/modes_test).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdio>

#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"

namespace tribo::study {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
constexpr double kM = 10, kK = 300, kG = 9.81, kMuS = 0.35, kMuK = 0.3, kVs = 0.01;

struct Case {
  double v_b, sigma0, sigma1;
};

// The lumped system's eigenvalue of largest real part (the in-plane pair, or its faster
// root when a steep slope makes it real).
std::complex<double> lumpedPair(const Case& c) {
  const double n = kM * kG, r = c.v_b / kVs;
  const double g = kMuK + (kMuS - kMuK) * std::exp(-r * r);
  const double dg = -(kMuS - kMuK) * 2 * r / kVs * std::exp(-r * r);
  const double a = c.v_b * dg / g, b = -c.sigma0 * c.v_b / g;
  Eigen::Matrix3d m;
  m << 0, 1, 0, -kK / kM, -n * c.sigma1 * a / kM, -n * (c.sigma0 + c.sigma1 * b) / kM, 0, a, b;
  const Eigen::Vector3cd values = Eigen::EigenSolver<Eigen::Matrix3d>(m).eigenvalues();
  std::complex<double> best(-INFINITY, 0);
  for (const auto& v : values)
    if (v.real() > best.real() || (v.real() == best.real() && v.imag() > best.imag())) best = v;
  return best;
}

TEST(ModesDynamicFriction, LuGreBeltPairIsTheLumpedBristleSystems) {
  // Oscillating pairs (v_b 0.018 to 0.025 m/s) and a slope so steep that the growing root
  // is real (0.01 m/s); light and stiff bristles, with and without bristle damping.
  for (const Case& c :
       {Case{0.02, 1e3, 0}, Case{0.018, 1e4, 10}, Case{0.025, 1e5, 30}, Case{0.01, 3e3, 0}}) {
    char v[64], s0[64], s1[64];
    std::snprintf(v, sizeof v, "v_b=%.17g", c.v_b);
    std::snprintf(s0, sizeof s0, "sigma0=%.17g", c.sigma0);
    std::snprintf(s1, sizeof s1, "sigma1=%.17g", c.sigma1);
    const io::Scene scene = io::loadScene(kBelt, {"friction=lugre", v, s0, s1});
    const ModesResult r = analyzeModes(scene);
    const std::complex<double> want = lumpedPair(c);
    const double f = want.imag() / (2 * M_PI);
    ASSERT_FALSE(r.modes.empty());
    const Mode* got = &r.modes.front();  // the largest growth rate
    std::printf("v_b %g sigma0 %g sigma1 %g: growth %.8g (lumped %.8g), %.8g Hz (%.8g)\n", c.v_b,
                c.sigma0, c.sigma1, got->growth_rate, want.real(), got->frequency, f);
    // Central differences at h ~ 1e-7 relative: 1e-5 of the pair's size.
    EXPECT_NEAR(got->growth_rate, want.real(), 1e-5 * std::abs(want));
    EXPECT_NEAR(got->frequency, f, 1e-5 * std::abs(want) / (2 * M_PI));
  }
}

TEST(ModesDynamicFriction, StiffBristlesTendToTheSteadyStateCurve) {
  const double n = kM * kG, r = 2.0;  // v_b = 2 v_s: an oscillating pair
  const double dg = -(kMuS - kMuK) * 2 * r / kVs * std::exp(-r * r);
  const double memoryless = -n * dg / (2 * kM);
  double previous = INFINITY;
  for (double sigma0 : {1e3, 1e4, 1e5, 1e6}) {
    char s0[64];
    std::snprintf(s0, sizeof s0, "sigma0=%.17g", sigma0);
    const ModesResult r =
        analyzeModes(io::loadScene(kBelt, {"friction=lugre", "v_b=0.02", s0, "sigma1=0"}));
    const double gap = std::abs(r.modes.front().growth_rate - memoryless);
    std::printf("sigma0 %g: growth %.8g, memoryless %.8g\n", sigma0, r.modes.front().growth_rate,
                memoryless);
    EXPECT_LT(gap, previous) << sigma0;  // closer with every decade
    previous = gap;
  }
  EXPECT_LT(previous, 0.01 * memoryless);
}

}  // namespace
}  // namespace tribo::study
