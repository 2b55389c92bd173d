// The generalized Stribeck curve shared by the dynamic laws' steady states (elasto_plastic
// with delta = 2 as in LuGre, gms with its shape exponent):
//
//   g(v) = mu_c + (mu_s - mu_c) exp(-(|v| / v_s)^delta)
//
// (Armstrong-Helouvry, Dupont & Canudas de Wit, "A survey of models, analysis tools and
// compensation methods for the control of machines with friction", Automatica 30(7), 1994).
// mu_c Coulomb level [-], mu_s static level [-], v_s Stribeck speed [m/s], delta shape [-].
// Values only: the laws check the parameters (mu_s >= mu_c > 0, v_s > 0, delta > 0).
#pragma once

#include <cmath>
#include <limits>

namespace tribo::friction {

struct StribeckCurve {
  double mu_c = 1.0;
  double mu_s = 1.5;
  double v_s = 1e-3;
  double delta = 2.0;

  // g(|v|), in [mu_c, mu_s]. Far beyond v_s (exponent past 745) exp underflows to 0: return
  // mu_c directly (glibc's exp is slow there); delta = 2 avoids pow.
  double value(double v) const {
    const double r = std::abs(v) / v_s;
    const double p = delta == 2.0 ? r * r : std::pow(r, delta);
    if (p > 745.0) return mu_c;
    return mu_c + (mu_s - mu_c) * std::exp(-p);
  }
  // dg/dv (odd in v); at v = 0 the limit from v > 0: 0 for delta > 1, -(mu_s - mu_c) / v_s
  // for delta = 1, -infinity for delta < 1 (0 when mu_s = mu_c).
  double derivative(double v) const {
    const double r = std::abs(v) / v_s;
    if (r == 0.0) {
      if (delta > 1.0 || mu_s == mu_c) return 0.0;
      return delta == 1.0 ? -(mu_s - mu_c) / v_s : -std::numeric_limits<double>::infinity();
    }
    const double p = std::pow(r, delta);
    const double d = -(mu_s - mu_c) * delta * p / std::abs(v) * std::exp(-p);
    return v < 0.0 ? -d : d;
  }
};

}  // namespace tribo::friction
