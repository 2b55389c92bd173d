// The belt scene reduced by hand to one degree of freedom, as the paper states it:
//   m x'' = -k x + mu(v_b - x') m g        (box on a belt at v_b, spring to a wall)
// with, optionally, a wall damper c beside the spring (- c x'; none by default: the paper's
// model exactly), integrated with classical RK4. It shares nothing with the engine but the
// friction law, so it is an independent reference for the scene tests and the baseline of
// the benches (the cheapest possible simulation of this scene). Not an engine feature.
#pragma once

#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::test {

struct OneDofBelt {
  double m = 10.0, k = 300.0, v_b = 1.5, g = 9.81;
  const friction::FrictionLaw* law = nullptr;
  double c = 0.0;  // the wall damper [N s/m]

  double acceleration(double x, double v) const {
    return (-k * x - c * v + law->coefficient(v_b - v) * m * g) / m;
  }

  // Advances (x, v) by n RK4 steps of h; calls sample(t, x, v) after each step if given.
  template <typename Sample>
  void run(double& x, double& v, double h, long n, Sample&& sample) const {
    double t = 0.0;
    for (long i = 0; i < n; ++i) {
      const double a1 = acceleration(x, v);
      const double x2 = x + 0.5 * h * v, v2 = v + 0.5 * h * a1;
      const double a2 = acceleration(x2, v2);
      const double x3 = x + 0.5 * h * v2, v3 = v + 0.5 * h * a2;
      const double a3 = acceleration(x3, v3);
      const double x4 = x + h * v3, v4 = v + h * a3;
      const double a4 = acceleration(x4, v4);
      x += h / 6.0 * (v + 2 * v2 + 2 * v3 + v4);
      v += h / 6.0 * (a1 + 2 * a2 + 2 * a3 + a4);
      t += h;
      sample(t, x, v);
    }
  }
};

}  // namespace tribo::test
