// Test support for the dynamic friction laws: a law built through the factory, and a classical
// RK4 integration of its state equation dz/dt = rate(z, s, F_n) written here, independent of the
// laws' own stableStep updates.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "friction/dynamic_law.hpp"
#include "friction/friction_law.hpp"

namespace tribo::friction::test {

using StateVector = std::vector<double>;

// A law from the factory and its dynamic view (the test fails if the law is not dynamic).
struct BuiltLaw {
  std::unique_ptr<const FrictionLaw> owner;
  const DynamicFrictionLaw* law = nullptr;
};

inline BuiltLaw buildDynamic(const LawSpec& spec) {
  BuiltLaw built;
  built.owner = makeFrictionLaw(spec);
  built.law = built.owner->dynamic();
  EXPECT_NE(built.law, nullptr) << spec.name << " is not a dynamic law";
  return built;
}

inline StateVector initialState(const DynamicFrictionLaw& law) {
  StateVector z(law.stateSize());
  law.initialState(z.data());
  return z;
}

inline StateVector rateOf(const DynamicFrictionLaw& law, const StateVector& z,
                          const Eigen::Vector3d& slip, double fn) {
  StateVector zdot(z.size());
  law.rate(z.data(), slip, fn, zdot.data());
  return zdot;
}

// Force on B at state z (its rate evaluated at the same slip), and optionally mu.
inline Eigen::Vector3d forceAt(const DynamicFrictionLaw& law, const StateVector& z,
                               const Eigen::Vector3d& slip, double fn, double* mu = nullptr) {
  const StateVector zdot = rateOf(law, z, slip, fn);
  return law.force(z.data(), zdot.data(), slip, fn, mu);
}

// One classical RK4 step of the state at frozen slip.
inline void rk4Step(const DynamicFrictionLaw& law, StateVector& z, const Eigen::Vector3d& slip,
                    double fn, double h) {
  const std::size_t n = z.size();
  auto shifted = [&](const StateVector& k, double c) {
    StateVector out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = z[i] + c * k[i];
    return out;
  };
  const StateVector k1 = rateOf(law, z, slip, fn);
  const StateVector k2 = rateOf(law, shifted(k1, 0.5 * h), slip, fn);
  const StateVector k3 = rateOf(law, shifted(k2, 0.5 * h), slip, fn);
  const StateVector k4 = rateOf(law, shifted(k3, h), slip, fn);
  for (std::size_t i = 0; i < n; ++i) z[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

// RK4 over time t in `steps` equal steps at frozen slip; `each` (optional) sees every state.
inline void rk4(const DynamicFrictionLaw& law, StateVector& z, const Eigen::Vector3d& slip,
                double fn, double t, long steps,
                const std::function<void(const StateVector&)>& each = {}) {
  const double h = t / static_cast<double>(steps);
  for (long i = 0; i < steps; ++i) {
    rk4Step(law, z, slip, fn, h);
    if (each) each(z);
  }
}

}  // namespace tribo::friction::test
