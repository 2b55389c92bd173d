// study/orbit_shape on signals whose orbit is known by construction, through the same
// cycle detection the run summary uses: a sine (period 1); a sine plus its subharmonic at
// half the frequency, whose maxima alternate in height (period 2: the families' figures are
// those of the signal's two humps, computed here from the formula); a sine whose amplitude
// steps through four levels (period 4: irregular for a period-1/2 classifier); a decaying
// sine (irregular: a transient); too few cycles (none).
#include "study/orbit_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace tribo::study {
namespace {

std::vector<Cycle> cyclesOf(const std::function<double(double)>& f, double duration) {
  std::vector<double> t, x;
  for (double s = 0; s <= duration; s += 1e-3) {
    t.push_back(s);
    x.push_back(f(s));
  }
  return summarizeOscillation(t, x, {}).cycles;
}

TEST(OrbitShape, SineIsPeriodOneAtAnyScale) {
  for (const double a : {1e-6, 1.0, 3e3})
    for (const double w : {2.0, 7.0}) {
      const OrbitShape o =
          classifyOrbit(cyclesOf([&](double t) { return a * std::sin(w * t); }, 30));
      EXPECT_EQ(o.kind, OrbitKind::kPeriod1) << a << " " << w;
      EXPECT_NEAR(o.peak_to_peak_a, 2 * a, 1e-4 * a);
      EXPECT_NEAR(o.duration_a, 2 * M_PI / w, 1e-4);
    }
}

TEST(OrbitShape, SubharmonicMakesPeriodTwoWithBothFamiliesFigures) {
  // x = sin(2 w t) + e sin(w t + phi): maxima of alternating height, the orbit closes every
  // 2 pi / w; the two cycles between successive maxima have unequal durations. (At e = 0.2
  // the families differ by 1.5% in peak-to-peak, 0.77% from their mean: period 1 within
  // the 1% tolerance.)
  for (const double e : {0.5, 0.8}) {
    const double w = 3.0, phi = 0.7;
    auto f = [&](double t) { return std::sin(2 * w * t) + e * std::sin(w * t + phi); };
    const OrbitShape o = classifyOrbit(cyclesOf(f, 40));
    ASSERT_EQ(o.kind, OrbitKind::kPeriod2) << e;
    // The pair of cycles spans the full period 2 pi / w.
    EXPECT_NEAR(o.duration_a + o.duration_b, 2 * M_PI / w, 2e-3);
    EXPECT_GT(std::abs(o.duration_a - o.duration_b) + std::abs(o.peak_to_peak_a - o.peak_to_peak_b),
              0.01);
    // Independent figures: the signal's extremes over one full period, sampled finely; each
    // family's peak-to-peak spans from its opening maximum to the lowest point in between,
    // so the larger family reaches the signal's full range.
    double hi = -1e9, lo = 1e9;
    for (double t = 0; t < 2 * M_PI / w; t += 1e-5) {
      hi = std::max(hi, f(t));
      lo = std::min(lo, f(t));
    }
    EXPECT_NEAR(std::max(o.peak_to_peak_a, o.peak_to_peak_b), hi - lo, 1e-4);
  }
}

TEST(OrbitShape, FourLevelsAndTransientsAreIrregular) {
  auto steps = [](double t) {
    const int k = static_cast<int>(std::floor(t / (2 * M_PI))) % 4;
    return (1.0 + 0.2 * k) * std::sin(t);
  };
  EXPECT_EQ(classifyOrbit(cyclesOf(steps, 80)).kind, OrbitKind::kIrregular);
  EXPECT_EQ(
      classifyOrbit(cyclesOf([](double t) { return std::exp(-0.05 * t) * std::sin(t); }, 80)).kind,
      OrbitKind::kIrregular);
}

TEST(OrbitShape, FewerThanTwoCyclesIsNone) {
  EXPECT_EQ(classifyOrbit(cyclesOf([](double t) { return std::sin(t); }, 7)).kind,
            OrbitKind::kNone);
  EXPECT_EQ(orbitKindName(OrbitKind::kPeriod2), "period_2");
}

}  // namespace
}  // namespace tribo::study
