// The damped belt of the orbit tests in closed form: one box (m = 10 kg, N = m g) on the belt
// at v_b, held by the wall spring k = 300 N/m beside a viscous damper c, with Stribeck's law
//   mu(v) = mu_k + (mu_s - mu_k) exp(-(v / v_st)^2),  mu_s 0.35, mu_k 0.3, v_st 0.15 m/s
// (its tanh(v / v_eps) factor is 1 to 1e-19 at these speeds). Steady sliding's in-plane pair
// has growth rate -(c + N mu'(v_b)) / (2 m): a Hopf point where c + N mu'(v_H) = 0 on the
// law's falling side, with the undamped frequency sqrt(k / m) there. Near it the orbit's
// amplitude follows from the energy balance of m x'' + k x = F(x') over x = A cos(w t),
// F(u) = -d u + N mu''(v_b) u^2 / 2 - N mu'''(v_b) u^3 / 6, d = c + N mu'(v_b):
//   (A w)^2 = -8 d / (N mu'''(v_b))      (averaging; the u^2 term does no work over a cycle)
// to leading order in d (Krylov-Bogoliubov averaging: Nayfeh & Mook, "Nonlinear
// Oscillations", Wiley 1979, sec. 3.3). The independent reference of the Hopf tests.
#pragma once

#include <cmath>

namespace tribo {

struct DampedStribeckBelt {
  double c = 10.0;
  double m = 10.0, k = 300.0, g = 9.81;
  double mu_s = 0.35, mu_k = 0.3, v_st = 0.15;

  double normal() const { return m * g; }
  // mu'(v) and mu'''(v) of the law above.
  double slope(double v) const {
    const double s = v / v_st;
    return (mu_s - mu_k) * (-2.0 * s) * std::exp(-s * s) / v_st;
  }
  double thirdDerivative(double v) const {
    const double s = v / v_st;
    return (mu_s - mu_k) * (12.0 * s - 8.0 * s * s * s) * std::exp(-s * s) / (v_st * v_st * v_st);
  }
  // d(v_b) = c + N mu'(v_b): minus twice the mass times steady sliding's growth rate.
  double damping(double v) const { return c + normal() * slope(v); }

  // The Hopf speed: the root of d on the falling side, by bisection between the steepest
  // slope and 1 m/s.
  double hopfSpeed() const {
    double lo = v_st / std::sqrt(2.0), hi = 1.0;
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (damping(mid) < 0.0 ? lo : hi) = mid;
    }
    return lo;
  }

  // The orbit's peak-to-peak amplitude 2 A at v_b to leading order (NaN where there is none).
  double amplitudePp(double v) const {
    const double w2 = k / m;
    return 2.0 * std::sqrt(-8.0 * damping(v) / (normal() * thirdDerivative(v) * w2));
  }
};

}  // namespace tribo
