// One point of a sweep: the scene loaded with the sweep's fixed overrides and then the
// point's values, run (until its oscillation settles, if asked: study/sweep/sweep_settle.hpp), and
// reduced to the figures of one results row. Never throws for a bad point: a scene error
// (e.g. mu_s <= mu_k at this point) or a diverged run comes back as a status with its
// message, so the sweep goes on. Independent points share nothing mutable, so points may
// run on any number of threads at once.
// Not here: the grid (study/sweep/sweep_grid.hpp), the results file
// (study/sweep/sweep_results.hpp).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "friction/name_table.hpp"
#include "study/sweep/sweep_settle.hpp"

namespace tribo::friction {
class FrictionLaw;
}
namespace tribo::io {
class SceneDocument;
}

namespace tribo::study {

// What a point computes: a run of the scene (the oscillation figures), the linear
// stability of its steady state (study/modes/modes.hpp: largest growth rate, its frequency, the
// number of unstable modes; milliseconds instead of a simulation), or its periodic orbit
// (study/orbit/periodic_orbit.hpp: period, amplitude, stability; a forced scene's orbit has the
// forcing's period, so a sweep of the forcing frequency is a frequency-response curve).
enum class SweepAnalysis { kRun, kModes, kOrbit };
inline constexpr NameTable<SweepAnalysis, 3> kSweepAnalysisNames{
    "analysis",
    {{{SweepAnalysis::kRun, "run"},
      {SweepAnalysis::kModes, "modes"},
      {SweepAnalysis::kOrbit, "orbit"}}}};

// What every point of one sweep shares.
struct SweepSetup {
  std::string scene_path;                    // for messages and Scene::path
  std::string scene_text;                    // the scene's YAML, read once for all points
  std::vector<std::string> fixed_overrides;  // NAME=VALUE (--set), applied before the point's
  std::optional<SettleRule> settle;          // run each point until settled (duration: cap)
  SweepAnalysis analysis = SweepAnalysis::kRun;
  // Laws the caller adds (io::UserLaws: the Python module's laws written in Python, which a
  // material's `friction:` may select); empty for the command line.
  std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> user_laws = {};
};

enum class PointStatus { kComplete, kDiverged, kError };
inline constexpr NameTable<PointStatus, 3> kPointStatusNames{"point status",
                                                             {{{PointStatus::kComplete, "complete"},
                                                               {PointStatus::kDiverged, "diverged"},
                                                               {PointStatus::kError, "error"}}}};

// The row figures of one point. Figures are meaningful only for kComplete.
struct PointOutcome {
  PointStatus status = PointStatus::kError;
  double amplitude_pp = 0;    // as OscillationSummary
  double period = 0;          // [s]
  double time_to_98 = 0;      // [s]
  double rise_time = 0;       // time_to_98 refined: when the cycles' peak-to-peak crosses
                              // 98% of amplitude_pp, linear between the ends of the cycles
                              // around the crossing [s]; smooth in the parameters, unlike
                              // time_to_98, which moves in whole periods
  double stuck_fraction = 0;  // [-]
  double x_mean = 0;          // mean of the observed coordinate over the last cycles
  double first_pp = 0;        // peak-to-peak of the first cycle (the start of the growth)
  int cycles = 0;             // cycles detected over the whole run
  double simulated = 0;       // simulated time actually run [s]
  bool settled = false;       // the run stopped because its oscillation settled
  // SweepAnalysis::kModes only: the leading mode and the count of growing ones.
  double max_growth_rate = 0;   // [1/s]
  double growth_frequency = 0;  // of the leading mode [Hz]
  int unstable_modes = 0;
  // SweepAnalysis::kOrbit only (with amplitude_pp and period above): the orbit's extremes of
  // the observed coordinate, its largest multiplier's modulus (the trivial one aside),
  // stability and Newton's iterations and residual.
  double x_min = 0, x_max = 0;
  double largest_multiplier = 0;
  bool stable = false;
  int iterations = 0;
  double residual = 0;
  std::vector<std::string> warnings;
  std::string message;  // the scene error or the divergence, empty when complete
};

std::string pointStatusName(PointStatus status);

// Runs one point (with SweepAnalysis::kModes: analyses it; a scene without a steady state
// or whose eigenproblem fails is an error point; with kOrbit: shoots for its orbit on one
// thread, the sweep spreading points over the cores; no orbit found is an error point). With
// `trajectory_dir`, also writes the run's trajectory.csv and summary.json there (a write failure
// makes the point an error). `document`: the setup's scene text already parsed (io::SceneDocument,
// one per thread), so the point only rebuilds the model with its overrides; null: parsed here.
PointOutcome runPoint(const SweepSetup& setup, const std::vector<std::string>& point_overrides,
                      const std::filesystem::path* trajectory_dir = nullptr,
                      const io::SceneDocument* document = nullptr);

}  // namespace tribo::study
