// scenes/two_boxes_on_belt.yaml: two boxes coupled by a spring on one belt settle into a
// period-2 stick-slip orbit (the observed box alternates between a large and a small
// cycle; the same orbit at 1 ms and 0.5 ms RK4 and bdf, to 1e-4 m). The run summary must
// say period 2 and give both families' figures. The expectation is read off the recorded
// samples directly, without the summary's analysis: the maxima of x (samples larger than
// both neighbours and than everything within 0.5 s) and, per max-to-max cycle, its
// max - min; over the settled second half the cycles alternate (cycle k like cycle k + 2 to
// 1%, unlike cycle k + 1 by more than 5%).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/orbit_shape.hpp"
#include "study/scene_run.hpp"

namespace tribo::study {
namespace {

TEST(TwoBoxesOnBelt, PeriodTwoOrbitIsReportedWithBothCycles) {
  const io::Scene scene =
      io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/two_boxes_on_belt.yaml", {});
  const RunResult r = runScene(scene);
  ASSERT_TRUE(r.complete) << r.message;
  const auto t = r.trajectory.column(0);
  const auto x = r.trajectory.column(r.trajectory.columnIndex("box2.x"));
  // Maxima over a 0.5 s window (a cycle lasts over 2 s), in the second half of the run.
  const std::size_t window = 500;
  std::vector<std::size_t> maxima;
  for (std::size_t i = window; i + window < x.size(); ++i) {
    if (t[i] < 30.0) continue;
    const auto lo = x.begin() + static_cast<long>(i - window);
    const auto hi = x.begin() + static_cast<long>(i + window + 1);
    if (x[i] == *std::max_element(lo, hi)) maxima.push_back(i);
  }
  ASSERT_GE(maxima.size(), 6u);
  std::vector<double> pp, duration;
  for (std::size_t k = 0; k + 1 < maxima.size(); ++k) {
    const auto lo = x.begin() + static_cast<long>(maxima[k]);
    const auto hi = x.begin() + static_cast<long>(maxima[k + 1]) + 1;
    pp.push_back(*std::max_element(lo, hi) - *std::min_element(lo, hi));
    duration.push_back(t[maxima[k + 1]] - t[maxima[k]]);
  }
  for (std::size_t k = 0; k + 2 < pp.size(); ++k) {
    EXPECT_NEAR(pp[k], pp[k + 2], 0.01 * pp[k]) << k;
    EXPECT_GT(std::abs(pp[k] - pp[k + 1]), 0.05 * pp[k]) << k;
  }
  const double big = std::max(pp[pp.size() - 1], pp[pp.size() - 2]);
  const double small = std::min(pp[pp.size() - 1], pp[pp.size() - 2]);
  const double t_big = pp.back() > pp[pp.size() - 2] ? duration.back() : duration[pp.size() - 2];
  const double t_small = pp.back() > pp[pp.size() - 2] ? duration[pp.size() - 2] : duration.back();

  const OrbitShape orbit = classifyOrbit(r.summary.cycles);
  ASSERT_EQ(orbit.kind, OrbitKind::kPeriod2);
  const double a = orbit.peak_to_peak_a, b = orbit.peak_to_peak_b;
  // The summary refines its extrema between samples (1 ms): agreement to 1e-3 relative.
  EXPECT_NEAR(std::max(a, b), big, 1e-3 * big);
  EXPECT_NEAR(std::min(a, b), small, 1e-3 * small);
  const double d_big = a > b ? orbit.duration_a : orbit.duration_b;
  const double d_small = a > b ? orbit.duration_b : orbit.duration_a;
  EXPECT_NEAR(d_big, t_big, 2e-3);
  EXPECT_NEAR(d_small, t_small, 2e-3);
}

}  // namespace
}  // namespace tribo::study
