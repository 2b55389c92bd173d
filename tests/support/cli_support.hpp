// Helpers for the tests that run the `tribo` binary end to end (tribo_cli_test,
// sweep_cli_test, tradeoff_cli_test): run a command and collect its exit status and output,
// read a file back, and a folder per test named after it. The binary is TRIBO_BINARY, set by
// tests/apps/CMakeLists.txt for each test. Not here: expectations; each test states its own.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace tribo::test {

namespace fs = std::filesystem;

inline const std::string kTribo = TRIBO_BINARY;
inline const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

struct Result {
  int status;          // exit status, -1 when the command did not exit normally
  std::string output;  // stdout and stderr
};

// Runs `command` in the shell, stderr merged into stdout.
inline Result runCommand(const std::string& command) {
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (p && std::fgets(buf.data(), buf.size(), p)) out += buf.data();
  const int raw = p ? pclose(p) : -1;
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

// Runs `tribo ARGS` (ARGS as one shell-quoted string).
inline Result runTribo(const std::string& args) { return runCommand(kTribo + " " + args); }

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline long lines(const fs::path& p) {
  const std::string s = slurp(p);
  return std::count(s.begin(), s.end(), '\n');
}

// A fixture whose dir_ is a folder named `prefix` + the running test's name + the process
// id (two test runs at once, e.g. of two build trees, never share one), removed before and
// after the test. It is not created: a test may check that nothing was written.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (prefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;

 private:
  std::string prefix_;
};

}  // namespace tribo::test
