// The local sweep runner on the belt scene: an interrupted sweep (stopped after a few
// points, its last line cut off) resumed gives the same bytes as an uninterrupted one, on
// any number of threads; a failed or diverged point is a row with its error and the sweep
// goes on; settling stops points early; bad axes fail before anything runs.
#include "study/sweep/sweep_runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "io/scene_parameters.hpp"
#include "support/sweep_support.hpp"

namespace tribo::study {
namespace {

using test::num;
using test::readRows;
using test::slurp;
using test::TempDir;

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

// The belt, quick: dt, output_interval and duration fixed unless an axis sweeps them (a
// parameter both fixed and swept is an error).
SweepSpec beltSpec(std::vector<SweepAxis> axes, std::vector<std::string> fixed = {}) {
  SweepSpec spec;
  spec.scene_path = kBelt;
  for (const std::string name : {"dt=0.008", "output_interval=0.008", "duration=20"})
    if (std::none_of(axes.begin(), axes.end(),
                     [&](const SweepAxis& a) { return name.rfind(a.name + "=", 0) == 0; }))
      spec.fixed_overrides.push_back(name);
  spec.fixed_overrides.insert(spec.fixed_overrides.end(), fixed.begin(), fixed.end());
  spec.axes = std::move(axes);
  return spec;
}

TEST(SweepRunner, InterruptedAndResumedSweepEqualsUninterrupted) {
  TempDir whole("tribo_sweep_whole_"), parts("tribo_sweep_parts_");
  const SweepPlan plan = planSweep(
      beltSpec({parseGridAxis("a=1.2:2.4:4"), parseListAxis("friction=roh_yoo,recurdyn")}));
  const SweepReport full = runSweepLocally(plan, whole.path(), {2, nullptr, 0});
  EXPECT_TRUE(full.complete);
  EXPECT_EQ(full.ran, 8u);
  EXPECT_EQ(full.failed, 0u);

  const SweepReport first = runSweepLocally(plan, parts.path(), {2, nullptr, 3});
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.ran, 3u);
  // As if killed while writing the next line.
  std::ofstream(parts / "results.csv", std::ios::app) << "5,2,recurdyn,compl";
  const SweepReport second = runSweepLocally(plan, parts.path(), {1, nullptr, 0});
  EXPECT_TRUE(second.complete);
  EXPECT_EQ(second.resumed, 3u);
  EXPECT_EQ(second.dropped, 1u);
  EXPECT_EQ(second.ran, 5u);
  EXPECT_EQ(slurp(parts / "results.csv"), slurp(whole / "results.csv"));
  EXPECT_EQ(slurp(parts / "sweep.json"), slurp(whole / "sweep.json"));

  // Run again once complete: nothing to do, nothing changes.
  const SweepReport again = runSweepLocally(plan, parts.path(), {2, nullptr, 0});
  EXPECT_EQ(again.ran, 0u);
  EXPECT_EQ(slurp(parts / "results.csv"), slurp(whole / "results.csv"));
}

TEST(SweepRunner, FailedPointsAreRowsWithTheirErrorAndTheSweepGoesOn) {
  TempDir dir("tribo_sweep_");
  const SweepPlan plan =
      planSweep(beltSpec({parseListAxis("mu_k=0.3,0.4"), parseListAxis("dt=0.008,0.02")}));
  const SweepReport r = runSweepLocally(plan, dir.path(), {2, nullptr, 0});
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.failed, 3u);
  const auto rows = readRows(dir / "results.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].at("status"), "complete");
  EXPECT_GT(num(rows[0], "amplitude_pp"), 0.5);
  // dt = 0.02 s is past the contact's stability limit: the run diverges, says where, and
  // leaves no figures (never NaN).
  EXPECT_EQ(rows[1].at("status"), "diverged");
  EXPECT_NE(rows[1].at("message").find("diverged at step"), std::string::npos)
      << rows[1].at("message");
  EXPECT_NE(rows[1].at("warnings").find("exceeds the estimated stability limit"),
            std::string::npos);
  EXPECT_EQ(rows[1].at("amplitude_pp"), "");
  // mu_k = 0.4 > mu_s = 0.35: the law refuses it; the row names file, key and rule.
  for (const int i : {2, 3}) {
    EXPECT_EQ(rows[i].at("status"), "error");
    EXPECT_NE(rows[i].at("message").find("belt.yaml"), std::string::npos);
    EXPECT_NE(rows[i].at("message").find("mu_s must exceed mu_k"), std::string::npos);
  }
  for (const auto& row : rows)
    for (const auto& [column, value] : row) EXPECT_EQ(value.find("nan"), std::string::npos);
}

TEST(SweepRunner, SettlingStopsEachPointOnceItsCycleStopsChanging) {
  TempDir dir("tribo_sweep_");
  SweepSpec spec = beltSpec({parseListAxis("friction=roh_yoo,recurdyn")}, {"duration=300"});
  spec.settle = SettleRule{1e-3, 5.0};
  const SweepReport r = runSweepLocally(planSweep(spec), dir.path(), {2, nullptr, 0});
  EXPECT_EQ(r.unsettled, 0u);
  const auto rows = readRows(dir / "results.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("settled"), "1");
    EXPECT_LT(num(row, "simulated"), 300.0);
    // Stopped at a check, after the 98% point and the six cycles the rule compares.
    EXPECT_GT(num(row, "simulated"), num(row, "time_to_98"));
    EXPECT_GE(num(row, "cycles"), 6);
  }
  // The roh_yoo cycle is the one of the fixed-duration reference run (README: 0.5625 m).
  EXPECT_NEAR(num(rows[0], "amplitude_pp"), 0.56245, 1e-3 * 0.56245);
}

TEST(SweepRunner, PlanningRejectsAxesTheSceneCannotTake) {
  try {
    planSweep(beltSpec({parseListAxis("nope=1,2")}));
    ADD_FAILURE() << "unknown parameter accepted";
  } catch (const SweepSpecError& e) {
    EXPECT_NE(std::string(e.what()).find("'nope' is not a parameter"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("v_b"), std::string::npos);  // lists known names
  }
  EXPECT_THROW(planSweep(beltSpec({parseListAxis("k=300,abc")})), SweepSpecError);
  EXPECT_THROW(planSweep(beltSpec({parseListAxis("k=300")}, {"v_b=fast"})), io::SceneError);
  SweepSpec missing = beltSpec({parseListAxis("k=300")});
  missing.scene_path = "/nonexistent/scene.yaml";
  EXPECT_THROW(planSweep(missing), io::SceneError);
  // The first point may fail (mu_k above the file's mu_s) while the sweep is fine.
  EXPECT_NO_THROW(planSweep(beltSpec({parseListAxis("mu_k=0.4,0.3")})));
}

}  // namespace
}  // namespace tribo::study
