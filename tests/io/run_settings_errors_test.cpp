// A bad run setting (time step, duration, tolerances, threads, output interval; and a URDF
// run's --set values) is a SceneError naming the file and the setting's key, for a scene file
// given RunSettings and for a URDF run, never the builder's ModelError or a
// std::invalid_argument; a URDF file given to the scene loader is refused naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "io/run_settings_check.hpp"
#include "io/scene_loader.hpp"
#include "io/urdf_scene.hpp"
#include "support/pendulum_scene.hpp"

namespace tribo::io {
namespace {

namespace fs = std::filesystem;

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// The message of the SceneError `load` throws; a failure for any other outcome.
std::string sceneErrorOf(const std::function<void()>& load) {
  try {
    load();
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a SceneError: " << e.what();
  }
  return "";
}

TEST(RunSettingsErrors, ASceneGivenABadSettingNamesTheFileAndTheKey) {
  struct Case {
    std::string key;
    std::function<void(RunSettings&, double)> set;
    std::vector<double> bad;
  };
  const std::vector<Case> cases{
      {"simulation.time_step",
       [](RunSettings& r, double v) { r.time_step = v; },
       {0.0, -1e-3, -kInf, kNan, kInf, 100.0, 1e-300}},
      {"simulation.duration",
       [](RunSettings& r, double v) { r.duration = v; },
       {0.0, -1.0, kNan, kInf}},
      {"simulation.rtol",
       [](RunSettings& r, double v) { r.relative_tolerance = v; },
       {0.0, -1e-6, 1.0, 2.0, kNan}},
      {"simulation.atol",
       [](RunSettings& r, double v) { r.absolute_tolerance = v; },
       {0.0, -1e-9, kNan, kInf}},
      {"simulation.threads",
       [](RunSettings& r, double v) { r.threads = static_cast<int>(v); },
       {-1.0, -100.0}},
      {"output.interval",
       [](RunSettings& r, double v) { r.output_interval = v; },
       {0.0, -1.0, kNan}},
  };
  const std::string yaml = test::pendulumSceneYaml(0.3, Vec3(0, 0, 1), 1.0);
  for (const Case& c : cases) {
    for (double v : c.bad) {
      SCOPED_TRACE(c.key + " = " + std::to_string(v));
      RunSettings settings;
      c.set(settings, v);
      const std::string e = sceneErrorOf(
          [&] { loadSceneFromString(yaml, "scenes/pendulum.yaml", {}, {}, settings); });
      EXPECT_EQ(e.rfind("scenes/pendulum.yaml", 0), 0u) << e;
      EXPECT_NE(e.find(c.key), std::string::npos) << e;
    }
  }
  // The message says what was expected and what was found.
  RunSettings zero;
  zero.time_step = 0.0;
  EXPECT_EQ(sceneErrorOf([&] { loadSceneFromString(yaml, "p.yaml", {}, {}, zero); }),
            "p.yaml: run setting 'simulation.time_step' (time_step): must be > 0, got 0");
}

TEST(RunSettingsErrors, AUrdfRunGivenABadSettingNamesTheFileAndTheKey) {
  const std::string urdf = std::string(TRIBO_SOURCE_DIR) + "/scenes/robots/pendulum.urdf";
  struct Case {
    std::string set, key;
  };
  for (const Case& c : {Case{"dt=0", "'dt' (time_step): must be > 0, got 0"},
                        Case{"dt=-0.001", "'dt' (time_step): must be > 0, got -0.001"},
                        Case{"dt=nan", "--set dt: expected a number, got 'nan'"},
                        Case{"dt=inf", "--set dt: expected a number, got 'inf'"},
                        Case{"dt=2", "'dt' (time_step): must be at most the duration"},
                        Case{"duration=0", "'duration' (duration): must be > 0, got 0"},
                        Case{"duration=-5", "'duration' (duration): must be > 0, got -5"},
                        Case{"duration=nan", "--set duration: expected a number, got 'nan'"},
                        Case{"min_dt=0", "'min_dt' (min_dt): must be > 0, got 0"},
                        Case{"penetration=-1", "'penetration' (penetration): must be > 0"},
                        Case{"mu=-0.5", "'mu' (mu): must be >= 0, got -0.5"},
                        Case{"stiffness=0", "'stiffness' (stiffness): must be > 0, got 0"},
                        Case{"damping=-1", "'damping' (damping): must be >= 0, got -1"},
                        Case{"integrator=leapfrog", "run setting 'integrator'"},
                        Case{"base=loose", "--set base: expected auto, fixed or floating"}}) {
    SCOPED_TRACE(c.set);
    const std::string e = sceneErrorOf([&] { sceneFromUrdf(urdf, {}, {c.set}); });
    EXPECT_EQ(e.rfind(urdf + ": ", 0), 0u) << e;
    EXPECT_NE(e.find(c.key), std::string::npos) << e;
  }
  // A run shorter than the automatic step takes the run's length as its step.
  const Scene short_run = sceneFromUrdf(urdf, {}, {"duration=1e-4"});
  EXPECT_DOUBLE_EQ(short_run.model->options.time_step, 1e-4);
}

TEST(RunSettingsErrors, AUrdfGivenToTheSceneLoaderIsRefusedNamingIt) {
  const std::string urdf = std::string(TRIBO_SOURCE_DIR) + "/scenes/robots/pendulum.urdf";
  const std::string e = sceneErrorOf([&] { loadScene(urdf); });
  EXPECT_NE(e.find(urdf + ": a URDF robot"), std::string::npos) << e;
}

}  // namespace
}  // namespace tribo::io
