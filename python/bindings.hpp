// The parts of the `tribo` Python module, one function per concern, called in this order by
// module.cpp: exceptions first (the others' docstrings name them), then friction laws,
// scenes and runs, the step-by-step simulator, and the studies (modes, tradeoff, sweeps).
// The extension is the package's `tribo._core`; python/tribo/ re-exports it and adds the
// parts written in Python (notebook display, sweeps on executors).
// Conventions shared by all parts (docs/python.md):
//   - arrays of per-body vectors are (n, 3) float64, quaternions (n, 4) in (x, y, z, w) order
//     (Eigen's and scipy's), world frame, SI units;
//   - arrays that view memory a result owns keep that result alive (no copy);
//   - the GIL is released while the engine runs (runs, steps, sweeps, modes, law loops).
// Not here: physics, analysis or file formats of their own; everything is the C++ library's.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/math.hpp"

namespace tribo {
class Simulator;
}

namespace tribo::python {

namespace py = pybind11;

void bindErrors(py::module_& m);
void bindFriction(py::module_& m);
void bindScene(py::module_& m);
void bindSimulator(py::module_& m);
void bindControl(py::module_& m);
void bindStudies(py::module_& m);
void bindSweep(py::module_& m);

// "NAME=VALUE" strings (the command line's --set) from a dict of name -> str, int, float or
// bool; floats in Python's shortest round-trip spelling, so a value crosses exactly.
std::vector<std::string> overridesFrom(const py::object& set);
// A list of str / os.PathLike (or None) as strings.
std::vector<std::string> pathsFrom(const py::object& paths);
// The run's controller hook (study::RunOptions::controller) calling the Python callable `f`
// with a tribo.Control (python/bind_control.cpp); an exception in `f` stops the run and is
// kept in `raised` for the caller to raise again.
std::function<std::string(Simulator&)> pythonController(py::object f,
                                                        std::shared_ptr<py::object> raised);
// Simulator.set_load and Control.set_load: load `name`'s force and torque held at the given
// 3-vectors (sequences or NumPy arrays, in the load's frame) in place of its signals; a part
// given as None goes back to its signals. Raises KeyError naming the loads, ValueError for a
// vector that is not 3 finite numbers.
// Returns what it commanded.
struct LoadCommand {
  std::size_t load = 0;
  std::optional<Vec3> force = std::nullopt, torque = std::nullopt;
};
LoadCommand setLoadFromPython(Simulator& sim, const std::string& name, const py::object& force,
                              const py::object& torque);
// Python's json.loads of a JSON text (the engine's own JSON, e.g. summary.json's).
py::object jsonToPython(const std::string& text);

}  // namespace tribo::python
