// Where steady sliding turns unstable along one scene parameter: bisection on the sign of
//   s(p) = sigma_max(p) - growth_tolerance
// (sigma_max the largest growth rate of study/modes/modes.hpp with the parameter set to p through
// the scene's `--set` overrides), from a bracket [lo, hi] where s changes sign, halving it
// until hi - lo <= tolerance. Each evaluation reloads the scene (the model is immutable and
// everything derived from the parameter follows) and redoes the steady state, linearization
// and eigenvalues. With damping-free modes sigma_max is 0 below a flutter boundary and
// grows like sqrt(p - p_c) above it, so the growth tolerance moves the answer by
// O(tolerance^2); a boundary where the growth rate crosses zero with slope s moves by
// tolerance / s.
// Not here: several crossings inside the bracket (bisection finds one of them), parameters
// that are not numbers, the map over two parameters (tribo sweep --analysis modes).
#pragma once

#include <string>
#include <vector>

#include "study/modes/modes.hpp"

namespace tribo::study {

struct BoundarySpec {
  std::string scene_path;
  std::vector<std::string> overrides;  // NAME=VALUE, applied before the parameter's value
  std::string parameter;
  double lo = 0.0, hi = 0.0;
  double tolerance = 1e-8;  // on the parameter
  ModesSpec modes;
};

struct BoundaryResult {
  double critical = 0.0;                    // the bracket's midpoint at the end
  double lo = 0.0, hi = 0.0;                // the final bracket
  bool unstable_above = true;               // the unstable side is hi
  double growth_lo = 0.0, growth_hi = 0.0;  // sigma_max at the initial ends [1/s]
  double frequency_unstable = 0.0;  // of the leading mode at the unstable end of the bracket [Hz]
  int analyses = 0;
};

// The largest growth rate of the scene with `overrides` (throws as analyzeModes, and
// io::SceneError for a bad value).
ModesResult analyzeScene(const std::string& scene_path, const std::vector<std::string>& overrides,
                         const ModesSpec& spec);

// Throws std::invalid_argument when s does not change sign over [lo, hi].
BoundaryResult findBoundary(const BoundarySpec& spec);

}  // namespace tribo::study
