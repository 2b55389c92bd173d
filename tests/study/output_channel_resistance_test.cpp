// The pair_resistance channels (io/output_channels.hpp: a pair's coefficient in the slip
// direction and its rolling and spinning moment) against closed forms:
//   the anisotropic slider (scenes/experiments/anisotropic_slider.yaml, tanh Coulomb at v_eps,
//   ratios r1 = forward or backward along the grain by the sign of the slip, r2 across it):
//   the force F = -mu F_n tanh(|R s| / v_eps) R^2 s / |R s| dissipates
//   -F . s / (F_n |s|) = mu tanh(|R s| / v_eps) |R s| / |s| per unit load and slip speed, at
//   every row of three launch directions (the slip is the block's velocity: the floor
//   stands still), and it has no resisting moment;
//   the spinning top (scenes/experiments/spinning_top.yaml): the tip's moment is
//   mu_spin r_c m g while it spins and vanishes once stopped, and its work, integrated over
//   the recorded rows, is the kinetic energy the top lost, I w0^2 / 2.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"
#include "support/recorded_run.hpp"
#include "support/scene_text.hpp"

namespace tribo::study {
namespace {

const std::string kExperiments = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/";
constexpr double kG = 9.81;

std::string textOf(const std::string& file) { return test::fileText(kExperiments + file); }

test::RecordedRun record(const std::string& yaml, const std::string& file,
                         const std::vector<std::string>& overrides) {
  return test::recordRun(yaml, kExperiments + file, overrides);
}

TEST(OutputChannelResistance, TheSlidersCoefficientInTheSlipDirectionIsTheLimitSurfaces) {
  const double mu = 0.3, v_eps = 1e-3, forward = 0.5, backward = 3.0, across = 1.5;
  for (const double beta : {0.6, 2.0, -1.0}) {
    SCOPED_TRACE(beta);
    const test::RecordedRun run =
        record(textOf("anisotropic_slider.yaml"), "anisotropic_slider.yaml",
               {"beta=" + std::to_string(beta), "duration=0.8"});
    const TrajectoryRecorder& tr = run.result.trajectory;
    ASSERT_GT(tr.rows(), 100u);
    const auto vx = tr.column(tr.columnIndex("block.vx"));
    const auto vy = tr.column(tr.columnIndex("block.vy"));
    const auto mu_slip = tr.column(tr.columnIndex("floor/sole.mu_slip"));
    const auto moment = tr.column(tr.columnIndex("floor/sole.resisting_moment"));
    double worst = 0.0, lowest = 1.0, highest = 0.0;
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      const double r1 = vx[i] >= 0.0 ? forward : backward;
      const double slip = std::hypot(vx[i], vy[i]), scaled = std::hypot(r1 * vx[i], across * vy[i]);
      const double expected = slip > 0.0 ? mu * std::tanh(scaled / v_eps) * scaled / slip : 0.0;
      worst = std::max(worst, std::abs(mu_slip[i] - expected));
      if (slip > 1e-2) {
        lowest = std::min(lowest, mu_slip[i]);
        highest = std::max(highest, mu_slip[i]);
      }
      EXPECT_EQ(moment[i], 0.0);
    }
    std::printf("beta %.2f: mu_slip within %.2e of mu tanh(|Rs|/v_eps)|Rs|/|s|, %.4f to %.4f\n",
                beta, worst, lowest, highest);
    EXPECT_LT(worst, 1e-12);
    // It varies with the slip's direction between the ratios' bounds: the channel is not the
    // law's mu.
    EXPECT_GT(highest - lowest, 0.05);
    // (Above 1 cm/s the law is saturated to tanh(5 mm/s / v_eps) at least.)
    EXPECT_GE(lowest, forward * mu * std::tanh(forward * 1e-2 / v_eps));
    EXPECT_LE(highest, backward * mu * (1 + 1e-12));
  }
}

TEST(OutputChannelResistance, TheTopsSpinningMomentIsMuSpinRcMgAndItsWorkTheEnergyLost) {
  // Every step recorded, so that the work integrates as finely as the motion.
  const std::string yaml =
      test::replaced(textOf("spinning_top.yaml"), "  interval: 0.005\n", "  interval: 1.0e-4\n");
  const double w0 = 30.0;
  for (const double m : {0.2, 5.0}) {
    SCOPED_TRACE(m);
    const test::RecordedRun run = record(yaml, "spinning_top.yaml", {"m=" + std::to_string(m)});
    const TrajectoryRecorder& tr = run.result.trajectory;
    const auto t = tr.column(tr.columnIndex("t"));
    const auto w = tr.column(tr.columnIndex("top.wz"));
    const auto moment = tr.column(tr.columnIndex("floor/tip.resisting_moment"));
    const double expected = 0.3 * 0.005 * m * kG, inertia = 0.5 * m * 0.04 * 0.04;
    double work = 0.0, worst_spinning = 0.0, after_stop = 0.0;
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      if (i > 0) work += 0.5 * (moment[i] * w[i] + moment[i - 1] * w[i - 1]) * (t[i] - t[i - 1]);
      if (w[i] > 1e-2) worst_spinning = std::max(worst_spinning, std::abs(moment[i] - expected));
      if (t[i] > 2.0) after_stop = std::max(after_stop, moment[i]);
    }
    const double lost = 0.5 * inertia * (w0 * w0 - w[tr.rows() - 1] * w[tr.rows() - 1]);
    std::printf(
        "m %.1f: moment within %.2e of %.6f N m while spinning, %.2e after; work %.8f J, "
        "energy lost %.8f J\n",
        m, worst_spinning, expected, after_stop, work, lost);
    EXPECT_LT(worst_spinning, 1e-12 * expected);
    EXPECT_LT(after_stop, 1e-9 * expected);
    EXPECT_NEAR(work, lost, 1e-4 * lost);
  }
}

}  // namespace
}  // namespace tribo::study
