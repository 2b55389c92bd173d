#include "study/sweep/sweep_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "core/thread_count.hpp"
#include "io/file_read.hpp"
#include "io/scene_loader.hpp"
#include "io/utf8_check.hpp"
#include "study/sweep/sweep_progress.hpp"
#include "study/sweep/sweep_results.hpp"

namespace tribo::study {

namespace fs = std::filesystem;

namespace {

// FNV-1a, 64 bit: identifies the scene text in sweep.json (not a security hash).
std::string fnv1a(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string manifestFor(const SweepSpec& spec, const std::string& scene_text,
                        const SweepGrid& grid) {
  nlohmann::ordered_json j;
  j["tribo_sweep"] = 1;
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(fs::absolute(spec.scene_path), ec);
  j["scene"] = ec ? spec.scene_path : abs.string();
  j["scene_fnv1a64"] = fnv1a(scene_text);
  j["set"] = spec.fixed_overrides;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (const auto& a : grid.axes()) axes.push_back({{"name", a.name}, {"values", a.values}});
  j["axes"] = axes;
  if (spec.settle)
    j["settle"] = {{"tolerance", spec.settle->tolerance},
                   {"check_interval", spec.settle->check_interval}};
  else
    j["settle"] = nullptr;
  // Written only for a modes sweep, so the manifests of run sweeps stay as they were.
  if (spec.analysis != SweepAnalysis::kRun) j["analysis"] = kSweepAnalysisNames.name(spec.analysis);
  j["columns"] = sweepColumns(grid, spec.analysis);
  return j.dump(2) + "\n";
}

// A parameter fixed by --set and swept by --grid/--list: which should win is a guess, and
// sweep.json would record both; refused, naming both.
void requireNoFixedSweptParameter(const SweepSpec& spec) {
  for (const std::string& item : spec.fixed_overrides) {
    std::string name = item.substr(0, item.find('='));
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    for (const SweepAxis& axis : spec.axes)
      if (axis.name == name)
        throw SweepSpecError("--set " + io::printableText(item) + " fixes parameter '" + name +
                             "', which is also swept (--grid or --list " + name +
                             "=...); give it one or the other");
  }
}

fs::path pointDir(const fs::path& out, std::size_t index, std::size_t total) {
  const std::size_t width = std::to_string(total > 0 ? total - 1 : 0).size();
  std::string name = std::to_string(index);
  name.insert(0, width - std::min(width, name.size()), '0');
  return out / "points" / name;
}

}  // namespace

std::string readSceneText(const std::string& path) {
  try {
    return io::readFileBounded(path, "scene file", io::kMaxSceneBytes);
  } catch (const io::FileReadError& e) {
    throw io::SceneError(e.what());
  }
}

SweepPlan planSweep(const SweepSpec& spec) {
  return planSweep(spec, readSceneText(spec.scene_path));
}

SweepPlan planSweep(const SweepSpec& spec, const std::string& scene_text) {
  const std::string analysis = kSweepAnalysisNames.name(spec.analysis);
  if (spec.settle && spec.analysis != SweepAnalysis::kRun)
    throw SweepSpecError("--settle applies to runs, not to --analysis " + analysis);
  if (spec.keep_trajectories && spec.analysis != SweepAnalysis::kRun)
    throw SweepSpecError("--keep-trajectories applies to runs, not to --analysis " + analysis);
  requireNoFixedSweptParameter(spec);
  if (const std::size_t bad = io::firstBadUtf8(spec.scene_path); bad != std::string::npos)
    throw io::SceneError("scene file path '" + io::printableText(spec.scene_path) +
                         "': expected UTF-8 text, found " +
                         io::badUtf8Reason(spec.scene_path, bad));
  SweepPlan plan{{spec.scene_path, scene_text, spec.fixed_overrides, spec.settle, spec.analysis,
                  spec.user_laws},
                 SweepGrid(spec.axes),
                 "",
                 spec.keep_trajectories};
  // The scene as most points will see it: with the first point's values if that loads,
  // else with the fixed overrides alone (the first point may be one that fails).
  std::optional<io::Scene> scene;
  try {
    auto with_point = spec.fixed_overrides;
    for (auto& o : plan.grid.overrides(0)) with_point.push_back(std::move(o));
    scene =
        io::loadSceneFromString(scene_text, spec.scene_path, with_point, {}, {}, spec.user_laws);
  } catch (const io::SceneError&) {
  }
  if (!scene)
    scene = io::loadSceneFromString(scene_text, spec.scene_path, spec.fixed_overrides, {}, {},
                                    spec.user_laws);
  for (const auto& axis : plan.grid.axes()) {
    const auto p = std::find_if(scene->parameters.begin(), scene->parameters.end(),
                                [&](const auto& nv) { return nv.first == axis.name; });
    if (p == scene->parameters.end()) {
      std::string known;
      for (const auto& [name, value] : scene->parameters) {
        if (!known.empty()) known += ", ";
        known += name;
      }
      throw SweepSpecError("'" + axis.name + "' is not a parameter of " + spec.scene_path +
                           " (known parameters: " + known + ")");
    }
    if (!io::parseNumber(p->second)) continue;
    for (const auto& v : axis.values)
      if (!io::parseNumber(v))
        throw SweepSpecError("parameter '" + axis.name + "' of " + spec.scene_path +
                             " is a number; value '" + v + "' is not");
  }
  if (spec.settle) {
    try {
      SettleWatch check(*scene, *spec.settle);
    } catch (const std::invalid_argument& e) {
      throw SweepSpecError(std::string("--settle: ") + e.what());
    }
  }
  plan.manifest = manifestFor(spec, scene_text, plan.grid);
  return plan;
}

unsigned defaultJobs(unsigned ranks_here) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max(1u, cores / std::max(1u, ranks_here));
}

void runPointsOnThreads(const SweepPlan& plan, const fs::path& out, unsigned jobs,
                        const std::function<std::optional<std::size_t>()>& next,
                        const std::function<void(const FinishedPoint&)>& done) {
  auto worker = [&] {
    // Points already share the cores: each evaluation keeps to its thread (no helper threads
    // per point on top of `jobs` threads). With one job the scene's own threads apply.
    const ScopedThreadLimit one_each(jobs > 1 ? 1 : 0);
    // The scene text parsed once per thread (planSweep has loaded it, so it parses).
    const io::SceneDocument document(plan.setup.scene_text, plan.setup.scene_path);
    while (const auto index = next()) {
      const fs::path dir = pointDir(out, *index, plan.grid.size());
      const PointOutcome o = runPoint(plan.setup, plan.grid.overrides(*index),
                                      plan.keep_trajectories ? &dir : nullptr, &document);
      done({*index, formatSweepRow(*index, plan.grid, o, plan.setup.analysis),
            o.status != PointStatus::kComplete,
            plan.setup.settle && o.status == PointStatus::kComplete && !o.settled});
    }
  };
  std::vector<std::thread> threads;
  for (unsigned i = 1; i < std::max(1u, jobs); ++i) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
}

SweepReport runSweepLocally(const SweepPlan& plan, const fs::path& out,
                            const LocalRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SweepResultsFile results(out, plan.manifest, plan.grid, plan.setup.analysis);
  SweepReport report;
  report.points = plan.grid.size();
  report.resumed = results.doneCount();
  report.dropped = results.droppedLines();

  const std::vector<std::size_t> pending = results.pendingPoints();
  std::atomic<std::size_t> cursor{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // guards report and the first write error
  std::optional<SweepOutputError> write_error;
  SweepProgress progress(options.progress, report.points, report.resumed);

  const unsigned jobs = std::min<std::size_t>(options.jobs ? options.jobs : defaultJobs(),
                                              std::max<std::size_t>(1, pending.size()));
  runPointsOnThreads(
      plan, out, jobs,
      [&]() -> std::optional<std::size_t> {
        if (stop) return std::nullopt;
        const std::size_t k = cursor++;
        if (k >= pending.size()) return std::nullopt;
        return pending[k];
      },
      [&](const FinishedPoint& p) {
        std::lock_guard lock(mutex);
        if (stop) return;
        try {
          results.append(p.index, p.line);
        } catch (const SweepOutputError& e) {
          write_error = e;
          stop = true;
          return;
        }
        ++report.ran;
        report.failed += p.failed;
        report.unsettled += p.unsettled;
        progress.pointDone(p.failed);
        if (options.stop_after && report.ran >= options.stop_after) stop = true;
      });
  if (write_error) throw *write_error;
  report.complete = results.doneCount() == plan.grid.size();
  if (report.complete) results.finish();
  progress.finish();
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace tribo::study
