// A branch of periodic orbits started at a Hopf point of steady sliding
// (study/orbit/hopf_start.hpp, BranchSpec::from_hopf) against the damped belt in closed form
// (tests/study/stribeck_hopf.hpp): where the Hopf point lies, the period there, and the
// amplitude of the unstable cycle the subcritical Hopf point sends out, which a settling run
// can never find. Also: the refusals when the range holds no Hopf point or the law keeps
// contact anchors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "stribeck_hopf.hpp"
#include "study/orbit/hopf_start.hpp"
#include "study/orbit/orbit_branch.hpp"

namespace tribo {
namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

std::vector<std::string> dampedBelt(double c) {
  return {"friction=stribeck", "springs[wall_spring].damping=" + std::to_string(c)};
}

// The branch in the belt speed from the Hopf point between `from` and `to`, `points` at most.
study::BranchSpec hopfSpec(double from, double to, int points = 20) {
  study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = from;
  spec.to = to;
  spec.from_hopf = true;
  spec.step = 0.004;
  spec.max_points = points;
  return spec;
}

TEST(OrbitHopfStart, TheUnstableCycleOfTheSubcriticalHopfGrowsAsTheAveragedEquationSays) {
  // Two dampers: the Hopf point moves with c, the amplitude law with it.
  for (double c : {10.0, 6.0}) {
    const DampedStribeckBelt belt{c};
    const double v_h = belt.hopfSpeed();
    study::BranchSpec spec = hopfSpec(0.15, 0.5, 4);
    spec.hopf_amplitude = 1e-3;
    const study::BranchResult r = study::continueOrbit(kBelt, dampedBelt(c), spec);
    ASSERT_GE(r.points.size(), 3u) << r.stop_reason;
    // The Hopf point and its frequency: d(v_H) = 0 and the undamped sqrt(k / m).
    EXPECT_NEAR(r.hopf_parameter, v_h, 1e-5 * v_h) << "c " << c;
    EXPECT_NEAR(r.hopf_omega, std::sqrt(belt.k / belt.m), 1e-6 * std::sqrt(belt.k / belt.m));
    // The first orbit peaks 1 mm above steady sliding: about 2 mm peak to peak, at the speed
    // where the averaged amplitude is that, with the period 2 pi sqrt(m / k) there (its shift
    // is second order in the amplitude).
    const study::BranchPoint& first = r.points.front();
    EXPECT_NEAR(first.amplitude_pp / 2e-3, 1.0, 0.02) << "c " << c;
    EXPECT_NEAR(first.period / (2 * std::numbers::pi * std::sqrt(belt.m / belt.k)), 1.0, 1e-3);
    EXPECT_LE(first.residual, 1e-9);
    // Subcritical: the cycle lives where steady sliding is stable (v_b > v_H) and is itself
    // unstable; the branch leaves the Hopf point towards higher speed.
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const study::BranchPoint& p = r.points[i];
      EXPECT_GT(p.parameter, v_h) << i;
      EXPECT_FALSE(p.stable) << i << ": v_b " << p.parameter;
      EXPECT_LT(p.steady_growth, 0.0) << i;
      EXPECT_LT(p.trivial_error, 1e-3) << i;
      // The amplitude against the averaged equation at the point's speed: it holds to
      // leading order, its error is O(v_b - v_H) = O(A^2) (measured: 85 A_pp^2 with c = 10,
      // 40 A_pp^2 with c = 6, A_pp in m; 5e-5 at the first point's 2 mm, 0.07 at 3 cm).
      EXPECT_NEAR(p.amplitude_pp / belt.amplitudePp(p.parameter), 1.0,
                  1e-4 + 100.0 * p.amplitude_pp * p.amplitude_pp)
          << i << ": c " << c << ", v_b " << p.parameter << ", A " << p.amplitude_pp;
      if (i > 0) {
        EXPECT_GT(p.amplitude_pp, r.points[i - 1].amplitude_pp) << i;
      }
    }
  }
}

TEST(OrbitHopfStart, LuGresBristlesAreUnknownsOfTheOrbitAndLeaveTheHopfPointWhereItWas) {
  // LuGre without bristle damping and with Stribeck's speed 0.15 m/s slides steadily on the
  // same Gaussian curve as the stribeck law: the same Hopf point and, its bristles being
  // stiff (1e4 per newton), the same cycles to leading order, now with the bristle states
  // among the orbit's unknowns (semi-implicit Euler, which updates them exactly).
  const DampedStribeckBelt belt{10.0};
  const double v_h = belt.hopfSpeed();
  const study::BranchSpec spec = hopfSpec(0.15, 0.5, 3);
  const study::BranchResult r =
      study::continueOrbit(kBelt,
                           {"friction=lugre", "v_s=0.15", "sigma1=0",
                            "integrator=semi_implicit_euler", "springs[wall_spring].damping=10"},
                           spec);
  ASSERT_EQ(r.points.size(), 3u) << r.stop_reason;
  EXPECT_NEAR(r.hopf_parameter, v_h, 1e-5 * v_h);  // measured 1e-7
  EXPECT_GT(r.points.front().start.size(), 12);    // the box's 12 and the bristles'
  EXPECT_NEAR(r.points.front().amplitude_pp / 2e-3, 1.0, 0.02);
  EXPECT_NEAR(r.points.front().period / (2 * std::numbers::pi * std::sqrt(belt.m / belt.k)), 1.0,
              1e-3);
  for (const study::BranchPoint& p : r.points) {
    EXPECT_GT(p.parameter, v_h);
    EXPECT_FALSE(p.stable);
    // The averaged equation of the rigid law, plus a few per cent: the bristles' compliance
    // shifts the cycles near the Hopf point (measured 2.8 % at 2 mm, 1.3 % at 1 cm).
    EXPECT_NEAR(p.amplitude_pp / belt.amplitudePp(p.parameter), 1.0,
                0.04 + 100.0 * p.amplitude_pp * p.amplitude_pp)
        << "v_b " << p.parameter << ", A " << p.amplitude_pp;
  }
}

TEST(OrbitHopfStart, ARangeWithoutAHopfPointIsRefusedWithTheGrowthRatesAtItsEnds) {
  // Above v_H steady sliding is stable all the way: nothing crosses.
  const study::BranchSpec spec = hopfSpec(0.3, 0.6);
  try {
    study::continueOrbit(kBelt, dampedBelt(10.0), spec);
    FAIL() << "expected OrbitError";
  } catch (const study::OrbitError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no Hopf point between 0.3 and 0.6"), std::string::npos) << what;
    EXPECT_NE(what.find("keeps its sign"), std::string::npos) << what;
  }
}

TEST(OrbitHopfStart, ALawWithAnchorsIsRefusedNamingTheModesAnalysis) {
  // The belt with elastic_stick, whose contact anchors the linearization does not take.
  std::ifstream in(kBelt);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string at = "  rate_state: {";
  ASSERT_NE(text.find(at), std::string::npos);
  text.insert(text.find(at),
              "  elastic_stick: {mu_s: $mu_s, mu_k: $mu_k, stiffness: 1.0e5, damping: 100}\n");
  const study::BranchSpec spec = hopfSpec(0.15, 0.5);
  try {
    study::continueOrbitFromText(text, kBelt, {"friction=elastic_stick"}, spec);
    FAIL() << "expected OrbitError";
  } catch (const study::OrbitError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("modes analysis of steady sliding failed at 0.15"), std::string::npos)
        << what;
    EXPECT_NE(what.find("elastic_stick"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tribo
