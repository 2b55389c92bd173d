// scenes/rate_state_slider.yaml: the stability of steady sliding of a spring-slider under
// rate-and-state friction, measured by simulation against the linear theory derived here.
//
// Block of mass m on a normal load N, on a belt moving at V and held by a spring k (in its
// frame: pulled at V through the spring);
// mu = a asinh((v / 2 v0) exp((mu0 + b psi) / a)), psi = ln(v0 theta / d_c), aging
// dpsi/dt = (v0 e^-psi - v) / d_c or slip dpsi/dt = -(v / d_c)(psi + ln(v / v0)). About
// steady sliding (v = V, psi = ln(v0 / V)) put v = V + u, psi = psi_ss + p, x = x_ss + y:
// both evolution laws linearize to the same dp/dt = -(V p + u) / d_c, and the friction to
// d mu = c (a u / V + b p), c = tanh(mu_ss / a) (the arcsinh's slope: d asinh(e^L) / dL =
// tanh(asinh(e^L)); c = 1 for the plain logarithmic law). With m y'' = -k y - N d mu and
// p = -u / (d_c s + V) in Laplace variables:
//   m d_c s^3 + (m V + N c a d_c / V) s^2 + (k d_c - N c (b - a)) s + k V = 0.
// Routh-Hurwitz (all coefficients positive and c2 c1 > c3 c0) gives stability iff
//   k > k_cr = (N (b - a) / d_c) (c + m V^2 / (N a d_c)),
// which for c = 1 is Rice & Ruina's (J. Appl. Mech. 50:343, 1983) k_cr = (N (b - a) / d_c)
// (1 + m V^2 / (N a d_c)); the regularization scales only the quasi-static part, by
// tanh(mu_ss / a) = tanh(60) = 1 - 1e-52 here. At k_cr the oscillation's frequency is
// (V / d_c) sqrt((b - a) / a). The test measures the growth rate sigma of the block's speed
// oscillation (log of its successive peaks, least squares) at k = (1 -+ 5%) k_cr, checks the
// signs, and takes the boundary as the zero of the straight line through the two (the
// linear theory's own sigma(k) puts that zero within 3e-4 of k_cr): within 0.1% of k_cr. At
// V = 1e-3 m/s the inertia term is 2: k_cr = 3 N (b - a) / d_c, and the quasi-static value,
// by which k = 0.95 k_cr would be stable, is wrong by a factor 3.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/rate_state_slider.yaml";
constexpr double kM = 1.0, kN = 1.0, kMu0 = 0.6, kA = 0.01, kB = 0.015, kDc = 5e-5;

// k_cr above; mu_ss = mu0 (v0 = V in the scene).
double criticalStiffness(double v) {
  return kN * (kB - kA) / kDc * (std::tanh(kMu0 / kA) + kM * v * v / (kN * kA * kDc));
}

// The largest real part among the roots of the characteristic cubic above (Durand-Kerner).
std::complex<double> leadingRoot(double k, double v) {
  const double c = std::tanh(kMu0 / kA);
  const double c3 = kM * kDc, c2 = kM * v + kN * c * kA * kDc / v,
               c1 = k * kDc - kN * c * (kB - kA), c0 = k * v;
  std::array<std::complex<double>, 3> r = {
      std::complex<double>(0.4, 0.9), {-0.65, 0.72}, {-0.3, -0.95}};
  const double scale = std::abs(c0 / c3) > 0 ? std::cbrt(std::abs(c0 / c3)) : 1.0;
  for (auto& z : r) z *= scale;
  for (int it = 0; it < 500; ++it) {
    for (int i = 0; i < 3; ++i) {
      std::complex<double> den = c3;
      for (int j = 0; j < 3; ++j)
        if (j != i) den *= r[i] - r[j];
      r[i] -= (((c3 * r[i] + c2) * r[i] + c1) * r[i] + c0) / den;
    }
  }
  std::complex<double> best = r[0];
  for (const auto& z : r)
    if (std::abs(z.imag()) > std::abs(best.imag())) best = z;
  return best;
}

struct Growth {
  double sigma;   // growth rate of the speed oscillation's peaks [1/s]
  double period;  // mean spacing of the peaks [s]
  double first;   // first peak used, relative to V [-]
};

// Runs the scene and fits ln(peak of v - V) = const + sigma t over the peaks after t_skip.
Growth measure(double k, double v, double duration, double t_skip, const std::string& evolution) {
  const io::Scene scene = io::loadScene(
      kScene, {"k=" + std::to_string(k), "v=" + std::to_string(v), "evolution=" + evolution,
               "duration=" + std::to_string(duration), "dt=0.002", "df=1e-5"});
  Simulator sim(scene.model);
  const int block = scene.model->findBody("block")->value;
  std::vector<double> t, u;
  while (sim.state().time < duration - 1e-9) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) return {NAN, NAN, NAN};
    t.push_back(sim.state().time);
    u.push_back(sim.state().bodies[block].velocity.x());
  }
  // Peaks: a parabola through three samples around each local maximum of u.
  std::vector<double> pt, pu;
  for (std::size_t i = 1; i + 1 < u.size(); ++i) {
    if (t[i] < t_skip || !(u[i] > u[i - 1] && u[i] >= u[i + 1]) || u[i] <= 0) continue;
    const double d2 = u[i - 1] - 2 * u[i] + u[i + 1], d1 = (u[i + 1] - u[i - 1]) / 2;
    const double shift = d2 != 0 ? -d1 / d2 : 0;
    pt.push_back(t[i] + shift * (t[i + 1] - t[i]));
    pu.push_back(std::log(u[i] - d1 * d1 / (2 * d2)));
  }
  EXPECT_GE(pt.size(), 4u);
  double st = 0, su = 0, stt = 0, stu = 0;
  const double n = static_cast<double>(pt.size());
  for (std::size_t i = 0; i < pt.size(); ++i) {
    st += pt[i];
    su += pu[i];
    stt += pt[i] * pt[i];
    stu += pt[i] * pu[i];
  }
  const double sigma = (n * stu - st * su) / (n * stt - st * st);
  return {sigma, (pt.back() - pt.front()) / (n - 1), std::exp(pu.front()) / v};
}

// The boundary from two simulations at (1 -+ 5%) k_cr.
double measuredBoundary(double v, double period, const std::string& evolution) {
  const double k_cr = criticalStiffness(v);
  const double k1 = 0.95 * k_cr, k2 = 1.05 * k_cr;
  // Skip the first period (the fast real mode, rate N a / (m V) or faster, is gone after it)
  // and fit the next six.
  const Growth g1 = measure(k1, v, 7 * period, period, evolution);
  const Growth g2 = measure(k2, v, 7 * period, period, evolution);
  for (const auto& [k, g] : {std::pair{k1, g1}, std::pair{k2, g2}}) {
    const std::complex<double> s = leadingRoot(k, v);
    std::printf(
        "%s V %g k %.4g: sigma %.5g 1/s (linear theory %.5g), period %.5g s (%.5g), "
        "first peak %.2g V\n",
        evolution.c_str(), v, k, g.sigma, s.real(), g.period,
        2 * std::numbers::pi / std::abs(s.imag()), g.first);
    // Against the linear theory: the amplitude |u| / V <= 2e-3 (df = 1e-5 N) makes the
    // nonlinear terms' shift of sigma about (u / V)^2 w = 4e-6 w, 2e-4 of |sigma| = 0.018 w
    // at 5% from k_cr; the parabolic peaks on the step grid err by less than (w h)^2 = 8e-4
    // (w h = 0.028 at V = 1e-3 m/s); RK4's phase and amplitude errors at h w <= 0.03 are
    // below 1e-8 per cycle. Sum 1e-3, and the block's vertical contact dynamics, which the
    // theory leaves out: measured at most 1.6e-3, held to 3e-3. The period: the same
    // (w h)^2; measured to 2e-5 (docs/friction-laws.md: "5 digits"), held to 1e-4.
    EXPECT_NEAR(g.sigma, s.real(), 3e-3 * std::abs(s.real())) << evolution << " k " << k;
    EXPECT_NEAR(g.period, 2 * std::numbers::pi / std::abs(s.imag()),
                1e-4 * 2 * std::numbers::pi / std::abs(s.imag()))
        << evolution;
  }
  EXPECT_GT(g1.sigma, 0) << "unstable below k_cr";
  EXPECT_LT(g2.sigma, 0) << "stable above k_cr";
  return k1 + (k2 - k1) * g1.sigma / (g1.sigma - g2.sigma);
}

TEST(RateStateSlider, QuasiStaticBoundaryIsCriticalStiffness) {
  // V = 5e-5 m/s: m V^2 / (N a d_c) = 0.005, k_cr = 100.5 N/m, period 8.9 s.
  const double v = 5e-5;
  const double k_qs = kN * (kB - kA) / kDc;
  const double k = measuredBoundary(v, 9.0, "aging");
  std::printf("quasi-static: measured boundary %.5g N/m, k_cr %.5g, (b - a) N / d_c %.5g\n", k,
              criticalStiffness(v), k_qs);
  EXPECT_NEAR(k, criticalStiffness(v), 1e-3 * criticalStiffness(v));
  EXPECT_NEAR(k, k_qs, 0.01 * k_qs);  // k_cr is 0.5% above the quasi-static value here
}

TEST(RateStateSlider, InertiaRaisesTheBoundaryAsRiceAndRuinaPredict) {
  // V = 1e-3 m/s: m V^2 / (N a d_c) = 2, k_cr = 300 N/m, three times the quasi-static 100;
  // period 0.44 s. Both evolution laws share the linearization.
  const double v = 1e-3;
  const double k_qs = kN * (kB - kA) / kDc;
  for (const char* evolution : {"aging", "slip"}) {
    const double k = measuredBoundary(v, 0.45, evolution);
    std::printf("%s with inertia: measured boundary %.5g N/m, k_cr %.5g, quasi-static %.5g\n",
                evolution, k, criticalStiffness(v), k_qs);
    EXPECT_NEAR(k, criticalStiffness(v), 1e-3 * criticalStiffness(v)) << evolution;
    EXPECT_GT(k, 2.5 * k_qs) << evolution;
  }
}

}  // namespace
}  // namespace tribo
