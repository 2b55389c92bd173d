// The orbit's accuracy against the step (study/orbit/step_check.hpp). The forced linear
// oscillator (scenes/forced_oscillator.yaml) has a closed-form response, 2 F0 / sqrt((k - m
// w^2)^2 + (c w)^2) peak to peak: the error of the orbit found at a step h is known exactly,
// and the check's change (the orbit at h/2 less the orbit at h) must predict it by
// Richardson's factor 2^p / (2^p - 1) for a method of order p converging at its order (rk4:
// 16/15, semi-implicit Euler: 2). On the belt (stick-slip, nonlinear), the check's orbit at
// half the step is the orbit `findPeriodicOrbit` finds on the scene at that step from its own
// settling run.
#include "study/orbit/step_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>
#include <string>

#include "io/scene_loader.hpp"
#include "study/orbit/periodic_orbit.hpp"

namespace tribo {
namespace {

const std::string kOscillator = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

std::string assign(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

// The orbit at `overrides` and its check at the finer setting.
study::OrbitResult checkedOrbit(const std::string& path, const std::vector<std::string>& overrides,
                                const study::OrbitSpec& spec = {}) {
  const io::Scene scene = io::loadScene(path, overrides);
  study::OrbitResult r = study::findPeriodicOrbit(scene, spec);
  std::string setting;
  double value = 0;
  const io::RunSettings finer = study::finerSettings(*scene.model, setting, value);
  r.step_check =
      study::checkAgainstFinerSetting(io::loadScene(path, overrides, {}, finer), r, spec);
  EXPECT_EQ(r.step_check->setting, setting);
  EXPECT_EQ(r.step_check->value, value);
  return r;
}

struct OscillatorCase {
  const char* integrator;
  int order;
  double step;
};

void PrintTo(const OscillatorCase& c, std::ostream* os) {
  *os << c.integrator << " at " << c.step << " s";
}

class StepCheckOscillator : public testing::TestWithParam<OscillatorCase> {};

TEST_P(StepCheckOscillator, TheChangePredictsTheErrorAgainstTheClosedForm) {
  const OscillatorCase c = GetParam();
  const double m = 1.0, k = 100.0, damping = 2.0, F0 = 10.0, f = 1.2;  // the scene's
  const double w = 2 * std::numbers::pi * f;
  const double exact = 2 * F0 / std::hypot(k - m * w * w, damping * w);
  const study::OrbitResult r =
      checkedOrbit(kOscillator, {assign("dt", c.step), std::string("integrator=") + c.integrator});
  ASSERT_TRUE(r.step_check->converged) << r.step_check->why;
  EXPECT_EQ(r.step_check->setting, "time_step");
  EXPECT_EQ(r.step_check->value, c.step / 2);
  EXPECT_EQ(r.step_check->period_change, 0.0);  // the forcing's period at either step
  const double error = r.amplitude_pp - exact;
  const double richardson = std::pow(2.0, c.order) / (std::pow(2.0, c.order) - 1.0);
  const double predicted = -r.step_check->amplitude_change * richardson;
  // Measured 0.97 to 1.03 (rk4: errors 7.5e-6 to 3.8e-8 m; Euler: 1e-2 to 2.6e-3 m).
  EXPECT_NEAR(error / predicted, 1.0, 0.05)
      << "error " << error << ", change " << r.step_check->amplitude_change;
  EXPECT_NEAR(r.step_check->amplitude_pp, r.amplitude_pp + r.step_check->amplitude_change, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, StepCheckOscillator,
    testing::Values(OscillatorCase{"rk4", 4, 0.02}, OscillatorCase{"rk4", 4, 0.01},
                    OscillatorCase{"rk4", 4, 0.005}, OscillatorCase{"semi_implicit_euler", 1, 0.02},
                    OscillatorCase{"semi_implicit_euler", 1, 0.01},
                    OscillatorCase{"semi_implicit_euler", 1, 0.005}),
    [](const testing::TestParamInfo<OscillatorCase>& info) {
      std::string name = std::string(info.param.integrator) + "_dt" +
                         std::to_string(static_cast<int>(std::lround(info.param.step * 1e3)));
      return name;
    });

// The stick-slip belt at 1 ms (rk4) and at 0.2 ms (semi-implicit Euler), two masses: the
// check's orbit at half the step against the one found there from scratch.
TEST(StepCheck, TheBeltsOrbitAtHalfTheStepIsTheOneFoundThereFromItsOwnRun) {
  for (const auto& [integrator, dt, mass] :
       {std::tuple{"rk4", 1e-3, 10.0}, std::tuple{"rk4", 1e-3, 5.0},
        std::tuple{"semi_implicit_euler", 2e-4, 10.0}}) {
    SCOPED_TRACE(std::string(integrator) + " " + std::to_string(dt) + " m " + std::to_string(mass));
    const std::vector<std::string> overrides = {std::string("integrator=") + integrator,
                                                assign("dt", dt), assign("m", mass)};
    const study::OrbitResult r = checkedOrbit(kBelt, overrides);
    ASSERT_TRUE(r.step_check->converged) << r.step_check->why;
    std::vector<std::string> halved = overrides;
    halved.push_back(assign("dt", dt / 2));
    const study::OrbitResult fine = study::findPeriodicOrbit(io::loadScene(kBelt, halved));
    EXPECT_NEAR(r.step_check->period, fine.period, 1e-9 * fine.period);
    EXPECT_NEAR(r.step_check->amplitude_pp, fine.amplitude_pp, 1e-8 * fine.amplitude_pp);
    // The change is the step's, not the tolerance's: far above the orbit's residual.
    EXPECT_GT(std::abs(r.step_check->period_change), 1e3 * r.step_check->tolerance);
    EXPECT_DOUBLE_EQ(r.step_check->tolerance, study::OrbitSpec{}.tolerance / 100);
  }
}

// A scene that refuses the finer setting (the loader throws, as io::loadScene does for a
// setting a URDF scene does not take): no check, and why not, never an exception.
TEST(StepCheck, ALoaderThatRefusesTheFinerSettingGivesACheckNotDoneSayingWhy) {
  const io::Scene scene = io::loadScene(kOscillator);
  const study::OrbitResult r = study::findPeriodicOrbit(scene);
  const study::StepCheck c = study::checkOrbitAgainstStep(
      *scene.model, r, study::OrbitSpec{}, [](const io::RunSettings& finer) -> io::Scene {
        EXPECT_EQ(finer.time_step.value_or(0.0), 0.0005);  // the scene's 1 ms over 2
        throw io::SceneError(
            "robot.urdf: a URDF scene takes duration, time_step and integrator only");
      });
  EXPECT_FALSE(c.converged);
  EXPECT_EQ(c.setting, "time_step");
  EXPECT_EQ(c.value, 0.0005);
  EXPECT_NE(c.why.find("robot.urdf: a URDF scene takes"), std::string::npos) << c.why;
}

}  // namespace
}  // namespace tribo
