// Bracketing a grazing point that the arclength corrector cannot pass (study/orbit/
// orbit_branch.hpp): where the orbits of a law with a kink at its stick speed (roh_yoo, a
// coulomb law with a linear ramp: FrictionLaw::breakpoints) stop or start sticking, the
// shooting rows have no derivative, and Newton's iteration fails there at every step.
// Instead the orbit is solved at fixed values of the parameter, from the last point on: steps
// h, 2h, 4h, ... from the last orbit found until an orbit lies on the other side of the stick
// speed (or none is found), then bisection until the bracket is `width` wide. The grazing point
// lies in the bracket; the continuation goes on from the orbit on the far side (orbit_branch.cpp),
// and the event is located between the two as any grazing. Internal to study/orbit/. Not here:
// solving an orbit at a fixed parameter and telling its side (the caller's probe), the
// continuation, the events (branch_events.cpp).
#pragma once

#include <cmath>
#include <functional>

namespace tribo::study::branch {

// Where the orbit at a probed parameter lies: on the side of the stick speed the branch came
// from, across it, or nowhere (no orbit found, or only an equilibrium).
enum class GrazingSide { kSame, kCrossed, kNone };

struct GrazingBracket {
  bool bracketed = false;  // a probe left the side of `from`
  double inside = NAN;     // the last parameter whose orbit lies on the side of `from`
  double outside = NAN;    // the nearest one beyond it whose orbit does not
  GrazingSide outside_side = GrazingSide::kNone;
  int evaluations = 0;  // probes
};

// From `from` (the last point's parameter, kSame) in `direction` (+1 or -1): probes at
// from + h, + 3h, + 7h, ... (each 2^k h past the one before, at most `expansions` of them)
// until one is not kSame, then bisects until |outside - inside| <= width or
// `max_evaluations` probes are spent. Within each side the probes come in order: the
// caller's last kSame result is `inside`'s, its last other one `outside`'s.
GrazingBracket bracketGrazing(double from, double direction, double h, double width, int expansions,
                              int max_evaluations, const std::function<GrazingSide(double)>& probe);

}  // namespace tribo::study::branch
