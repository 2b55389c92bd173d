// Friction laws as Python objects: tribo.friction_law(name, **parameters) builds a law
// exactly as a scene's friction_laws entry does (friction/friction_law.hpp: the same names,
// keys, defaults and checks), and its mu(v) and slope(v) take a number or any array of slip
// speeds [m/s], looping in C++ with the GIL released. For a law with internal state
// (lugre, dahl, ...) these are its steady-state curve.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "friction/friction_law.hpp"
#include "friction/tabulated_law.hpp"
#include "io/friction_curve.hpp"
#include "io/scene_parameters.hpp"
#include "python/bindings.hpp"

namespace tribo::python {
namespace {

using Law = friction::FrictionLaw;

// f applied to a number (a float back) or elementwise to an array (an array of its shape).
template <class F>
py::object elementwise(const Law& law, const py::object& v, F f) {
  if (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v))
    return py::float_(f(law, v.cast<double>()));
  auto in = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  if (!in) throw py::type_error("expected a number or an array of slip speeds [m/s]");
  py::array_t<double> out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
  const double* src = in.data();
  double* dst = out.mutable_data();
  const py::ssize_t n = in.size();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) dst[i] = f(law, src[i]);
  }
  return out;
}

// The tabulated law: file=CSV (speed, coefficient; io/friction_curve.hpp) or speeds=[...],
// coefficients=[...]; the curve's own checks apply.
std::shared_ptr<const Law> tabulatedLaw(const py::kwargs& parameters) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : parameters) keys.push_back(key.cast<std::string>());
  std::sort(keys.begin(), keys.end());
  if (keys == std::vector<std::string>{"file"}) {
    const std::string path =
        py::module_::import("os").attr("fspath")(parameters["file"]).cast<std::string>();
    const io::FrictionCurve curve = io::readFrictionCurve(path);
    return std::make_shared<friction::TabulatedLaw>(curve.speeds, curve.coefficients);
  }
  if (keys == std::vector<std::string>{"coefficients", "speeds"})
    return std::make_shared<friction::TabulatedLaw>(
        parameters["speeds"].cast<std::vector<double>>(),
        parameters["coefficients"].cast<std::vector<double>>());
  throw py::type_error(
      "tabulated: give file=CSV (speed, coefficient) or speeds=[...] and coefficients=[...]");
}

std::shared_ptr<Law> makeLaw(const std::string& name, const py::kwargs& parameters) {
  if (name == "tabulated")  // pybind11 holds laws by shared_ptr to non-const; none mutates one
    return std::const_pointer_cast<Law>(tabulatedLaw(parameters));
  friction::LawSpec spec;
  spec.name = name;
  for (const auto& [key, value] : parameters) {
    const std::string k = key.cast<std::string>();
    if (py::isinstance<py::bool_>(value))
      throw py::type_error(name + ": " + k + " must be a number or a string, not a bool");
    if (py::isinstance<py::str>(value)) {
      const std::string text = value.cast<std::string>();
      // A number's text is the number, as in a scene file ("0.3"); other text an option.
      if (const auto number = io::parseNumber(text))
        spec.values[k] = *number;
      else
        spec.options[k] = text;
    } else if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
      spec.values[k] = value.cast<double>();
    } else {
      throw py::type_error(name + ": " + k + " must be a number or a string, not " +
                           std::string(py::str(value.get_type().attr("__name__"))));
    }
  }
  return std::const_pointer_cast<Law>(std::shared_ptr<const Law>(friction::makeFrictionLaw(spec)));
}

}  // namespace

void bindFriction(py::module_& m) {
  py::class_<Law, std::shared_ptr<Law>>(m, "FrictionLaw",
                                        "A friction law: mu(v), its slope, its stick speed.")
      .def_property_readonly("name", [](const Law& l) { return std::string(l.name()); })
      .def(
          "mu",
          [](const Law& l, const py::object& v) {
            return elementwise(l, v, [](const Law& law, double x) { return law.coefficient(x); });
          },
          py::arg("v"), "Friction coefficient at signed slip speed(s) v [m/s] (odd in v).")
      .def(
          "slope",
          [](const Law& l, const py::object& v) {
            return elementwise(l, v, [](const Law& law, double x) { return law.slope(x); });
          },
          py::arg("v"), "d mu / dv at v [s/m].")
      .def_property_readonly("stick_speed", &Law::stickSpeed,
                             "Speed [m/s] below which a contact counts as stuck.")
      .def("max_coefficient", &Law::maxCoefficient, py::arg("v_max"),
           "Largest |mu| over |v| <= v_max.")
      .def_property_readonly("breakpoints", &Law::breakpoints,
                             "Positive slip speeds where the law's piecewise definition changes.")
      .def_property_readonly(
          "has_internal_state", [](const Law& l) { return l.dynamic() != nullptr; },
          "True for laws with internal state integrated with the motion (mu is then the "
          "steady-state curve).")
      .def("__repr__",
           [](const Law& l) { return "<tribo.FrictionLaw " + std::string(l.name()) + ">"; });

  m.def("friction_law", &makeLaw, py::arg("name"),
        "friction_law(name, **parameters): a law as a scene's friction_laws entry builds it "
        "(numbers by key, a number's text as the number, other strings as options); "
        "friction_law('tabulated', file=CSV) or (speeds=[...], coefficients=[...]). Raises "
        "FrictionParameterError.");
  m.def(
      "friction_laws",
      [] {
        py::dict d;
        d["memoryless"] = friction::knownFrictionLaws();
        d["stateful"] = friction::knownStatefulFrictionLaws();
        d["dynamic"] = friction::knownDynamicFrictionLaws();
        d["tabulated"] = std::vector<std::string>{"tabulated"};
        return d;
      },
      "The law names friction_law accepts, by kind.");
}

}  // namespace tribo::python
