// Sweeps from Python, three ways, all ending in the results.csv `tribo sweep` writes (the
// same plan, rows and bytes: study/sweep/):
//   - _sweep_on_threads: the local threads, as `tribo sweep` (study/sweep/sweep_runner.hpp),
//     or one slice of the grid into a shared folder, as `tribo sweep --slice I/N`
//     (study/sweep/sweep_slice.hpp); merge_sweep completes a sliced folder (--merge);
//   - _SweepTask and _SweepFolder: the pieces python/tribo/_sweep.py hands to any
//     concurrent.futures executor: a task is the checked sweep as a picklable value whose
//     run_point(k) runs point k anywhere and returns its results line; the folder records the
//     lines as they come back (study/sweep/sweep_shared_folder.hpp: resumable, results.csv
//     written whole in point order at the end).
// The GIL is released while points run. Not here: the executor loop (python/tribo/_sweep.py).
#include <pybind11/stl.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include "core/thread_count.hpp"
#include "python/bindings.hpp"
#include "python/python_law.hpp"
#include "python/scene_handle.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_runner.hpp"
#include "study/sweep/sweep_shared_folder.hpp"
#include "study/sweep/sweep_slice.hpp"

namespace tribo::python {
namespace {

// What a sweep is made of, as given from Python.
struct SweepSource {
  std::string text, path;
  std::vector<std::string> overrides;  // the SceneHandle's own (load_scene(set=))
  py::dict laws;                       // the Python law objects, by name (executors only)
};

// The scene's YAML text and path for a sweep: a path, or a Scene loaded from a file or text.
// `laws_allowed`: a Scene with laws written in Python gives their objects (the executor path
// sends them to its workers); else such a scene is refused.
SweepSource sweepSource(const py::object& scene, bool laws_allowed) {
  SweepSource s;
  if (py::isinstance<SceneHandle>(scene)) {
    const auto& h = scene.cast<const SceneHandle&>();
    if (h.source == SceneHandle::Source::kUrdf)
      throw py::value_error(
          "sweep: a URDF scene cannot be swept; write a scene file with a "
          "robots: entry");
    if (!h.user_laws.empty()) {
      if (!laws_allowed)
        throw py::value_error(
            "sweep: a scene with laws given in Python cannot be swept on threads (each "
            "thread loads the scene from its text); give sweep(..., executor=...) a "
            "concurrent.futures executor, which sends the laws to its workers");
      s.laws = lawObjectsOf(h.user_laws);
    }
    s.overrides = h.overrides;
    if (h.source == SceneHandle::Source::kText) {
      s.text = h.origin;
      s.path = h.scene.path;
    } else {
      s.text = study::readSceneText(h.origin);
      s.path = h.origin;
    }
    return s;
  }
  s.path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  s.text = study::readSceneText(s.path);
  return s;
}

// One axis from a "START:STOP:COUNT" string or a sequence of values.
study::SweepAxis axisFrom(const std::string& name, const py::handle& values) {
  if (py::isinstance<py::str>(values))
    return study::parseGridAxis(name + "=" + values.cast<std::string>());
  std::string list;
  for (const py::handle v : values) {
    if (!list.empty()) list += ",";
    list += py::str(v).cast<std::string>();
  }
  return study::parseListAxis(name + "=" + list);
}

study::SweepAnalysis analysisFrom(const std::string& analysis) {
  if (analysis == "modes") return study::SweepAnalysis::kModes;
  if (analysis == "orbit") return study::SweepAnalysis::kOrbit;
  if (analysis != "run")
    throw py::value_error("sweep: analysis must be 'run', 'modes' or 'orbit' (got '" + analysis +
                          "')");
  return study::SweepAnalysis::kRun;
}

// The sweep's spec: the scene, the fixed overrides (the Scene's own, then set=), the axes.
study::SweepSpec specFrom(const SweepSource& source, const py::dict& grid, const py::object& set,
                          const std::string& analysis) {
  study::SweepSpec spec;
  spec.scene_path = source.path;
  spec.fixed_overrides = source.overrides;
  for (std::string& o : overridesFrom(set)) spec.fixed_overrides.push_back(std::move(o));
  for (const auto& [name, values] : grid)
    spec.axes.push_back(axisFrom(name.cast<std::string>(), values));
  spec.analysis = analysisFrom(analysis);
  return spec;
}

// A field as a float when it is a whole number's text, else the text (empty: None).
py::object fieldValue(const std::string& text) {
  if (text.empty()) return py::none();
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc() && end == text.data() + text.size()) return py::float_(v);
  return py::str(text);
}

// results.csv's rows as dicts, numbers as floats.
py::list readResults(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read '" + file.string() + "'");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = study::splitCsvLine(line);
  py::list rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = study::splitCsvLine(line);
    py::dict row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i)
      row[py::str(header[i])] = fieldValue(fields[i]);
    rows.append(row);
  }
  return rows;
}

// A new empty folder under the system's temporary folder.
std::filesystem::path temporaryFolder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "tribo-sweep-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a temporary folder: " +
                             std::string(std::strerror(errno)));
  return pattern;
}

std::filesystem::path pathOf(const py::object& p) {
  return py::module_::import("os").attr("fspath")(p).cast<std::string>();
}

py::object runOnThreads(const py::object& scene, const py::dict& grid, const py::object& set,
                        unsigned jobs, const std::string& analysis, const py::object& out,
                        bool keep_trajectories, bool progress, const py::object& slice) {
  const SweepSource source = sweepSource(scene, false);
  study::SweepSpec spec = specFrom(source, grid, set, analysis);
  spec.keep_trajectories = keep_trajectories;
  const study::SweepPlan plan = study::planSweep(spec, source.text);
  const bool temporary = out.is_none();
  if (temporary && keep_trajectories)
    throw py::value_error("sweep: keep_trajectories needs an out folder");
  std::optional<study::SweepSlice> part;
  if (!slice.is_none()) {
    if (temporary)
      throw py::value_error("sweep: a slice needs an out folder, shared by all slices");
    try {
      part = study::parseSweepSlice(py::str(slice).cast<std::string>());
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("sweep: ") + e.what());
    }
  }
  const std::filesystem::path dir = temporary ? temporaryFolder() : pathOf(out);
  study::LocalRunOptions options;
  options.jobs = jobs;
  options.progress = progress ? stderr : nullptr;
  try {
    if (part) {
      study::SliceReport report;
      {
        py::gil_scoped_release release;
        report = study::runSweepSlice(plan, dir, *part, options);
      }
      // The other slices' rows may still be missing: the rows of the whole sweep, or None.
      if (!report.results_written) return py::none();
      return readResults(dir / "results.csv");
    }
    {
      py::gil_scoped_release release;
      study::runSweepLocally(plan, dir, options);
    }
    py::list rows = readResults(dir / "results.csv");
    if (temporary) std::filesystem::remove_all(dir);
    return rows;
  } catch (...) {
    if (temporary) {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
    throw;
  }
}

py::list mergeSweep(const py::object& folder) {
  const std::filesystem::path dir = pathOf(folder);
  study::MergeReport report;
  {
    py::gil_scoped_release release;
    report = study::mergeSweep(dir);
  }
  if (!report.written) {
    std::string which;
    for (std::size_t i = 0; i < report.missing.size() && i < study::kMissingNamed; ++i) {
      if (!which.empty()) which += ", ";
      which += std::to_string(report.missing[i]);
    }
    throw std::runtime_error("merge_sweep: " + std::to_string(report.missing.size()) + " of " +
                             std::to_string(report.points) + " points of '" + dir.string() +
                             "' have no row yet (points " + which +
                             (report.missing.size() > study::kMissingNamed ? ", ..." : "") +
                             "): run their slices, then merge again");
  }
  return readResults(dir / "results.csv");
}

// A checked sweep that any process can run a point of: pickled as its scene text, overrides,
// axes, analysis and Python laws; the plan is made again (checked again) where it lands.
class SweepTask {
 public:
  SweepTask(const std::string& text, const std::string& path, const std::vector<std::string>& fixed,
            const std::vector<study::SweepAxis>& axes, const std::string& analysis, py::dict laws)
      : laws_(std::move(laws)), plan_(makePlan(text, path, fixed, axes, analysis, laws_)) {}

  const study::SweepPlan& plan() const { return plan_; }
  std::size_t points() const { return plan_.grid.size(); }

  // Point k's results line (with its '\n'), as the threads of `tribo sweep` make it: one
  // thread per evaluation, a point's failure recorded in its row.
  std::string runPoint(std::size_t k) const {
    if (k >= points())
      throw py::index_error("sweep: point " + std::to_string(k) + " of a sweep of " +
                            std::to_string(points()) + " points");
    study::PointOutcome outcome;
    {
      py::gil_scoped_release release;
      const ScopedThreadLimit one(1);
      outcome = study::runPoint(plan_.setup, plan_.grid.overrides(k));
    }
    // A Python law's exception made the point fail (its row says so); clear it.
    try {
      raisePythonLawErrors(plan_.setup.user_laws);
    } catch (const py::error_already_set&) {
    }
    return study::formatSweepRow(k, plan_.grid, outcome, plan_.setup.analysis);
  }

  py::tuple state() const {
    py::list axes;
    // What the plan was made from, read back from it (the plan keeps all of it).
    for (const study::SweepAxis& a : plan_.grid.axes())
      axes.append(py::make_tuple(a.name, a.values));
    const study::SweepSetup& setup = plan_.setup;
    return py::make_tuple(setup.scene_text, setup.scene_path, setup.fixed_overrides, axes,
                          study::kSweepAnalysisNames.name(setup.analysis), laws_);
  }
  static study::SweepPlan makePlan(const std::string& text, const std::string& path,
                                   const std::vector<std::string>& fixed,
                                   const std::vector<study::SweepAxis>& axes,
                                   const std::string& analysis, const py::dict& laws) {
    study::SweepSpec spec;
    spec.scene_path = path;
    spec.fixed_overrides = fixed;
    spec.axes = axes;
    spec.analysis = analysisFrom(analysis);
    spec.user_laws = userLawsFrom(laws);
    return study::planSweep(spec, text);
  }
  static SweepTask fromState(const py::tuple& t) {
    if (t.size() != 6) throw std::runtime_error("sweep task: not a pickled sweep task");
    std::vector<study::SweepAxis> axes;
    for (const py::handle a : t[3].cast<py::list>()) {
      const auto pair = a.cast<py::tuple>();
      axes.push_back({pair[0].cast<std::string>(), pair[1].cast<std::vector<std::string>>()});
    }
    return SweepTask(t[0].cast<std::string>(), t[1].cast<std::string>(),
                     t[2].cast<std::vector<std::string>>(), std::move(axes),
                     t[4].cast<std::string>(), t[5].cast<py::dict>());
  }
  const py::dict& laws() const { return laws_; }

 private:
  py::dict laws_;  // the Python objects (setup.user_laws wraps them), to pickle
  study::SweepPlan plan_;
};

SweepTask makeTask(const py::object& scene, const py::dict& grid, const py::object& set,
                   const std::string& analysis) {
  const SweepSource source = sweepSource(scene, true);
  study::SweepSpec spec = specFrom(source, grid, set, analysis);
  return SweepTask(source.text, source.path, spec.fixed_overrides, spec.axes, analysis,
                   source.laws);
}

// The sweep folder an executor's results land in (keeps its task alive: the folder reads
// the task's grid).
class SweepFolder {
 public:
  SweepFolder(const py::object& dir, py::object task)
      : task_(std::move(task)),
        folder_(pathOf(dir), task_.cast<const SweepTask&>().plan().manifest,
                task_.cast<const SweepTask&>().plan().grid,
                task_.cast<const SweepTask&>().plan().setup.analysis) {}
  study::SharedSweepFolder& folder() { return folder_; }

 private:
  py::object task_;
  study::SharedSweepFolder folder_;
};

}  // namespace

void bindSweep(py::module_& m) {
  m.def("_sweep_on_threads", &runOnThreads, py::arg("scene"), py::arg("grid"),
        py::arg("set") = py::none(), py::arg("jobs") = 0u, py::arg("analysis") = "run",
        py::arg("out") = py::none(), py::arg("keep_trajectories") = false,
        py::arg("progress") = false, py::arg("slice") = py::none(),
        "The threaded sweep behind tribo.sweep (see there).");
  m.def("merge_sweep", &mergeSweep, py::arg("folder"),
        "merge_sweep(folder) -> list of dicts: completes the results.csv of a folder that "
        "sweep(..., slice='I/N', out=folder) calls (or `tribo sweep --slice`) wrote, as "
        "`tribo sweep --merge` does, and returns its rows. Raises RuntimeError naming the "
        "points still missing.");

  py::class_<SweepTask>(m, "_SweepTask",
                        "A checked sweep whose points any process can run (pickles).")
      .def(py::init(&makeTask), py::arg("scene"), py::arg("grid"), py::arg("set") = py::none(),
           py::arg("analysis") = "run")
      .def_property_readonly("points", &SweepTask::points)
      .def_property_readonly("laws", &SweepTask::laws)
      .def("run_point", &SweepTask::runPoint, py::arg("k"),
           "Runs point k; returns its results line.")
      .def(py::pickle([](const SweepTask& t) { return t.state(); },
                      [](const py::tuple& t) { return SweepTask::fromState(t); }));

  py::class_<SweepFolder>(m, "_SweepFolder", "A sweep folder rows are recorded into.")
      .def(py::init<const py::object&, py::object>(), py::arg("dir"), py::arg("task"))
      .def("missing", [](SweepFolder& f) { return f.folder().missingPoints(); })
      .def(
          "record",
          [](SweepFolder& f, std::size_t k, const std::string& line) {
            f.folder().record(k, line);
          },
          py::arg("k"), py::arg("line"))
      .def("write_results", [](SweepFolder& f) { return f.folder().writeResultsIfComplete(); })
      .def("rows", [](SweepFolder& f) { return readResults(f.folder().resultsPath()); });
}

}  // namespace tribo::python
