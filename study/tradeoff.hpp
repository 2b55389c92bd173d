// The speed-accuracy trade of a scene, measured (`tribo tradeoff`).
//
// Runs every integrator over a ladder of settings, fixed steps G/n (G = 40 ms, n = 2 .. 640,
// continued by doubling n while fewer than two rungs lie at or below the limit; those
// between limit/64 and 2.5 limit of the a-priori stability estimate) for
// semi_implicit_euler and rk4, tolerances rtol = 1e-3 .. 1e-8 (atol = 1e-3 rtol) at a
// 10 ms communication interval for dopri5 and bdf (with and without event location), and
// compares each run with a converged reference (rk4 at a step of at most limit/8 and
// 0.1 ms, checked against half that step):
//   amplitude error   |A - A_ref| / A_ref of the summary's limit-cycle amplitude, A_ref from
//                     the reference sampled at the run's own output interval (the same
//                     estimator on the same grid, so sampling does not count as error);
//   trajectory error  max |x(t_k) - x_ref(t_k)| / A_ref over t_k = k G <= window (10 s) of
//                     the summary coordinate (cubic Hermite in x and its velocity between
//                     samples; exact on the sample times, which the ladder is chosen to hit);
// against its cost: processor time of the run (stepping, recording, summary) and wall time of
// the stepping, each the least of `repeat` runs. Every setting reaches the run through
// io::RunSettings (the scene is loaded again with it), never by editing a built model.
// Not here: argument parsing and the printed table (apps/tradeoff_command.cpp), the plot
// (scripts/plot_work_precision.sh).
#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model.hpp"

namespace tribo::study {

struct TradeoffSpec {
  std::string scene_path;
  std::vector<std::string> overrides;  // NAME=VALUE, as --set
  std::vector<IntegratorType> integrators = {IntegratorType::kSemiImplicitEuler,
                                             IntegratorType::kRk4, IntegratorType::kDopri5,
                                             IntegratorType::kBdf};
  double window = 10.0;  // [s] of the trajectory error
  int repeat = 1;        // runs per setting; the least time counts
};

struct TradeoffSetting {
  IntegratorType integrator = IntegratorType::kRk4;
  bool events = true;
  double step = 0.0;  // fixed-step methods [s]
  double rtol = 0.0;  // adaptive methods
  // "rk4", "dopri5_noevents", ...
  std::string label() const;
  // "dt" or "rtol", and its value.
  const char* valueName() const;
  double value() const;
};

struct TradeoffRow {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  TradeoffSetting setting;
  std::string status;  // complete | warned | diverged | reference
  std::string message;
  double amplitude = kNaN, amplitude_error = kNaN, trajectory_error = kNaN;
  double wall = kNaN, cpu = kNaN, simulated = 0.0;
  long steps = 0, rejected = 0, evaluations = 0, events = 0;
};

struct TradeoffResult {
  TradeoffSetting reference;      // the converged reference's setting
  std::vector<TradeoffRow> rows;  // first the reference at half its step ("reference")
};

// The reference itself did not complete: no error can be measured against it.
class TradeoffReferenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The ladder of settings for the scene (fixed steps inside the stability window).
std::vector<TradeoffSetting> tradeoffLadder(const TradeoffSpec& spec);

// Measures every setting of the ladder. `on_reference` hears the reference's setting once it
// has run; `on_row` each row as it is measured (progress). Throws io::SceneError for a bad
// scene or one that observes no body, TradeoffReferenceError when the reference fails.
TradeoffResult measureTradeoff(const TradeoffSpec& spec,
                               const std::function<void(const TradeoffSetting&)>& on_reference = {},
                               const std::function<void(const TradeoffRow&)>& on_row = {});

// The cheapest (processor time) complete run without a stability warning whose amplitude
// error (and trajectory error, when `both`) is at most `target`; nullptr when none is.
const TradeoffRow* cheapestRow(const std::vector<TradeoffRow>& rows, double target, bool both);

// One field of a row as tradeoff.csv and the Python module's tradeoff() give it: a number
// (the file keeps `digits` significant digits; non-finite is an empty field), a count or a
// text. The one place the columns are named.
struct TradeoffField {
  enum class Kind { kNumber, kCount, kText };
  const char* name;
  Kind kind;
  double number = 0.0;
  long count = 0;
  std::string text;
  int digits = 6;
};

// The fields of one row, in column order (the header is their names).
std::vector<TradeoffField> tradeoffFields(const std::string& scene_name, const TradeoffRow& row);

// DIR/tradeoff.csv: one row per run (the fields above), written whole or not at all
// (study/file_commit.hpp). Throws std::runtime_error naming the file on failure.
void writeTradeoffCsv(const std::filesystem::path& file, const std::string& scene_name,
                      const std::vector<TradeoffRow>& rows);

}  // namespace tribo::study
