// The friction coefficient a simulator's contacts show at its current state: the sum of
// their friction forces' magnitudes over the sum of their normal forces (the rate-and-state
// velocity step tests read it against the law's closed form). Not here: per-contact values.
#pragma once

#include "core/simulator.hpp"

namespace tribo::test {

inline double contactCoefficient(Simulator& sim) {
  double ft = 0, fn = 0;
  for (const contact::ContactRecord& c : sim.current().contacts) {
    ft += c.friction_force.norm();
    fn += c.normal_force;
  }
  return ft / fn;
}

}  // namespace tribo::test
