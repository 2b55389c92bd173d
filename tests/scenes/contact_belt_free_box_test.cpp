// scenes/belt_free_box.yaml: the paper's belt scene with the box left as a free 6-DOF body
// (no planar joint). Friction at the corners, the spring at the centre: the box pitches a
// little but its motion along the belt must still grow into the stick-slip limit cycle of
// the jointed scene (docs/belt-scene.md: 0.5625 m peak to peak, period 1.15 s).
#include <gtest/gtest.h>

#include <cmath>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"

namespace tribo {
namespace {

const std::string kDir = std::string(TRIBO_SOURCE_DIR) + "/scenes/";

TEST(BeltFreeBoxScene, StillGrowsIntoTheLimitCycleOfTheJointedScene) {
  const study::RunResult jointed =
      study::runScene(io::loadScene(kDir + "belt.yaml", {"duration=40"}));
  const study::RunResult free =
      study::runScene(io::loadScene(kDir + "belt_free_box.yaml", {"duration=40"}));
  ASSERT_TRUE(jointed.complete) << jointed.message;
  ASSERT_TRUE(free.complete) << free.message;
  EXPECT_TRUE(free.summary.oscillating);
  ASSERT_FALSE(free.summary.cycles.empty());
  // It grew: the first cycle far below the limit cycle.
  EXPECT_LT(free.summary.cycles.front().peak_to_peak, 0.6 * free.summary.amplitude_pp);
  EXPECT_NEAR(free.summary.amplitude_pp / jointed.summary.amplitude_pp, 1.0, 2e-3);
  EXPECT_NEAR(free.summary.period / jointed.summary.period, 1.0, 2e-3);
  EXPECT_GT(free.summary.stuck_fraction, 0.5 * jointed.summary.stuck_fraction);
}

}  // namespace
}  // namespace tribo
