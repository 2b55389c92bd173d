// The errors of the stability analysis (study/modes/modes.hpp, study/modes/sparse_modes.hpp), in a
// header of their own so that the eigensolvers and the analysis can both throw them.
//   ModesError            what cannot be analysed (stateful friction, no dynamic body, a
//                         sparse request on a system too small for it): `tribo modes` exit 2
//   LinearizationFailure  the numbers failed (a non-finite linearization, an eigenproblem that
//                         did not converge or whose residual is too large): exit 10
// Not here: NoSteadyState (study/modes/steady_state.hpp).
#pragma once

#include <stdexcept>

namespace tribo::study {

class ModesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// The numbers failed: a non-finite linearization or an eigenproblem that did not converge.
class LinearizationFailure : public ModesError {
 public:
  using ModesError::ModesError;
};

}  // namespace tribo::study
