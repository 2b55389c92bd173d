#include "study/modes/stability_boundary.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tribo::study {

ModesResult analyzeScene(const std::string& scene_path, const std::vector<std::string>& overrides,
                         const ModesSpec& spec) {
  const io::Scene scene = io::loadScene(scene_path, overrides);
  return analyzeModes(scene, spec);
}

namespace {

std::string setting(const std::string& name, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return name + "=" + text;
}

}  // namespace

BoundaryResult findBoundary(const BoundarySpec& spec) {
  if (!(spec.lo < spec.hi)) throw std::invalid_argument("--boundary: expected LO < HI");
  BoundaryResult out;
  auto growth = [&](double p, double* frequency = nullptr) {
    std::vector<std::string> overrides = spec.overrides;
    overrides.push_back(setting(spec.parameter, p));
    const ModesResult r = analyzeScene(spec.scene_path, overrides, spec.modes);
    ++out.analyses;
    if (frequency) *frequency = r.leading().frequency;
    return r.leading().growth_rate - spec.modes.growth_tolerance;
  };
  double lo = spec.lo, hi = spec.hi;
  const double s_lo = growth(lo), s_hi = growth(hi);
  out.growth_lo = s_lo + spec.modes.growth_tolerance;
  out.growth_hi = s_hi + spec.modes.growth_tolerance;
  if ((s_lo > 0) == (s_hi > 0)) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the largest growth rate does not cross zero between %s=%g (%.4g 1/s) and "
                  "%g (%.4g 1/s)",
                  spec.parameter.c_str(), lo, out.growth_lo, hi, out.growth_hi);
    throw std::invalid_argument(text);
  }
  out.unstable_above = s_hi > 0;
  while (hi - lo > spec.tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // no double left between them
    if ((growth(mid) > 0) == out.unstable_above)
      hi = mid;
    else
      lo = mid;
  }
  out.lo = lo;
  out.hi = hi;
  out.critical = 0.5 * (lo + hi);
  growth(out.unstable_above ? hi : lo, &out.frequency_unstable);
  return out;
}

}  // namespace tribo::study
