#include "study/orbit/step_check.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <vector>

#include "core/integrator.hpp"
#include "study/orbit/orbit_coordinates.hpp"
#include "study/orbit/periodic_orbit.hpp"
#include "study/orbit/picard.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study {

namespace {
// Chord steps after the return map, at most.
constexpr int kMostChordSteps = 12;
// The finer orbit is solved this many times tighter than the orbit's tolerance (a change of
// the orbit below its own tolerance would otherwise read as none), and accepted at the orbit's
// tolerance where the finer flow's noise stops it short of that.
constexpr double kTighter = 100.0;
}  // namespace

io::RunSettings finerSettings(const Model& model, std::string& setting, double& value) {
  io::RunSettings finer;
  if (isAdaptive(model.options.integrator)) {
    finer.relative_tolerance = model.options.relative_tolerance / 100.0;
    finer.absolute_tolerance = model.options.absolute_tolerance / 100.0;
    setting = "relative_tolerance";
    value = *finer.relative_tolerance;
  } else {
    finer.time_step = model.options.time_step / 2.0;
    setting = "time_step";
    value = *finer.time_step;
  }
  return finer;
}

StepCheck checkAgainstFinerSetting(const io::Scene& finer, const OrbitResult& orbit,
                                   const OrbitSpec& spec) {
  StepCheck c;
  const bool adaptive = isAdaptive(finer.model->options.integrator);
  c.setting = adaptive ? "relative_tolerance" : "time_step";
  c.value = adaptive ? finer.model->options.relative_tolerance : finer.model->options.time_step;
  const OrbitCoordinates coords(*finer.model, orbit.reference);
  const Eigen::Index n = coords.size();
  if (n != orbit.start.size())
    throw OrbitError("the scene at the finer setting has " + std::to_string(n) +
                     " unknowns, the orbit " + std::to_string(orbit.start.size()));
  const shooting::Flow flow(finer.model, coords);
  const int body = shooting::observedBody(finer);
  const int axis = finer.output.summary.coordinate;
  const Eigen::Index phase = coords.velocityIndex(body, axis);
  Eigen::VectorXd y = orbit.start;
  double T = orbit.period;
  const double tight = spec.tolerance / kTighter;
  auto residualOf = [&](const Eigen::VectorXd& end) {
    const double closing = (end - y).squaredNorm();
    const double off = orbit.forced ? 0.0 : y[phase] * y[phase];
    return std::sqrt(closing + off) / (1.0 + y.norm());
  };
  try {
    const shooting::PicardOutcome o =
        orbit.forced
            ? shooting::picardForced(flow, y, T, tight)
            : shooting::picardAutonomous(flow, y, T, phase, finer.model->options.time_step, tight);
    c.iterations = o.iterations;
    c.residual = o.residual;
    c.converged = o.converged;
    // Chord steps with the orbit's Jacobian: the monodromy less I, d phi / d T and the phase
    // row (autonomous), least squares as Newton's (the joints' constraints make it singular in
    // the directions they remove).
    if (!c.converged && orbit.monodromy.size() > 0 && std::isfinite(o.residual)) {
      const Eigen::Index rows = orbit.forced ? n : n + 1;
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> chord(shooting::closingJacobian(
          orbit.monodromy, orbit.forced ? nullptr : &orbit.period_column, phase));
      // The best iterate is kept: a chord step that does not shrink the residual ends them.
      Eigen::VectorXd best_y = y;
      double best_T = T, best = INFINITY;
      for (int step = 0; step < kMostChordSteps; ++step) {
        const Eigen::VectorXd end = flow(y, T);
        Eigen::VectorXd F(rows);
        F.head(n) = end - y;
        if (!orbit.forced) F[n] = y[phase];
        const double residual = residualOf(end);
        ++c.iterations;
        if (!(residual < best)) break;
        best = residual, best_y = y, best_T = T;
        if (residual <= tight) break;
        const Eigen::VectorXd dz = chord.solve(-F);
        if (!dz.allFinite()) break;
        y += dz.head(n);
        if (!orbit.forced) T += dz[n];
      }
      y = best_y;
      T = best_T;
      c.residual = best;
      c.converged = best <= tight;
    }
  } catch (const OrbitError& e) {
    c.why = std::string("a step failed at the finer setting: ") + e.what();
    c.flows = flow.count();
    return c;
  }
  if (!c.converged && c.residual <= spec.tolerance) c.converged = true;
  c.tolerance = c.residual <= tight ? tight : spec.tolerance;
  if (!c.converged) {
    c.why = "the orbit at the finer setting was not reached (the return map" +
            std::string(orbit.monodromy.size() > 0 ? " and the orbit's Jacobian" : "") +
            "; residual " + shooting::messageNumber(c.residual) + ")";
    c.flows = flow.count();
    return c;
  }
  // Its amplitude as the orbit's: one period sampled at the step.
  const shooting::SampledPeriod sampled =
      shooting::samplePeriod(flow, coords, y, T, body, axis, orbit.forced);
  c.period = T;
  c.amplitude_pp = sampled.x_max - sampled.x_min;
  c.period_change = c.period - orbit.period;
  c.amplitude_change = c.amplitude_pp - orbit.amplitude_pp;
  c.relative_period_change = c.period_change / orbit.period;
  c.relative_amplitude_change =
      orbit.amplitude_pp != 0.0 ? c.amplitude_change / orbit.amplitude_pp : 0.0;
  c.flows = flow.count();
  return c;
}

StepCheck checkOrbitAgainstStep(const Model& model, const OrbitResult& orbit, const OrbitSpec& spec,
                                const std::function<io::Scene(const io::RunSettings&)>& load) {
  std::string setting;
  double value = 0;
  const io::RunSettings finer = finerSettings(model, setting, value);
  try {
    return checkAgainstFinerSetting(load(finer), orbit, spec);
  } catch (const std::exception& e) {
    StepCheck refused;
    refused.setting = setting;
    refused.value = value;
    refused.why = e.what();
    return refused;
  }
}

}  // namespace tribo::study
