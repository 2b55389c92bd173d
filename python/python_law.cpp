#include "python/python_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribo::python {

PythonLaw::PythonLaw(std::string name, py::object law) : name_(std::move(name)) {
  if (py::hasattr(law, "mu")) {
    mu_ = law.attr("mu");
    slope_ = py::getattr(law, "slope", py::none());
    max_ = py::getattr(law, "max_coefficient", py::none());
    const py::object stick = py::getattr(law, "stick_speed", py::none());
    if (!stick.is_none()) stick_speed_ = stick.cast<double>();
  } else if (PyCallable_Check(law.ptr())) {
    mu_ = law;
    slope_ = max_ = py::none();
  } else {
    throw py::type_error("law '" + name_ + "': expected a callable mu(v) or an object with a mu method");
  }
  if (!(stick_speed_ > 0.0) || !std::isfinite(stick_speed_))
    throw py::value_error("law '" + name_ + "': stick_speed must be > 0");
}

PythonLaw::~PythonLaw() {
  // The engine may drop its last reference to a law without the GIL.
  if (!Py_IsInitialized()) return;
  py::gil_scoped_acquire hold;
  mu_ = py::object();
  slope_ = py::object();
  max_ = py::object();
  error_.reset();
}

double PythonLaw::call(const py::object& f, double v) const {
  py::gil_scoped_acquire hold;
  try {
    return f(v).cast<double>();
  } catch (py::error_already_set& e) {
    if (!error_) error_ = std::make_shared<py::error_already_set>(std::move(e));
  } catch (const py::cast_error& e) {
    if (!error_) {
      PyErr_SetString(PyExc_TypeError, ("law '" + name_ + "': mu(v) must return a number").c_str());
      error_ = std::make_shared<py::error_already_set>();
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double PythonLaw::coefficient(double v) const { return call(mu_, v); }

double PythonLaw::slope(double v) const {
  if (!slope_.is_none()) return call(slope_, v);
  const double h = 1e-6 * std::max(std::abs(v), stick_speed_);
  return (call(mu_, v + h) - call(mu_, v - h)) / (2.0 * h);
}

double PythonLaw::maxCoefficient(double v_max) const {
  if (!max_.is_none()) return call(max_, v_max);
  double bound = 0.0;
  constexpr int kSamples = 2000;
  for (int i = 0; i <= kSamples; ++i) bound = std::max(bound, std::abs(call(mu_, v_max * i / kSamples)));
  return bound;
}

std::shared_ptr<py::error_already_set> PythonLaw::takeError() const {
  auto e = std::move(error_);
  error_.reset();
  return e;
}

std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> userLawsFrom(
    const py::object& laws) {
  std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> out;
  if (laws.is_none()) return out;
  for (const auto& [key, value] : laws.cast<py::dict>()) {
    const std::string name = key.cast<std::string>();
    if (py::isinstance<friction::FrictionLaw>(value))  // a built-in law made in Python
      out[name] = value.cast<std::shared_ptr<friction::FrictionLaw>>();
    else
      out[name] = std::make_shared<PythonLaw>(name, py::reinterpret_borrow<py::object>(value));
  }
  return out;
}

void raisePythonLawErrors(
    const std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>& laws) {
  for (const auto& [name, law] : laws)
    if (const auto* p = dynamic_cast<const PythonLaw*>(law.get()))
      if (auto error = p->takeError()) {
        error->restore();
        throw py::error_already_set();
      }
}

}  // namespace tribo::python
