// Exceptions: each C++ error class of the library becomes a Python exception carrying the
// same message (what() reads "FILE:LINE:COL: key.path: expected ..., found ..." for scenes),
// all derived from tribo.Error and from the Python class a caller would catch for that kind
// of problem (ValueError for bad input, RuntimeError for a computation that failed).
// tribo.SceneError also carries file, line, column, key and detail as attributes.
#include <Python.h>

#include "contact/mesh_shape.hpp"
#include "core/model_builder.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_parameters.hpp"
#include "io/urdf_reader.hpp"
#include "python/bindings.hpp"
#include "study/modes/modes.hpp"
#include "study/modes/steady_state.hpp"
#include "study/orbit/periodic_orbit.hpp"
#include "study/output_budget.hpp"
#include "study/sweep/sweep_grid.hpp"

namespace tribo::python {
namespace {

// A new exception class tribo.NAME deriving from `bases` (a tuple), added to the module.
py::object newError(py::module_& m, const char* name, const py::tuple& bases, const char* doc) {
  const std::string qualified = std::string("tribo.") + name;
  py::dict namespace_dict;
  namespace_dict["__doc__"] = doc;
  PyObject* type = PyErr_NewException(qualified.c_str(), bases.ptr(), namespace_dict.ptr());
  if (type == nullptr) throw py::error_already_set();
  py::object result = py::reinterpret_steal<py::object>(type);
  m.attr(name) = result;
  return result;
}

// Set as the pending Python error: an instance of `type` with `message`.
void raise(const py::object& type, const char* message) { PyErr_SetString(type.ptr(), message); }

}  // namespace

void bindErrors(py::module_& m) {
  const py::object base = newError(m, "Error", py::make_tuple(py::handle(PyExc_Exception)),
                                   "Any error of the tribo library.");
  const py::handle value_error(PyExc_ValueError), runtime_error(PyExc_RuntimeError);
  // Leaked on purpose: the translator below lives as long as the interpreter.
  static py::object* scene = new py::object(newError(
      m, "SceneError", py::make_tuple(base, value_error),
      "A problem with a scene file, its text or its overrides. Attributes: file, line, column "
      "(1-based, 0 when unknown), key (the key path) and detail (the message without place)."));
  static py::object* urdf = new py::object(newError(
      m, "UrdfError", py::make_tuple(base, value_error), "A URDF file that cannot be used."));
  static py::object* law =
      new py::object(newError(m, "FrictionParameterError", py::make_tuple(base, value_error),
                              "A friction law's name or parameters are wrong."));
  static py::object* model = new py::object(newError(
      m, "ModelError", py::make_tuple(base, value_error), "A model that cannot be built."));
  static py::object* mesh = new py::object(
      newError(m, "MeshError", py::make_tuple(base, value_error), "A mesh that cannot be used."));
  static py::object* sweep =
      new py::object(newError(m, "SweepSpecError", py::make_tuple(base, value_error),
                              "A sweep's grid or settings are wrong."));
  static py::object* steady = new py::object(
      newError(m, "NoSteadyState", py::make_tuple(base, runtime_error),
               "The steady-state search of a modes analysis found no steady state."));
  static py::object* modes = new py::object(
      newError(m, "ModesError", py::make_tuple(base, runtime_error),
               "A scene that cannot be analysed for modes, or numbers that failed."));
  static py::object* output =
      new py::object(newError(m, "OutputTooLarge", py::make_tuple(base, runtime_error),
                              "A run whose recording would not fit the memory cap."));
  static py::object* orbit = new py::object(
      newError(m, "OrbitError", py::make_tuple(base, runtime_error),
               "No periodic orbit: a forced scene, no oscillation, or Newton not converging."));

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::SceneError& e) {
      py::object error = (*scene)(e.what());
      error.attr("file") = e.where().file;
      error.attr("line") = e.where().line;
      error.attr("column") = e.where().column;
      error.attr("key") = e.keyPath();
      error.attr("detail") = e.detail();
      PyErr_SetObject(scene->ptr(), error.ptr());
    } catch (const io::UrdfError& e) {
      raise(*urdf, e.what());
    } catch (const friction::FrictionParameterError& e) {
      raise(*law, e.what());
    } catch (const ModelError& e) {
      raise(*model, e.what());
    } catch (const contact::MeshError& e) {
      raise(*mesh, e.what());
    } catch (const study::SweepSpecError& e) {
      raise(*sweep, e.what());
    } catch (const study::NoSteadyState& e) {
      raise(*steady, e.what());
    } catch (const study::ModesError& e) {
      raise(*modes, e.what());
    } catch (const study::OutputTooLarge& e) {
      raise(*output, e.what());
    } catch (const study::OrbitError& e) {
      raise(*orbit, e.what());
    }
  });
}

}  // namespace tribo::python
