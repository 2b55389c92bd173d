// A run's output when it is streamed rather than kept: the spilled columns read back what
// was appended, the oscillation analysis gives the same bits from a spill as from memory,
// a streamed run writes the rows a kept run holds, a stop request ends the run at an output
// row, the output budget refuses what would not fit and names the keys, a locked folder
// refuses a second writer, and a streamed trajectory's rows are their numbers' text.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <ostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/csv_text.hpp"
#include "study/dir_lock.hpp"
#include "study/oscillation_summary.hpp"
#include "study/output_budget.hpp"
#include "study/result_writer.hpp"
#include "study/scene_run.hpp"
#include "study/series_spill.hpp"

namespace tribo::study {
namespace {

namespace fs = std::filesystem;
const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tribo_run_output_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(SpilledColumn, ReadsBackEveryValueInAnyOrderAndLeavesNoFile) {
  const fs::path dir = freshDir("spill");
  SpilledColumn c(dir);
  const std::size_t n = 100'003;  // pages of 8192: a partial last page stays in memory
  for (std::size_t i = 0; i < n; ++i) c.append(std::sin(0.001 * static_cast<double>(i)) + i);
  ASSERT_EQ(c.size(), n);
  for (std::size_t i = 0; i < n; i += 7)
    ASSERT_EQ(c.at(i), std::sin(0.001 * static_cast<double>(i)) + i) << i;
  for (std::size_t i = n; i-- > 0;)  // backwards, through every cache slot
    ASSERT_EQ(c.at(i), std::sin(0.001 * static_cast<double>(i)) + i) << i;
  EXPECT_TRUE(fs::is_empty(dir));  // unlinked at creation
  fs::remove_all(dir);
}

// A record in memory behind SampleSeries (the analysis must not care where samples live).
class VectorSeries : public SampleSeries {
 public:
  explicit VectorSeries(const std::vector<double>& v) : v_(v) {}
  std::size_t size() const override { return v_.size(); }
  double at(std::size_t i) const override { return v_[i]; }

 private:
  const std::vector<double>& v_;
};

TEST(OscillationSummaryFromSeries, SameBitsAsFromMemoryAndTheSignalsAmplitude) {
  // A growing, then steady oscillation of amplitude 0.5 (p-p 1) over 50 000 samples (many
  // integral strides), with a slip channel half the time below the stick speed.
  std::vector<double> t, x, slip;
  for (int i = 0; i < 50'000; ++i) {
    const double ti = 0.01 * i;
    t.push_back(ti);
    x.push_back(0.5 * (1 - std::exp(-ti / 20)) * std::sin(2 * std::numbers::pi * ti / 1.3) + 2);
    slip.push_back(std::abs(std::cos(2 * std::numbers::pi * ti / 1.3)));
  }
  const OscillationSummary a = summarizeOscillation(t, x, slip);
  const VectorSeries ts(t), xs(x), ss(slip);
  const OscillationSummary b = summarizeOscillation(ts, xs, &ss);
  EXPECT_NEAR(b.amplitude_pp, 1.0, 1e-6);
  EXPECT_NEAR(b.period, 1.3, 1e-6);
  EXPECT_NEAR(b.x_mean, 2.0, 1e-4);
  EXPECT_EQ(a.amplitude_pp, b.amplitude_pp);
  EXPECT_EQ(a.period, b.period);
  EXPECT_EQ(a.time_to_98, b.time_to_98);
  EXPECT_EQ(a.stuck_fraction, b.stuck_fraction);
  EXPECT_EQ(a.x_mean, b.x_mean);
  ASSERT_EQ(a.cycles.size(), b.cycles.size());
  for (std::size_t i = 0; i < a.cycles.size(); ++i) EXPECT_EQ(a.cycles[i].mean, b.cycles[i].mean);
  // No cycle: a ramp; figures over the last half of the record.
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 3 * t[i];
  const OscillationSummary c = summarizeOscillation(ts, xs, nullptr);
  EXPECT_FALSE(c.oscillating);
  EXPECT_NEAR(c.amplitude_pp, 3 * (t.back() - t.back() / 2), 0.03 + 1e-9);
  EXPECT_NEAR(c.x_mean, 3 * 0.75 * t.back(), 1e-6);
  EXPECT_EQ(c.x_mean, summarizeOscillation(t, x, {}).x_mean);
}

// Collects streamed rows.
struct Rows : RowSink {
  std::vector<std::vector<double>> rows;
  void row(std::span<const double> v) override { rows.emplace_back(v.begin(), v.end()); }
};

TEST(StreamedRun, WritesTheRowsAKeptRunHoldsAndTheSameSummary) {
  const io::Scene scene = io::loadScene(kBelt, {"duration=4"});
  const RunResult kept = runScene(scene);
  Rows rows;
  RunOptions options;
  options.sink = &rows;
  const fs::path dir = freshDir("streamed");
  options.spill_dir = dir;
  const RunResult streamed = runScene(scene, options);
  ASSERT_TRUE(kept.complete);
  ASSERT_TRUE(streamed.complete);
  EXPECT_FALSE(streamed.trajectory.keepsRows());
  EXPECT_EQ(streamed.trajectory.column(0).size(), 0u);  // nothing kept
  ASSERT_EQ(rows.rows.size(), kept.trajectory.rows());
  EXPECT_EQ(streamed.trajectory.rows(), kept.trajectory.rows());
  for (std::size_t r = 0; r < rows.rows.size(); r += 97)
    for (std::size_t c = 0; c < rows.rows[r].size(); ++c)
      ASSERT_EQ(rows.rows[r][c], kept.trajectory.column(c)[r]) << r << " " << c;
  EXPECT_TRUE(kept.summary.oscillating);
  EXPECT_EQ(streamed.summary.amplitude_pp, kept.summary.amplitude_pp);
  EXPECT_EQ(streamed.summary.period, kept.summary.period);
  EXPECT_EQ(streamed.summary.stuck_fraction, kept.summary.stuck_fraction);
  EXPECT_EQ(streamed.summary.x_mean, kept.summary.x_mean);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

// output.summary: {channel: ...} alone (no body) is analysed in a streamed run (tribo run)
// as in a kept one (Python's Scene.run), and a coordinate observed as a channel gives the
// figures it gives observed as {body, coordinate}, less the stuck fraction (no body, no
// slip). Over a stick-slip box (position and velocity), a free pendulum and a double
// pendulum's joint angles.
struct ChannelCase {
  const char* scene;
  const char* channel;
  const char* body;  // the same coordinate as {body, coordinate: x}, or nullptr
  const char* duration;
};

// Names the case (scene and channel), for the test's name and its folder.
std::string caseName(const ChannelCase& c) {
  std::string name = std::string(c.scene) + "_" + c.channel;
  for (char& ch : name)
    if (ch == '.') ch = '_';
  return name;
}
void PrintTo(const ChannelCase& c, std::ostream* os) { *os << caseName(c); }

class ChannelSummary : public ::testing::TestWithParam<ChannelCase> {};

TEST_P(ChannelSummary, StreamedEqualsKeptAndTheBodysFigures) {
  const ChannelCase c = GetParam();
  io::Scene scene = io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/" + c.scene,
                                  {std::string("duration=") + c.duration});
  const io::SummarySpec by_body = scene.output.summary;
  if (!io::hasGroup(scene.output.channels, "joints")) scene.output.channels.push_back("joints");
  scene.output.summary.body.clear();
  scene.output.summary.channel = c.channel;
  const RunResult kept = runScene(scene);
  Rows rows;
  RunOptions options;
  options.sink = &rows;
  // A folder of its own: ctest runs the cases side by side, and each clears its folder.
  const fs::path dir = freshDir("channel_" + caseName(c));
  options.spill_dir = dir;
  const RunResult streamed = runScene(scene, options);
  ASSERT_TRUE(kept.complete && streamed.complete);
  EXPECT_TRUE(kept.summary.oscillating) << c.channel;
  EXPECT_GE(kept.summary.cycles.size(), 3u) << c.channel;
  EXPECT_EQ(streamed.summary.cycles.size(), kept.summary.cycles.size());
  EXPECT_EQ(streamed.summary.amplitude_pp, kept.summary.amplitude_pp);
  EXPECT_EQ(streamed.summary.period, kept.summary.period);
  EXPECT_EQ(streamed.summary.x_mean, kept.summary.x_mean);
  EXPECT_EQ(streamed.summary.stuck_fraction, kept.summary.stuck_fraction);
  if (c.body != nullptr) {
    scene.output.summary = by_body;
    const RunResult body = runScene(scene);
    EXPECT_EQ(kept.summary.amplitude_pp, body.summary.amplitude_pp);
    EXPECT_EQ(kept.summary.period, body.summary.period);
    EXPECT_EQ(kept.summary.cycles.size(), body.summary.cycles.size());
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ChannelSummary,
                         ::testing::Values(ChannelCase{"belt.yaml", "box.x", "box", "6"},
                                           ChannelCase{"belt.yaml", "box.vx", nullptr, "6"},
                                           ChannelCase{"pendulum.yaml", "pivot.q", nullptr, "20"},
                                           ChannelCase{"double_pendulum.yaml", "elbow.q", nullptr,
                                                       "20"}));

// output.digits: 17 significant digits write every double exactly (strtod gives back the
// same bits); the default 10 do not. Over the belt's positions, speeds and forces.
TEST(TrajectoryCsv, SeventeenDigitsGiveBackEveryBit) {
  const io::Scene scene = io::loadScene(kBelt, {"duration=0.5", "output.digits=17"});
  EXPECT_EQ(scene.output.digits, 17);
  const RunResult kept = runScene(scene);
  ASSERT_TRUE(kept.complete);
  const fs::path dir = freshDir("digits");
  for (const int digits : {17, 10}) {
    const fs::path file = dir / ("t" + std::to_string(digits) + ".csv");
    writeTrajectoryCsv(file, kept.trajectory, digits);
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);  // header
    std::size_t row = 0, differ = 0;
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string field;
      for (std::size_t c = 0; std::getline(fields, field, ','); ++c)
        differ += std::strtod(field.c_str(), nullptr) != kept.trajectory.column(c)[row];
      ++row;
    }
    EXPECT_EQ(row, kept.trajectory.rows());
    if (digits == 17)
      EXPECT_EQ(differ, 0u);
    else
      EXPECT_GT(differ, 0u);  // 10 digits round
  }
  fs::remove_all(dir);
  for (const char* bad : {"output.digits=18", "output.digits=0", "output.digits=2.5"}) {
    try {
      (void)io::loadScene(kBelt, {bad});
      ADD_FAILURE() << bad << " was accepted";
    } catch (const io::SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("output.digits"), std::string::npos) << e.what();
    }
  }
}

// TrajectoryCsvFile's rows (one write a row): each row is its numbers' text (csvNumber, to the
// file's digits; a non-finite number an empty field) joined by commas, under the header: rows
// of 1, 3 and 20 801 columns (wider than a 1600-box run's 12 809), numbers of every size and
// sign, subnormal and non-finite ones, at 10 and 17 digits, written while a second thread runs.
TEST(TrajectoryCsv, EachRowIsItsNumbersTextJoinedByCommas) {
  const fs::path dir = freshDir("rows");
  std::atomic<bool> stop{false};
  std::thread other([&] {
    while (!stop.load()) std::this_thread::yield();
  });
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::vector<double>> rows = {
      {0.5},
      {-1.0 / 3.0, 6.02214076e23, 4.9e-324},
      {std::nan(""), inf, -inf},
      {1e-310, -0.0, 123456789.123456789},
  };
  std::vector<double> wide(20801);
  for (std::size_t c = 0; c < wide.size(); ++c)
    wide[c] = std::sin(0.37 * static_cast<double>(c)) *
              std::pow(10.0, static_cast<double>(c % 41) - 20.0);
  for (const int digits : {10, 17}) {
    const fs::path file = dir / ("rows" + std::to_string(digits) + ".csv");
    std::string expected = "a,b\n";
    {
      TrajectoryCsvFile csv(file, {"a", "b"}, digits);
      auto add = [&](std::span<const double> values) {
        csv.row(values);
        for (std::size_t c = 0; c < values.size(); ++c) {
          if (c > 0) expected += ',';
          expected += csvNumber(values[c], digits);
        }
        expected += '\n';
      };
      for (const std::vector<double>& r : rows) add(r);
      add(wide);
      add(wide);
      csv.commit();
    }
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().size(), expected.size()) << digits << " digits";
    EXPECT_TRUE(text.str() == expected) << digits << " digits: the file differs";
  }
  stop = true;
  other.join();
  fs::remove_all(dir);
}

TEST(StreamedRun, AStopRequestEndsTheRunBackAtTheLastOutputRow) {
  // Output every 10 steps; the stop comes at the first progress call (after 64 steps),
  // mid-interval: the run goes back to the row at 60 steps.
  const io::Scene scene =
      io::loadScene(kBelt, {"duration=1000", "dt=0.001", "output_interval=0.01"});
  std::atomic<bool> stop{false};
  Rows rows;
  RunOptions options;
  options.sink = &rows;
  options.stop = &stop;
  options.progress_interval = 0.0;
  int calls = 0;
  options.progress = [&](double) {
    ++calls;
    stop = true;
  };
  const RunResult r = runScene(scene, options);
  EXPECT_FALSE(r.complete);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(calls, 1);
  ASSERT_EQ(rows.rows.size(), 7u);                      // t = 0, 0.01, ..., 0.06
  EXPECT_EQ(rows.rows.back()[0], r.simulated_seconds);  // the last row is the last state
  EXPECT_NEAR(r.simulated_seconds, 0.06, 1e-12);
  EXPECT_NE(r.message.find("interrupted at t = "), std::string::npos) << r.message;
  // Those rows are an uninterrupted run's, bit for bit.
  const RunResult full =
      runScene(io::loadScene(kBelt, {"duration=0.1", "dt=0.001", "output_interval=0.01"}));
  ASSERT_TRUE(full.complete);
  for (std::size_t row = 0; row < rows.rows.size(); ++row)
    for (std::size_t c = 0; c < rows.rows[row].size(); ++c)
      ASSERT_EQ(rows.rows[row][c], full.trajectory.column(c)[row]) << row << " " << c;
}

TEST(StreamedRun, AStopRequestEndsALongStepOfTheAdaptiveIntegratorsInsideIt) {
  // One step (one output interval) of 1000 s of the belt: minutes of internal steps for bdf
  // and dopri5. The request comes from another thread while the first step runs; the run
  // gives it up and ends at its only row, t = 0.
  for (const std::string integrator : {"bdf", "dopri5"}) {
    const io::Scene scene = io::loadScene(
        kBelt, {"integrator=" + integrator, "duration=1000", "dt=1000", "output_interval=1000"});
    std::atomic<bool> stop{false};
    Rows rows;
    RunOptions options;
    options.sink = &rows;
    options.stop = &stop;
    std::thread raise([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      stop = true;
    });
    const RunResult r = runScene(scene, options);
    raise.join();
    EXPECT_TRUE(r.interrupted) << integrator;
    EXPECT_FALSE(r.complete);
    ASSERT_EQ(rows.rows.size(), 1u) << integrator;
    EXPECT_EQ(r.simulated_seconds, 0.0);
    EXPECT_EQ(rows.rows.back()[0], 0.0);
  }
}

TEST(OutputBudget, RefusesWhatWouldNotFitAndNamesTheKeys) {
  const io::Scene huge = io::loadScene(kBelt, {"duration=1e12", "dt=1"});
  const OutputEstimate e = estimateOutput(huge);
  EXPECT_DOUBLE_EQ(e.rows, 1e12 / 1.0 + 2);  // output.interval 1 ms < step: every step
  EXPECT_EQ(e.columns, 1 + 2 * 8);           // the belt and the box
  try {
    checkOutputFitsDisk(huge, fs::temp_directory_path() / "tribo_no_such_folder" / "out");
    ADD_FAILURE() << "1e12 rows fit the disk";
  } catch (const OutputTooLarge& x) {
    const std::string m = x.what();
    EXPECT_NE(m.find("output.interval"), std::string::npos) << m;
    EXPECT_NE(m.find("duration 1e+12 s"), std::string::npos) << m;
    EXPECT_NE(m.find("free in '"), std::string::npos) << m;
  }
  EXPECT_THROW(checkOutputFitsMemory(huge), OutputTooLarge);
  // A kept run checks before it allocates anything.
  EXPECT_THROW(runScene(huge), OutputTooLarge);
  const io::Scene small = io::loadScene(kBelt, {"duration=3"});
  EXPECT_NO_THROW(checkOutputFitsDisk(small, fs::temp_directory_path()));
  EXPECT_NO_THROW(checkOutputFitsMemory(small));
}

TEST(DirLock, ASecondLockOnTheFolderIsRefusedUntilTheFirstIsGone) {
  const fs::path dir = freshDir("lock");
  {
    DirLock first(dir);
    EXPECT_THROW(DirLock second(dir), DirLockedError);
  }
  EXPECT_NO_THROW(DirLock again(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribo::study
