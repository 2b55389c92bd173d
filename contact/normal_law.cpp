#include "contact/normal_law.hpp"

#include <cmath>
#include <stdexcept>

namespace tribo::contact {

void NormalLaw::validate() const {
  auto fail = [](const std::string& what, double got) {
    throw std::invalid_argument("normal law: " + what + " (got " + std::to_string(got) + ")");
  };
  if (!std::isfinite(stiffness) || stiffness <= 0.0) fail("stiffness must be > 0", stiffness);
  if (!std::isfinite(damping) || damping < 0.0) fail("damping must be >= 0", damping);
  if (type == NormalLawType::kHuntCrossley && (!std::isfinite(exponent) || exponent < 1.0))
    fail("exponent must be >= 1", exponent);
}

NormalLawType normalLawFromName(const std::string& name) {
  if (name == "linear") return NormalLawType::kLinear;
  if (name == "hunt_crossley") return NormalLawType::kHuntCrossley;
  throw std::invalid_argument("unknown normal law '" + name +
                              "' (expected one of: linear, hunt_crossley)");
}

}  // namespace tribo::contact
