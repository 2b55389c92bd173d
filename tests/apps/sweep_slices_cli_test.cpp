// `tribo sweep --slice I/N` and `--merge DIR` end to end: three slice processes started at
// once into one folder end with the results file of a one-process sweep, byte for byte
// (written by the slice that ends last, and again by the merge); a slice of a different
// sweep in the same folder is refused; a merge with a slice missing names its points and
// fails; bad --slice values are usage errors; a killed slice run again completes; a plain
// run of the sweep completes a folder of unfinished slices.
#include <gtest/gtest.h>
#include <signal.h>

#include <string>
#include <vector>

#include "support/cli_support.hpp"
#include "support/process_support.hpp"

namespace {

using namespace tribo::test;

class SweepSlicesCli : public CliTest {
 protected:
  SweepSlicesCli() : CliTest("tribo_sweep_slices_cli_") {}
  void SetUp() override {
    CliTest::SetUp();
    fs::create_directories(dir_);
  }
  // A one-process sweep of `args` into dir_/one; its results.csv.
  std::string oneProcess(const std::vector<std::string>& args) {
    const Result r = runTribo("sweep" + joined(args) + " --out " + (dir_ / "one").string());
    EXPECT_EQ(r.status, 0) << r.output;
    return slurp(dir_ / "one" / "results.csv");
  }
  static std::string joined(const std::vector<std::string>& args) {
    std::string s;
    for (const auto& a : args) s += " " + a;
    return s;
  }
  // `tribo sweep ARGS --out OUT --slice SLICE` as a child process.
  Child startSlice(const std::vector<std::string>& args, const fs::path& out,
                   const std::string& slice) {
    std::vector<std::string> all{"sweep"};
    all.insert(all.end(), args.begin(), args.end());
    all.insert(all.end(), {"--out", out.string(), "--slice", slice});
    return spawnChild(kTribo, all, dir_ / ("slice" + std::to_string(started_++)));
  }

 private:
  int started_ = 0;
};

// 12 points (4 a x 3 mu_s), short runs: the points a=1.2,1.8,2.4,3 x mu_s=0.33,0.35,0.4.
const std::vector<std::string> kSmall = {
    kBelt,        "--grid", "a=1.2:3:4", "--list", "mu_s=0.33,0.35,0.4",    "--set",
    "duration=5", "--set",  "dt=0.002",  "--set",  "output_interval=0.004", "--jobs",
    "1",          "--quiet"};

TEST_F(SweepSlicesCli, ThreeSlicesAtOnceEndWithTheOneProcessFileAndSoDoesTheMerge) {
  const std::string expected = oneProcess(kSmall);
  ASSERT_EQ(lines(dir_ / "one" / "results.csv"), 1 + 12);
  const fs::path out = dir_ / "sliced";
  std::vector<Child> slices;
  for (const std::string s : {"1/3", "2/3", "3/3"}) slices.push_back(startSlice(kSmall, out, s));
  for (const Child& c : slices) {
    ASSERT_GT(c.pid, 0);
    const Exit e = waitChild(c);
    EXPECT_EQ(e.status, 0) << slurp(c.err);
  }
  // Every slice wrote its rows before looking for the others', so the last to look saw all.
  EXPECT_EQ(slurp(out / "results.csv"), expected);
  EXPECT_EQ(slurp(out / "sweep.json"), slurp(dir_ / "one" / "sweep.json"));
  fs::remove(out / "results.csv");
  const Result merged = runTribo("sweep --merge " + out.string());
  EXPECT_EQ(merged.status, 0) << merged.output;
  EXPECT_NE(merged.output.find("merged           12 points"), std::string::npos) << merged.output;
  EXPECT_EQ(slurp(out / "results.csv"), expected);
  // Nothing but the rows and the shared files: no temporary left by a finished slice.
  for (const auto& entry : fs::directory_iterator(out / "rows"))
    EXPECT_EQ(entry.path().extension(), ".csv") << entry.path();
}

TEST_F(SweepSlicesCli, ASliceOfADifferentSweepInTheSameFolderIsRefused) {
  const fs::path out = dir_ / "sliced";
  const Result first =
      runTribo("sweep" + joined(kSmall) + " --out " + out.string() + " --slice 1/3");
  ASSERT_EQ(first.status, 0) << first.output;
  const std::string manifest = slurp(out / "sweep.json");
  std::vector<std::string> other = kSmall;
  other[2] = "a=1.2:3:5";  // one more value of a
  const Result refused =
      runTribo("sweep" + joined(other) + " --out " + out.string() + " --slice 2/3");
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("holds a different sweep"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("differs from this one's in axes"), std::string::npos)
      << refused.output;
  EXPECT_EQ(slurp(out / "sweep.json"), manifest);
  // Slice 1/3 of 12 points holds 0, 3, 6, 9; the refused slice added none.
  long rows = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(out / "rows")) ++rows;
  EXPECT_EQ(rows, 4);
  // A different setting (--set) is refused the same way.
  std::vector<std::string> longer = kSmall;
  longer[6] = "duration=6";
  const Result settings =
      runTribo("sweep" + joined(longer) + " --out " + out.string() + " --slice 2/3");
  EXPECT_EQ(settings.status, 1) << settings.output;
  EXPECT_NE(settings.output.find("differs from this one's in set"), std::string::npos)
      << settings.output;
}

TEST_F(SweepSlicesCli, AMergeWithASliceMissingNamesItsPointsAndFails) {
  const std::string expected = oneProcess(kSmall);
  const fs::path out = dir_ / "sliced";
  for (const std::string s : {"1/3", "3/3"})
    ASSERT_EQ(
        runTribo("sweep" + joined(kSmall) + " --out " + out.string() + " --slice " + s).status, 0);
  const Result merged = runTribo("sweep --merge " + out.string());
  EXPECT_EQ(merged.status, 3) << merged.output;
  EXPECT_NE(merged.output.find("4 of 12 points missing"), std::string::npos) << merged.output;
  // Slice 2/3 holds points 1, 4, 7, 10: mu_s = 0.35 (the middle value) at each a.
  for (const std::string point : {"point 1 (a=1.2, mu_s=0.35)", "point 4 (a=1.8, mu_s=0.35)",
                                  "point 7 (a=2.4, mu_s=0.35)", "point 10 (a=3, mu_s=0.35)"})
    EXPECT_NE(merged.output.find(point), std::string::npos) << point << "\n" << merged.output;
  EXPECT_EQ(merged.output.find("point 0 "), std::string::npos) << merged.output;
  EXPECT_FALSE(fs::exists(out / "results.csv"));

  // The missing slice completes the sweep; the merge then agrees.
  const Result last =
      runTribo("sweep" + joined(kSmall) + " --out " + out.string() + " --slice 2/3");
  ASSERT_EQ(last.status, 0) << last.output;
  EXPECT_EQ(slurp(out / "results.csv"), expected);
  EXPECT_EQ(runTribo("sweep --merge " + out.string()).status, 0);
  EXPECT_EQ(slurp(out / "results.csv"), expected);
  // A folder without a sweep is no merge.
  const Result none = runTribo("sweep --merge " + (dir_ / "none").string());
  EXPECT_EQ(none.status, 1) << none.output;
  EXPECT_NE(none.output.find("holds no sweep"), std::string::npos) << none.output;
}

TEST_F(SweepSlicesCli, BadSliceValuesAreUsageErrorsNamingTheOptionAndWhatWasFound) {
  const std::string out = " --out " + (dir_ / "s").string();
  for (const std::string bad : {"0/3", "4/3", "3", "1/0", "a/3", "-1/3", "1/3/3", "2/1", "1/"}) {
    const Result r = runTribo("sweep" + joined(kSmall) + out + " --slice '" + bad + "'");
    EXPECT_EQ(r.status, 1) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("--slice: expected I/N"), std::string::npos) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("found '" + bad + "'"), std::string::npos) << bad << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "s")) << bad;
  }
  const Result merge_and_scene = runTribo("sweep --merge " + (dir_ / "s").string() + " " + kBelt);
  EXPECT_EQ(merge_and_scene.status, 1) << merge_and_scene.output;
  EXPECT_NE(merge_and_scene.output.find("--merge DIR reads the sweep from DIR/sweep.json"),
            std::string::npos)
      << merge_and_scene.output;
  EXPECT_FALSE(fs::exists(dir_ / "s"));
}

// 24 points of some 25 ms of one core each (as sweep_cli_test's killable sweep): slice 1/2
// holds 12, slow enough to kill midway.
const std::vector<std::string> kKillable = {
    kBelt,         "--grid", "a=1.2:3:8", "--list", "mu_s=0.33,0.35,0.4",    "--set",
    "duration=20", "--set",  "dt=0.002",  "--set",  "output_interval=0.004", "--jobs",
    "1",           "--quiet"};

TEST_F(SweepSlicesCli, AKilledSliceRunAgainCompletes) {
  const std::string expected = oneProcess(kKillable);
  const fs::path out = dir_ / "sliced";
  const Child c = startSlice(kKillable, out, "1/2");
  ASSERT_GT(c.pid, 0);
  const auto rows = [&] {
    long n = 0;
    std::error_code ec;
    for (fs::directory_iterator it(out / "rows", ec), end; !ec && it != end; it.increment(ec))
      n += it->path().extension() == ".csv";
    return n;
  };
  waitUntil([&] { return rows() >= 2; }, std::chrono::seconds(120));
  ::kill(c.pid, SIGKILL);
  const Exit killed = waitChild(c);
  ASSERT_EQ(killed.signal, SIGKILL) << "the slice ended before it could be killed";
  const long kept = rows();
  EXPECT_GE(kept, 2);
  EXPECT_LT(kept, 12);

  const Result again =
      runTribo("sweep" + joined(kKillable) + " --out " + out.string() + " --slice 1/2");
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find(std::to_string(kept) + " resumed"), std::string::npos)
      << again.output;
  EXPECT_NE(again.output.find(std::to_string(12 - kept) + " recorded now"), std::string::npos)
      << again.output;
  EXPECT_FALSE(fs::exists(out / "results.csv"));
  ASSERT_EQ(
      runTribo("sweep" + joined(kKillable) + " --out " + out.string() + " --slice 2/2").status, 0);
  EXPECT_EQ(slurp(out / "results.csv"), expected);
}

TEST_F(SweepSlicesCli, APlainRunCompletesAFolderOfUnfinishedSlices) {
  const std::string expected = oneProcess(kSmall);
  const fs::path out = dir_ / "sliced";
  ASSERT_EQ(runTribo("sweep" + joined(kSmall) + " --out " + out.string() + " --slice 2/3").status,
            0);
  const Result plain = runTribo("sweep" + joined(kSmall) + " --out " + out.string());
  ASSERT_EQ(plain.status, 0) << plain.output;
  EXPECT_NE(plain.output.find("8 recorded now (0 failed), 4 resumed"), std::string::npos)
      << plain.output;
  EXPECT_EQ(slurp(out / "results.csv"), expected);
}

}  // namespace
