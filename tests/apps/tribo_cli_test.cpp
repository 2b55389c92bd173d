// The `tribo` command end to end: exit status, what lands in the output folder, and the
// error text a user sees for bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
const std::string kTribo = TRIBO_BINARY;
const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

struct Result {
  int status;
  std::string output;  // stdout and stderr
};

Result run(const std::string& args) {
  const std::string cmd = kTribo + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (p && std::fgets(buf.data(), buf.size(), p)) out += buf.data();
  const int raw = p ? pclose(p) : -1;
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class TriboCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tribo_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(TriboCli, RunWritesTrajectoryAndSummary) {
  const Result r = run("run " + kBelt + " --out " + dir_.string() + " --set duration=3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("amplitude (p-p)"), std::string::npos) << r.output;
  const std::string csv = slurp(dir_ / "trajectory.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* col : {"t", "box.x", "box.y", "box.z", "box.vx", "box.vy", "box.vz"})
    EXPECT_NE(("," + header + ",").find(std::string(",") + col + ","), std::string::npos) << col;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3001);  // header + t = 0..3 s at 1 ms
  const std::string summary = slurp(dir_ / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"complete\""), std::string::npos);
  for (const char* key : {"amplitude_pp", "time_to_98", "period", "stuck_fraction"})
    EXPECT_NE(summary.find(std::string("\"") + key + "\""), std::string::npos) << key;
  EXPECT_FALSE(fs::exists(dir_ / "trajectory.csv.partial"));
}

TEST_F(TriboCli, BadParametersFailWithFileAndKeyAndWriteNothing) {
  struct Case {
    std::string set;
    std::string expected;
  };
  for (const Case& c :
       {Case{"--set nope=1", "nope"}, Case{"--set friction=magic", "magic"},
        Case{"--set a=0.9", "a must be > 1"}, Case{"--set mu_k=0.4", "mu_s must exceed mu_k"},
        Case{"--set k=abc", "expected a number"}}) {
    const Result r = run("run " + kBelt + " --out " + dir_.string() + " " + c.set);
    EXPECT_EQ(r.status, 2) << c.set << "\n" << r.output;
    EXPECT_NE(r.output.find("belt.yaml"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_)) << c.set;
  }
}

TEST_F(TriboCli, DivergedRunExitsNonZeroAndMarksTheSummary) {
  const Result r =
      run("run " + kBelt + " --out " + dir_.string() + " --set dt=0.02 --set duration=5");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("warning: time step 0.02 s exceeds"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("diverged at step"), std::string::npos) << r.output;
  const std::string summary = slurp(dir_ / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"diverged\""), std::string::npos) << summary;
  EXPECT_EQ(slurp(dir_ / "trajectory.csv").find("nan"), std::string::npos);
}

TEST_F(TriboCli, UsageErrors) {
  EXPECT_EQ(run("").status, 1);
  EXPECT_EQ(run("fly").status, 1);
  EXPECT_EQ(run("run " + kBelt).status, 1);  // no --out
  const Result missing = run("run /nonexistent/scene.yaml --out " + dir_.string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("/nonexistent/scene.yaml"), std::string::npos);
  EXPECT_EQ(run("--help").status, 0);
}

TEST_F(TriboCli, InfoPrintsTheUrdfTreeAndRefusesAnInvalidOne) {
  const fs::path corpus = fs::path(TRIBO_SOURCE_DIR) / ".." / "shared" / "urdf";
  if (!fs::exists(corpus / "bullet3" / "r2d2.urdf")) GTEST_SKIP() << "no URDF corpus at " << corpus;
  const Result ok = run("info " + (corpus / "bullet3" / "r2d2.urdf").string());
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_NE(ok.output.find("links 16, joints 15 (5 continuous, 7 fixed, 1 prismatic, 2 revolute), "
                           "total mass 65.25 kg"),
            std::string::npos)
      << ok.output;
  EXPECT_NE(ok.output.find("left_gripper  [revolute 'left_gripper_joint']"), std::string::npos);
  const Result loop =
      run("info " + (corpus / "ros_urdf/urdf/test/fail_pr2_desc_loop.urdf").string());
  EXPECT_EQ(loop.status, 2) << loop.output;
  EXPECT_NE(loop.output.find("no root link: joint"), std::string::npos) << loop.output;
}

}  // namespace
