// The shared part of the single-bristle laws (LuGre, Dahl, elasto-plastic; Canudas de Wit
// et al. 1995, Dahl 1968, Dupont et al. 2002): their internal state is one tangent vector z
// [m], the mean deflection of the bristles in the contact plane (3 numbers in the contact's
// frame, named z.x z.y z.z), starting undeflected; their steady curves have no breakpoints.
// Each law gives its own rate, force, bounded step and parameters.
// Not here: multi-element or scalar states (gms, rate_state derive DynamicFrictionLaw).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "friction/dynamic_law.hpp"

namespace tribo::friction {

class BristleLaw : public DynamicFrictionLaw {
 public:
  std::vector<double> breakpoints() const final { return {}; }
  int stateSize() const final { return 3; }
  int tangentVectors() const final { return 1; }
  std::string stateName(int i) const final {
    static constexpr const char* kNames[] = {"z.x", "z.y", "z.z"};
    return kNames[std::clamp(i, 0, 2)];
  }
  void initialState(double* z) const final { z[0] = z[1] = z[2] = 0.0; }
};

}  // namespace tribo::friction
