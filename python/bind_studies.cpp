// Studies from Python: tribo.sweep runs a parameter sweep on the local cores as `tribo sweep`
// does (study/sweep/sweep_runner.hpp: the same plan, the same results.csv) and returns its
// rows as a list of dicts; tribo.modes analyses a scene's linear stability as `tribo modes`
// does (study/modes/modes.hpp) and returns the steady state's figures and the modes as a dict.
// tribo.tradeoff measures the speed-accuracy ladder as `tribo tradeoff` does
// (study/tradeoff.hpp) and returns its rows. The GIL is released while they run. Not here:
// plotting.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "python/bindings.hpp"
#include "python/python_law.hpp"
#include "python/scene_handle.hpp"
#include "study/modes/modes.hpp"
#include "study/modes/modes_report.hpp"
#include "study/sweep/sweep_results.hpp"
#include "study/sweep/sweep_runner.hpp"
#include "study/tradeoff.hpp"

namespace tribo::python {
namespace {

// The scene's YAML text and path for a sweep: a path, or a Scene loaded from a file or text.
std::pair<std::string, std::string> sweepSceneText(const py::object& scene) {
  if (py::isinstance<SceneHandle>(scene)) {
    const auto& h = scene.cast<const SceneHandle&>();
    if (h.source == SceneHandle::Source::kUrdf)
      throw py::value_error(
          "sweep: a URDF scene cannot be swept; write a scene file with a "
          "robots: entry");
    if (!h.user_laws.empty())
      throw py::value_error(
          "sweep: a scene with laws given in Python cannot be swept (each "
          "sweep thread loads the scene from its text)");
    if (!h.overrides.empty())
      throw py::value_error("sweep: give the scene's overrides as sweep(..., set=...)");
    if (h.source == SceneHandle::Source::kText) return {h.origin, h.scene.path};
    return {study::readSceneText(h.origin), h.origin};
  }
  const std::string path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  return {study::readSceneText(path), path};
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

// A field as a float when it is a whole number's text, else the text (empty: None).
py::object fieldValue(const std::string& text) {
  if (text.empty()) return py::none();
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc() && end == text.data() + text.size()) return py::float_(v);
  return py::str(text);
}

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
    throw std::runtime_error("cannot create a temporary folder: " + std::string(strerror(errno)));
  return pattern;
}

py::list runSweep(const py::object& scene, const py::dict& grid, const py::object& set,
                  unsigned jobs, const std::string& analysis, const py::object& out,
                  bool keep_trajectories, bool progress) {
  study::SweepSpec spec;
  const auto [text, path] = sweepSceneText(scene);
  spec.scene_path = path;
  spec.fixed_overrides = overridesFrom(set);
  for (const auto& [name, values] : grid)
    spec.axes.push_back(axisFrom(name.cast<std::string>(), values));
  if (analysis == "modes")
    spec.analysis = study::SweepAnalysis::kModes;
  else if (analysis != "run")
    throw py::value_error("sweep: analysis must be 'run' or 'modes' (got '" + analysis + "')");
  spec.keep_trajectories = keep_trajectories;
  const study::SweepPlan plan = study::planSweep(spec, text);
  const bool temporary = out.is_none();
  if (temporary && keep_trajectories)
    throw py::value_error("sweep: keep_trajectories needs an out folder");
  const std::filesystem::path dir =
      temporary ? temporaryFolder()
                : std::filesystem::path(
                      py::module_::import("os").attr("fspath")(out).cast<std::string>());
  study::LocalRunOptions options;
  options.jobs = jobs;
  options.progress = progress ? stderr : nullptr;
  try {
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

// modes.json's document as a dict (study/modes/modes_report.hpp spells its fields).
py::array_t<double> matrixArray(const Eigen::MatrixXd& m) {
  py::array_t<double> a({static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())});
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      a.mutable_at(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = m(i, j);
  return a;
}

py::object runModes(const SceneHandle& scene, bool settle, double settle_time, bool matrices) {
  study::ModesSpec spec;
  spec.steady.settle = settle;
  spec.steady.settle_time = settle_time;
  spec.linear_model = matrices;
  study::ModesResult r;
  try {
    py::gil_scoped_release release;
    r = study::analyzeModes(scene.scene, spec);
  } catch (const std::exception&) {
    raisePythonLawErrors(scene.user_laws);  // a Python law's error is the cause: say it
    throw;
  }
  raisePythonLawErrors(scene.user_laws);
  py::object out = jsonToPython(study::modesJsonText(scene.scene, r));
  if (r.linear) {
    py::dict lm;
    lm["A"] = matrixArray(r.linear->a);
    lm["B"] = matrixArray(r.linear->b);
    lm["K"] = matrixArray(r.linear->k);
    lm["C"] = matrixArray(r.linear->c);
    lm["states"] = r.linear->states;
    lm["inputs"] = r.linear->inputs;
    out["linear_model"] = lm;
  }
  return out;
}

py::list runTradeoff(const py::object& scene, const py::object& set,
                     const std::vector<std::string>& integrators, double window, int repeat) {
  study::TradeoffSpec spec;
  if (py::isinstance<SceneHandle>(scene)) {
    const auto& h = scene.cast<const SceneHandle&>();
    if (h.source != SceneHandle::Source::kFile || !h.user_laws.empty())
      throw py::value_error("tradeoff: give a scene file (the study loads it once per setting)");
    spec.scene_path = h.origin;
    spec.overrides = h.overrides;
  } else {
    spec.scene_path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  }
  for (const std::string& o : overridesFrom(set)) spec.overrides.push_back(o);
  if (!integrators.empty()) {
    spec.integrators.clear();
    for (const std::string& name : integrators) {
      try {
        spec.integrators.push_back(integratorFromName(name));
      } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
      }
    }
  }
  spec.window = window;
  spec.repeat = repeat;
  study::TradeoffResult result;
  {
    py::gil_scoped_release release;
    result = study::measureTradeoff(spec);
  }
  // tradeoff.csv's columns (study::tradeoffFields), numbers at full precision, NaN for none.
  const std::string scene_name = std::filesystem::path(spec.scene_path).stem().string();
  py::list rows;
  for (const study::TradeoffRow& r : result.rows) {
    py::dict d;
    for (const study::TradeoffField& f : study::tradeoffFields(scene_name, r)) {
      using K = study::TradeoffField::Kind;
      if (f.kind == K::kNumber)
        d[f.name] = f.number;
      else if (f.kind == K::kCount)
        d[f.name] = f.count;
      else
        d[f.name] = f.text;
    }
    rows.append(d);
  }
  return rows;
}

}  // namespace

void bindStudies(py::module_& m) {
  m.def("sweep", &runSweep, py::arg("scene"), py::arg("grid"), py::arg("set") = py::none(),
        py::arg("jobs") = 0u, py::arg("analysis") = "run", py::arg("out") = py::none(),
        py::arg("keep_trajectories") = false, py::arg("progress") = false,
        "sweep(scene, grid={name: 'START:STOP:COUNT' or [values]}, set={...}, jobs=0, "
        "analysis='run'|'modes', out=None) -> list of dicts, one per grid point, the rows of "
        "results.csv (numbers as floats). out=None: a temporary folder, removed afterwards; "
        "with out, the folder `tribo sweep --out` writes (resumable). jobs=0: one per core.");
  m.def("modes", &runModes, py::arg("scene"), py::arg("settle") = false,
        py::arg("settle_time") = 0.0, py::arg("matrices") = false,
        "modes(scene, settle=False) -> dict: the linear stability of the scene's steady "
        "sliding, as `tribo modes` computes it: modes.json's document (modes sorted by "
        "decreasing growth rate, 'unstable_count' the unstable ones; a figure that is not "
        "finite is None). matrices=True adds 'linear_model': the arrays A, B, K, C of y' = A y + "
        "B w with the names of their 'states' and 'inputs' (the loads' components and the "
        "actuators' targets). Raises NoSteadyState, ModesError.");
  m.def("tradeoff", &runTradeoff, py::arg("scene"), py::arg("set") = py::none(),
        py::arg("integrators") = std::vector<std::string>{}, py::arg("window") = 10.0,
        py::arg("repeat") = 1,
        "tradeoff(scene_file, set={...}, integrators=[...], window=10, repeat=1) -> list of "
        "dicts, one per setting (tradeoff.csv's columns and rows at full precision, NaN for "
        "an empty field; the first is the reference at half its step), as `tribo tradeoff` "
        "measures them: amplitude and trajectory errors "
        "against a converged reference, and the processor time.");
}

}  // namespace tribo::python
