#include "study/output_stride.hpp"

#include <algorithm>
#include <cmath>

#include "core/number_text.hpp"

namespace tribo::study {

namespace {

// An interval at or below the step records every step, as asked (it cannot be finer).
bool onSteps(double interval, double dt) {
  const double ratio = interval / dt;
  return ratio <= 1.0 || std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio;
}

}  // namespace

long outputStride(double interval, double dt) {
  const double ratio = interval / dt;
  if (!(ratio >= 1.5)) return 1;
  return std::lround(std::min(ratio, 1e15));
}

double outputInterval(double interval, double dt) {
  if (interval <= dt) return dt;
  return onSteps(interval, dt) ? interval : static_cast<double>(outputStride(interval, dt)) * dt;
}

std::optional<std::string> outputStrideNote(double interval, double dt) {
  if (onSteps(interval, dt)) return std::nullopt;
  const long every = outputStride(interval, dt);
  return "output.interval " + numberText(interval) + " s is not a whole multiple of the step " +
         numberText(dt) + " s: rows are recorded every " + std::to_string(every) +
         (every == 1 ? " step" : " steps") + " (" + numberText(outputInterval(interval, dt)) +
         " s) so that they are evenly spaced";
}

}  // namespace tribo::study
