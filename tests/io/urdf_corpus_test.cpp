// Every URDF of the shared corpus (real files written for ROS, Gazebo and PyBullet) read
// through urdfdom: link and joint counts, joints by type, total mass, collision elements and
// their mesh files against the corpus' expected.json (written independently, from the XML
// with Python's standard library); the one invalid file is refused with urdfdom's reason.
#include "support/urdf_corpus.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "io/urdf_reader.hpp"

namespace tribo::io {
namespace {

namespace fs = std::filesystem;

fs::path corpus() { return test::urdfCorpusFolder().value_or(""); }

nlohmann::json expected() {
  std::ifstream in(corpus() / "expected.json");
  return nlohmann::json::parse(in);
}

PackagePaths corpusPackages() { return PackagePaths({corpus().string()}); }

class UrdfCorpus : public ::testing::TestWithParam<std::string> {
 protected:
  // Fails when the corpus is missing (skips with TRIBO_URDF_CORPUS=none).
  void SetUp() override { TRIBO_REQUIRE_URDF_CORPUS(folder); }
};

TEST_P(UrdfCorpus, MatchesExpectedFacts) {
  const std::string file = GetParam();
  const nlohmann::json all = expected();
  const nlohmann::json facts = all["urdfs"][file];
  const std::string path = (corpus() / file).string();
  if (!facts["is_valid_tree"].get<bool>()) {
    try {
      readUrdf(path, corpusPackages());
      FAIL() << file << " is not a valid tree and must be refused";
    } catch (const UrdfError& e) {
      EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("root"), std::string::npos) << e.what();
    }
    return;
  }
  const UrdfRobot robot = readUrdf(path, corpusPackages());
  EXPECT_EQ(robot.links.size(), facts["num_links"].get<std::size_t>());
  EXPECT_EQ(robot.joints.size(), facts["num_joints"].get<std::size_t>());
  std::map<std::string, int> by_type;
  for (const auto& j : robot.joints) ++by_type[j.type];
  std::map<std::string, int> expected_types;
  for (const auto& [type, n] : facts["joints_by_type"].items()) expected_types[type] = n;
  EXPECT_EQ(by_type, expected_types);
  EXPECT_NEAR(robot.totalMass(), facts["total_mass"].get<double>(), 1e-9);
  ASSERT_EQ(facts["root_links"].size(), 1u);
  EXPECT_EQ(robot.root, facts["root_links"][0].get<std::string>());

  // Every collision element is kept, including those urdfdom drops (capsules).
  std::size_t collisions = 0;
  std::map<std::string, int> kinds;
  static const char* kKind[] = {"box", "sphere", "cylinder", "capsule", "mesh"};
  for (const auto& l : robot.links) {
    collisions += l.collisions.size();
    for (const auto& c : l.collisions) ++kinds[kKind[static_cast<int>(c.kind)]];
  }
  EXPECT_EQ(collisions, facts["num_collision_elements"].get<std::size_t>());
  std::map<std::string, int> expected_kinds;
  for (const auto& [kind, n] : facts["collision_geometry"].items()) expected_kinds[kind] = n;
  EXPECT_EQ(kinds, expected_kinds);

  // Collision meshes resolve to the files the corpus names.
  for (const auto& mesh : facts["mesh_files"]) {
    const auto used = mesh["used_in"];
    if (std::find(used.begin(), used.end(), "collision") == used.end()) continue;
    const std::string want = (corpus() / mesh["resolved"].get<std::string>()).lexically_normal();
    bool found = false;
    for (const auto& l : robot.links)
      for (const auto& c : l.collisions) found |= c.mesh_path == want;
    EXPECT_TRUE(found) << "collision mesh " << want;
  }
  bool mesh_error = false;
  for (const auto& i : robot.issues)
    mesh_error |= i.severity == UrdfIssue::Severity::kError &&
                  i.message.find("collision mesh") != std::string::npos;
  EXPECT_FALSE(mesh_error);
}

std::vector<std::string> corpusFiles() {
  std::vector<std::string> files;
  if (corpus().empty() || !fs::exists(corpus() / "expected.json")) return {"(corpus missing)"};
  const nlohmann::json all = expected();
  for (const auto& [file, facts] : all["urdfs"].items()) files.push_back(file);
  return files;
}

INSTANTIATE_TEST_SUITE_P(All, UrdfCorpus, ::testing::ValuesIn(corpusFiles()), [](const auto& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

}  // namespace
}  // namespace tribo::io
