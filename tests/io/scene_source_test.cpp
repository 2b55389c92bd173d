// The one entry point for scene files (io/scene_source.hpp): a URDF robot is told by its
// content whatever its name ends with, a scene YAML loads as a scene, a .urdf name that is
// not XML reaches the URDF reader (which says what is wrong), and the run settings reach the
// built model for both kinds (threads) or are refused where a URDF run takes them as --set.
#include "io/scene_source.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/model.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::io {
namespace {

namespace fs = std::filesystem;

const std::string kSource = TRIBO_SOURCE_DIR;

// A folder of this test's own (CTest runs the cases side by side).
fs::path testFolder() {
  const fs::path dir = fs::temp_directory_path() /
                       ("tribo_scene_source_" +
                        std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::create_directories(dir);
  return dir;
}

fs::path copyTo(const std::string& from, const std::string& name) {
  const fs::path dir = testFolder();
  const fs::path to = dir / name;
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  return to;
}

TEST(SceneSource, AUrdfIsToldByItsContentWhateverItsName) {
  const std::string urdf = kSource + "/scenes/robots/pendulum.urdf";
  for (const std::string name : {"pendulum.urdf", "pendulum.URDF", "pendulum.xml", "robot"}) {
    const fs::path file = copyTo(urdf, name);
    EXPECT_TRUE(isUrdfScene(file.string())) << name;
    SceneRequest request;
    request.settings.threads = 3;
    const Scene scene = loadAnyScene(file.string(), request);
    EXPECT_EQ(scene.model->options.threads, 3) << name;
    // The file's arm link (2 kg), the massless base welded to the world.
    const auto arm = scene.model->findBody("arm");
    ASSERT_TRUE(arm.has_value()) << name;
    EXPECT_EQ(scene.model->bodies[arm->value].mass, 2.0) << name;
  }
}

TEST(SceneSource, ASceneFileLoadsAsASceneWithItsOverridesAndSettings) {
  const fs::path file = copyTo(kSource + "/scenes/belt.yaml", "belt.yaml");
  EXPECT_FALSE(isUrdfScene(file.string()));
  SceneRequest request;
  request.overrides = {"m=2.5"};
  request.settings.threads = 2;
  request.settings.time_step = 5e-4;
  const Scene scene = loadAnyScene(file.string(), request);
  EXPECT_EQ(scene.model->options.threads, 2);
  EXPECT_EQ(scene.model->options.time_step, 5e-4);
  EXPECT_EQ(scene.model->bodies[scene.model->findBody("box")->value].mass, 2.5);
}

TEST(SceneSource, ANonXmlFileNamedUrdfReachesTheUrdfReader) {
  const fs::path file = testFolder() / "broken.urdf";
  std::ofstream(file) << "bodies: []\n";
  EXPECT_TRUE(isUrdfScene(file.string()));
  EXPECT_THROW(loadAnyScene(file.string(), {}), UrdfError);
}

TEST(SceneSource, AUrdfRunRefusesRunSettingsItTakesAsSetNames) {
  const fs::path file = copyTo(kSource + "/scenes/robots/pendulum.urdf", "pendulum.urdf");
  for (int which = 0; which < 3; ++which) {
    SceneRequest request;
    if (which == 0) request.settings.time_step = 1e-4;
    if (which == 1) request.settings.duration = 2.0;
    if (which == 2) request.settings.integrator = IntegratorType::kBdf;
    try {
      (void)loadAnyScene(file.string(), request);
      ADD_FAILURE() << "setting " << which << " was taken";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("--set"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace tribo::io
