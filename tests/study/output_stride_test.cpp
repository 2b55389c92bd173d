// Rows of a run are evenly spaced whatever output.interval is asked for: an interval that is
// a whole multiple of the step gives exactly it and no warning; any other interval above
// the step is replaced by the nearest whole multiple, with a warning that names the
// interval asked for, the step and the one used; an interval at or below the step records
// every step. Checked on the belt with fixed-step and adaptive integrators over steps and
// intervals of several orders of magnitude, against the spacing worked out here by hand.
#include "study/output_stride.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"

namespace tribo::study {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

struct Case {
  IntegratorType integrator;
  double dt, interval;
  double spacing;  // expected row spacing [s], worked out by hand
  bool warned;
};

class OutputStride : public ::testing::TestWithParam<Case> {};

TEST_P(OutputStride, RowsAreEvenlySpacedAndAChangedIntervalIsSaid) {
  const Case c = GetParam();
  io::RunSettings settings;
  settings.integrator = c.integrator;
  settings.time_step = c.dt;
  settings.output_interval = c.interval;
  settings.duration = 40 * c.spacing;
  const io::Scene scene = io::loadScene(kBelt, {}, {}, settings);
  const RunResult r = runScene(scene);
  ASSERT_TRUE(r.complete) << r.message;
  const auto t = r.trajectory.column(r.trajectory.columnIndex("t"));
  ASSERT_GE(t.size(), 40u);
  for (std::size_t i = 1; i < t.size(); ++i)
    ASSERT_NEAR(t[i] - t[i - 1], c.spacing, 1e-9 * c.spacing) << "row " << i;
  bool said = false;
  for (const std::string& w : r.warnings) said = said || w.find("output.interval") != w.npos;
  EXPECT_EQ(said, c.warned);
  EXPECT_NEAR(outputInterval(c.interval, c.dt), c.spacing, 1e-12 * c.spacing);
}

INSTANTIATE_TEST_SUITE_P(
    StepsAndIntervals, OutputStride,
    ::testing::Values(
        // the case: 1.5 ms rows of 1.2 ms steps -> every step
        Case{IntegratorType::kSemiImplicitEuler, 1.2e-3, 1.5e-3, 1.2e-3, true},
        Case{IntegratorType::kRk4, 1e-3, 1.5e-3, 2e-3, true},     // 1.5 steps -> 2
        Case{IntegratorType::kRk4, 1e-4, 3.33e-4, 3e-4, true},    // 3.33 steps -> 3
        Case{IntegratorType::kRk4, 2e-5, 1.09e-3, 1.1e-3, true},  // 54.5 steps -> 55
        Case{IntegratorType::kRk4, 2.5e-4, 1e-3, 1e-3, false},    // a whole multiple
        Case{IntegratorType::kSemiImplicitEuler, 1e-4, 0.01, 0.01, false},
        Case{IntegratorType::kRk4, 1e-3, 1e-4, 1e-3, false},      // below the step: every step
        Case{IntegratorType::kDopri5, 4e-4, 1e-3, 1.2e-3, true},  // 2.5 steps -> 3
        Case{IntegratorType::kDopri5, 5e-4, 2e-3, 2e-3, false}));

TEST(OutputStride, StrideIsTheNearestWholeMultipleAndAtLeastOne) {
  EXPECT_EQ(outputStride(1e-3, 1e-3), 1);
  EXPECT_EQ(outputStride(1e-4, 1e-3), 1);
  EXPECT_EQ(outputStride(1.49e-3, 1e-3), 1);
  EXPECT_EQ(outputStride(1.5e-3, 1e-3), 2);
  EXPECT_EQ(outputStride(0.1, 1e-3), 100);                    // 0.1 / 0.001 is 100.00000000000001
  EXPECT_EQ(outputStride(1e300, 1e-300), 1000000000000000L);  // capped, no overflow
  EXPECT_FALSE(outputStrideNote(0.1, 1e-3));
  EXPECT_FALSE(outputStrideNote(1e-5, 1e-3));
  const auto note = outputStrideNote(1.5e-3, 1.2e-3);
  ASSERT_TRUE(note);
  EXPECT_NE(note->find("0.0015"), note->npos) << *note;
  EXPECT_NE(note->find("0.0012"), note->npos) << *note;
  EXPECT_NE(note->find("every 1 step"), note->npos) << *note;
}

}  // namespace
}  // namespace tribo::study
