// Penalty normal-force laws for one contact point, a closed, enum-selected set.
//
//   linear:        F_n = max(0, k d + c d')                      (spring-damper)
//   hunt_crossley: F_n = max(0, k d^p (1 + alpha d'))            (Hunt & Crossley 1975,
//                  "Coefficient of restitution interpreted as damping in vibroimpact",
//                  J. Appl. Mech. 42(2):440-445)
// with depth d [m] > 0 when penetrating and depth rate d' [m/s]. Never pulls (no adhesion).
// Parameters are per contact point: a box resting on a face carries its weight on four.
// Not here: the restitution-to-damping relation (later), Hertz geometry-derived stiffness.
#pragma once

#include <cmath>
#include <string>

namespace tribo::contact {

enum class NormalLawType { kLinear, kHuntCrossley };

struct NormalLaw {
  NormalLawType type = NormalLawType::kLinear;
  double stiffness = 1e5;  // k: [N/m] (linear) or [N/m^p] (hunt_crossley)
  double damping = 0.0;    // c [N s/m] (linear) or alpha [s/m] (hunt_crossley)
  double exponent = 1.5;   // p, hunt_crossley only

  double force(double depth, double depth_rate) const {
    if (depth <= 0.0) return 0.0;
    double f = 0.0;
    if (type == NormalLawType::kLinear) {
      f = stiffness * depth + damping * depth_rate;
    } else {
      f = stiffness * std::pow(depth, exponent) * (1.0 + damping * depth_rate);
    }
    return f > 0.0 ? f : 0.0;
  }

  // Throws std::invalid_argument naming the bad parameter.
  void validate() const;
};

// "linear" or "hunt_crossley"; throws std::invalid_argument listing the known names.
NormalLawType normalLawFromName(const std::string& name);

}  // namespace tribo::contact
