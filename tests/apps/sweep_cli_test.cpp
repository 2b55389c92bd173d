// `tribo sweep` end to end: a sweep killed midway (SIGKILL) and started again with the same
// arguments ends with the same results file as an uninterrupted one; the same sweep under
// `mpirun -n 2` too; exit status and messages for bad input and for a folder that holds
// another sweep.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli_support.hpp"

namespace {

using namespace tribo::test;

// Starts `tribo ARGS...` in the background, output to /dev/null.
pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(kTribo.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (std::freopen("/dev/null", "w", stdout) && std::freopen("/dev/null", "w", stderr))
      execv(kTribo.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

class SweepCli : public CliTest {
 protected:
  SweepCli() : CliTest("tribo_sweep_cli_") {}
  void SetUp() override {
    CliTest::SetUp();
    fs::create_directories(dir_);
  }
};

// 12 points of some 25 ms of one core each (Release; 2 ms steps over 20 s): slow enough to
// kill midway, quick enough for a sanitizer build.
const std::vector<std::string> kKillable = {
    kBelt,         "--grid", "a=1.2:3:4", "--list", "mu_s=0.33,0.35,0.4",    "--set",
    "duration=20", "--set",  "dt=0.002",  "--set",  "output_interval=0.004", "--jobs",
    "1",           "--quiet"};

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const auto& a : args) s += " " + a;
  return s;
}

TEST_F(SweepCli, KilledSweepRestartedWritesTheSameFileAsAnUninterruptedOne) {
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  const Result r = runTribo("sweep" + joined(kKillable) + " --out " + whole.string());
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_EQ(lines(whole / "results.csv"), 1 + 12);

  std::vector<std::string> args{"sweep"};
  args.insert(args.end(), kKillable.begin(), kKillable.end());
  args.insert(args.end(), {"--out", killed.string()});
  const pid_t pid = spawn(args);
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (lines(killed / "results.csv") < 1 + 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it could be killed";
  const long kept = lines(killed / "results.csv") - 1;
  EXPECT_GE(kept, 3);
  EXPECT_LT(kept, 12);

  const Result resumed = runTribo("sweep" + joined(kKillable) + " --out " + killed.string());
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find(std::to_string(kept) + " resumed"), std::string::npos)
      << resumed.output;
  EXPECT_EQ(slurp(killed / "results.csv"), slurp(whole / "results.csv"));
}

TEST_F(SweepCli, TwoMpiRanksWriteTheSameFileAsOneProcess) {
#ifndef TRIBO_WITH_MPI
  GTEST_SKIP() << "tribo was built without MPI (TRIBO_WITH_MPI=OFF)";
#else
  const std::string mpirun = TRIBO_MPIEXEC;
  if (mpirun.empty() || !fs::exists(mpirun))
    GTEST_SKIP() << "no mpirun found (Debian: openmpi-bin)";
  const std::string sweep =
      " sweep " + kBelt +
      " --grid v_b=1:3:5 --list friction=roh_yoo,recurdyn --set dt=0.008 "
      "--set output_interval=0.008 --set duration=200 --settle 1e-3 --jobs 1 --quiet --out ";
  const Result local = runTribo(sweep + (dir_ / "local").string());
  ASSERT_EQ(local.status, 0) << local.output;
  // Root may run it (CI does); two ranks on a two-core machine need --oversubscribe only
  // where fewer cores are free.
  // In a sanitizer build, OpenMPI's components (unloaded at MPI_Finalize) leave allocations
  // that LeakSanitizer can neither attribute nor suppress; the sweep's own code is leak
  // checked by the local runs here and in sweep_io_test. The setting is inert otherwise.
  const char* asan = std::getenv("ASAN_OPTIONS");
  const std::string env =
      "ASAN_OPTIONS='" + std::string(asan ? asan : "") + (asan ? ":" : "") + "detect_leaks=0' ";
  const Result ranks = runCommand(env + mpirun + " --allow-run-as-root --oversubscribe -n 2 " +
                                  kTribo + sweep + (dir_ / "mpi").string());
  ASSERT_EQ(ranks.status, 0) << ranks.output;
  EXPECT_NE(ranks.output.find("2 MPI ranks"), std::string::npos) << ranks.output;
  EXPECT_EQ(slurp(dir_ / "mpi" / "results.csv"), slurp(dir_ / "local" / "results.csv"));
  EXPECT_EQ(lines(dir_ / "mpi" / "results.csv"), 1 + 10);
#endif
}

TEST_F(SweepCli, ExitStatusAndMessages) {
  const std::string out = " --out " + (dir_ / "s").string();
  EXPECT_EQ(runTribo("sweep --help").status, 0);
  struct Case {
    std::string args;
    int status;
    std::string expected;
  };
  for (const Case& c :
       {Case{"sweep " + kBelt + out, 1, "nothing to sweep"},
        Case{"sweep " + kBelt + " --grid v_b=1:2", 1, "--grid 'v_b=1:2': expected"},
        Case{"sweep " + kBelt + out + " --grid v_b=1:2:2 --jobs 0", 1, "--jobs"},
        Case{"sweep " + kBelt + out + " --grid v_b=1:2:2 --settle -1", 1, "--settle"},
        Case{"sweep " + kBelt + out + " --grid v_b=1:2:2 --frobnicate", 1, "unknown option"},
        Case{"sweep " + kBelt + out + " --grid nope=1:2:2", 2, "'nope' is not a parameter"},
        Case{"sweep /nonexistent/scene.yaml" + out + " --grid v_b=1:2:2", 2,
             "/nonexistent/scene.yaml"},
        Case{"sweep " + kBelt + out + " --grid v_b=1:2:2 --set k=abc", 2, "expected a number"}}) {
    const Result r = runTribo(c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
  // Refused before anything is written: a parameter both fixed and swept, a grid past the
  // point limit (once 2.4 GB and a 249 MB sweep.json before the first point), text that is
  // not UTF-8 (once found only when summary.json was written, after the run).
  for (const Case& c :
       {Case{"sweep " + kBelt + out + " --grid v_b=1:2:2 --set v_b=9", 2,
             "--set v_b=9 fixes parameter 'v_b', which is also swept"},
        Case{"sweep " + kBelt + out + " --set v_b=9 --list v_b=1,2", 2,
             "--set v_b=9 fixes parameter 'v_b', which is also swept"},
        Case{"sweep " + kBelt + out + " --grid v_b=0:1:10000000", 1,
             "COUNT 10000000 is more points than a sweep may have (at most 1000000)"},
        Case{"sweep " + kBelt + out + " --grid v_b=0:1:1000 --grid k=1:2:1001", 2,
             "the grid spans 1.001e+06 points (1000 v_b x 1001 k); a sweep may have at most "
             "1000000"},
        Case{"sweep " + kBelt + out + " --list friction=roh_yoo,\xff", 1,
             "--list 'friction=roh_yoo,\\xFF': expected UTF-8 text"},
        Case{"sweep " + kBelt + out + " --grid v_b=1:2:2 --set friction=\xc0\x80", 2,
             "--set friction=\\xC0\\x80: expected UTF-8 text"}}) {
    const Result r = runTribo(c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "s")) << c.args;
  }
  // A folder that holds another sweep is refused, not mixed.
  const std::string quick = " --set duration=2 --set dt=0.008 --quiet";
  ASSERT_EQ(runTribo("sweep " + kBelt + out + " --list v_b=1,2" + quick).status, 0);
  const Result other = runTribo("sweep " + kBelt + out + " --list v_b=1,3" + quick);
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.output.find("holds a different sweep"), std::string::npos) << other.output;
  // Output below a file cannot be written.
  std::ofstream(dir_ / "file") << "x";
  const Result unwritable = runTribo("sweep " + kBelt + " --out " + (dir_ / "file" / "s").string() +
                                     " --list v_b=1" + quick);
  EXPECT_EQ(unwritable.status, 4) << unwritable.output;
}

}  // namespace
