// Friction laws written in Python, for prototyping. Two kinds:
//   memoryless: a callable mu(v), or an object with a `mu(v)` method;
//   with internal state (friction/dynamic_law.hpp): an object with `state_size`,
//     `rate(z, slip, fn)` (dz/dt) and `force(z, zdot, slip, fn)` (tangential force on B, a
//     3-vector) besides its steady-state curve `mu(v)`; z, zdot and slip cross as NumPy
//     arrays (copies). Optional: `tangent_vectors` (0), `initial_state()` (zeros),
//     `stable_step(z, slip, fn, h)` (the new z; else one explicit Euler step, which is not
//     bounded for stiff states: use rk4, dopri5 or bdf then), `presliding` ((stiffness,
//     damping) per unit load, (0, 0)), `state_stiffness(v_max)` (0) and `direct_slope(v)` (0:
//     d|F_t|/d|s| per unit load with the state held, DynamicFrictionLaw::directSlope; the
//     steady curve mu(v) cannot give it, as it is the slope before the state responds:
//     rate-and-state's a / v against the curve's (a - b) / v).
// Optional for both: `slope(v)` (else a central difference of mu with step
// 1e-6 max(|v|, stick_speed)), `stick_speed` [m/s] (1e-3), `max_coefficient(v_max)` (else the
// largest |mu| over 2001 speeds from 0 to v_max, a sampled bound).
// The engine calls them with the GIL taken for each call. A Python exception inside one makes
// the result NaN, so the step fails cleanly (the engine's non-finite force check names the
// step and body), and the binding that ran the step raises the exception again.
// Not here: sweeps (their threads load scenes from text), speed (each call is a Python call;
// docs/python.md).
#pragma once

#include <pybind11/pybind11.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "friction/dynamic_law.hpp"

namespace tribo::python {

namespace py = pybind11;

// The Python calls a law makes, and the first exception one raised.
class PythonCalls {
 public:
  PythonCalls(std::string name, const py::object& law);
  ~PythonCalls();
  // f(args...) as a double (NaN after an exception).
  template <class... A>
  py::object call(const py::object& f, A&&... args) const;
  double number(const py::object& f, double v) const;
  // The steady curve: mu, slope, bound. A coefficient that is not finite or whose sign is
  // not v's (one that drives the slip), or a slope that is NaN, is recorded as a ValueError
  // naming the law, the value and the slip speed, and comes back as NaN so that the step fails
  // there.
  double mu(double v) const;
  double slope(double v) const;
  double maxCoefficient(double v_max) const;
  double stickSpeed() const { return stick_speed_; }
  const std::string& name() const { return name_; }
  // The Python object the law was made from (to send it to other processes).
  const py::object& object() const { return object_; }
  // The law's method `key` (None when it has none): rate, force, stable_step,
  // state_stiffness, looked up once.
  const py::object& method(const std::string& key) const;
  // The first Python exception a call raised, if any (then cleared); needs the GIL.
  std::shared_ptr<py::error_already_set> takeError() const;
  void fail(const std::string& what) const;  // records a TypeError (GIL held)
  // Records a ValueError "law 'NAME': <what>" (GIL held); the first error is kept.
  void failValue(const std::string& what) const;

 private:
  std::string name_;
  py::object object_;
  py::object mu_, slope_, max_;  // slope_, max_: None when the object has none
  std::map<std::string, py::object> methods_;
  double stick_speed_ = 1e-3;
  mutable std::shared_ptr<py::error_already_set> error_;
};

// The steady curve's part of a law's interface, answered by the Python object.
template <class Base>
class PythonCurveLaw : public Base {
 public:
  PythonCurveLaw(std::string name, const py::object& law) : calls_(std::move(name), law) {}
  double coefficient(double v) const override { return calls_.mu(v); }
  double slope(double v) const override { return calls_.slope(v); }
  double maxCoefficient(double v_max) const override { return calls_.maxCoefficient(v_max); }
  double stickSpeed() const override { return calls_.stickSpeed(); }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return calls_.name(); }
  const PythonCalls& calls() const { return calls_; }

 protected:
  PythonCalls calls_;
};

class PythonLaw final : public PythonCurveLaw<friction::FrictionLaw> {
 public:
  using PythonCurveLaw::PythonCurveLaw;
};

class PythonDynamicLaw final : public PythonCurveLaw<friction::DynamicFrictionLaw> {
 public:
  PythonDynamicLaw(std::string name, const py::object& law);
  int stateSize() const override { return size_; }
  int tangentVectors() const override { return tangent_vectors_; }
  std::string stateName(int i) const override { return "z" + std::to_string(i); }
  void initialState(double* z) const override;
  void rate(const double* z, const Eigen::Vector3d& slip, double fn, double* zdot) const override;
  Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const override;
  void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const override;
  Presliding presliding() const override { return presliding_; }
  double stateStiffness(double v_max) const override;
  double directSlope(double v) const override;

 private:
  // The Python result `r` copied into out[0..n) (NaN and a recorded error when it is not a
  // sequence of n numbers).
  void copyOut(const py::object& r, double* out, int n, const char* what) const;
  // A ValueError naming the call, the entry and the slip when an output of finite inputs is
  // not finite (GIL held).
  void checkFinite(const double* v, int n, const char* what, const Eigen::Vector3d& slip,
                   double fn) const;

  int size_ = 0, tangent_vectors_ = 0;
  Presliding presliding_;
  std::vector<double> initial_;
};

// The laws given to load_scene(laws={name: law}) as engine laws.
std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> userLawsFrom(
    const py::object& laws);
// The Python objects userLawsFrom made `laws` from, by name (to pickle them for other
// processes). Raises TypeError naming a law that is not one (a tribo.FrictionLaw).
py::dict lawObjectsOf(
    const std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>& laws);
// Raises (as a Python exception) the first error any of the Python laws caught.
void raisePythonLawErrors(
    const std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>& laws);

}  // namespace tribo::python
