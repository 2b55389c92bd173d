// `tribo tradeoff` end to end on the belt scene, RK4 only, 10 s runs (about 1 s per tradeoff
// in Release): the CSV has the documented columns; every row's amplitude error is the
// distance of that setting's amplitude from a converged reference on the same sampling grid
// (both recomputed here with `tribo run`); steps past RK4's stability limit for the contact's
// vertical mode (computed here from the scene's parameters) are reported as failed, without
// numbers; RK4's errors fall like h^4 while the motion is smooth; bad input gives a clear
// message and a non-zero exit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_support.hpp"

namespace {

using namespace tribo::test;

// The belt scene's box and contact, set explicitly so that the stability limit below is that
// of the runs: 10 kg on four corners of 2.5e5 N/m and 1.5e3 N s/m each, started at its
// static depth z0 = 0.05 - m g / (4 k) (checked below).
constexpr double kMass = 10.0, kCornerStiffness = 2.5e5, kCornerDamping = 1.5e3, kG = 9.81;
constexpr double kZ0 = 0.0499019;
constexpr double kDuration = 10.0;  // [s] the box slips throughout (checked below)
const std::string kSettings =
    " --set duration=10 --set m=10 --set contact_stiffness=2.5e5 --set contact_damping=1.5e3"
    " --set z0=0.0499019";

// The columns of tradeoff.csv (docs/speed-accuracy.md; scripts/plot_work_precision.sh reads
// them by position).
constexpr const char* kHeader =
    "scene,integrator,setting,value,status,amplitude,amplitude_error,trajectory_error,"
    "wall_seconds,cpu_seconds,sim_seconds_per_cpu_second,steps,rejected_steps,force_evaluations,"
    "events,message";

// One CSV line split into fields ("..." quoting with "" for a quote).
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      out.back() += line[++i];
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

using Row = std::map<std::string, std::string>;

struct Csv {
  std::vector<std::string> header;
  std::vector<Row> rows;
};

Csv readCsv(const fs::path& file) {
  Csv csv;
  std::istringstream in(slurp(file));
  for (std::string line; std::getline(in, line);) {
    const auto f = fields(line);
    if (csv.header.empty()) {
      csv.header = f;
      continue;
    }
    EXPECT_EQ(f.size(), csv.header.size()) << line;
    Row r;
    for (std::size_t i = 0; i < f.size() && i < csv.header.size(); ++i) r[csv.header[i]] = f[i];
    csv.rows.push_back(r);
  }
  return csv;
}

// A figure; an empty field is a figure the run does not have (never the text "nan").
double number(const std::string& text) {
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  if (text.empty()) return std::nan("");
  std::size_t used = 0;
  const double v = std::stod(text, &used);
  EXPECT_EQ(used, text.size()) << text;
  return v;
}

// |R(h lambda)| of classical RK4 (R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24) for the box's
// vertical contact mode, x'' + (c/m) x' + (k/m) x = 0 with k, c of the four corners.
double rk4Growth(double h) {
  const double k_over_m = 4 * kCornerStiffness / kMass, c_over_m = 4 * kCornerDamping / kMass;
  const std::complex<double> lambda(-c_over_m / 2, std::sqrt(k_over_m - c_over_m * c_over_m / 4));
  const std::complex<double> z = h * lambda;
  return std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
}

// The largest step (to 1 us) at which that mode does not grow.
double rk4Limit() {
  double h = 0.0;
  while (rk4Growth(h + 1e-6) <= 1.0) h += 1e-6;
  return h;
}

nlohmann::json summaryOf(const fs::path& dir) {
  return nlohmann::json::parse(slurp(dir / "summary.json"));
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

class TradeoffCli : public CliTest {
 protected:
  TradeoffCli() : CliTest("tribo_tradeoff_cli_") {}

  // `tribo tradeoff SCENE` with RK4 over 10 s; its rows (the reference check first).
  Csv tradeoff(const std::string& scene) {
    const fs::path out = dir_ / "tradeoff";
    const Result r =
        runTribo("tradeoff " + scene + kSettings + " --integrators rk4 --out " + out.string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("results          " + (out / "tradeoff.csv").string()),
              std::string::npos)
        << r.output;
    return readCsv(out / "tradeoff.csv");
  }

  // The summary amplitude of `tribo run SCENE` at step `dt`, sampled every `interval`.
  double amplitude(const std::string& scene, double dt, double interval, const std::string& name) {
    const fs::path out = dir_ / name;
    const Result r =
        runTribo("run " + scene + kSettings + " --set dt=" + format(dt) +
                 " --set output_interval=" + format(interval) + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << r.output;
    return summaryOf(out).value("amplitude_pp", std::nan(""));
  }
};

TEST_F(TradeoffCli, RowsAreMeasuredAgainstTheConvergedReferenceAndUnstableStepsFail) {
  const Csv csv = tradeoff(kBelt);
  EXPECT_EQ(slurp(dir_ / "tradeoff" / "tradeoff.csv").substr(0, std::string(kHeader).size() + 1),
            std::string(kHeader) + "\n");
  ASSERT_GE(csv.rows.size(), 4u);

  // First row: the reference (rk4 at min(0.1 ms, limit / 8) = 0.1 ms) against half its step.
  const Row& check = csv.rows.front();
  EXPECT_EQ(check.at("status"), "reference");
  EXPECT_EQ(check.at("integrator"), "rk4");
  EXPECT_DOUBLE_EQ(number(check.at("value")), 0.5e-4);
  EXPECT_LT(number(check.at("amplitude_error")), 1e-9) << "the reference has not converged";

  const double limit = rk4Limit();
  ASSERT_NEAR(limit, 0.009, 0.0005);   // h w = 2.84 at w = 316 rad/s, damping ratio 0.95
  std::map<double, double> reference;  // output interval -> reference amplitude
  int above = 0, below = 0;
  for (std::size_t i = 1; i < csv.rows.size(); ++i) {
    const Row& row = csv.rows[i];
    SCOPED_TRACE("rk4 dt=" + row.at("value"));
    EXPECT_EQ(row.at("scene"), "belt");
    EXPECT_EQ(row.at("integrator"), "rk4");
    EXPECT_EQ(row.at("setting"), "dt");
    const double h = number(row.at("value"));
    // The documented ladder: 40 ms / n.
    EXPECT_NEAR(0.04 / h, std::round(0.04 / h), 1e-6);

    if (h > limit) {
      ++above;
      // Past the limit the contact mode grows by |R| per step: beyond a millionfold within
      // the run, the run must have been stopped; in any case it is not reported as complete.
      EXPECT_NE(row.at("status"), "complete");
      if (std::pow(rk4Growth(h), kDuration / h) > 1e6) {
        EXPECT_EQ(row.at("status"), "diverged");
      }
      if (row.at("status") == "diverged") {
        for (const char* col : {"amplitude", "amplitude_error", "trajectory_error"})
          EXPECT_TRUE(std::isnan(number(row.at(col)))) << col << " " << row.at(col);
        EXPECT_NE(row.at("message").find("diverged at step"), std::string::npos)
            << row.at("message");
      } else {
        EXPECT_EQ(row.at("status"), "warned");
        EXPECT_NE(row.at("message").find("exceeds the estimated stability limit"),
                  std::string::npos)
            << row.at("message");
      }
      continue;
    }
    ++below;
    ASSERT_EQ(row.at("status"), "complete") << row.at("message");
    // The same setting run on its own (sampled as tradeoff samples it: every step, at least
    // 1 ms apart) gives the row's amplitude ...
    const double interval = std::max(0.001, h);
    const double a = number(row.at("amplitude"));
    const double a_run = amplitude(kBelt, h, interval, "run_" + row.at("value"));
    EXPECT_NEAR(a, a_run, 1e-8 * a_run);
    // ... and its error is the distance from the 0.1 ms reference sampled on the same grid.
    if (!reference.count(interval))
      reference[interval] = amplitude(kBelt, 1e-4, interval, "reference_" + format(interval));
    const double a_ref = reference[interval];
    const double expected = std::abs(a_run - a_ref) / a_ref;
    EXPECT_NEAR(number(row.at("amplitude_error")), expected, 1e-3 * expected + 1e-13)
        << "amplitude " << a_run << ", reference " << a_ref;
    EXPECT_TRUE(std::isfinite(number(row.at("trajectory_error"))));
  }
  EXPECT_GE(above, 1) << "the ladder should reach past the stability limit";
  EXPECT_GE(below, 4);
}

// RK4 is fourth order where the right-hand side is smooth. The box starts at its static
// depth: started just touching (z = 0.05), its contact would close inside the first step,
// where the penalty force jumps by c d' (contact closing is not event-located), one O(h^2)
// error that made the whole run second order (measured: errors fell 4.1-4.8 times per
// halving). With the box slipping throughout the 10 s (no stick), the errors must fall
// 2^4 = 16 times per halving: observed order 4 +- 0.5.
TEST_F(TradeoffCli, Rk4ErrorsFallLikeTheFourthPowerOfTheStepWhileTheMotionIsSmooth) {
  ASSERT_NEAR(kZ0, 0.05 - kMass * kG / (4 * kCornerStiffness), 1e-12);
  fs::create_directories(dir_);
  const std::string scene = kBelt;
  const Result premise =
      runTribo("run " + scene + kSettings + " --out " + (dir_ / "premise").string());
  ASSERT_EQ(premise.status, 0) << premise.output;
  EXPECT_EQ(summaryOf(dir_ / "premise").value("stuck_fraction", -1.0), 0.0)
      << "the box sticks within the window: the friction law's kink is crossed";

  const Csv csv = tradeoff(scene);
  std::map<double, Row> by_step;
  for (std::size_t i = 1; i < csv.rows.size(); ++i)
    by_step[number(csv.rows[i].at("value"))] = csv.rows[i];
  const double reference_error = number(csv.rows.front().at("amplitude_error"));
  for (const double h : {0.004, 0.002}) {
    ASSERT_TRUE(by_step.count(h) && by_step.count(h / 2)) << "no rows for " << h << ", " << h / 2;
    for (const char* col : {"amplitude_error", "trajectory_error"}) {
      const double coarse = number(by_step[h].at(col)), fine = number(by_step[h / 2].at(col));
      ASSERT_EQ(by_step[h].at("status"), "complete");
      ASSERT_EQ(by_step[h / 2].at("status"), "complete");
      EXPECT_GT(fine, 1e3 * reference_error) << col << ": the reference cannot resolve it";
      const double order = std::log2(coarse / fine);
      EXPECT_NEAR(order, 4.0, 0.5)
          << col << " at dt " << h << " -> " << h / 2 << ": " << coarse << " -> " << fine;
    }
  }
}

TEST_F(TradeoffCli, BadInputGivesAClearMessageAndNonZeroExitAndWritesNothing) {
  const std::string out = " --out " + dir_.string();
  const Result help = runTribo("tradeoff --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("Usage: tribo tradeoff"), std::string::npos) << help.output;
  struct Case {
    std::string args;
    int status;
    std::string expected;
  };
  for (const Case& c : {
           Case{"tradeoff" + out, 1, "SCENE is required"},
           Case{"tradeoff " + kBelt + out + " --integrators rk5", 1, "unknown integrator 'rk5'"},
           Case{"tradeoff " + kBelt + out + " --integrators ''", 1, "--integrators"},
           Case{"tradeoff " + kBelt + out + " --window abc", 1,
                "--window: expected a positive number, found 'abc'"},
           Case{"tradeoff " + kBelt + out + " --window -1", 1, "--window"},
           Case{"tradeoff " + kBelt + out + " --repeat 1.5", 1, "--repeat"},
           Case{"tradeoff " + kBelt + out + " --frobnicate", 1, "unknown option '--frobnicate'"},
           Case{"tradeoff " + kBelt + out + " --set nope=1", 2, "unknown parameter 'nope'"},
           Case{"tradeoff /nonexistent/scene.yaml" + out, 2, "/nonexistent/scene.yaml"},
       }) {
    const Result r = runTribo(c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("tribo tradeoff: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir_)) << c.args;
  }
  // An output folder below a file: the runs are done, the table cannot be written.
  fs::create_directories(dir_);
  std::ofstream(dir_ / "file") << "x";
  const Result unwritable =
      runTribo("tradeoff " + kBelt + " --set duration=1 --integrators rk4 --out " +
               (dir_ / "file" / "t").string());
  EXPECT_EQ(unwritable.status, 4) << unwritable.output;
  EXPECT_NE(unwritable.output.find((dir_ / "file").string()), std::string::npos)
      << unwritable.output;
}

}  // namespace
