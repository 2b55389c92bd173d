// Step-by-step control: tribo.Simulator(scene) owns a core Simulator (core/simulator.hpp)
// and steps it as `tribo run` does; its state is a tribo.State whose positions,
// orientations, velocities and angular velocities are NumPy arrays viewing the State's own
// memory ((n, 3) and (n, 4), writable: edit them, then assign the State back). A State
// also carries the friction laws' internal states, so state get/set round-trips bit for
// bit. contacts() gives the current contact points and forces as arrays; status the last
// step's outcome with the same message the command line prints. set_parameters changes
// scene parameters in the middle of a run: the model is built again with the new values
// (a built Model is never edited) and the run goes on from the same state, when the state's
// layout (bodies, friction states, contact pairs) is unchanged.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <string>

#include "core/simulator.hpp"
#include "python/bindings.hpp"
#include "python/python_law.hpp"
#include "python/scene_handle.hpp"
#include "study/result_writer.hpp"

namespace tribo::python {
namespace {

// BodyState is four Eigen members; the arrays stride over them in place.
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
static_assert(sizeof(Quat) == 4 * sizeof(double), "Quat must be four packed doubles");

// An (n, width) array over member `offset` of every BodyState; keeps `owner` alive.
py::array bodyArray(const py::object& owner, State& s, std::size_t offset, py::ssize_t width) {
  auto* base = reinterpret_cast<double*>(reinterpret_cast<char*>(s.bodies.data()) + offset);
  return py::array_t<double>(
      {static_cast<py::ssize_t>(s.bodies.size()), width},
      {static_cast<py::ssize_t>(sizeof(BodyState)), static_cast<py::ssize_t>(sizeof(double))}, base,
      owner);
}

template <std::size_t Offset, py::ssize_t Width>
py::cpp_function bodyField() {
  return py::cpp_function(
      [](const py::object& self) { return bodyArray(self, self.cast<State&>(), Offset, Width); });
}

py::dict statusDict(const StepStatus& s) {
  py::dict d;
  d["ok"] = s.ok;
  d["message"] = s.message;
  d["time"] = s.time;
  d["body"] = s.body;
  d["quantity"] = s.quantity;
  return d;
}

// One array per contact quantity, one row per contact point of the current evaluation.
py::dict contactsOf(const Model& model, const Workspace& ws) {
  const auto n = static_cast<py::ssize_t>(ws.contacts.size());
  py::array_t<double> position({n, py::ssize_t{3}}), normal({n, py::ssize_t{3}}),
      friction({n, py::ssize_t{3}}), slip({n, py::ssize_t{3}});
  py::array_t<double> depth(n), normal_force(n), mu(n);
  py::list body_a, body_b;
  auto bodyName = [&](int geometry) {
    const BodyIndex b = model.geometries[static_cast<std::size_t>(geometry)].body;
    return b.isWorld() ? std::string("world")
                       : model.bodies[static_cast<std::size_t>(b.value)].name;
  };
  for (py::ssize_t i = 0; i < n; ++i) {
    const contact::ContactRecord& c = ws.contacts[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      position.mutable_at(i, k) = c.point.position[k];
      normal.mutable_at(i, k) = c.point.normal[k];
      friction.mutable_at(i, k) = c.friction_force[k];
      slip.mutable_at(i, k) = c.slip[k];
    }
    depth.mutable_at(i) = c.point.depth;
    normal_force.mutable_at(i) = c.normal_force;
    mu.mutable_at(i) = c.mu;
    const ContactPair pair = model.contactPair(c.point.pair);
    body_a.append(bodyName(pair.geometry_a));
    body_b.append(bodyName(pair.geometry_b));
  }
  py::dict d;
  d["position"] = position;
  d["normal"] = normal;  // from A into B
  d["depth"] = depth;
  d["normal_force"] = normal_force;
  d["friction_force"] = friction;  // on B
  d["slip"] = slip;                // B relative to A
  d["mu"] = mu;
  d["body_a"] = body_a;
  d["body_b"] = body_b;
  return d;
}

// Steps between two looks for a pending signal (Ctrl-C) in step(n).
constexpr long kSignalSteps = 1024;

// The Python-side simulator: the scene it runs, the core simulator and the status of its
// last step.
struct PySimulator {
  SceneHandle scene;
  std::shared_ptr<const Model> model;
  io::UserLaws user_laws;  // the scene's Python laws, for their exceptions
  std::unique_ptr<Simulator> sim;
  StepStatus status;
  std::map<int, double> commands;  // actuator commands given (joint -> value), kept across
                                   // set_parameters
  std::map<std::size_t, LoadCommand> load_commands;  // likewise, the loads' (by index)
  explicit PySimulator(const SceneHandle& handle)
      : scene(handle),
        model(scene.scene.model),
        user_laws(scene.user_laws),
        sim(std::make_unique<Simulator>(model)) {}
};

// A friction law's part of the state's layout: -1 without memory, 0 for stick anchors, the
// internal state's size for a dynamic law (with its tangent vectors, which are rotated).
std::pair<int, int> memoryOf(const friction::FrictionLaw& law) {
  if (const friction::DynamicFrictionLaw* d = law.dynamic())
    return {d->stateSize(), d->tangentVectors()};
  return {law.stateful() ? 0 : -1, 0};
}

// Why a state of `from` cannot go on in `to`, or empty: the parts of the state a step reads
// by position (bodies, joints) or sizes by each material's and joint's friction law.
std::string layoutDifference(const Model& from, const Model& to) {
  auto count = [](const char* what, std::size_t a, std::size_t b) {
    return std::string(what) + " " + std::to_string(a) + " -> " + std::to_string(b);
  };
  if (from.bodies.size() != to.bodies.size())
    return count("bodies", from.bodies.size(), to.bodies.size());
  if (from.joints.size() != to.joints.size())
    return count("joints", from.joints.size(), to.joints.size());
  if (from.loads.size() != to.loads.size())
    return count("loads", from.loads.size(), to.loads.size());
  if (from.materials.size() != to.materials.size())
    return count("contact materials", from.materials.size(), to.materials.size());
  for (std::size_t i = 0; i < from.materials.size(); ++i) {
    const auto a = memoryOf(*from.materials[i].friction), b = memoryOf(*to.materials[i].friction);
    if (a != b)
      return "the friction memory of contact material " + std::to_string(i) + ": " +
             std::string(from.materials[i].friction->name()) + " -> " +
             std::string(to.materials[i].friction->name());
  }
  for (std::size_t j = 0; j < from.joints.size(); ++j) {
    const auto& fa = from.joints[j].elements.friction;
    const auto& fb = to.joints[j].elements.friction;
    const std::pair<int, int> none{-1, 0};
    if ((fa ? memoryOf(*fa->law) : none) != (fb ? memoryOf(*fb->law) : none))
      return "the friction memory of joint '" + from.joints[j].name + "'";
  }
  return "";
}

// set_parameters: the scene with `set` merged into its overrides (a name given again takes
// the new value), the model built again, the run continued from the current state.
void setParameters(PySimulator& s, const py::object& set) {
  const std::vector<std::string> more = overridesFrom(set);
  if (more.empty()) return;
  std::vector<std::string> merged = s.scene.overrides;
  for (const std::string& o : more) {
    const std::string name = o.substr(0, o.find('='));
    std::erase_if(merged, [&](const std::string& m) { return m.rfind(name + "=", 0) == 0; });
    merged.push_back(o);
  }
  SceneHandle next = s.scene;
  next.overrides = merged;
  next.scene = next.reload();
  const State state = s.sim->state();
  if (const std::string d = layoutDifference(*s.model, *next.scene.model); !d.empty())
    throw py::value_error("set_parameters: the new values change the state's layout (" + d +
                          "); load the scene again with them and start a new run");
  auto sim = std::make_unique<Simulator>(next.scene.model);
  sim->setState(state);
  for (const auto& [joint, value] : s.commands) sim->setActuatorCommand(joint, value);
  for (const auto& [load, c] : s.load_commands) sim->setLoadCommand(load, c.force, c.torque);
  s.scene = std::move(next);
  s.model = s.scene.scene.model;
  s.sim = std::move(sim);
}

}  // namespace

void bindSimulator(py::module_& m) {
  py::class_<State>(m, "State",
                    "A run's state: time, per-body arrays viewing this object's memory, and "
                    "the friction laws' internal states (opaque).")
      .def_readwrite("time", &State::time)
      .def_property_readonly("positions", bodyField<offsetof(BodyState, position), 3>(),
                             "(n, 3) world positions of the body origins [m]")
      .def_property_readonly("orientations", bodyField<offsetof(BodyState, orientation), 4>(),
                             "(n, 4) body-to-world unit quaternions (x, y, z, w)")
      .def_property_readonly("velocities", bodyField<offsetof(BodyState, velocity), 3>(),
                             "(n, 3) world velocities of the body origins [m/s]")
      .def_property_readonly("angular_velocities",
                             bodyField<offsetof(BodyState, angular_velocity), 3>(),
                             "(n, 3) world angular velocities [rad/s]")
      .def_property_readonly(
          "friction_values",
          [](const State& s) {
            return py::array_t<double>(static_cast<py::ssize_t>(s.friction_values.size()),
                                       s.friction_values.data());
          },
          "A copy of the dynamic friction laws' internal states.")
      .def("copy", [](const State& s) { return State(s); })
      .def("__eq__", [](const State& a, const State& b) {
        // Bit for bit on everything a restart needs.
        if (a.time != b.time || a.bodies.size() != b.bodies.size() ||
            a.friction_values != b.friction_values ||
            a.stick_anchors.size() != b.stick_anchors.size() ||
            a.friction_states.size() != b.friction_states.size())
          return false;
        for (std::size_t i = 0; i < a.bodies.size(); ++i) {
          const BodyState &x = a.bodies[i], &y = b.bodies[i];
          if (x.position != y.position || x.orientation.coeffs() != y.orientation.coeffs() ||
              x.velocity != y.velocity || x.angular_velocity != y.angular_velocity)
            return false;
        }
        return true;
      });

  py::class_<PySimulator>(m, "Simulator",
                          "Step-by-step control of a scene's run (the same steps `tribo run` "
                          "takes).")
      .def(py::init<const SceneHandle&>(), py::arg("scene"))
      .def(
          "step",
          [](PySimulator& s, long n) {
            if (n < 1) throw py::value_error("step(n): n must be >= 1");
            if (n == 1) {  // no GIL hand-over for one step: it costs more than the call
              s.status = s.sim->step();
            } else {
              bool interrupted = false;
              {
                py::gil_scoped_release release;
                for (long i = 0; i < n && !interrupted; ++i) {
                  s.status = s.sim->step();
                  if (!s.status.ok) break;
                  // Every kSignalSteps steps (a few ms on the belt) a pending Ctrl-C stops
                  // here, after a whole step: the state is that step's.
                  if ((i + 1) % kSignalSteps == 0) {
                    py::gil_scoped_acquire hold;
                    interrupted = PyErr_CheckSignals() != 0;
                  }
                }
              }
              if (interrupted) throw py::error_already_set();  // KeyboardInterrupt
            }
            if (!s.status.ok) raisePythonLawErrors(s.user_laws);
            return s.status.ok;
          },
          py::arg("n") = 1,
          "Advances n model time steps (stops at a failed one); True when all succeeded. "
          "status says why a step failed. Ctrl-C stops it after a whole step "
          "(KeyboardInterrupt); the state is then that step's.")
      .def_property_readonly(
          "status", [](const PySimulator& s) { return statusDict(s.status); },
          "The last step's outcome: ok, message, time, body, quantity.")
      .def_property_readonly("time", [](const PySimulator& s) { return s.sim->state().time; })
      .def_property(
          "state", [](const PySimulator& s) { return State(s.sim->state()); },
          [](PySimulator& s, const State& state) {
            if (state.bodies.size() != s.model->bodies.size())
              throw py::value_error("state has " + std::to_string(state.bodies.size()) +
                                    " bodies, the scene " + std::to_string(s.model->bodies.size()));
            s.sim->setState(state);
          },
          "A copy of the current state; assigning one restarts from it.")
      .def_property_readonly("body_names",
                             [](const PySimulator& s) {
                               std::vector<std::string> names;
                               for (const Body& b : s.model->bodies) names.push_back(b.name);
                               return names;
                             })
      .def(
          "set_actuator",
          [](PySimulator& s, const std::string& name, double value) {
            const auto joint = s.model->findActuator(name);
            if (!joint) throw py::key_error("no actuator '" + name + "'");
            if (std::isinf(value)) throw py::value_error("actuator command must be finite");
            s.sim->setActuatorCommand(*joint, value);
            if (std::isnan(value))
              s.commands.erase(*joint);
            else
              s.commands[*joint] = value;
          },
          py::arg("actuator"), py::arg("value"),
          "Commands an actuator (its target: effort, position or rate) from the next step on, "
          "in place of its target signal; NaN returns it to the signal.")
      .def(
          "set_load",
          [](PySimulator& s, const std::string& name, const py::object& force,
             const py::object& torque) {
            const LoadCommand c = setLoadFromPython(*s.sim, name, force, torque);
            if (c.force || c.torque)
              s.load_commands[c.load] = c;
            else
              s.load_commands.erase(c.load);
          },
          py::arg("load"), py::arg("force") = py::none(), py::arg("torque") = py::none(),
          "set_load(name, force=None, torque=None): holds the load's force and/or torque (3 "
          "numbers or a NumPy array each, in the load's frame: world or body) at these values "
          "from the next step on, in place of its signals (a zero-order hold); a part given as "
          "None goes back to its signals, so set_load(name) releases the load. Raises KeyError "
          "naming the scene's loads, ValueError for a vector that is not 3 finite numbers.")
      .def("set_parameters", &setParameters, py::arg("set"),
           "set_parameters({name: value}): changes scene parameters from the next step on "
           "(the model is built again with them; the state, the time and the actuator "
           "commands go on). Raises SceneError for a bad value and ValueError when the new "
           "values change the state's layout (bodies, joints, friction states). The run "
           "statistics start again.")
      .def_property_readonly(
          "parameters",
          [](const PySimulator& s) {
            py::dict d;
            for (const auto& [name, value] : s.scene.scene.parameters) d[py::str(name)] = value;
            return d;
          },
          "The scene's parameters now (name -> text as the scene reads it).")
      .def(
          "contacts", [](PySimulator& s) { return contactsOf(*s.model, s.sim->current()); },
          "The contact points of the current state: position, normal (A into B), depth, "
          "normal_force, friction_force (on B), slip (B rel. A), mu, body_a, body_b.")
      .def_property_readonly(
          "stats",
          [](const PySimulator& s) {
            return jsonToPython(study::stepStatsJsonText(s.sim->stats()));
          },
          "The run statistics so far, as summary.json's \"run\" block names them.");
}

}  // namespace tribo::python
