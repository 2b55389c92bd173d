#include "study/orbit/branch_grazing.hpp"

namespace tribo::study::branch {

GrazingBracket bracketGrazing(double from, double direction, double h, double width, int expansions,
                              int max_evaluations,
                              const std::function<GrazingSide(double)>& probe) {
  GrazingBracket b;
  b.inside = from;
  if (!(h > 0.0) || !(width > 0.0)) return b;
  double step = h;
  for (int k = 0; k < expansions && b.evaluations < max_evaluations; ++k, step *= 2) {
    const double p = b.inside + direction * step;
    const GrazingSide side = probe(p);
    ++b.evaluations;
    if (side == GrazingSide::kSame) {
      b.inside = p;
      continue;
    }
    b.bracketed = true;
    b.outside = p;
    b.outside_side = side;
    break;
  }
  if (!b.bracketed) return b;
  while (std::abs(b.outside - b.inside) > width && b.evaluations < max_evaluations) {
    const double mid = 0.5 * (b.inside + b.outside);
    if (mid == b.inside || mid == b.outside) break;  // the doubles between them are spent
    const GrazingSide side = probe(mid);
    ++b.evaluations;
    if (side == GrazingSide::kSame) {
      b.inside = mid;
    } else {
      b.outside = mid;
      b.outside_side = side;
    }
  }
  return b;
}

}  // namespace tribo::study::branch
