#include "apps/tradeoff_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/integrator.hpp"
#include "core/stability.hpp"
#include "io/oscillation_summary.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_parameters.hpp"
#include "io/scene_run.hpp"

namespace tribo::app {
namespace {

constexpr double kGrid = 0.04;           // [s] comparison grid; fixed steps divide it
constexpr double kCommunication = 0.01;  // [s] interval of the adaptive integrators
constexpr double kRecord = 0.001;        // [s] finest output interval
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kLadder[] = {2, 4, 5, 8, 10, 20, 40, 80, 160, 320, 640};  // steps G / n
constexpr double kTolerances[] = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};

constexpr const char* kUsage =
    "usage: tribo tradeoff SCENE.yaml [--set NAME=VALUE ...] [--out DIR] [--window S]\n"
    "                      [--repeat N] [--integrators A,B,...]\n"
    "  runs every integrator over a ladder of steps or tolerances against a converged\n"
    "  reference; writes DIR/tradeoff.csv (default DIR: out/tradeoff) and prints a table\n";

struct Setting {
  IntegratorType integrator = IntegratorType::kRk4;
  bool events = true;
  double step = 0.0;  // fixed-step methods [s]
  double rtol = 0.0;  // adaptive methods
  std::string label() const {
    return integratorName(integrator) + (isAdaptive(integrator) && !events ? "_noevents" : "");
  }
  double value() const { return isAdaptive(integrator) ? rtol : step; }
};

// The summary coordinate of a run, its velocity and the masked slip channel.
struct Samples {
  std::vector<double> t, x, v, slip;
};

struct Outcome {
  Setting setting;
  std::string status;  // complete | warned | diverged | reference
  std::string message;
  double amplitude = kNaN, amplitude_error = kNaN, trajectory_error = kNaN;
  double wall = kNaN, cpu = kNaN, simulated = 0.0;
  long steps = 0, rejected = 0, evaluations = 0, events = 0;
};

Samples observe(const io::RunResult& r, const io::Scene& scene) {
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
  io::OscillationOptions o;
  o.last_cycles = spec.last_cycles;
  o.stick_speed = spec.stick_speed;
  try {
    return io::summarizeOscillation(d.t, d.x, d.slip, o).amplitude_pp;
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

io::Scene withSetting(const io::Scene& base, const Setting& s) {
  auto model = std::make_shared<Model>(*base.model);
  SimulationOptions& o = model->options;
  o.integrator = s.integrator;
  if (isAdaptive(s.integrator)) {
    o.time_step = kCommunication;
    o.relative_tolerance = s.rtol;
    o.absolute_tolerance = 1e-3 * s.rtol;
    o.event_location = s.events;
  } else {
    o.time_step = s.step;
  }
  io::Scene scene = base;
  scene.model = model;
  scene.output.interval = std::max(kRecord, o.time_step);
  return scene;
}

// A run and its cost: wall time of the stepping (io::runScene) and processor time of the
// whole run (stepping, recording and the summary), each the least of `repeat` runs. On a
// shared machine the processor time is the steadier measure.
struct Timed {
  io::RunResult result;
  double cpu = kNaN;  // [s]
};

Timed run(const io::Scene& scene, int repeat) {
  std::clock_t start = std::clock();
  Timed t{io::runScene(scene), 0.0};
  t.cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  for (int i = 1; i < repeat && t.result.complete; ++i) {
    start = std::clock();
    const double wall = io::runScene(scene).wall_seconds;
    t.cpu = std::min(t.cpu, static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
    t.result.wall_seconds = std::min(t.result.wall_seconds, wall);
  }
  return t;
}

Outcome measure(const Setting& s, const Timed& timed, const io::Scene& scene, const Samples& ref,
                double window) {
  const io::RunResult& r = timed.result;
  Outcome o;
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

std::vector<Setting> ladder(const io::Scene& base, const std::vector<IntegratorType>& wanted) {
  std::vector<Setting> out;
  for (IntegratorType type : wanted) {
    if (isAdaptive(type)) {
      for (bool events : {true, false})
        for (double rtol : kTolerances) out.push_back({type, events, 0.0, rtol});
      continue;
    }
    auto model = std::make_shared<Model>(*base.model);
    model->options.integrator = type;
    const double limit = estimateStableStep(*model).limit.max_step;
    for (int n : kLadder) {
      const double step = kGrid / n;
      if (std::isinf(limit) || (step >= limit / 64 && step <= 2.5 * limit))
        out.push_back({type, true, step, 0.0});
    }
  }
  return out;
}

std::string csvText(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void writeCsv(const std::filesystem::path& file, const std::string& scene,
              const std::vector<Outcome>& rows) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  out << "scene,integrator,setting,value,status,amplitude,amplitude_error,trajectory_error,"
         "wall_seconds,cpu_seconds,sim_seconds_per_cpu_second,steps,rejected_steps,"
         "force_evaluations,events,message\n";
  char buf[512];
  for (const Outcome& o : rows) {
    std::snprintf(
        buf, sizeof buf, "%s,%s,%s,%.6g,%s,%.9g,%.4g,%.4g,%.6g,%.6g,%.6g,%ld,%ld,%ld,%ld,",
        scene.c_str(), o.setting.label().c_str(), isAdaptive(o.setting.integrator) ? "rtol" : "dt",
        o.setting.value(), o.status.c_str(), o.amplitude, o.amplitude_error, o.trajectory_error,
        o.wall, o.cpu, o.simulated / o.cpu, o.steps, o.rejected, o.evaluations, o.events);
    out << buf << csvText(o.message) << '\n';
  }
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

// The cheapest (processor time) complete, unwarned run per target: by amplitude error alone,
// and by both errors (an amplitude that lands close while the trajectory is off is a fluke).
void printRecommendation(const std::vector<Outcome>& rows) {
  for (const bool both : {false, true}) {
    std::printf("\ncheapest complete run without a stability warning, by %s:\n",
                both ? "amplitude and trajectory error" : "amplitude error");
    for (double target : {1e-2, 1e-3, 1e-4}) {
      const Outcome* best = nullptr;
      for (const Outcome& o : rows)
        if (o.status == "complete" && o.amplitude_error <= target &&
            (!both || o.trajectory_error <= target) && (!best || o.cpu < best->cpu))
          best = &o;
      if (!best) {
        std::printf("  %-6g none reaches it\n", target);
        continue;
      }
      std::printf(
          "  %-6g %s %s=%g: amplitude error %.2g, trajectory error %.2g, %.3g s cpu "
          "(%.0f simulated s per cpu s)\n",
          target, best->setting.label().c_str(),
          isAdaptive(best->setting.integrator) ? "rtol" : "dt", best->setting.value(),
          best->amplitude_error, best->trajectory_error, best->cpu, best->simulated / best->cpu);
    }
  }
}

std::vector<IntegratorType> parseIntegrators(const std::string& list) {
  std::vector<IntegratorType> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) out.push_back(integratorFromName(name));
  if (out.empty()) throw std::invalid_argument("--integrators: no integrator named");
  return out;
}

// The value of `option`: a number > 0, and a whole one when `whole`.
double positiveNumber(const std::string& option, const std::string& text, bool whole) {
  const auto v = io::parseNumber(text);
  if (!v || !(*v > 0) || (whole && (*v != std::floor(*v) || *v > 1e6)))
    throw std::invalid_argument(option + ": expected a " +
                                (whole ? "whole number from 1 to 1e6" : "positive number") +
                                ", found '" + text + "'");
  return *v;
}

}  // namespace

int tradeoffCommand(const std::vector<std::string>& args) {
  std::string scene_path, out_dir = "out/tradeoff";
  std::vector<std::string> overrides;
  double window = 10.0;
  int repeat = 1;
  std::vector<IntegratorType> wanted = {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4,
                                        IntegratorType::kDopri5, IntegratorType::kBdf};
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a == "--help" || a == "-h") {
        std::printf("%s", kUsage);
        return 0;
      }
      const bool takes_value = a == "--set" || a == "--out" || a == "--window" || a == "--repeat" ||
                               a == "--integrators";
      if (takes_value && i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      if (a == "--set")
        overrides.push_back(args[++i]);
      else if (a == "--out")
        out_dir = args[++i];
      else if (a == "--window")
        window = positiveNumber(a, args[++i], false);
      else if (a == "--repeat")
        repeat = static_cast<int>(positiveNumber(a, args[++i], true));
      else if (a == "--integrators")
        wanted = parseIntegrators(args[++i]);
      else if (a.rfind("--", 0) == 0)
        throw std::invalid_argument("unknown option '" + a + "'");
      else if (scene_path.empty())
        scene_path = a;
      else
        throw std::invalid_argument("more than one scene given");
    }
    if (scene_path.empty()) throw std::invalid_argument("no scene file given");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n\n%s", e.what(), kUsage);
    return 1;
  }
  io::Scene base;
  try {
    base = io::loadScene(scene_path, overrides);
    if (base.output.summary.body.empty())
      throw std::invalid_argument(scene_path + ": output.summary names no body to observe");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n", e.what());
    return 2;
  }

  // Reference: rk4 at a divisor of the grid below limit/8 and 0.1 ms, checked at half of it.
  auto rk4 = std::make_shared<Model>(*base.model);
  rk4->options.integrator = IntegratorType::kRk4;
  const double limit = estimateStableStep(*rk4).limit.max_step;
  const double ref_step = kGrid / std::ceil(kGrid / std::min(1e-4, limit / 8));
  const Setting ref_setting{IntegratorType::kRk4, true, ref_step, 0.0};
  const io::Scene ref_scene = withSetting(base, ref_setting);
  std::printf("reference: rk4, dt = %g s\n", ref_step);
  const io::RunResult ref_run = run(ref_scene, 1).result;
  if (!ref_run.complete) {
    std::fprintf(stderr, "tribo tradeoff: the reference run failed: %s\n", ref_run.message.c_str());
    return 3;
  }
  const Samples ref = observe(ref_run, ref_scene);
  const Setting check_setting{IntegratorType::kRk4, true, ref_step / 2, 0.0};
  const io::Scene check_scene = withSetting(base, check_setting);
  Outcome check = measure(check_setting, run(check_scene, 1), check_scene, ref, window);
  check.status = "reference";
  check.message = "the reference at half its step";
  std::printf("reference check (dt/2): amplitude %.9g, difference %.2g, trajectory %.2g\n",
              check.amplitude, check.amplitude_error, check.trajectory_error);

  std::vector<Outcome> rows{check};
  std::printf("%-20s %-9s %-9s %-10s %-10s %-10s %-10s %-11s %s\n", "integrator", "setting",
              "status", "ampl.err", "traj.err", "wall [s]", "cpu [s]", "sim s/cpu s",
              "evaluations");
  for (const Setting& s : ladder(base, wanted)) {
    const io::Scene scene = withSetting(base, s);
    const Outcome o = measure(s, run(scene, repeat), scene, ref, window);
    std::printf("%-20s %-9.3g %-9s %-10.2g %-10.2g %-10.3g %-10.3g %-11.4g %ld\n",
                s.label().c_str(), s.value(), o.status.c_str(), o.amplitude_error,
                o.trajectory_error, o.wall, o.cpu, o.simulated / o.cpu, o.evaluations);
    std::fflush(stdout);
    rows.push_back(o);
  }
  printRecommendation(rows);
  const std::filesystem::path file = std::filesystem::path(out_dir) / "tradeoff.csv";
  try {
    writeCsv(file, std::filesystem::path(scene_path).stem().string(), rows);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n", e.what());
    return 4;
  }
  std::printf("results          %s\n", file.string().c_str());
  return 0;
}

}  // namespace tribo::app
