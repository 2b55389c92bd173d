// `tribo run` on long and bad runs, end to end: input whose output could never be stored
// is refused before anything is written; a run stopped by SIGINT or SIGTERM writes what it
// computed, marked interrupted, as a byte-for-byte prefix of an uninterrupted run; a second
// run on the same folder is refused while the first works; memory does not grow with the
// duration (trajectory.csv is streamed); the progress line shows when asked and not with
// --quiet; --threads gives the same trajectory bit for bit and refuses bad values.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_support.hpp"
#include "support/process_support.hpp"

namespace {

using namespace tribo::test;
using namespace std::chrono_literals;

class TriboRun : public CliTest {
 protected:
  TriboRun() : CliTest("tribo_run_cli_") {}
  // A run far longer than any test waits for, sampled every 10 ms (about 100 simulated s
  // per wall s).
  std::vector<std::string> longRun(const fs::path& out) const {
    return {"run",   kBelt,          "--out", out.string(),
            "--set", "duration=1e5", "--set", "output_interval=0.01"};
  }
};

nlohmann::json summaryOf(const fs::path& dir) {
  return nlohmann::json::parse(slurp(dir / "summary.json"));
}

TEST_F(TriboRun, OutputsThatCannotFitAreRefusedNamingTheKeysAndNothingIsWritten) {
  struct Case {
    std::string sets, expected;
  };
  for (const Case& c :
       {Case{"--set duration=1e12 --set dt=1",
             "output.interval 0.001 s (step 1 s) over duration "
             "1e+12 s gives about 1e+12 rows of 17 columns"},
        Case{"--set duration=1e7", "over duration 1e+07 s gives about 1e+10 rows"},
        Case{"--set duration=1e15 --set dt=0.1", "steps, more than the 1e+15 a run may take"},
        Case{"--set dt=1e300", "time_step (1e+300 s) is larger than the duration (60 s)"},
        Case{"--set duration=inf", "parameters.duration"},
        // Not UTF-8: once the whole run, then exit 4 when summary.json was written.
        Case{"--set friction=ab\xff",
             "--set friction=ab\\xFF: expected UTF-8 text, found byte 0xFF"},
        Case{"--set friction=\xed\xa0\x80", "a UTF-16 surrogate"}}) {
    const Result r = runTribo("run " + kBelt + " --out " + dir_.string() + " " + c.sets);
    EXPECT_EQ(r.status, 2) << c.sets << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.sets << "\n" << r.output;
    EXPECT_EQ(r.output.find("Aborted"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_)) << c.sets;
  }
}

TEST_F(TriboRun, SigintOrSigtermStopsWithResultsUpToThereMarkedInterrupted) {
  fs::create_directories(dir_);
  for (const int signal : {SIGINT, SIGTERM}) {
    const fs::path out = dir_ / ("out" + std::to_string(signal));
    // --progress: the line appears after 2 s, then the signal comes.
    std::vector<std::string> args = longRun(out);
    args.push_back(signal == SIGINT ? "--progress" : "--quiet");
    const Child child = spawnChild(kTribo, args, dir_ / ("io" + std::to_string(signal)));
    ASSERT_GT(child.pid, 0);
    const bool shown =
        waitUntil([&] { return slurp(child.err).find("simulated s (") != std::string::npos; }, 8s);
    EXPECT_EQ(shown, signal == SIGINT) << slurp(child.err);
    EXPECT_TRUE(fs::exists(out / "trajectory.csv.partial"));
    EXPECT_FALSE(fs::exists(out / "trajectory.csv"));
    ::kill(child.pid, signal);
    const Exit e = waitChild(child);
    const std::string err = slurp(child.err);
    EXPECT_EQ(e.status, 5) << err;
    EXPECT_NE(err.find("interrupted at t = "), std::string::npos) << err;
    const auto summary = summaryOf(out);
    EXPECT_EQ(summary["status"], "interrupted");
    const double simulated = summary["run"]["simulated_seconds"];
    EXPECT_GT(simulated, 1.0);
    EXPECT_FALSE(fs::exists(out / "trajectory.csv.partial"));
    const std::string csv = slurp(out / "trajectory.csv");
    ASSERT_FALSE(csv.empty());
    ASSERT_EQ(csv.back(), '\n');
    const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
    EXPECT_NEAR(std::strtod(last.c_str(), nullptr), simulated, 1e-9 * simulated) << last;
    // The same rows as an uninterrupted run a little longer, byte for byte.
    const fs::path ref = dir_ / ("ref" + std::to_string(signal));
    const Result full = runTribo(
        "run " + kBelt + " --out " + ref.string() +
        " --set output_interval=0.01 --set duration=" + std::to_string(std::ceil(simulated) + 1));
    ASSERT_EQ(full.status, 0) << full.output;
    const std::string whole = slurp(ref / "trajectory.csv");
    ASSERT_GT(whole.size(), csv.size());
    EXPECT_EQ(whole.compare(0, csv.size(), csv), 0);
  }
}

TEST_F(TriboRun, ASecondRunOnTheSameFolderIsRefusedWhileTheFirstWorks) {
  fs::create_directories(dir_);
  const fs::path out = dir_ / "out";
  const Child first = spawnChild(kTribo, longRun(out), dir_ / "first");
  ASSERT_GT(first.pid, 0);
  ASSERT_TRUE(waitUntil([&] { return fs::exists(out / "trajectory.csv.partial"); }, 5s));
  const std::string before = slurp(out / "trajectory.csv.partial");
  const Result second = runTribo("run " + kBelt + " --out " + out.string() + " --set duration=1");
  EXPECT_EQ(second.status, 6) << second.output;
  EXPECT_NE(second.output.find("is in use by another tribo run or sweep"), std::string::npos)
      << second.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // The first run's file was not restarted.
  EXPECT_EQ(slurp(out / "trajectory.csv.partial").compare(0, before.size(), before), 0);
  ::kill(first.pid, SIGTERM);
  EXPECT_EQ(waitChild(first).status, 5);
  // Free again once the first is gone.
  EXPECT_EQ(runTribo("run " + kBelt + " --out " + out.string() + " --set duration=1").status, 0);
}

TEST_F(TriboRun, PeakMemoryDoesNotGrowWithTheDuration) {
  fs::create_directories(dir_);
  long rss[2] = {0, 0};
  const char* durations[2] = {"duration=200", "duration=2000"};
  for (int i = 0; i < 2; ++i) {
    const Child c =
        spawnChild(kTribo,
                   {"run", kBelt, "--out", (dir_ / durations[i]).string(), "--set", durations[i],
                    "--set", "dt=0.008", "--set", "output_interval=0.008", "--quiet"},
                   dir_ / ("io" + std::to_string(i)));
    const Exit e = waitChild(c);
    ASSERT_EQ(e.status, 0) << slurp(c.err);
    rss[i] = e.max_rss_kib;
  }
  // 10 times the rows (250 000 of 17 columns: 34 MB if kept) within 30% of the peak.
  EXPECT_LT(static_cast<double>(rss[1]) / rss[0], 1.3) << rss[0] << " KiB vs " << rss[1] << " KiB";
  std::printf("peak resident memory: %ld KiB (200 s), %ld KiB (2000 s)\n", rss[0], rss[1]);
  EXPECT_EQ(lines(dir_ / durations[1] / "trajectory.csv"), 1 + 250'001);
}

}  // namespace

namespace {

// --threads: the same trajectory.csv, byte for byte at 17 digits (every double exactly: the
// same bits), on 1 and 2 threads and auto (400 boxes, 1600 contact points: the stages split),
// the summary saying what the steps ran on; a value that is not a whole number >= 1 or auto
// is a usage error naming the option.
TEST_F(TriboRun, ThreadsGiveTheSameTrajectoryAndBadValuesAreRefused) {
  const std::string grid = std::string(TRIBO_SOURCE_DIR) + "/scenes/box_grid20.yaml";
  std::string csv[3];
  const std::string names[3] = {"1", "2", "auto"};
  for (int k = 0; k < 3; ++k) {
    const fs::path out = dir_ / names[k];
    const Result r =
        runTribo("run " + grid + " --out " + out.string() +
                 " --quiet --set duration=0.05 --set output.digits=17 --threads " + names[k]);
    ASSERT_EQ(r.status, 0) << r.output;
    csv[k] = slurp(out / "trajectory.csv");
    const std::size_t line = r.output.find("threads          ");
    if (k == 0) {
      EXPECT_EQ(line, std::string::npos) << r.output;  // the default: nothing to say
    } else if (k == 1) {
      EXPECT_NE(r.output.find("threads          2: 2 a step on the mean, of up to 2\n"),
                std::string::npos)
          << r.output;
    } else {
      ASSERT_NE(line, std::string::npos) << r.output;
      double mean = 0.0;
      int most = 0;
      ASSERT_EQ(std::sscanf(r.output.c_str() + line,
                            "threads          auto (measured choice): %lf a step on the mean, "
                            "of up to %d",
                            &mean, &most),
                2)
          << r.output;
      EXPECT_GE(mean, 1.0);
      EXPECT_LE(mean, most);
    }
  }
  EXPECT_GT(lines(dir_ / "1" / "trajectory.csv"), 2);
  EXPECT_TRUE(csv[0] == csv[1]);
  EXPECT_TRUE(csv[0] == csv[2]);
  const Result small = runTribo("run " + kBelt + " --out " + (dir_ / "belt").string() +
                                " --quiet --set duration=0.01 --threads 2");
  EXPECT_NE(small.output.find("threads          2: 1 a step on the mean, of up to 1 (the scene "
                              "is too small to split)"),
            std::string::npos)
      << small.output;
  for (const std::string bad : {"0", "-1", "2.5", "x"}) {
    const Result r =
        runTribo("run " + kBelt + " --out " + (dir_ / "bad").string() + " --threads " + bad);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("--threads: expected auto or a whole number from 1 to 4096, found '" +
                            bad + "'"),
              std::string::npos)
        << r.output;
  }
  const Result missing =
      runTribo("run " + kBelt + " --out " + (dir_ / "bad").string() + " --threads");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("--threads needs a value"), std::string::npos) << missing.output;
}

}  // namespace
