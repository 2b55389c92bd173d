// Penalty normal-force laws for one contact point, a closed, enum-selected set. With depth
// d [m] > 0 when penetrating and depth rate d' [m/s]:
//
//   linear:        F_n = k d + c d'                                  (spring-damper)
//   hertz:         F_n = k d^(3/2)                                   (Hertz 1882, elastic;
//                  k = 4/3 E* sqrt(R*) for two spheres, see hertzStiffness)
//   hunt_crossley: F_n = k d^p (1 + alpha d')                        (Hunt & Crossley 1975,
//                  "Coefficient of restitution interpreted as damping in vibroimpact",
//                  J. Appl. Mech. 42(2):440-445)
//   recurdyn:      F_n = k d^p + havsin(d, 0, 0, d_max, c) d'        (RecurDyn/ADAMS IMPACT
//                  style: the damping is ramped in over the first d_max of depth)
// and F_n = max(0, .): a law never pulls (no adhesion). Parameters are per contact point: a
// box resting on a face carries its weight on four.
//
// Hunt-Crossley restitution. Integrating m d'' = -k d^p (1 + alpha d') over the impact gives,
// with u = alpha d' (independent of m, k and p),
//   m/alpha^2 (u - ln(1 + u)) + k d^(p+1)/(p+1) = const,
// so an impact at speed v_in leaves at e v_in with
//   u_in - ln(1 + u_in) = -e u_in - ln(1 - e u_in),   u_in = alpha v_in.
// huntCrossleyRestitution and huntCrossleyDamping solve this exactly (to 1e-14); for e near 1
// it reduces to Hunt & Crossley's alpha = 3 (1 - e) / (2 v_in).
// Not here: geometry-derived stiffness for shapes other than spheres, adhesion, plasticity.
#pragma once

#include <cmath>
#include <string>

#include "friction/smooth_step.hpp"

namespace tribo::contact {

enum class NormalLawType { kLinear, kHertz, kHuntCrossley, kRecurDyn };

struct NormalLaw {
  NormalLawType type = NormalLawType::kLinear;
  double stiffness = 1e5;   // k: [N/m] (linear) or [N/m^p]
  double damping = 0.0;     // c [N s/m] (linear, recurdyn: full damping), alpha [s/m]
                            // (hunt_crossley); hertz: must be 0
  double exponent = 1.5;    // p: hunt_crossley, recurdyn (hertz: always 3/2)
  double max_depth = 1e-4;  // d_max [m]: recurdyn, depth at which damping is full

  double force(double depth, double depth_rate) const {
    if (depth <= 0.0) return 0.0;
    double f = 0.0;
    switch (type) {
      case NormalLawType::kLinear:
        f = stiffness * depth + damping * depth_rate;
        break;
      case NormalLawType::kHertz:
        f = stiffness * depth * std::sqrt(depth);
        break;
      case NormalLawType::kHuntCrossley:
        f = stiffness * std::pow(depth, exponent) * (1.0 + damping * depth_rate);
        break;
      case NormalLawType::kRecurDyn:
        f = stiffness * std::pow(depth, exponent) +
            friction::havsin(depth, 0.0, 0.0, max_depth, damping) * depth_rate;
        break;
    }
    return f > 0.0 ? f : 0.0;
  }

  // The exponent p of the elastic part k d^p: 1 (linear), 3/2 (hertz), `exponent` (the
  // others).
  double elasticExponent() const {
    return type == NormalLawType::kLinear ? 1.0 : type == NormalLawType::kHertz ? 1.5 : exponent;
  }
  // Elastic potential energy stored at depth d [J]: k d^(p+1) / (p+1), the integral of the
  // elastic part (the energy guard's contact term, core/energy.hpp). Inline for the linear
  // law, k d^2 / 2 (asked once a contact point a step by the guard).
  double energy(double depth) const {
    if (depth <= 0.0) return 0.0;
    if (type == NormalLawType::kLinear) return 0.5 * stiffness * depth * depth;
    return powerEnergy(depth);
  }
  // The same for the power laws (p != 1), at a depth > 0.
  double powerEnergy(double depth) const;

  // Throws std::invalid_argument naming the law and the bad parameter.
  void validate() const;
};

// "linear", "hertz", "hunt_crossley" or "recurdyn"; throws std::invalid_argument listing
// the known names.
NormalLawType normalLawFromName(const std::string& name);
std::string normalLawName(NormalLawType type);

// Restitution e of a Hunt-Crossley impact for u = alpha v_in > 0 (exact; see above).
double huntCrossleyRestitution(double alpha_times_speed);
// alpha [s/m] that gives restitution e in (0, 1] for an impact at speed v_in > 0 [m/s].
// Throws std::invalid_argument for e or v_in out of range.
double huntCrossleyDamping(double restitution, double impact_speed);

// Hertz stiffness of two elastic spheres [N/m^1.5]: k = 4/3 E* sqrt(R*), with
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 and 1/R* = 1/R1 + 1/R2 (R = infinity for a plane).
double hertzStiffness(double e1, double nu1, double e2, double nu2, double r1, double r2);

}  // namespace tribo::contact
