#include "io/run_settings_check.hpp"

#include <cmath>

#include "core/model_builder.hpp"
#include "core/number_text.hpp"
#include "core/thread_count.hpp"
#include "io/scene_parameters.hpp"

namespace tribo::io {

RunSettingKeys RunSettingKeys::urdf() {
  RunSettingKeys k;
  k.time_step = "dt";
  k.duration = "duration";
  return k;
}

void requireRunSetting(bool ok, const std::string& file, const std::string& key,
                       const std::string& field, const std::string& must, double value) {
  if (ok) return;
  throw SceneError(file + ": run setting '" + key + "' (" + field + "): must be " + must +
                   ", got " + numberText(value));
}

void checkRunOptions(const SimulationOptions& o, const std::string& file,
                     const RunSettingKeys& keys) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  requireRunSetting(positive(o.time_step), file, keys.time_step, "time_step", "> 0", o.time_step);
  requireRunSetting(positive(o.duration), file, keys.duration, "duration", "> 0", o.duration);
  const auto fail = [&](const std::string& key, const std::string& field, const std::string& what) {
    throw SceneError(file + ": run setting '" + key + "' (" + field + "): " + what);
  };
  // One step longer than the whole run would simulate nothing (or overshoot the duration).
  if (o.time_step > o.duration)
    fail(keys.time_step, "time_step",
         "must be at most the duration: time_step (" + numberText(o.time_step) +
             " s) is larger than the duration (" + numberText(o.duration) + " s)");
  if (o.duration / o.time_step > kMaxSteps)
    fail(keys.time_step, "time_step",
         "duration / time_step = " + numberText(o.duration / o.time_step) +
             " steps, more than the " + numberText(kMaxSteps) + " a run may take (duration " +
             numberText(o.duration) + " s, time_step " + numberText(o.time_step) + " s)");
  requireRunSetting(positive(o.relative_tolerance) && o.relative_tolerance < 1.0, file,
                    keys.relative_tolerance, "relative_tolerance", "in (0, 1)",
                    o.relative_tolerance);
  requireRunSetting(positive(o.absolute_tolerance), file, keys.absolute_tolerance,
                    "absolute_tolerance", "> 0", o.absolute_tolerance);
  requireRunSetting(o.threads == kAutoThreads || o.threads >= 1, file, keys.threads, "threads",
                    "auto (0) or >= 1", o.threads);
}

}  // namespace tribo::io
