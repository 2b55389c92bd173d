#include "python/python_law.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/number_text.hpp"

namespace tribo::python {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

py::array_t<double> arrayOf(const double* v, int n) {
  return py::array_t<double>(n, v);  // a copy: Python may keep it
}

}  // namespace

PythonCalls::PythonCalls(std::string name, const py::object& law)
    : name_(std::move(name)), object_(law) {
  if (py::hasattr(law, "mu")) {
    mu_ = law.attr("mu");
  } else if (PyCallable_Check(law.ptr())) {
    mu_ = law;
  } else {
    throw py::type_error("law '" + name_ +
                         "': expected a callable mu(v) or an object with a mu method");
  }
  slope_ = py::getattr(law, "slope", py::none());
  max_ = py::getattr(law, "max_coefficient", py::none());
  for (const char* key : {"rate", "force", "stable_step", "state_stiffness", "direct_slope"})
    if (py::hasattr(law, key)) methods_[key] = law.attr(key);
  const py::object stick = py::getattr(law, "stick_speed", py::none());
  if (!stick.is_none()) stick_speed_ = stick.cast<double>();
  if (!(stick_speed_ > 0.0) || !std::isfinite(stick_speed_))
    throw py::value_error("law '" + name_ + "': stick_speed must be > 0");
}

PythonCalls::~PythonCalls() {
  // The engine may drop its last reference to a law without the GIL.
  if (!Py_IsInitialized()) return;
  py::gil_scoped_acquire hold;
  object_ = mu_ = slope_ = max_ = py::object();
  methods_.clear();
  error_.reset();
}

template <class... A>
py::object PythonCalls::call(const py::object& f, A&&... args) const {
  try {
    return f(std::forward<A>(args)...);
  } catch (py::error_already_set& e) {
    if (!error_) error_ = std::make_shared<py::error_already_set>(std::move(e));
  }
  return py::none();
}

void PythonCalls::fail(const std::string& what) const {
  if (error_) return;
  PyErr_SetString(PyExc_TypeError, ("law '" + name_ + "': " + what).c_str());
  error_ = std::make_shared<py::error_already_set>();
}

double PythonCalls::number(const py::object& f, double v) const {
  py::gil_scoped_acquire hold;
  const py::object r = call(f, v);
  if (r.is_none()) return kNaN;
  try {
    return r.cast<double>();
  } catch (const py::cast_error&) {
    fail("mu(v) must return a number");
  }
  return kNaN;
}

void PythonCalls::failValue(const std::string& what) const {
  if (error_) return;
  PyErr_SetString(PyExc_ValueError, ("law '" + name_ + "': " + what).c_str());
  error_ = std::make_shared<py::error_already_set>();
}

namespace {

bool finite(const double* v, int n) {
  return std::all_of(v, v + n, [](double x) { return std::isfinite(x); });
}

std::string atSlip(double v) { return " at slip speed v = " + numberText(v) + " m/s"; }

}  // namespace

double PythonCalls::mu(double v) const {
  const double m = number(mu_, v);
  if (!std::isfinite(v)) return m;  // NaN in, NaN out: not the law's doing
  // Odd in v (friction/friction_law.hpp): the sign of the slip, so that it opposes it.
  if (std::isfinite(m) && (v > 0.0 ? m >= 0.0 : v < 0.0 ? m <= 0.0 : true)) return m;
  py::gil_scoped_acquire hold;
  failValue("mu(v) returned " + numberText(m) + atSlip(v) +
            "; a friction coefficient is finite and has the sign of v (mu(-v) = -mu(v)), so "
            "that friction opposes the slip");
  return kNaN;
}

double PythonCalls::slope(double v) const {
  if (!slope_.is_none()) {
    const double s = number(slope_, v);
    // Infinite is allowed: roh_yoo's slope with beta < 1 is unbounded at v = 0.
    if (!std::isnan(s) || !std::isfinite(v)) return s;
    py::gil_scoped_acquire hold;
    failValue("slope(v) returned nan" + atSlip(v) + "; expected a number");
    return kNaN;
  }
  const double h = 1e-6 * std::max(std::abs(v), stick_speed_);
  return (mu(v + h) - mu(v - h)) / (2.0 * h);
}

double PythonCalls::maxCoefficient(double v_max) const {
  if (!max_.is_none()) return number(max_, v_max);
  double bound = 0.0;
  constexpr int kSamples = 2000;
  for (int i = 0; i <= kSamples; ++i) bound = std::max(bound, std::abs(mu(v_max * i / kSamples)));
  return bound;
}

const py::object& PythonCalls::method(const std::string& key) const {
  static const py::object* none = new py::object(py::none());  // outlives the interpreter's end
  const auto it = methods_.find(key);
  return it == methods_.end() ? *none : it->second;
}

std::shared_ptr<py::error_already_set> PythonCalls::takeError() const {
  auto e = std::move(error_);
  error_.reset();
  return e;
}

PythonDynamicLaw::PythonDynamicLaw(std::string name, const py::object& law)
    : PythonCurveLaw(std::move(name), law) {
  const std::string& n = calls_.name();
  size_ = law.attr("state_size").cast<int>();
  if (size_ < 1) throw py::value_error("law '" + n + "': state_size must be >= 1");
  tangent_vectors_ = py::getattr(law, "tangent_vectors", py::int_(0)).cast<int>();
  if (tangent_vectors_ < 0 || 3 * tangent_vectors_ > size_)
    throw py::value_error("law '" + n + "': tangent_vectors must be in 0..state_size/3");
  for (const char* key : {"rate", "force"})
    if (!py::hasattr(law, key)) throw py::type_error("law '" + n + "': needs a " + key + " method");
  initial_.assign(static_cast<std::size_t>(size_), 0.0);
  if (py::hasattr(law, "initial_state")) {
    const auto z0 = law.attr("initial_state")().cast<std::vector<double>>();
    if (z0.size() != initial_.size())
      throw py::value_error("law '" + n + "': initial_state() must give state_size numbers");
    initial_ = z0;
  }
  if (py::hasattr(law, "presliding")) {
    const auto p = law.attr("presliding").cast<std::pair<double, double>>();
    presliding_ = {p.first, p.second};
  }
}

void PythonDynamicLaw::copyOut(const py::object& r, double* out, int n, const char* what) const {
  try {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(r);
    if (a && a.size() == n) {
      std::copy(a.data(), a.data() + n, out);
      return;
    }
  } catch (const py::error_already_set&) {
  }
  PyErr_Clear();
  if (!r.is_none()) calls_.fail(std::string(what) + " must give " + std::to_string(n) + " numbers");
  std::fill(out, out + n, kNaN);
}

void PythonDynamicLaw::checkFinite(const double* v, int n, const char* what,
                                   const Eigen::Vector3d& slip, double fn) const {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) {
      calls_.failValue(std::string(what) + " gave " + numberText(v[i]) + " (entry " +
                       std::to_string(i) + ")" + atSlip(slip.norm()) + ", fn = " + numberText(fn) +
                       " N; expected finite numbers");
      return;
    }
}

void PythonDynamicLaw::initialState(double* z) const {
  std::copy(initial_.begin(), initial_.end(), z);
}

void PythonDynamicLaw::rate(const double* z, const Eigen::Vector3d& slip, double fn,
                            double* zdot) const {
  py::gil_scoped_acquire hold;
  const py::object r =
      calls_.call(calls_.method("rate"), arrayOf(z, size_), arrayOf(slip.data(), 3), fn);
  copyOut(r, zdot, size_, "rate(z, slip, fn)");
  if (finite(z, size_) && slip.allFinite() && std::isfinite(fn))
    checkFinite(zdot, size_, "rate(z, slip, fn)", slip, fn);
}

Eigen::Vector3d PythonDynamicLaw::force(const double* z, const double* zdot,
                                        const Eigen::Vector3d& slip, double fn,
                                        double* mu_out) const {
  py::gil_scoped_acquire hold;
  const py::object r = calls_.call(calls_.method("force"), arrayOf(z, size_), arrayOf(zdot, size_),
                                   arrayOf(slip.data(), 3), fn);
  Eigen::Vector3d f;
  copyOut(r, f.data(), 3, "force(z, zdot, slip, fn)");
  if (finite(z, size_) && finite(zdot, size_) && slip.allFinite() && std::isfinite(fn))
    checkFinite(f.data(), 3, "force(z, zdot, slip, fn)", slip, fn);
  if (mu_out != nullptr) *mu_out = fn > 0.0 ? f.norm() / fn : 0.0;
  return f;
}

void PythonDynamicLaw::stableStep(double* z, const Eigen::Vector3d& slip, double fn,
                                  double h) const {
  {
    py::gil_scoped_acquire hold;
    const py::object& step = calls_.method("stable_step");
    if (!step.is_none()) {
      const py::object r = calls_.call(step, arrayOf(z, size_), arrayOf(slip.data(), 3), fn, h);
      copyOut(r, z, size_, "stable_step(z, slip, fn, h)");
      return;
    }
  }
  std::vector<double> zdot(static_cast<std::size_t>(size_));
  rate(z, slip, fn, zdot.data());
  for (int i = 0; i < size_; ++i) z[i] += h * zdot[static_cast<std::size_t>(i)];
}

double PythonDynamicLaw::stateStiffness(double v_max) const {
  py::gil_scoped_acquire hold;
  const py::object& f = calls_.method("state_stiffness");
  return f.is_none() ? 0.0 : calls_.number(f, v_max);
}

double PythonDynamicLaw::directSlope(double v) const {
  py::gil_scoped_acquire hold;
  const py::object& f = calls_.method("direct_slope");
  return f.is_none() ? 0.0 : calls_.number(f, v);
}

std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> userLawsFrom(
    const py::object& laws) {
  std::map<std::string, std::shared_ptr<const friction::FrictionLaw>> out;
  if (laws.is_none()) return out;
  for (const auto& [key, value] : laws.cast<py::dict>()) {
    const std::string name = key.cast<std::string>();
    const auto law = py::reinterpret_borrow<py::object>(value);
    if (py::isinstance<friction::FrictionLaw>(law))  // a built-in law made in Python
      out[name] = law.cast<std::shared_ptr<friction::FrictionLaw>>();
    else if (py::hasattr(law, "state_size"))
      out[name] = std::make_shared<PythonDynamicLaw>(name, law);
    else
      out[name] = std::make_shared<PythonLaw>(name, law);
  }
  return out;
}

py::dict lawObjectsOf(
    const std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>& laws) {
  py::dict out;
  for (const auto& [name, law] : laws) {
    const PythonCalls* calls = nullptr;
    if (const auto* p = dynamic_cast<const PythonLaw*>(law.get())) calls = &p->calls();
    if (const auto* p = dynamic_cast<const PythonDynamicLaw*>(law.get())) calls = &p->calls();
    if (calls == nullptr)
      throw py::type_error("law '" + name +
                           "' is a tribo.FrictionLaw built in Python, which cannot be sent to "
                           "other processes: give it as a friction_laws: entry of the scene");
    out[py::str(name)] = calls->object();
  }
  return out;
}

void raisePythonLawErrors(
    const std::map<std::string, std::shared_ptr<const friction::FrictionLaw>>& laws) {
  for (const auto& [name, law] : laws) {
    const PythonCalls* calls = nullptr;
    if (const auto* p = dynamic_cast<const PythonLaw*>(law.get())) calls = &p->calls();
    if (const auto* p = dynamic_cast<const PythonDynamicLaw*>(law.get())) calls = &p->calls();
    if (calls == nullptr) continue;
    if (auto error = calls->takeError()) {
      error->restore();
      throw py::error_already_set();
    }
  }
}

}  // namespace tribo::python
