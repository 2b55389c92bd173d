// The settled stick-slip cycle of the belt scene's paper model (one degree of freedom,
// tests/support/one_dof_belt.hpp, RK4 at 10 us for 60 s, sharing nothing with the engine but
// the friction law): the period between its last two maxima, the peak-to-peak amplitude of
// the last cycle and the fraction of it spent stuck (slip speed v_b - v below v_s = 0.01). The
// independent reference of the orbit tests (periodic_orbit_test, orbit_branch_test).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "friction/friction_law.hpp"
#include "support/one_dof_belt.hpp"

namespace tribo {

struct ReferenceCycle {
  double period = 0, amplitude_pp = 0, stick_fraction = 0;
};

inline ReferenceCycle oneDofCycle(double m, double v_b) {
  const auto law = friction::makeFrictionLaw(
      {"roh_yoo",
       {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3.0}},
       {}});
  test::OneDofBelt ref{m, 300.0, v_b, 9.81, law.get()};
  double x = 0.0, v = 0.0, prev_v = 0.0, lo = 1e9, hi = -1e9, lo_done = 0, hi_done = 0;
  double stuck = 0, stuck_done = 0;
  std::vector<double> maxima;
  const double h = 1e-5;
  ref.run(x, v, h, std::lround(60.0 / h), [&](double t, double xs, double vs) {
    lo = std::min(lo, xs), hi = std::max(hi, xs);
    if (std::abs(v_b - vs) < 0.01) stuck += h;
    if (prev_v > 0.0 && vs <= 0.0) {
      maxima.push_back(t - h + h * prev_v / (prev_v - vs));
      lo_done = lo, hi_done = hi, lo = 1e9, hi = -1e9;
      stuck_done = stuck, stuck = 0;
    }
    prev_v = vs;
  });
  EXPECT_GE(maxima.size(), 10u);
  if (maxima.size() < 2) return {};
  const double period = maxima.back() - maxima[maxima.size() - 2];
  return {period, hi_done - lo_done, stuck_done / period};
}

}  // namespace tribo
