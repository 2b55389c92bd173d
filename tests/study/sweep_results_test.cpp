// The results folder of a sweep: row format, reading back an interrupted run (dropping a
// line cut off by a kill), refusing another sweep's folder, the lock, and the final rewrite
// in point order.
#include "study/sweep/sweep_results.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tribo::study {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class SweepResults : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tribo_sweep_results_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static PointOutcome complete(double amplitude) {
    PointOutcome o;
    o.status = PointStatus::kComplete;
    o.amplitude_pp = amplitude;
    o.period = 1.25;
    o.cycles = 7;
    o.simulated = 30;
    o.settled = true;
    return o;
  }

  fs::path dir_;
  SweepGrid grid_{{parseListAxis("a=1,2"), parseListAxis("b=x,y")}};
};

TEST_F(SweepResults, RowsHoldParametersFiguresAndQuotedText) {
  const auto columns = sweepColumns(grid_);
  ASSERT_GE(columns.size(), 6u);
  EXPECT_EQ(columns[0], "point");
  EXPECT_EQ(columns[1], "a");
  EXPECT_EQ(columns[2], "b");
  EXPECT_EQ(columns[3], "status");
  const std::string row = formatSweepRow(3, grid_, complete(0.5));
  EXPECT_EQ(row.back(), '\n');
  const auto f = splitCsvLine(row.substr(0, row.size() - 1));
  ASSERT_EQ(f.size(), columns.size());
  EXPECT_EQ(f[0], "3");
  EXPECT_EQ(f[1], "2");
  EXPECT_EQ(f[2], "y");
  EXPECT_EQ(f[3], "complete");
  EXPECT_EQ(f[4], "0.5");

  PointOutcome failed;
  failed.status = PointStatus::kError;
  failed.message = "belt.yaml:3: mu_s must exceed mu_k, found \"0.3\", 0.35\nsecond line";
  const std::string bad = formatSweepRow(0, grid_, failed);
  EXPECT_EQ(std::count(bad.begin(), bad.end(), '\n'), 1);  // one line per point
  const auto g = splitCsvLine(bad.substr(0, bad.size() - 1));
  ASSERT_EQ(g.size(), columns.size());
  EXPECT_EQ(g[3], "error");
  EXPECT_EQ(g[4], "");  // no figures for a failed point, never NaN
  EXPECT_EQ(g.back(), "belt.yaml:3: mu_s must exceed mu_k, found \"0.3\", 0.35 second line");
  EXPECT_TRUE(splitCsvLine("1,\"open").empty());
}

TEST_F(SweepResults, ResumeKeepsCompleteLinesDropsTheCutOffOneAndSortsAtTheEnd) {
  const std::string manifest = "{\"sweep\": 1}\n";
  {
    SweepResultsFile f(dir_, manifest, grid_);
    EXPECT_EQ(f.doneCount(), 0u);
    f.append(2, formatSweepRow(2, grid_, complete(0.2)));
    f.append(0, formatSweepRow(0, grid_, complete(0.0)));
  }
  // A kill in the middle of writing point 3's line.
  const std::string cut = formatSweepRow(3, grid_, complete(0.3));
  std::ofstream(dir_ / "results.csv", std::ios::app) << cut.substr(0, cut.size() / 2);

  SweepResultsFile f(dir_, manifest, grid_);
  EXPECT_EQ(f.doneCount(), 2u);
  EXPECT_EQ(f.droppedLines(), 1u);
  EXPECT_TRUE(f.done()[0]);
  EXPECT_FALSE(f.done()[1]);
  EXPECT_TRUE(f.done()[2]);
  EXPECT_FALSE(f.done()[3]);
  f.append(3, formatSweepRow(3, grid_, complete(0.3)));
  f.append(1, formatSweepRow(1, grid_, complete(0.1)));
  f.append(1, formatSweepRow(1, grid_, complete(9.9)));  // a point is recorded once
  f.finish();

  std::string expected;
  for (const auto& c : sweepColumns(grid_)) {
    if (!expected.empty()) expected += ',';
    expected += c;
  }
  expected += '\n';
  for (int i = 0; i < 4; ++i) expected += formatSweepRow(i, grid_, complete(0.1 * i));
  EXPECT_EQ(slurp(dir_ / "results.csv"), expected);
  EXPECT_EQ(slurp(dir_ / "sweep.json"), manifest);
}

TEST_F(SweepResults, LinesOfAnotherGridAreDropped) {
  const std::string manifest = "{}\n";
  { SweepResultsFile f(dir_, manifest, grid_); }
  std::ofstream(dir_ / "results.csv", std::ios::app)
      << "1,1,z,complete,1,,,,,,,,,,,,\n"   // b=z is not point 1's value
      << "9,2,y,complete,1,,,,,,,,,,,,\n";  // no point 9
  SweepResultsFile f(dir_, manifest, grid_);
  EXPECT_EQ(f.doneCount(), 0u);
  EXPECT_EQ(f.droppedLines(), 2u);
}

TEST_F(SweepResults, AnotherSweepsFolderIsRefusedAndALockedOneToo) {
  {
    SweepResultsFile f(dir_, "{\"scene\": \"a.yaml\"}\n", grid_);
    try {
      SweepResultsFile g(dir_, "{\"scene\": \"a.yaml\"}\n", grid_);
      ADD_FAILURE() << "a locked folder was opened twice";
    } catch (const SweepOutputError& e) {
      EXPECT_EQ(e.reason(), SweepOutputError::Reason::kInUse);
      EXPECT_NE(std::string(e.what()).find(dir_.string()), std::string::npos);
    }
  }
  try {
    SweepResultsFile f(dir_, "{\"scene\": \"b.yaml\"}\n", grid_);
    ADD_FAILURE() << "another sweep's folder was resumed";
  } catch (const SweepOutputError& e) {
    EXPECT_EQ(e.reason(), SweepOutputError::Reason::kOtherSweep);
    EXPECT_NE(std::string(e.what()).find("different sweep"), std::string::npos) << e.what();
  }
}

TEST_F(SweepResults, UnwritableFolderIsAnOutputError) {
  std::ofstream(dir_.string()) << "a file, not a folder";
  try {
    SweepResultsFile f(dir_ / "sub", "{}\n", grid_);
    ADD_FAILURE() << "wrote below a file";
  } catch (const SweepOutputError& e) {
    EXPECT_EQ(e.reason(), SweepOutputError::Reason::kCannotWrite);
    EXPECT_NE(std::string(e.what()).find("sub"), std::string::npos) << e.what();
  }
  fs::remove(dir_);
}

}  // namespace
}  // namespace tribo::study
