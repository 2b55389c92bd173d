// scenes/experiments/servo_stick_slip.yaml (a position servo tracking a ramp against LuGre
// friction on a prismatic guide) against a reference computed here, outside the engine: the
// slide's one-degree-of-freedom equations
//   m x'' = kp (v t - x) + kd (v - x') - F_n (sigma0 z + sigma1 z' + sigma2 x'),
//   z' = x' - sigma0 |x'| z / g(x'),  g(v) = mu_c + (mu_s - mu_c) exp(-(v / v_s)^2)
// (Canudas de Wit, Olsson, Astrom & Lischinsky 1995, eqs. (2)-(4) and Fig. 5's rig, the
// servo's gain standing for the spring), integrated by classical RK4 at 5 us. Checked: the
// trajectory at samples in stick and slip for kd = 0 and a damped kd, the largest servo
// effort before the first slip (the break-away force), the run summary's period.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"

namespace tribo {
namespace {

const std::string kScene =
    std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/servo_stick_slip.yaml";
constexpr double kM = 1.0, kKp = 2.0, kV = 0.1, kFn = 1.0;
constexpr double kSigma0 = 1e5, kSigma1 = 316.22776601683796, kSigma2 = 0.4;
constexpr double kMuC = 1.0, kMuS = 1.5, kVs = 1e-3;

// Samples in the first stick, the first slip, the second stick and slip.
const std::vector<double> kTimes = {3.0, 7.0, 7.6, 8.0, 9.0, 10.0, 12.0, 14.2, 15.0};

struct Slide {
  double x, v, z;
};

Slide rk4Step(double t, const Slide& y, double h, double kd) {
  auto g = [](double v) {
    const double r = v / kVs;
    return kMuC + (kMuS - kMuC) * std::exp(-r * r);
  };
  auto f = [&](double s, const Slide& b) {
    const double zdot = b.v - kSigma0 * std::abs(b.v) * b.z / g(std::abs(b.v));
    const double friction = kFn * (kSigma0 * b.z + kSigma1 * zdot + kSigma2 * b.v);
    return Slide{b.v, (kKp * (kV * s - b.x) + kd * (kV - b.v) - friction) / kM, zdot};
  };
  auto add = [](const Slide& a, double c, const Slide& d) {
    return Slide{a.x + c * d.x, a.v + c * d.v, a.z + c * d.z};
  };
  const Slide k1 = f(t, y);
  const Slide k2 = f(t + h / 2, add(y, h / 2, k1));
  const Slide k3 = f(t + h / 2, add(y, h / 2, k2));
  const Slide k4 = f(t + h, add(y, h, k3));
  return {y.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
          y.v + h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v),
          y.z + h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z)};
}

struct Reference {
  std::vector<double> x;    // at kTimes
  double break_away = 0.0;  // largest kp (v t - x) + kd (v - x') before t = 7.6 s
  double period = 0.0;      // between the last two slip onsets before `end`
};

Reference reference(double kd, double end) {
  const double h = 5e-6;  // h sigma0 |v| / g <= 0.2 at the slip peak
  Slide y{0, 0, 0};
  Reference r;
  std::vector<double> onsets;
  std::size_t next = 0;
  for (long i = 0; i < std::lround(end / h); ++i) {
    const double t = i * h;
    if (next < kTimes.size() && std::abs(t - kTimes[next]) < h / 2) r.x.push_back(y.x), ++next;
    if (t < 7.6) r.break_away = std::max(r.break_away, kKp * (kV * t - y.x) + kd * (kV - y.v));
    const double v0 = y.v;
    y = rk4Step(t, y, h, kd);
    if (v0 < kV && y.v >= kV) onsets.push_back(t + h);
  }
  if (onsets.size() >= 2) r.period = onsets.back() - onsets[onsets.size() - 2];
  return r;
}

TEST(ServoStickSlip, TrajectoryAndBreakAwayMatchTheReference) {
  for (const double kd : {0.0, 0.3}) {
    const Reference ref = reference(kd, 15.0 + 1e-3);
    ASSERT_EQ(ref.x.size(), kTimes.size());
    const io::Scene scene = io::loadScene(kScene, {"duration=15", "kd=" + std::to_string(kd)});
    Simulator sim(scene.model);
    const int slide = scene.model->findBody("slide")->value;
    double worst = 0.0, break_away = 0.0;
    for (std::size_t i = 0; i < kTimes.size(); ++i) {
      while (sim.state().time < kTimes[i] - 1e-9) {
        const StepStatus status = sim.step();
        ASSERT_TRUE(status.ok) << status.message;
        if (sim.state().time < 7.6)
          break_away = std::max(break_away, sim.current().actuator_output[0].effort);
      }
      worst = std::max(worst, std::abs(sim.state().bodies[slide].position.x() - ref.x[i]));
    }
    std::printf("kd %g: worst |x - x_ref| %.3g m, break-away %.9g N (reference %.9g N)\n", kd,
                worst, break_away, ref.break_away);
    // RK4 at 5e-5 s against 5e-6 s: the scene's truncation error, ~1e-9 m here.
    EXPECT_LT(worst, 1e-7) << kd;
    // The effort is sampled every 5e-5 s, the reference's every 5e-6 s: at the peak the
    // effort changes by at most kp v dt = 1e-5 N a step.
    EXPECT_NEAR(break_away, ref.break_away, 1e-5) << kd;
    EXPECT_GT(break_away, 1.4);  // near F_s = 1.5 N: LuGre's break-away at this rate
  }
}

TEST(ServoStickSlip, TheRunSummaryFindsTheReferencePeriod) {
  const io::Scene scene = io::loadScene(kScene, {"duration=25"});
  const study::RunResult r = study::runScene(scene);
  ASSERT_TRUE(r.complete) << r.message;
  const double period = reference(0.0, 25.0).period;
  std::printf("servo stick-slip period: engine %.6g s, reference %.6g s\n", r.summary.period,
              period);
  EXPECT_TRUE(r.summary.oscillating);
  EXPECT_NEAR(r.summary.period, period, 0.005 * period);
  // Stuck (|x'| below the law's Stribeck speed) most of the time, as in the paper's figure.
  const auto v = r.trajectory.column(r.trajectory.columnIndex("slide.vx"));
  const auto stuck = std::count_if(v.begin(), v.end(), [](double x) { return std::abs(x) < kVs; });
  EXPECT_GT(static_cast<double>(stuck) / static_cast<double>(v.size()), 0.5);
}

}  // namespace
}  // namespace tribo
