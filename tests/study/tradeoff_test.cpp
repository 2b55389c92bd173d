// study/tradeoff at library level, on the belt scene with RK4 over 10 s: the ladder holds
// exactly the steps G/n inside [limit/64, 2.5 limit] of RK4's stability limit for the box's
// vertical contact mode (computed here from the scene's parameters, not by the engine); each
// setting reaches its run (the run takes duration/dt steps of that size); errors fall like
// h^4 where the motion is smooth; tradeoff.csv is written whole, with empty fields (never
// "nan") for figures a diverged run does not have, and quoted messages.
#include "study/tradeoff.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/stability.hpp"
#include "io/scene_loader.hpp"

namespace tribo::study {
namespace {

namespace fs = std::filesystem;

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
// The box and contact set explicitly: 10 kg on four corners of 2.5e5 N/m, 1.5e3 N s/m each.
constexpr double kMass = 10.0, kCornerStiffness = 2.5e5, kCornerDamping = 1.5e3;

TradeoffSpec beltSpec() {
  TradeoffSpec spec;
  spec.scene_path = kBelt;
  spec.overrides = {"duration=10", "m=10", "contact_stiffness=2.5e5", "contact_damping=1.5e3",
                    "z0=0.0499019"};
  spec.integrators = {IntegratorType::kRk4};
  return spec;
}

// |R(h lambda)| of RK4 for the vertical contact mode x'' + (c/m) x' + (k/m) x = 0.
double rk4Growth(double h) {
  const double k_m = 4 * kCornerStiffness / kMass, c_m = 4 * kCornerDamping / kMass;
  const std::complex<double> z = h * std::complex<double>(-c_m / 2, std::sqrt(k_m - c_m * c_m / 4));
  return std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
}

double rk4Limit() {
  double h = 0.0;
  while (rk4Growth(h + 1e-6) <= 1.0) h += 1e-6;
  return h;
}

TEST(Tradeoff, LadderHoldsTheGridStepsInsideTheStabilityWindow) {
  const double limit = rk4Limit();
  std::vector<double> expected;
  for (int n : {2, 4, 5, 8, 10, 20, 40, 80, 160, 320, 640}) {
    const double h = 0.04 / n;
    if (h >= limit / 64 && h <= 2.5 * limit) expected.push_back(h);
  }
  const auto ladder = tradeoffLadder(beltSpec());
  ASSERT_EQ(ladder.size(), expected.size());
  for (std::size_t i = 0; i < ladder.size(); ++i) {
    EXPECT_EQ(ladder[i].integrator, IntegratorType::kRk4);
    EXPECT_DOUBLE_EQ(ladder[i].step, expected[i]);
  }
  TradeoffSpec adaptive = beltSpec();
  adaptive.integrators = {IntegratorType::kDopri5};
  const auto tolerances = tradeoffLadder(adaptive);
  EXPECT_EQ(tolerances.size(), 12u);  // 1e-3 .. 1e-8, with and without event location
  EXPECT_EQ(tolerances.front().label(), "dopri5");
  EXPECT_EQ(tolerances.back().label(), "dopri5_noevents");
}

// A limit below the ladder's finest rung (40 ms / 640 = 62.5 us): LuGre's bristle on the belt,
// decay rate sigma0 |v| / mu_k = 1e4 * 6 / 0.3 = 2e5 1/s at the estimate's slip speed, so
// RK4's limit is 2.79 / 2e5 ~ 14 us. The ladder goes on halving the step until two rungs lie
// at or below the limit, each inside the window [limit/64, 2.5 limit].
TEST(Tradeoff, LadderReachesBelowALimitFinerThanItsLastRung) {
  TradeoffSpec spec = beltSpec();
  spec.overrides.push_back("friction=lugre");
  io::RunSettings rk4;
  rk4.integrator = IntegratorType::kRk4;
  const double limit =
      estimateStableStep(*io::loadScene(spec.scene_path, spec.overrides, {}, rk4).model)
          .limit.max_step;
  ASSERT_LT(limit, 2.79 / 2e5 * 1.01);
  ASSERT_GT(limit, 2.79 / 2e5 * 0.9);
  const auto ladder = tradeoffLadder(spec);
  ASSERT_FALSE(ladder.empty());
  int below = 0;
  for (const TradeoffSetting& s : ladder) {
    EXPECT_GE(s.step, limit / 64);
    EXPECT_LE(s.step, 2.5 * limit);
    const double n = 0.04 / s.step;
    EXPECT_NEAR(n, std::round(n), 1e-6 * n);  // divides the comparison grid
    below += s.step <= limit;
  }
  EXPECT_EQ(below, 2);
  EXPECT_LE(ladder.back().step, limit / 2 * 1.0001);  // the second rung below: half a step on
}

TEST(Tradeoff, EverySettingReachesItsRunAndErrorsFallLikeH4) {
  std::vector<TradeoffRow> heard;
  const TradeoffResult r =
      measureTradeoff(beltSpec(), {}, [&](const TradeoffRow& row) { heard.push_back(row); });
  ASSERT_EQ(r.rows.size(), tradeoffLadder(beltSpec()).size() + 1);
  ASSERT_EQ(heard.size(), r.rows.size());
  EXPECT_EQ(r.rows.front().status, "reference");
  EXPECT_LT(r.rows.front().amplitude_error, 1e-6);  // the reference against half its step
  const double limit = rk4Limit();
  std::vector<std::pair<double, double>> smooth;  // (h, amplitude error) well inside the limit
  for (std::size_t i = 1; i < r.rows.size(); ++i) {
    const TradeoffRow& row = r.rows[i];
    if (row.status == "diverged") {
      EXPECT_GT(row.setting.step, limit) << row.message;
      EXPECT_TRUE(std::isnan(row.amplitude_error));
      continue;
    }
    // The run took duration / dt steps: the setting, not the scene's own dt, drove it.
    EXPECT_EQ(row.steps, std::lround(10.0 / row.setting.step)) << row.setting.step;
    if (row.setting.step <= limit / 2 && row.setting.step >= 1e-3)
      smooth.emplace_back(row.setting.step, row.amplitude_error);
  }
  ASSERT_GE(smooth.size(), 2u);
  const auto& [h1, e1] = smooth.front();  // the largest smooth step
  const auto& [h2, e2] = smooth.back();
  const double order = std::log(e1 / e2) / std::log(h1 / h2);
  EXPECT_NEAR(order, 4.0, 0.7) << "errors " << e1 << " at " << h1 << ", " << e2 << " at " << h2;
}

TEST(Tradeoff, CsvIsWrittenWholeWithoutNan) {
  const fs::path dir = fs::temp_directory_path() / "tribo_tradeoff_test_csv";
  fs::remove_all(dir);
  TradeoffRow complete;
  complete.setting = {IntegratorType::kRk4, true, 0.008, 0.0};
  complete.status = "complete";
  complete.amplitude = 0.5624760123;
  complete.amplitude_error = 1.6e-5;
  complete.trajectory_error = 2e-4;
  complete.wall = complete.cpu = 0.02;
  complete.simulated = 10.0;
  TradeoffRow diverged;  // figures left NaN
  diverged.setting = {IntegratorType::kBdf, false, 0.0, 1e-3};
  diverged.status = "diverged";
  diverged.message = "diverged at step 3: body 'box', \"energy\"";
  writeTradeoffCsv(dir / "tradeoff.csv", "belt", {complete, diverged});
  EXPECT_FALSE(fs::exists(dir / "tradeoff.csv.partial"));
  std::ifstream in(dir / "tradeoff.csv");
  std::stringstream text;
  text << in.rdbuf();
  const std::string csv = text.str();
  EXPECT_EQ(csv.find("nan"), std::string::npos) << csv;
  EXPECT_NE(csv.find("belt,rk4,dt,0.008,complete,0.562476012,1.6e-05,0.0002,0.02,0.02,500,"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("belt,bdf_noevents,rtol,0.001,diverged,,,,,,,0,0,0,0,"
                     "\"diverged at step 3: body 'box', \"\"energy\"\"\"\n"),
            std::string::npos)
      << csv;
  EXPECT_THROW(writeTradeoffCsv(dir / "tradeoff.csv" / "inside_a_file.csv", "belt", {complete}),
               std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribo::study
