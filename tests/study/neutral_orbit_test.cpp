// Orbits that are one of a family: the free pendulum (scenes/pendulum.yaml, no friction, no
// damping) swings with any amplitude, so besides the trivial multiplier a second one sits at 1
// and the orbit's stability is undecided. Against the exact period of the physical pendulum,
// T = 4 sqrt(I_p / (m g L)) K(sin(theta0 / 2)), I_p = m L^2 + I_bob, K the complete elliptic
// integral of the first kind, computed here by the arithmetic-geometric mean
// (K = pi / (2 AGM(1, cos(theta0 / 2)))). Past 90 degrees the observed x peaks twice a cycle
// (as the bob passes the horizontal and at one turning point): the settling run's guess must
// count the cycle, not the interval between peaks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "io/scene_loader.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo {
namespace {

const std::string kPendulum = std::string(TRIBO_SOURCE_DIR) + "/scenes/pendulum.yaml";

std::string assign(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

double exactPeriod(double theta0) {
  const double m = 1.0, L = 1.0, g = 9.81, i_bob = 1e-4;  // the scene's
  double a = 1.0, b = std::cos(theta0 / 2);
  for (int i = 0; i < 40; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  const double K = std::numbers::pi / (2 * a);
  return 4 * std::sqrt((m * L * L + i_bob) / (m * g * L)) * K;
}

TEST(NeutralOrbit, TheFreePendulumsOrbitHasItsExactPeriodAndIsNeutral) {
  for (const double degrees : {60.0, 120.0, 170.0}) {
    SCOPED_TRACE(std::to_string(degrees) + " degrees");
    const double theta0 = degrees * std::numbers::pi / 180;
    const io::Scene scene =
        io::loadScene(kPendulum, {assign("x0", std::sin(theta0)), assign("z0", -std::cos(theta0))});
    study::OrbitSpec spec;
    spec.tolerance = 1e-7;  // the family's drift under RK4 stalls the return map near 1e-8
    const study::OrbitResult r = study::findPeriodicOrbit(scene, spec);
    // RK4 at 1 ms: measured -9.2e-6, 1.7e-6 and 3.5e-5 off at 60, 120 and 170 degrees (the
    // period is most sensitive to the energy's drift near the inverted position).
    EXPECT_NEAR(r.period / exactPeriod(theta0), 1.0, 1e-4) << r.period;
    // bob.x swings over 2 L sin(theta0), or 2 L past the horizontal (measured within 7e-5: the
    // energy's drift in the settling run moves the orbit along its family).
    const double swing = degrees > 90.0 ? 2.0 : 2.0 * std::sin(theta0);
    EXPECT_NEAR(r.amplitude_pp, swing, 1e-4);
    EXPECT_TRUE(r.neutral);
    EXPECT_FALSE(r.stable);
  }
}

TEST(NeutralOrbit, NewtonsFailureOnTheFamilySaysWhatAcceptsTheReturnMapsOrbit) {
  const double theta0 = 170.0 * std::numbers::pi / 180;
  const io::Scene scene =
      io::loadScene(kPendulum, {assign("x0", std::sin(theta0)), assign("z0", -std::cos(theta0))});
  try {
    study::findPeriodicOrbit(scene);  // tolerance 1e-9: below where the return map stalls
    ADD_FAILURE() << "the default tolerance was met";
  } catch (const study::OrbitError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("one of a family"), std::string::npos) << what;
    EXPECT_NE(what.find("--tolerance"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tribo
