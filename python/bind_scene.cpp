// Scenes and runs: tribo.load_scene / tribo.load_urdf give a Scene (its parameters, bodies,
// joints, settings and notes readable); Scene.run runs it as `tribo run` does
// (study/scene_run.hpp) and gives a Result: the trajectory's columns as NumPy arrays that view
// the recording (no copy) and the summary as the dict of the summary.json `tribo run` writes
// (study/result_writer.hpp: the same text, so the same numbers). The GIL is released during
// the run; Ctrl-C stops it at once, back at the last output row, and raises KeyboardInterrupt
// carrying the partial Result as its `result` attribute. Result.save writes the run folder
// `tribo run` writes; Result._view_page gives the replay page's HTML (study/view/view_page.hpp)
// for the notebook display of python/tribo/_notebook.py.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>

#include "io/output_channels.hpp"
#include "io/scene_parameters.hpp"
#include "python/bindings.hpp"
#include "python/python_law.hpp"
#include "python/scene_handle.hpp"
#include "study/result_writer.hpp"
#include "study/scene_run.hpp"
#include "study/view/view_page.hpp"

namespace tribo::python {
namespace {

struct PyResult {
  std::shared_ptr<const io::Scene> scene;
  study::RunResult run;
  std::string summary_text;
};

const char* statusName(const study::RunResult& r) { return study::runStatusName(r); }

// A read-only array viewing column c of the result's recording; keeps the result alive.
py::array columnArray(const py::object& owner, const PyResult& r, std::size_t c) {
  const auto column = r.run.trajectory.column(c);
  py::array_t<double> a({static_cast<py::ssize_t>(column.size())}, {sizeof(double)}, column.data(),
                        owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A run setting given in Python: a number (int or float, not bool), else a TypeError naming
// the argument and what was found.
double settingNumber(const py::object& value, const char* name, const char* unit) {
  if ((py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) &&
      !py::isinstance<py::bool_>(value))
    return value.cast<double>();
  throw py::type_error(std::string("run: ") + name + " must be a number [" + unit + "], got " +
                       std::string(py::str(value.get_type().attr("__name__"))) + " " +
                       std::string(py::repr(value)));
}

io::RunSettings settingsFrom(const py::object& duration, const py::object& time_step,
                             const py::object& integrator, const py::object& rtol,
                             const py::object& atol, const py::object& output_interval) {
  io::RunSettings s;
  if (!duration.is_none()) s.duration = settingNumber(duration, "duration", "s");
  if (!time_step.is_none()) s.time_step = settingNumber(time_step, "time_step", "s");
  if (!integrator.is_none()) {
    try {
      s.integrator = integratorFromName(integrator.cast<std::string>());
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
  }
  if (!rtol.is_none()) s.relative_tolerance = settingNumber(rtol, "relative_tolerance", "-");
  if (!atol.is_none()) s.absolute_tolerance = settingNumber(atol, "absolute_tolerance", "-");
  if (!output_interval.is_none())
    s.output_interval = settingNumber(output_interval, "output_interval", "s");
  return s;
}

py::object runHandle(const SceneHandle& h, const py::object& duration, const py::object& time_step,
                     const py::object& integrator, const py::object& rtol, const py::object& atol,
                     const py::object& output_interval, const py::object& controller,
                     double control_interval) {
  auto scene = std::make_shared<const io::Scene>(
      h.withSettings(settingsFrom(duration, time_step, integrator, rtol, atol, output_interval)));
  std::atomic<bool> stop{false};
  bool by_signal = false;
  study::RunOptions options;
  options.stop = &stop;
  // About every 0.25 s of wall time: a pending Ctrl-C stops the run at the next row.
  options.progress = [&](double) {
    py::gil_scoped_acquire hold;
    if (PyErr_CheckSignals() != 0) {
      PyErr_Clear();
      by_signal = true;
      stop = true;
    }
  };
  auto raised = std::make_shared<py::object>();
  if (!controller.is_none()) {
    if (!PyCallable_Check(controller.ptr()))
      throw py::type_error("controller must be callable: f(control) -> None or dict");
    if (!(control_interval >= 0.0) || !std::isfinite(control_interval))
      throw py::value_error("control_interval must be finite and >= 0 (0: every step)");
    options.controller = pythonController(controller, raised);
    options.control_interval = control_interval;
  }
  std::unique_ptr<PyResult> result;
  {
    py::gil_scoped_release release;
    result.reset(new PyResult{scene, study::runScene(*scene, options), {}});
  }
  raisePythonLawErrors(h.user_laws);  // a Python law's exception stopped the run
  result->summary_text = study::summaryJsonText(*scene, result->run);
  py::object owner = py::cast(std::move(result));
  if (*raised && !raised->is_none()) {  // the controller's exception, with the partial result
    raised->attr("result") = owner;
    PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(raised->ptr())), raised->ptr());
    throw py::error_already_set();
  }
  if (by_signal) {
    py::object interrupt = py::reinterpret_borrow<py::object>(PyExc_KeyboardInterrupt)(
        "run interrupted; the partial result is this exception's `result`");
    interrupt.attr("result") = owner;
    PyErr_SetObject(PyExc_KeyboardInterrupt, interrupt.ptr());
    throw py::error_already_set();
  }
  return owner;
}

py::list bodiesOf(const Model& model) {
  py::list out;
  for (const Body& b : model.bodies) {
    py::dict d;
    d["name"] = b.name;
    d["kind"] = b.kind == BodyKind::kDynamic ? "dynamic" : "kinematic";
    d["mass"] = b.mass;
    out.append(d);
  }
  return out;
}

py::list jointsOf(const Model& model) {
  py::list out;
  auto nameOf = [&](BodyIndex b) {
    return b.isWorld() ? std::string("world") : model.bodies[b.value].name;
  };
  for (const Joint& j : model.joints) {
    py::dict d;
    d["name"] = j.name;
    d["type"] = jointTypeName(j.type);
    d["parent"] = nameOf(j.parent);
    d["child"] = nameOf(j.child);
    out.append(d);
  }
  return out;
}

// The replay page of a result: written with its scene into a scratch folder (the page reads
// trajectory.csv and summary.json, as `tribo view` does), read back, the folder removed.
std::string viewPageOf(const PyResult& r, std::size_t frame_cap) {
  std::string pattern = (std::filesystem::temp_directory_path() / "tribo-view-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a temporary folder: " +
                             std::string(std::strerror(errno)));
  const std::filesystem::path dir = pattern;
  try {
    study::writeResults(dir, *r.scene, r.run);
    study::ViewOptions options;
    options.frame_cap = frame_cap;
    std::string page = study::runViewPage(*r.scene, dir, options);
    std::filesystem::remove_all(dir);
    return page;
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    throw;
  }
}

py::dict settingsOf(const io::Scene& s) {
  const SimulationOptions& o = s.model->options;
  py::dict d;
  d["integrator"] = integratorName(o.integrator);
  d["time_step"] = o.time_step;
  d["duration"] = o.duration;
  d["relative_tolerance"] = o.relative_tolerance;
  d["absolute_tolerance"] = o.absolute_tolerance;
  d["output_interval"] = s.output.interval;
  d["channels"] = s.output.channels;
  return d;
}

}  // namespace

std::vector<std::string> overridesFrom(const py::object& set) {
  std::vector<std::string> out;
  if (set.is_none()) return out;
  for (const auto& [key, value] : set.cast<py::dict>()) {
    std::string text;
    if (py::isinstance<py::bool_>(value))
      text = value.cast<bool>() ? "true" : "false";
    else if (py::isinstance<py::str>(value) || py::isinstance<py::int_>(value) ||
             py::isinstance<py::float_>(value))
      text = py::str(value).cast<std::string>();  // floats: the shortest exact spelling
    else
      throw py::type_error("set: the value of '" + key.cast<std::string>() +
                           "' must be a str, int, float or bool");
    out.push_back(key.cast<std::string>() + "=" + text);
  }
  return out;
}

std::vector<std::string> pathsFrom(const py::object& paths) {
  std::vector<std::string> out;
  if (paths.is_none()) return out;
  const py::object fspath = py::module_::import("os").attr("fspath");
  for (const py::handle p : paths) out.push_back(fspath(p).cast<std::string>());
  return out;
}

py::object jsonToPython(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

void bindScene(py::module_& m) {
  py::class_<PyResult>(m, "Result",
                       "A run's result: the trajectory's columns (NumPy arrays viewing the "
                       "recording), the summary dict (summary.json's content), the status.")
      .def_property_readonly("status", [](const PyResult& r) { return statusName(r.run); })
      .def_property_readonly("complete", [](const PyResult& r) { return r.run.complete; })
      .def_property_readonly("message", [](const PyResult& r) { return r.run.message; })
      .def_property_readonly("warnings", [](const PyResult& r) { return r.run.warnings; })
      .def_property_readonly("columns",
                             [](const PyResult& r) { return r.run.trajectory.columns(); })
      .def_property_readonly(
          "trajectory",
          [](const py::object& self) {
            const PyResult& r = self.cast<const PyResult&>();
            py::dict d;
            const auto& names = r.run.trajectory.columns();
            for (std::size_t c = 0; c < names.size(); ++c)
              d[py::str(names[c])] = columnArray(self, r, c);
            return d;
          },
          "Column name -> 1-D array (read-only view, no copy), in recording order.")
      .def(
          "__getitem__",
          [](const py::object& self, const std::string& name) {
            const PyResult& r = self.cast<const PyResult&>();
            std::size_t c = 0;
            try {
              c = r.run.trajectory.columnIndex(name);
            } catch (const std::out_of_range&) {
              throw py::key_error("no recorded column '" + name + "'");
            }
            return columnArray(self, r, c);
          },
          py::arg("column"))
      .def_property_readonly(
          "summary", [](const PyResult& r) { return jsonToPython(r.summary_text); },
          "The summary as `tribo run` writes it to summary.json, as a dict.")
      .def_property_readonly("summary_json", [](const PyResult& r) { return r.summary_text; })
      .def(
          "save",
          [](const PyResult& r, const py::object& folder) {
            const std::string dir =
                py::module_::import("os").attr("fspath")(folder).cast<std::string>();
            py::gil_scoped_release release;
            study::writeResults(dir, *r.scene, r.run);
          },
          py::arg("folder"),
          "save(folder): writes trajectory.csv and summary.json into folder (created if "
          "missing), the files `tribo run --out folder` writes; `tribo view folder` then draws "
          "it (for a scene loaded from a file).")
      .def(
          "_view_page",
          [](const PyResult& r, std::size_t frame_cap) {
            py::gil_scoped_release release;
            return viewPageOf(r, frame_cap);
          },
          py::arg("frame_cap") = 20000,
          "The replay page (`tribo view`'s view.html) of this result as one HTML text.")
      .def("__repr__", [](const PyResult& r) {
        return "<tribo.Result " + std::string(statusName(r.run)) + ", " +
               std::to_string(r.run.trajectory.rows()) + " rows>";
      });

  py::class_<SceneHandle>(m, "Scene", "A loaded scene (a scene file, YAML text or a URDF).")
      .def_property_readonly("path", [](const SceneHandle& h) { return h.scene.path; })
      .def_property_readonly(
          "parameters",
          [](const SceneHandle& h) {
            py::dict d;
            for (const auto& [name, value] : h.scene.parameters) {
              if (const auto number = io::parseNumber(value))
                d[py::str(name)] = *number;  // a number as a float
              else
                d[py::str(name)] = value;  // a word or an expression, as written
            }
            return d;
          },
          "Parameter name -> value after overrides, in file order: a float for a number, "
          "else the text (a word, or an expression as written).")
      .def_property_readonly("bodies",
                             [](const SceneHandle& h) { return bodiesOf(*h.scene.model); })
      .def_property_readonly("joints",
                             [](const SceneHandle& h) { return jointsOf(*h.scene.model); })
      .def_property_readonly("settings", [](const SceneHandle& h) { return settingsOf(h.scene); })
      .def_property_readonly("notes", [](const SceneHandle& h) { return h.scene.notes; })
      .def_property_readonly(
          "columns",
          [](const SceneHandle& h) {
            return study::TrajectoryRecorder(*h.scene.model, 0, false, h.scene.output.channels)
                .columns();
          },
          "The columns a run records (the scene's output.channels).")
      .def("run", &runHandle, py::arg("duration") = py::none(), py::arg("time_step") = py::none(),
           py::arg("integrator") = py::none(), py::arg("relative_tolerance") = py::none(),
           py::arg("absolute_tolerance") = py::none(), py::arg("output_interval") = py::none(),
           py::arg("controller") = py::none(), py::arg("control_interval") = 0.0,
           "Runs the scene (settings given replace the scene's own) and returns a Result. "
           "controller: f(tribo.Control) called before the first step and every "
           "control_interval [s] (0: every step) to command the scene's actuators; an "
           "exception in it stops the run and is raised with the partial Result as its "
           "`result`.")
      .def("__repr__", [](const SceneHandle& h) {
        return "<tribo.Scene " + h.scene.path + ", " +
               std::to_string(h.scene.model->bodies.size()) + " bodies>";
      });

  m.def(
      "load_scene",
      [](const py::object& source, const py::object& set, const py::object& package_paths,
         const py::object& laws) {
        const std::string text =
            py::isinstance<py::str>(source)
                ? source.cast<std::string>()
                : py::module_::import("os").attr("fspath")(source).cast<std::string>();
        auto overrides = overridesFrom(set);
        auto paths = pathsFrom(package_paths);
        auto user_laws = userLawsFrom(laws);
        py::gil_scoped_release release;
        return loadSceneHandle(text, std::move(overrides), std::move(paths), std::move(user_laws));
      },
      py::arg("source"), py::arg("set") = py::none(), py::arg("package_paths") = py::none(),
      py::arg("laws") = py::none(),
      "load_scene(path_or_yaml_text, set={name: value}, package_paths=[...]) -> Scene. A str "
      "naming an existing file is a path, other text with a line break or a colon is YAML. "
      "laws={name: law} adds friction laws a material's `friction:` may select: a "
      "tribo.FrictionLaw, a callable mu(v) or an object with mu(v) (and optionally slope(v), "
      "stick_speed, max_coefficient(v_max)). Raises SceneError.");
  m.def(
      "load_urdf",
      [](const py::object& path, const py::object& set, const py::object& package_paths,
         bool strict) {
        const std::string p = py::module_::import("os").attr("fspath")(path).cast<std::string>();
        auto overrides = overridesFrom(set);
        auto paths = pathsFrom(package_paths);
        py::gil_scoped_release release;
        return loadUrdfHandle(p, std::move(overrides), std::move(paths), strict);
      },
      py::arg("path"), py::arg("set") = py::none(), py::arg("package_paths") = py::none(),
      py::arg("strict") = false,
      "load_urdf(path, set={...}, package_paths=[...], strict=False) -> Scene: the robot "
      "dropped on a ground plane, as `tribo run ROBOT.urdf`. Raises UrdfError, SceneError.");
}

}  // namespace tribo::python
