#include "study/tradeoff.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/stability.hpp"
#include "io/scene_loader.hpp"
#include "study/csv_text.hpp"
#include "study/file_commit.hpp"
#include "study/oscillation_summary.hpp"
#include "study/scene_run.hpp"

namespace tribo::study {
namespace {

constexpr double kGrid = 0.04;           // [s] comparison grid; fixed steps divide it
constexpr double kCommunication = 0.01;  // [s] interval of the adaptive integrators
constexpr double kRecord = 0.001;        // [s] finest output interval
constexpr double kNaN = TradeoffRow::kNaN;
constexpr int kLadder[] = {2, 4, 5, 8, 10, 20, 40, 80, 160, 320, 640};  // steps G / n
constexpr double kTolerances[] = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};

// The summary coordinate of a run, its velocity and the masked slip channel.
struct Samples {
  std::vector<double> t, x, v, slip;
};

Samples observe(const RunResult& r, const io::Scene& scene) {
  static const char* kAxis[] = {"x", "y", "z"};
  const auto& spec = scene.output.summary;
  const auto& tr = r.trajectory;
  const std::string b = spec.body + ".";
  const auto col = [&](const std::string& name) {
    const auto c = tr.column(tr.columnIndex(name));
    return std::vector<double>(c.begin(), c.end());
  };
  Samples s{col("t"), col(b + kAxis[spec.coordinate]), col(b + "v" + kAxis[spec.coordinate]),
            col(b + "slip")};
  const auto normal = col(b + "normal_force");
  for (std::size_t i = 0; i < s.slip.size(); ++i)
    if (!(normal[i] > 0.0)) s.slip[i] = std::numeric_limits<double>::max();
  return s;
}

// Limit-cycle amplitude of every `stride`-th sample (the run summary's estimator).
double amplitudeOf(const Samples& s, const io::SummarySpec& spec, std::size_t stride) {
  Samples d;
  for (std::size_t i = 0; i < s.t.size(); i += stride) {
    d.t.push_back(s.t[i]);
    d.x.push_back(s.x[i]);
    d.slip.push_back(s.slip[i]);
  }
  OscillationOptions o;
  o.last_cycles = spec.last_cycles;
  o.stick_speed = spec.stick_speed;
  try {
    return summarizeOscillation(d.t, d.x, d.slip, o).amplitude_pp;
  } catch (const std::invalid_argument&) {
    return kNaN;
  }
}

// x(t) by cubic Hermite interpolation in x and v; exact at sample times.
double at(const Samples& s, double t) {
  const auto it = std::lower_bound(s.t.begin(), s.t.end(), t - 1e-9);
  if (it == s.t.end()) return kNaN;
  const std::size_t j = static_cast<std::size_t>(it - s.t.begin());
  if (std::abs(s.t[j] - t) <= 1e-9 || j == 0) return s.x[j];
  const std::size_t i = j - 1;
  const double h = s.t[j] - s.t[i], u = (t - s.t[i]) / h;
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * s.x[i] + (u3 - 2 * u2 + u) * h * s.v[i] +
         (-2 * u3 + 3 * u2) * s.x[j] + (u3 - u2) * h * s.v[j];
}

double trajectoryError(const Samples& run, const Samples& ref, double window, double scale) {
  double worst = 0.0;
  const double end = std::min({window, run.t.back(), ref.t.back()});
  for (int k = 1; k * kGrid <= end + 1e-9; ++k)
    worst = std::max(worst, std::abs(at(run, k * kGrid) - at(ref, k * kGrid)));
  return worst / scale;
}

io::RunSettings runSettings(const TradeoffSetting& s) {
  io::RunSettings r;
  r.integrator = s.integrator;
  if (isAdaptive(s.integrator)) {
    r.time_step = kCommunication;
    r.relative_tolerance = s.rtol;
    r.absolute_tolerance = 1e-3 * s.rtol;
    r.event_location = s.events;
    r.output_interval = std::max(kRecord, kCommunication);
  } else {
    r.time_step = s.step;
    r.output_interval = std::max(kRecord, s.step);
  }
  return r;
}

// The scene loaded again with the setting: the builder validates it and derives from it.
io::Scene sceneWith(const TradeoffSpec& spec, const io::RunSettings& settings) {
  io::Scene scene = io::loadScene(spec.scene_path, spec.overrides, {}, settings);
  if (scene.output.summary.body.empty())
    throw io::SceneError(spec.scene_path + ": output.summary names no body to observe");
  if (!scene.output.summary.channel.empty())
    throw io::SceneError(spec.scene_path +
                         ": the tradeoff observes a body's x, y or z (output.summary: {body, "
                         "coordinate}), not the channel '" +
                         scene.output.summary.channel + "'");
  // It interpolates the coordinate with its velocity and masks the slip out of contact.
  for (const char* group : {"position", "velocity", "contact"})
    if (!io::hasGroup(scene.output.channels, group)) scene.output.channels.push_back(group);
  return scene;
}

double stableStep(const TradeoffSpec& spec, IntegratorType type) {
  io::RunSettings r;
  r.integrator = type;
  return estimateStableStep(*sceneWith(spec, r).model).limit.max_step;
}

// A run and its cost: wall time of the stepping (runScene) and processor time of the whole
// run (stepping, recording and the summary), each the least of `repeat` runs. On a shared
// machine the processor time is the steadier measure.
struct Timed {
  RunResult result;
  double cpu = kNaN;  // [s]
};

Timed run(const io::Scene& scene, int repeat) {
  std::clock_t start = std::clock();
  Timed t{runScene(scene), 0.0};
  t.cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  for (int i = 1; i < repeat && t.result.complete; ++i) {
    start = std::clock();
    const double wall = runScene(scene).wall_seconds;
    t.cpu = std::min(t.cpu, static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
    t.result.wall_seconds = std::min(t.result.wall_seconds, wall);
  }
  return t;
}

TradeoffRow measure(const TradeoffSetting& s, const Timed& timed, const io::Scene& scene,
                    const Samples& ref, double window) {
  const RunResult& r = timed.result;
  TradeoffRow o;
  o.setting = s;
  o.cpu = timed.cpu;
  o.status = !r.complete ? "diverged" : (r.warnings.empty() ? "complete" : "warned");
  o.message = r.complete ? (r.warnings.empty() ? "" : r.warnings.front()) : r.message;
  o.wall = r.wall_seconds;
  o.simulated = r.simulated_seconds;
  o.steps = r.stats.integrator_steps;
  o.rejected = r.stats.rejected_steps;
  o.evaluations = r.stats.evaluations;
  o.events = r.stats.events;
  if (!r.complete) return o;
  const Samples samples = observe(r, scene);
  const auto stride = static_cast<std::size_t>(std::lround(scene.output.interval / kRecord));
  const double a_ref = amplitudeOf(ref, scene.output.summary, std::max<std::size_t>(stride, 1));
  o.amplitude = amplitudeOf(samples, scene.output.summary, 1);
  o.amplitude_error = std::abs(o.amplitude - a_ref) / a_ref;
  o.trajectory_error = trajectoryError(samples, ref, window, a_ref);
  return o;
}

std::string count(long v) { return std::to_string(v); }

}  // namespace

std::string TradeoffSetting::label() const {
  return integratorName(integrator) + (isAdaptive(integrator) && !events ? "_noevents" : "");
}

const char* TradeoffSetting::valueName() const { return isAdaptive(integrator) ? "rtol" : "dt"; }

double TradeoffSetting::value() const { return isAdaptive(integrator) ? rtol : step; }

std::vector<TradeoffSetting> tradeoffLadder(const TradeoffSpec& spec) {
  std::vector<TradeoffSetting> out;
  for (IntegratorType type : spec.integrators) {
    if (isAdaptive(type)) {
      for (bool events : {true, false})
        for (double rtol : kTolerances) out.push_back({type, events, 0.0, rtol});
      continue;
    }
    const double limit = stableStep(spec, type);
    auto inWindow = [&](double step) {
      return std::isinf(limit) || (step >= limit / 64 && step <= 2.5 * limit);
    };
    int below = 0;  // rungs at or below the limit
    for (int n : kLadder) {
      const double step = kGrid / n;
      if (inWindow(step)) out.push_back({type, true, step, 0.0});
      below += step <= limit;
    }
    // A limit below the finest rung (a stiff bristle: tens of microseconds): continue the
    // ladder by halving until two rungs lie at or below it.
    for (long n = 2L * kLadder[std::size(kLadder) - 1]; below < 2 && kGrid / n >= limit / 64;
         n *= 2) {
      const double step = kGrid / static_cast<double>(n);
      if (inWindow(step)) out.push_back({type, true, step, 0.0});
      below += step <= limit;
    }
  }
  return out;
}

TradeoffResult measureTradeoff(const TradeoffSpec& spec,
                               const std::function<void(const TradeoffSetting&)>& on_reference,
                               const std::function<void(const TradeoffRow&)>& on_row) {
  // Reference: rk4 at a divisor of the grid below limit/8 and 0.1 ms, checked at half of it.
  const double limit = stableStep(spec, IntegratorType::kRk4);
  const double ref_step = kGrid / std::ceil(kGrid / std::min(1e-4, limit / 8));
  TradeoffResult result;
  result.reference = {IntegratorType::kRk4, true, ref_step, 0.0};
  if (on_reference) on_reference(result.reference);
  const io::Scene ref_scene = sceneWith(spec, runSettings(result.reference));
  const RunResult ref_run = run(ref_scene, 1).result;
  if (!ref_run.complete)
    throw TradeoffReferenceError("the reference run failed: " + ref_run.message);
  const Samples ref = observe(ref_run, ref_scene);
  const TradeoffSetting check_setting{IntegratorType::kRk4, true, ref_step / 2, 0.0};
  const io::Scene check_scene = sceneWith(spec, runSettings(check_setting));
  TradeoffRow check = measure(check_setting, run(check_scene, 1), check_scene, ref, spec.window);
  check.status = "reference";
  check.message = "the reference at half its step";
  if (on_row) on_row(check);
  result.rows.push_back(check);
  for (const TradeoffSetting& s : tradeoffLadder(spec)) {
    const io::Scene scene = sceneWith(spec, runSettings(s));
    result.rows.push_back(measure(s, run(scene, spec.repeat), scene, ref, spec.window));
    if (on_row) on_row(result.rows.back());
  }
  return result;
}

const TradeoffRow* cheapestRow(const std::vector<TradeoffRow>& rows, double target, bool both) {
  const TradeoffRow* best = nullptr;
  for (const TradeoffRow& o : rows)
    if (o.status == "complete" && o.amplitude_error <= target &&
        (!both || o.trajectory_error <= target) && (!best || o.cpu < best->cpu))
      best = &o;
  return best;
}

std::vector<TradeoffField> tradeoffFields(const std::string& scene_name, const TradeoffRow& o) {
  using K = TradeoffField::Kind;
  auto number = [](const char* name, double v, int digits) {
    return TradeoffField{name, K::kNumber, v, 0, {}, digits};
  };
  auto counted = [](const char* name, long v) {
    return TradeoffField{name, K::kCount, 0.0, v, {}, 0};
  };
  auto text = [](const char* name, std::string v) {
    return TradeoffField{name, K::kText, 0.0, 0, std::move(v), 0};
  };
  return {text("scene", scene_name),
          text("integrator", o.setting.label()),
          text("setting", o.setting.valueName()),
          number("value", o.setting.value(), 6),
          text("status", o.status),
          number("amplitude", o.amplitude, 9),
          number("amplitude_error", o.amplitude_error, 4),
          number("trajectory_error", o.trajectory_error, 4),
          number("wall_seconds", o.wall, 6),
          number("cpu_seconds", o.cpu, 6),
          number("sim_seconds_per_cpu_second", o.simulated / o.cpu, 6),
          counted("steps", o.steps),
          counted("rejected_steps", o.rejected),
          counted("force_evaluations", o.evaluations),
          counted("events", o.events),
          text("message", o.message)};
}

void writeTradeoffCsv(const std::filesystem::path& file, const std::string& scene_name,
                      const std::vector<TradeoffRow>& rows) {
  std::vector<std::string> header;
  for (const TradeoffField& f : tradeoffFields(scene_name, TradeoffRow{})) header.push_back(f.name);
  std::string text = csvLine(header);
  for (const TradeoffRow& o : rows) {
    std::vector<std::string> fields;
    for (const TradeoffField& f : tradeoffFields(scene_name, o))
      fields.push_back(f.kind == TradeoffField::Kind::kNumber  ? csvNumber(f.number, f.digits)
                       : f.kind == TradeoffField::Kind::kCount ? count(f.count)
                                                               : f.text);
    text += csvLine(fields);
  }
  writeFileWhole(file, text);
}

}  // namespace tribo::study
