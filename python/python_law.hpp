// A friction law written in Python, for prototyping: mu(v) is a Python callable (or an
// object with a `mu` method), called from the engine with the GIL taken for each call.
// Optional attributes of the object: `slope(v)` (else a central difference of mu with step
// 1e-6 max(|v|, v_stick)), `stick_speed` [m/s] (else 1e-3), `max_coefficient(v_max)` (else
// the largest |mu| over 2001 speeds from 0 to v_max, a sampled bound). A Python exception
// inside mu makes the coefficient NaN, so the step fails cleanly (the engine's non-finite
// force check names the step and body); the run's binding then raises the exception.
// What it does not do: internal state (a law with state integrated with the motion must be
// written in C++, friction/dynamic_law.hpp), sweeps (their threads load scenes from text),
// speed (each call costs a Python call, docs/python.md).
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::python {

namespace py = pybind11;

class PythonLaw : public friction::FrictionLaw {
 public:
  PythonLaw(std::string name, py::object law);
  ~PythonLaw() override;

  double coefficient(double v) const override;
  double slope(double v) const override;
  double maxCoefficient(double v_max) const override;
  double stickSpeed() const override { return stick_speed_; }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return name_; }

  // The first Python exception a call raised, if any (then cleared); needs the GIL.
  std::shared_ptr<py::error_already_set> takeError() const;

 private:
  double call(const py::object& f, double v) const;

  std::string name_;
  py::object mu_, slope_, max_;  // slope_, max_: None when the object has none
  double stick_speed_ = 1e-3;
  mutable std::shared_ptr<py::error_already_set> error_;
};

// The laws given to load_scene(laws={name: law}) as engine laws.
std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> userLawsFrom(
    const py::object& laws);
// Raises (as a Python exception) the first error any of the scene's Python laws caught.
void raisePythonLawErrors(const std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>& laws);

}  // namespace tribo::python
