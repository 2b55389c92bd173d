// Break-away under a ramped push (scenes/experiments/break_away_ramp.yaml): a block on the
// ground with the elastic_stick law, pushed along x by F = rate t at its bottom face, stays
// put (|x| of the tangential springs' give, F / (4 k_t)) until F reaches mu_s m g and then
// slides with acceleration (F - mu_k m g) / m. Break-away time t* = mu_s m g / rate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene =
    std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/break_away_ramp.yaml";
constexpr double kG = 9.81, kMuS = 0.35, kMuK = 0.3, kKt = 1e5;

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

TEST(BreakAwayRamp, StaysUntilMuSMgThenSlides) {
  for (const auto& [m, rate] : {std::pair{1.0, 1.0}, {1.0, 5.0}, {3.0, 4.0}}) {
    const double t_star = kMuS * m * kG / rate;
    const io::Scene scene =
        io::loadScene(kScene, {set("m", m), set("rate", rate), set("duration", t_star + 0.5)});
    Simulator sim(scene.model);
    const int block = scene.model->findBody("block")->value;
    const double x0 = sim.state().bodies[static_cast<std::size_t>(block)].position.x();
    double worst_stuck = 0.0, t_break = -1.0;
    while (sim.state().time < t_star + 0.5 - 1e-9) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      const BodyState& s = sim.state().bodies[static_cast<std::size_t>(block)];
      const double t = sim.state().time;
      if (t < 0.99 * t_star) worst_stuck = std::max(worst_stuck, std::abs(s.position.x() - x0));
      // Sliding: faster than the stuck springs' rate (rate / (4 k_t) ~ 1e-5 m/s) by far.
      if (t_break < 0.0 && s.velocity.x() > 1e-3) t_break = t;
    }
    // Stuck: the springs' give F / (4 k_t) at most (about 1e-5 m here), with room for the
    // damped ringing of the first loading.
    EXPECT_LT(worst_stuck, 2.0 * kMuS * m * kG / (4 * kKt)) << m << " " << rate;
    // The law compares the corner force with mu_s F_n after each step, so it lets go at most
    // one step late; sliding then reaches 1e-3 m/s after (1e-3 m/s) / a, a = (mu_s - mu_k) g
    // at the jump. The tangential damping c_t u' (u' = rate / (4 k_t)) moves F by ~1e-5 of it.
    const double dt = scene.model->options.time_step;
    const double reach = 1e-3 / ((kMuS - kMuK) * kG);
    ASSERT_GT(t_break, 0.0) << "never slid";
    EXPECT_GT(t_break, t_star - dt) << m << " " << rate;
    EXPECT_LT(t_break, t_star + 2 * dt + reach) << m << " " << rate;
    // After break-away: kinetic friction, x'' = (rate t - mu_k m g) / m.
    const BodyState& s = sim.state().bodies[static_cast<std::size_t>(block)];
    const double t = sim.state().time, tb = t_star;
    // v(t) = integral from t* of (rate tau - mu_k m g) / m = (rate/2 (t^2 - t*^2) - mu_k m g
    // (t - t*)) / m, within what the ~1 ms uncertainty of the break-away moves it.
    const double v = (0.5 * rate * (t * t - tb * tb) - kMuK * m * kG * (t - tb)) / m;
    EXPECT_NEAR(s.velocity.x(), v, 0.01 * v + (kMuS - kMuK) * kG * 3 * dt) << m << " " << rate;
  }
}

}  // namespace
}  // namespace tribo
