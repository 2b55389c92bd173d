#include "study/orbit/picard.hpp"

#include <cmath>
#include <stdexcept>

#include "study/orbit/periodic_orbit.hpp"

namespace tribo::study::shooting {

namespace {

// The return map's iterations under the rule of picard.hpp. `advance(y, T, residual, end,
// iterate)` flows once, writes the residual of (y, T) and the flow's end, and, unless the
// residual is within the tolerance, replaces y and T with the next iterate.
template <class Advance>
PicardOutcome iterate(Eigen::VectorXd& y, double& T, double tolerance, Advance advance) {
  PicardOutcome out;
  Eigen::VectorXd best_y = y;
  double best_T = T, best = INFINITY, previous = INFINITY;
  for (int it = 0; it <= kPicardMostIterations; ++it) {
    Eigen::VectorXd next_y = y, end;
    double next_T = T, residual = INFINITY;
    try {
      advance(next_y, next_T, residual, end, it);
    } catch (const OrbitError&) {
      break;  // a failed step: Newton's method starts from the best iterate and reports it
    }
    // The first update may move the phase's error into T (picard.hpp): it need only not blow
    // up; every later one must contract.
    const bool contracting = it == 0 || residual * kPicardContraction <= previous ||
                             (it == 1 && residual <= 10.0 * previous);
    if (residual < best) {
      best = residual;
      best_y = y;
      best_T = T;
      out.end = end;
      out.iterations = it;
    }
    if (residual <= tolerance) {
      out.converged = true;
      break;
    }
    if (!contracting || it == kPicardMostIterations) break;
    previous = residual;
    if (!next_y.allFinite() || !(next_T > 0.0)) break;
    y = next_y;
    T = next_T;
  }
  y = best_y;
  T = best_T;
  out.residual = best;
  return out;
}

}  // namespace

// (A first-order difference errs by h f' / 2: at the section the observed coordinate's rate is
// 0, and that error would move the iterate off it.)
Eigen::VectorXd vectorField(const Flow& flow, const Eigen::VectorXd& y, double h) {
  return (4.0 * flow(y, h) - flow(y, 2.0 * h) - 3.0 * y) / (2.0 * h);
}

PicardOutcome picardAutonomous(const Flow& flow, Eigen::VectorXd& y, double& T, Eigen::Index phase,
                               double step, double tolerance, const IterateFlow& flow_of) {
  const double h = std::min(step, 0.01 * T);
  // The first guess lies off the section by up to a step of the run it came from (the time
  // from it to the section is no error of T): slid onto it along f first, so that the time to
  // the section after a period measures T's error alone.
  // Twice: the second slide takes out the first's error, of the order of its shift squared.
  const Eigen::VectorXd start = y;
  for (int slide = 0; slide < 2; ++slide) {
    const Eigen::VectorXd f0 = vectorField(flow, y, h);
    if (f0[phase] != 0.0 && std::abs(y[phase] / f0[phase]) <= 0.1 * T)
      y -= (y[phase] / f0[phase]) * f0;
  }
  const PicardOutcome out = iterate(
      y, T, tolerance,
      [&](Eigen::VectorXd& z, double& period, double& residual, Eigen::VectorXd& end, int iterate) {
        end = flow_of ? flow_of(z, period, iterate) : flow(z, period);
        const Eigen::Index n = z.size();
        Eigen::VectorXd F(n + 1);
        F.head(n) = end - z;
        F[n] = z[phase];
        residual = F.norm() / (1.0 + z.norm());
        if (residual <= tolerance) return;
        // The vector field at `end`, and the time to the section from there.
        const Eigen::VectorXd f = vectorField(flow, end, h);
        const double tau = f[phase] != 0.0 ? -end[phase] / f[phase] : 0.0;
        // A shift of more than a tenth of the period is no small correction: stop here.
        if (!(std::abs(tau) <= 0.1 * period)) {
          z.setConstant(NAN);
          return;
        }
        z = end + tau * f;
        period += tau;
      });
  if (!std::isfinite(out.residual)) y = start;  // not one flow came back: as it was
  return out;
}

PicardOutcome picardForced(const Flow& flow, Eigen::VectorXd& y, double T, double tolerance,
                           const IterateFlow& flow_of) {
  double period = T;
  return iterate(
      y, period, tolerance,
      [&](Eigen::VectorXd& z, double&, double& residual, Eigen::VectorXd& end, int iterate) {
        end = flow_of ? flow_of(z, T, iterate) : flow(z, T);
        residual = (end - z).norm() / (1.0 + z.norm());
        z = end;
      });
}

}  // namespace tribo::study::shooting
