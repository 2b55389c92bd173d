// The pieces of sliced sweeps, in process: --slice I/N parsing, slices that partition the
// grid, the manifest read back and compared, files created once and replaced whole while
// threads race for them, the folder lock's shared mode, and a sweep run as slices in one
// process against the same sweep run whole.
#include "study/sweep/sweep_slice.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "study/dir_lock.hpp"
#include "study/file_commit.hpp"
#include "study/sweep/sweep_manifest.hpp"
#include "study/sweep/sweep_results.hpp"
#include "support/sweep_support.hpp"

namespace tribo::study {
namespace {

namespace fs = std::filesystem;
using test::slurp;
using test::TempDir;

TEST(SweepSlice, ParsesIOverNAndRefusesTheRestNamingWhatWasFound) {
  const SweepSlice s = parseSweepSlice("2/8");
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 8u);
  EXPECT_EQ(parseSweepSlice("1/1").count, 1u);
  EXPECT_EQ(parseSweepSlice("1000000/1000000").index, 1000000u);
  for (const std::string bad : {"0/3", "4/3", "3", "", "/", "1/", "/3", "a/3", "1/b", "-1/3",
                                "+1/3", "1.0/3", "1/3/3", " 1/3", "1/1000001"}) {
    try {
      parseSweepSlice(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("--slice: expected I/N"), std::string::npos) << what;
      EXPECT_NE(what.find("found '" + bad + "'"), std::string::npos) << what;
    }
  }
}

TEST(SweepSlice, TheSlicesOfAGridHoldEveryPointOnceAndDifferInSizeByOneAtMost) {
  for (const std::size_t points : {1u, 2u, 7u, 12u, 100u})
    for (std::size_t n = 1; n <= 13; ++n) {
      std::vector<int> seen(points, 0);
      std::size_t smallest = points, largest = 0;
      for (std::size_t i = 1; i <= n; ++i) {
        const auto mine = slicePoints(points, {i, n});
        smallest = std::min(smallest, mine.size());
        largest = std::max(largest, mine.size());
        for (std::size_t k = 0; k < mine.size(); ++k) {
          ++seen[mine[k]];
          EXPECT_TRUE((SweepSlice{i, n}.contains(mine[k])));
          if (k > 0) {
            EXPECT_EQ(mine[k] - mine[k - 1], n);  // interleaved
          }
        }
      }
      for (std::size_t p = 0; p < points; ++p) EXPECT_EQ(seen[p], 1) << p << " of " << points;
      EXPECT_LE(largest - smallest, 1u) << points << " points, " << n << " slices";
    }
}

TEST(SweepManifest, NamesTheEntriesThatDifferAndReadsTheGridBack) {
  const std::string a =
      R"({"tribo_sweep": 1, "scene": "s.yaml", "set": [], "axes": [{"name": "v_b", "values": ["1", "2"]}, {"name": "friction", "values": ["roh_yoo"]}], "settle": null})";
  const std::string b =
      R"({"tribo_sweep": 1, "scene": "s.yaml", "set": ["k=2"], "axes": [{"name": "v_b", "values": ["1", "3"]}], "settle": null, "analysis": "modes"})";
  EXPECT_EQ(manifestDifferences(a, a), "");
  EXPECT_EQ(manifestDifferences(a, b), "set, axes, analysis");
  EXPECT_EQ(manifestDifferences(a, "not json"), "the whole file");
  const ManifestGrid g = readManifestGrid(a, "a.json");
  EXPECT_EQ(g.grid.size(), 2u);
  EXPECT_EQ(g.grid.values(1), (std::vector<std::string>{"2", "roh_yoo"}));
  EXPECT_EQ(g.analysis, SweepAnalysis::kRun);
  EXPECT_EQ(readManifestGrid(b, "b.json").analysis, SweepAnalysis::kModes);
  EXPECT_THROW(readManifestGrid(R"({"axes": []})", "c.json"), SweepOutputError);
  EXPECT_THROW(readManifestGrid(R"({"tribo_sweep": 1, "axes": [{"name": 3}]})", "d.json"),
               SweepOutputError);
}

TEST(FileCommit, OfThreadsCreatingOneFileExactlyOneWinsAndTheFileIsWhole) {
  TempDir dir("tribo_file_commit_");
  fs::create_directories(dir.path());
  const fs::path file = dir / "sweep.json";
  constexpr int kThreads = 8;
  std::atomic<int> winners{0}, winner{-1};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      if (createFileOnce(file, std::string(100000, static_cast<char>('a' + t)))) {
        ++winners;
        winner = t;
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(winners, 1);
  ASSERT_GE(winner, 0);
  EXPECT_EQ(slurp(file), std::string(100000, static_cast<char>('a' + winner)));
  EXPECT_FALSE(createFileOnce(file, "later"));
  // Replaced whole while threads write it at once: always one writer's text, nothing left
  // beside it.
  threads.clear();
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back(
        [&, t] { replaceFileWhole(file, std::string(100000, static_cast<char>('a' + t))); });
  for (auto& t : threads) t.join();
  const std::string text = slurp(file);
  ASSERT_EQ(text.size(), 100000u);
  EXPECT_EQ(text, std::string(100000, text[0]));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1u);
}

TEST(DirLock, SharedHoldersCoexistAndExcludeAnExclusiveOneAndTheReverse) {
  TempDir dir("tribo_dir_lock_");
  fs::create_directories(dir.path());
  {
    DirLock a(dir.path(), DirLock::Mode::kShared);
    DirLock b(dir.path(), DirLock::Mode::kShared);
    EXPECT_THROW(DirLock c(dir.path()), DirLockedError);
  }
  {
    DirLock a(dir.path());
    EXPECT_THROW(DirLock b(dir.path(), DirLock::Mode::kShared), DirLockedError);
  }
  EXPECT_NO_THROW(DirLock again(dir.path(), DirLock::Mode::kShared));
}

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

TEST(SweepSlice, SlicesRunOnThreadsAtOnceEndWithTheFileOfTheWholeSweep) {
  TempDir dir("tribo_sweep_slices_");
  SweepSpec spec;
  spec.scene_path = kBelt;
  spec.fixed_overrides = {"dt=0.008", "output_interval=0.008", "duration=5"};
  spec.axes = {parseGridAxis("v_b=1:3:5"), parseListAxis("friction=roh_yoo,recurdyn")};
  const SweepPlan plan = planSweep(spec);
  const SweepReport whole = runSweepLocally(plan, dir / "whole", {1, nullptr, 0});
  ASSERT_TRUE(whole.complete);

  constexpr std::size_t kSlices = 4;
  std::vector<SliceReport> reports(kSlices);
  std::vector<std::thread> threads;
  for (std::size_t i = 1; i <= kSlices; ++i)
    threads.emplace_back([&, i] {
      reports[i - 1] = runSweepSlice(plan, dir / "sliced", {i, kSlices}, {1, nullptr, 0});
    });
  for (auto& t : threads) t.join();
  std::size_t ran = 0, written = 0;
  for (const auto& r : reports) {
    ran += r.slice.ran;
    written += r.results_written;
    EXPECT_TRUE(r.slice.complete);
  }
  EXPECT_EQ(ran, 10u);
  EXPECT_GE(written, 1u);
  EXPECT_EQ(slurp(dir / "sliced" / "results.csv"), slurp(dir / "whole" / "results.csv"));
  const MergeReport merged = mergeSweep(dir / "sliced");
  EXPECT_TRUE(merged.written);
  EXPECT_TRUE(merged.missing.empty());
  EXPECT_EQ(slurp(dir / "sliced" / "results.csv"), slurp(dir / "whole" / "results.csv"));
}

}  // namespace
}  // namespace tribo::study
