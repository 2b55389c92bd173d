// scenes/lugre_presliding.yaml: a block stuck under LuGre friction (Canudas de Wit et al.
// 1995, Table I per newton of load; N = 1 N), pulled through a spring k whose far end moves
// as A sin(w t), k A = 0.9 mu_s N: the presliding hysteresis loop; and a free vibration
// about the unloaded stuck state. Expectations, from the law alone:
// * Quasi-static presliding (v << v_s so g = mu_s; the damping forces small): F = sigma0 z N
//   and dz/dx = 1 - sigma0 z sgn(v) / mu_s. Loading from z = 0 (the virgin curve):
//   x = -(mu_s / sigma0) ln(1 - F / (mu_s N)). From a reversal at (x_r, F_r) with v < 0:
//   x = x_r + (mu_s / sigma0) ln((mu_s + F / N) / (mu_s + F_r / N)), and from one with v > 0:
//   x = x_b - (mu_s / sigma0) ln((mu_s - F / N) / (mu_s - F_b / N)); between -+ f mu_s N the
//   loop closes, its width (mu_s / sigma0) ln((1 + f) / (1 - f)).
//   What the quasi-static curves leave out, the tolerance: the force also carries
//   dF = N (sigma1 dz/dt + sigma2 v) + m a (the spring pulls F = k (x_p - x)), so the
//   block lags by dx = dF dx/dF; with v = F' dx/dF, F' <= k A w = 0.135 N/s and dz/dt =
//   v (1 - F / (mu_s N)), that is dF = N F' dx/dF (sigma1 (1 - F / mu_s N) + sigma2), which
//   the test evaluates at each point: 4e-8 m at F = 0.85 mu_s N, 1.3e-3 of x there. g's dip
//   (v / v_s)^2 (mu_s - mu_c) ~ 1e-4 and m a ~ 1e-6 N are second order. Each point is held
//   to twice its own first-order lag (the lag's sign is known; no term is of the same size).
// * Small motion about z = 0: z' = v (the |v| z term is second order), F_friction =
//   N (sigma0 x + (sigma1 + sigma2) v): a free vibration at w_n = sqrt((sigma0 N + k) / m)
//   (the pulling spring adds k = 100 to sigma0 N = 1e5) with damping ratio
//   zeta = (sigma1 + sigma2) N / (2 sqrt((sigma0 N + k) m)) = 0.50; measured from the spacing
//   of the extremes (pi / w_d, w_d = w_n sqrt(1 - zeta^2)) and the ratio of successive ones
//   (exp(-pi zeta / sqrt(1 - zeta^2))).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/lugre_presliding.yaml";
constexpr double kM = 1.0, kN = 1.0, kK = 100.0, kA = 0.0135, kW = 0.1;
constexpr double kSigma0 = 1e5, kSigma1 = 316.22776601683796, kSigma2 = 0.4, kMuS = 1.5;

struct Sample {
  double t, x, f;  // time, block x [m], spring force k (x_p - x) [N]
};

std::vector<Sample> run(const std::vector<std::string>& overrides, double until) {
  const io::Scene scene = io::loadScene(kScene, overrides);
  Simulator sim(scene.model);
  const int block = scene.model->findBody("block")->value;
  const int puller = scene.model->findBody("puller")->value;
  std::vector<Sample> out;
  while (sim.state().time < until - 1e-12) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) break;
    const double x = sim.state().bodies[block].position.x();
    const double xp = sim.state().bodies[puller].position.x() - 1.0;
    out.push_back({sim.state().time, x, kK * (xp - x)});
  }
  return out;
}

// First-order quasi-static lag of x behind the curve with slope dx/dF, at force f whose
// rate is |F'| (see the header).
double lag(double dxdf, double f_over_mus, double force_rate) {
  const double v = force_rate * dxdf;
  return kN * v * (kSigma1 * (1 - std::abs(f_over_mus)) + kSigma2) * dxdf;
}

TEST(LuGrePresliding, VirginCurveAndHysteresisLoop) {
  const double period = 2 * std::numbers::pi / kW;
  // Two maxima of the drive (T/4 and 5T/4) and the minimum between; RK4 at 2 ms (the
  // a-priori limit is 7 ms); the drive is slow, RK4's error on it is (h w)^4 ~ 1e-15.
  const std::vector<Sample> s = run({"dt=0.002"}, 1.25 * period + 1.0);
  // Virgin curve: the first time F reaches each target.
  std::size_t i = 1;
  for (double fraction : {0.2, 0.5, 0.7, 0.85}) {
    const double target = fraction * kMuS * kN;
    while (i < s.size() && s[i].f < target) ++i;
    ASSERT_LT(i, s.size());
    const double u = (target - s[i - 1].f) / (s[i].f - s[i - 1].f);
    const double x = s[i - 1].x + u * (s[i].x - s[i - 1].x);
    const double t = s[i - 1].t + u * (s[i].t - s[i - 1].t);
    const double expected = -(kMuS / kSigma0) * std::log(1 - fraction);
    const double dxdf = 1 / (kSigma0 * kN * (1 - fraction));
    const double bound = lag(dxdf, fraction, kK * kA * kW * std::cos(kW * t));
    std::printf("virgin F = %.2f mu_s N: x %.6e m, closed form %.6e, lag bound %.2e\n", fraction, x,
                expected, bound);
    EXPECT_NEAR(x, expected, 2 * bound) << fraction;
    EXPECT_LT(x, expected) << "the damping forces make the block lag";
  }
  // The turning points: the force's extremes (the drive's reversals).
  auto extreme = [&](double t0, double t1, bool max) {
    Sample best{0, 0, max ? -INFINITY : INFINITY};
    for (const Sample& p : s)
      if (p.t >= t0 && p.t <= t1 && (max ? p.f > best.f : p.f < best.f)) best = p;
    return best;
  };
  const Sample top1 = extreme(0, 0.5 * period, true);
  const Sample bottom = extreme(0.5 * period, period, false);
  const Sample top2 = extreme(period, 1.25 * period + 1.0, true);
  // Descending branch from top1: x at the bottom's force; ascending from the bottom to top2.
  const double x_bottom =
      top1.x + (kMuS / kSigma0) * std::log((kMuS + bottom.f / kN) / (kMuS + top1.f / kN));
  const double x_top2 =
      bottom.x - (kMuS / kSigma0) * std::log((kMuS - top2.f / kN) / (kMuS - bottom.f / kN));
  const double f = (top1.f - bottom.f) / (2 * kMuS * kN);
  const double width = (kMuS / kSigma0) * std::log((1 + f) / (1 - f));
  std::printf(
      "loop: top %.6e m at %.5f N, bottom %.6e m at %.5f N (branch %.6e), second top "
      "%.6e m (branch %.6e); width %.6e m (symmetric closed form %.6e)\n",
      top1.x, top1.f, bottom.x, bottom.f, x_bottom, top2.x, x_top2, top1.x - bottom.x, width);
  // At the reversals the speed vanishes (no lag), and each branch starts from the measured
  // reversal, so the lag does not accumulate. Left: the drive's force turns while the block
  // still moves at the lag's speed over the time (sigma1 + sigma2) / sigma0 ~ 3 ms, a part in
  // 1e4 of the branch; and the extremes' sampling on the 2 ms grid, dF ~ k A (w h)^2 / 2 =
  // 3e-8 N. Measured 3.4e-10 m and 3.3e-10 m of the 4.4e-5 m width (7.8e-6, as
  // docs/friction-laws.md states); held to 1.5e-5 of the width.
  const double span = top1.x - bottom.x;
  EXPECT_NEAR(bottom.x, x_bottom, 1.5e-5 * span);
  EXPECT_NEAR(top2.x, x_top2, 1.5e-5 * span);
  // (The symmetric closed form is no check here: the extremes' forces differ, 1.3466 N up
  // and 1.3490 N down, and the width's slope in the bottom force is 1 / (mu_s N - |F|).)
}

TEST(LuGrePresliding, SmallMotionFrequencyAndDampingAboutTheStuckState) {
  // A kick of 1e-8 m/s: amplitude A = 1.7e-11 m, sigma0 A / mu_s = 1e-6 (the neglected
  // term). Its integral moves the rest position by about sigma0 A^2 / mu_s = 2e-17 m, 4e-5
  // of the third extreme (a kick of 1e-6 m/s made that 4e-3).
  const std::vector<Sample> s =
      run({"amplitude=0", "v_kick=1e-8", "dt=1e-5", "duration=0.05", "output_interval=1e-5"}, 0.05);
  // Extremes of x, refined by a parabola through three samples.
  std::vector<double> te, xe;
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    const double d1 = (s[i + 1].x - s[i - 1].x) / 2, d2 = s[i + 1].x - 2 * s[i].x + s[i - 1].x;
    const bool peak = (s[i].x > s[i - 1].x && s[i].x >= s[i + 1].x) ||
                      (s[i].x < s[i - 1].x && s[i].x <= s[i + 1].x);
    if (!peak || d2 == 0) continue;
    te.push_back(s[i].t - d1 / d2 * (s[i + 1].t - s[i].t));
    xe.push_back(s[i].x - d1 * d1 / (2 * d2));
  }
  ASSERT_GE(te.size(), 3u);
  const double wn = std::sqrt((kSigma0 * kN + kK) / kM);
  const double zeta = (kSigma1 + kSigma2) * kN / (2 * std::sqrt((kSigma0 * kN + kK) * kM));
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const double measured_wd = std::numbers::pi / (te[2] - te[1]);
  const double r = std::log(std::abs(xe[1] / xe[2]));  // pi zeta / sqrt(1 - zeta^2)
  const double measured_zeta = r / std::sqrt(std::numbers::pi * std::numbers::pi + r * r);
  std::printf(
      "free vibration: w_d %.6g rad/s (%.6g), zeta %.6g (%.6g); extremes %.3g, %.3g, "
      "%.3g m\n",
      measured_wd, wd, measured_zeta, zeta, xe[0], xe[1], xe[2]);
  // The neglected term and its offset, 4e-5 relative; parabolic extremes on the 10 us grid
  // (w h = 3e-3): (w h)^2 ~ 1e-5. Measured: w_d to 1e-7, zeta to 2e-5 (0.500372 against
  // 0.500382, as docs/friction-laws.md states); held to 1e-5 and 5e-5.
  EXPECT_NEAR(measured_wd, wd, 1e-5 * wd);
  EXPECT_NEAR(measured_zeta, zeta, 5e-5 * zeta);
}

}  // namespace
}  // namespace tribo
