#include "study/sweep/sweep_point.hpp"

#include <exception>

#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "study/orbit/periodic_orbit.hpp"
#include "study/result_writer.hpp"
#include "study/scene_run.hpp"

namespace tribo::study {

namespace {

double riseTime(const OscillationSummary& s) {
  const double target = 0.98 * s.amplitude_pp;
  const auto& c = s.cycles;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k].peak_to_peak < target) continue;
    if (k == 0) return c[0].t_end;
    const double share =
        (target - c[k - 1].peak_to_peak) / (c[k].peak_to_peak - c[k - 1].peak_to_peak);
    return c[k - 1].t_end + share * (c[k].t_end - c[k - 1].t_end);
  }
  return 0.0;
}

}  // namespace

std::string pointStatusName(PointStatus status) { return kPointStatusNames.name(status); }

PointOutcome runPoint(const SweepSetup& setup, const std::vector<std::string>& point_overrides,
                      const std::filesystem::path* trajectory_dir,
                      const io::SceneDocument* document) {
  PointOutcome out;
  try {
    std::vector<std::string> overrides = setup.fixed_overrides;
    overrides.insert(overrides.end(), point_overrides.begin(), point_overrides.end());
    const io::Scene scene = document ? document->load(overrides, {}, {}, setup.user_laws)
                                     : io::loadSceneFromString(setup.scene_text, setup.scene_path,
                                                               overrides, {}, {}, setup.user_laws);
    if (setup.analysis == SweepAnalysis::kModes) {
      const ModesResult m = analyzeModes(scene);
      out.status = PointStatus::kComplete;
      out.max_growth_rate = m.leading().growth_rate;
      out.growth_frequency = m.leading().frequency;
      out.unstable_modes = m.unstable_count;
      out.warnings = m.warnings;
      return out;
    }
    if (setup.analysis == SweepAnalysis::kOrbit) {
      OrbitSpec spec;
      spec.threads = 1;  // the sweep's points share the cores
      const OrbitResult r = findPeriodicOrbit(scene, spec);
      out.status = PointStatus::kComplete;
      out.period = r.period;
      out.amplitude_pp = r.amplitude_pp;
      out.x_min = r.x_min;
      out.x_max = r.x_max;
      out.largest_multiplier = r.largest_multiplier;
      out.stable = r.stable;
      out.iterations = r.iterations;
      out.residual = r.residual;
      return out;
    }
    std::optional<SettleWatch> watch;
    if (setup.settle) watch.emplace(scene, *setup.settle);
    const RunResult r = runScene(scene, watch ? watch->monitor() : RunMonitor{});
    out.warnings = r.warnings;
    out.simulated = r.simulated_seconds;
    if (trajectory_dir) writeResults(*trajectory_dir, scene, r);
    if (!r.complete) {
      out.status = PointStatus::kDiverged;
      out.message = r.message;
      return out;
    }
    const OscillationSummary& s = r.summary;
    out.status = PointStatus::kComplete;
    out.amplitude_pp = s.amplitude_pp;
    out.period = s.period;
    out.time_to_98 = s.time_to_98;
    out.stuck_fraction = s.stuck_fraction;
    out.x_mean = s.x_mean;
    out.cycles = static_cast<int>(s.cycles.size());
    out.rise_time = riseTime(s);
    out.first_pp = s.cycles.empty() ? 0.0 : s.cycles.front().peak_to_peak;
    out.settled = watch && watch->settled();
  } catch (const std::exception& e) {
    out.status = PointStatus::kError;
    out.message = e.what();
  }
  return out;
}

}  // namespace tribo::study
