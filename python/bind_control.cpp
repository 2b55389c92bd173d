// Controllers written in Python: run(..., controller=f, control_interval=dt_c) calls f(c)
// before the first step and then every dt_c of simulated time (every step when 0), with
// c a tribo.Control: the time, the scalar joints' names with their coordinates q and rates qd
// as NumPy arrays in that order (the values the engine's actuators see), the actuators'
// names, a copy of the state, and set(name, value) to command an actuator in place of its
// target signal (held until the next call: a zero-order hold). f may also return a dict of
// actuator name -> value. An exception in f stops the run cleanly after the rows so far; the
// run's Result is then the exception's `result`. A Control is valid only during its call.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/simulator.hpp"
#include "python/bindings.hpp"

namespace tribo::python {
namespace {

struct PyControl {
  Simulator* sim = nullptr;  // during the call only
  const Simulator& live() const {
    if (sim == nullptr)
      throw py::value_error("this Control was used after its controller call returned");
    return *sim;
  }
  void set(const std::string& name, double value) {
    if (sim == nullptr)
      throw py::value_error("this Control was used after its controller call returned");
    const auto joint = sim->model().findActuator(name);
    if (!joint) {
      std::string known;
      for (const Joint& j : sim->model().joints)
        if (j.elements.actuator) known += (known.empty() ? "" : ", ") + j.elements.actuator->name;
      throw py::key_error("no actuator '" + name +
                          "' (actuators: " + (known.empty() ? "none" : known) + ")");
    }
    if (!std::isfinite(value))
      throw py::value_error("actuator '" + name + "': command must be finite, got " +
                            std::to_string(value));
    sim->setActuatorCommand(*joint, value);
  }
  void setLoad(const std::string& name, const py::object& force, const py::object& torque) {
    if (sim == nullptr)
      throw py::value_error("this Control was used after its controller call returned");
    setLoadFromPython(*sim, name, force, torque);
  }
};

std::optional<Vec3> vectorFrom(const std::string& what, const py::object& v) {
  if (v.is_none()) return std::nullopt;
  std::vector<double> values;
  try {
    for (const py::handle x : v) values.push_back(x.cast<double>());
  } catch (const std::exception&) {
    throw py::value_error(what + ": expected 3 numbers");
  }
  if (values.size() != 3)
    throw py::value_error(what + ": expected 3 numbers, got " + std::to_string(values.size()));
  const Vec3 out(values[0], values[1], values[2]);
  if (!out.allFinite()) throw py::value_error(what + ": expected finite numbers");
  return out;
}

// q and q' of every revolute and prismatic joint at the simulator's state, with the
// rotations the engine itself derives from it (Dynamics::updatePoses), so the values are
// the actuators' to the last bit.
std::pair<py::array_t<double>, py::array_t<double>> coordinates(const Simulator& sim) {
  const Model& m = sim.model();
  const State& s = sim.state();
  std::vector<Mat3> rotations;
  rotations.reserve(s.bodies.size());
  for (const BodyState& b : s.bodies) rotations.push_back(b.orientation.toRotationMatrix());
  const MotionView motion(s, rotations);
  std::vector<double> q, qd;
  for (const Joint& j : m.joints) {
    if (!hasScalarCoordinate(j.type)) continue;
    const JointCoordinate c = jointCoordinate(j);
    CoordinateValue v;
    evaluateCoordinate(c, motion(c.parent), motion(c.child), v);
    q.push_back(v.q);
    qd.push_back(v.rate);
  }
  return {py::array_t<double>(static_cast<py::ssize_t>(q.size()), q.data()),
          py::array_t<double>(static_cast<py::ssize_t>(qd.size()), qd.data())};
}

}  // namespace

LoadCommand setLoadFromPython(Simulator& sim, const std::string& name, const py::object& force,
                              const py::object& torque) {
  const auto load = sim.model().findLoad(name);
  if (!load) {
    std::string known;
    for (const AppliedLoad& l : sim.model().loads) known += (known.empty() ? "" : ", ") + l.name;
    throw py::key_error("no load '" + name + "' (loads: " + (known.empty() ? "none" : known) + ")");
  }
  LoadCommand command{*load, vectorFrom("load '" + name + "' force", force),
                      vectorFrom("load '" + name + "' torque", torque)};
  sim.setLoadCommand(command.load, command.force, command.torque);
  return command;
}

std::function<std::string(Simulator&)> pythonController(py::object f,
                                                        std::shared_ptr<py::object> raised) {
  return [f = std::move(f), raised](Simulator& sim) -> std::string {
    py::gil_scoped_acquire hold;
    auto control = std::make_shared<PyControl>();
    control->sim = &sim;
    try {
      const py::object out = f(py::cast(control));
      if (py::isinstance<py::dict>(out))
        for (const auto& [name, value] : out.cast<py::dict>())
          control->set(name.cast<std::string>(), value.cast<double>());
      else if (!out.is_none())
        throw py::type_error("a controller returns None or a dict of actuator -> value, not " +
                             std::string(py::str(out.get_type().attr("__name__"))));
    } catch (py::error_already_set& e) {
      control->sim = nullptr;
      *raised = e.value();
      return "controller raised " + std::string(py::str(e.type().attr("__name__"))) + ": " +
             std::string(py::str(e.value())) + " at t = " + std::to_string(sim.state().time) + " s";
    } catch (const py::builtin_exception& e) {  // set()'s KeyError and ValueError
      control->sim = nullptr;
      e.set_error();
      const py::error_already_set error;  // takes the error just set
      *raised = error.value();
      return "controller raised " + std::string(py::str(error.type().attr("__name__"))) + ": " +
             e.what() + " at t = " + std::to_string(sim.state().time) + " s";
    }
    control->sim = nullptr;
    return {};
  };
}

void bindControl(py::module_& m) {
  py::class_<PyControl, std::shared_ptr<PyControl>>(
      m, "Control", "What a controller sees and commands at one call (valid during the call only).")
      .def_property_readonly(
          "time", [](const PyControl& c) { return c.live().state().time; }, "t [s]")
      .def_property_readonly(
          "joint_names",
          [](const PyControl& c) {
            std::vector<std::string> names;
            for (const Joint& j : c.live().model().joints)
              if (hasScalarCoordinate(j.type)) names.push_back(j.name);
            return names;
          },
          "The revolute and prismatic joints, in the order of q and qd.")
      .def_property_readonly(
          "q", [](const PyControl& c) { return coordinates(c.live()).first; },
          "Joint coordinates [rad or m] (revolute angles wrapped to (-pi, pi]).")
      .def_property_readonly(
          "qd", [](const PyControl& c) { return coordinates(c.live()).second; },
          "Joint rates [rad/s or m/s].")
      .def_property_readonly("actuator_names",
                             [](const PyControl& c) {
                               std::vector<std::string> names;
                               for (const Joint& j : c.live().model().joints)
                                 if (j.elements.actuator)
                                   names.push_back(j.elements.actuator->name);
                               return names;
                             })
      .def_property_readonly(
          "state", [](const PyControl& c) { return State(c.live().state()); },
          "A copy of the state.")
      .def("set", &PyControl::set, py::arg("actuator"), py::arg("value"),
           "Commands an actuator (its target: an effort, a position or a rate) from now until "
           "the next call, in place of its target signal.")
      .def("set_load", &PyControl::setLoad, py::arg("load"), py::arg("force") = py::none(),
           py::arg("torque") = py::none(),
           "Holds a load's force and/or torque (3 numbers or an array each, in the load's "
           "frame) in place of its signals from now on; a part given as None goes back to "
           "its signals.");
}

}  // namespace tribo::python
