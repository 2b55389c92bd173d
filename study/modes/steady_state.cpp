#include "study/modes/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/constraint_projection.hpp"
#include "core/stability.hpp"
#include "study/modes/linearization.hpp"
#include "study/modes/reduced_coordinates.hpp"

namespace tribo::study {

namespace {

void stopDynamicBodies(const Model& model, State& state) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].kind == BodyKind::kDynamic) {
      state.bodies[b].velocity.setZero();
      state.bodies[b].angular_velocity.setZero();
    }
}

std::string format(const char* pattern, double a, double b = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

// The damped settling run (see the header); returns the simulated time.
double settle(Dynamics& dynamics, const SteadyStateOptions& options, State& x, int& evaluations) {
  const Model& m = dynamics.model();
  const double limit = estimateStableStep(m).limit.max_step;
  const double h = std::min(m.options.time_step, std::isfinite(limit) ? limit / 2 : 1e300);
  const double until = options.settle_time > 0 ? options.settle_time : m.options.duration;
  const double gamma = options.settle_damping;
  double t = 0.0;
  while (t < until) {
    const Workspace& ws = dynamics.evaluate(x);
    ++evaluations;
    double v_max = 0.0, a_max = 0.0;
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if (m.bodies[b].kind != BodyKind::kDynamic) continue;
      BodyState& s = x.bodies[b];
      const Vec3 a = ws.linear_acceleration[b] - gamma * s.velocity;
      const Vec3 alpha = ws.angular_acceleration[b] - gamma * s.angular_velocity;
      a_max = std::max({a_max, a.cwiseAbs().maxCoeff(), alpha.cwiseAbs().maxCoeff()});
      v_max = std::max(
          {v_max, s.velocity.cwiseAbs().maxCoeff(), s.angular_velocity.cwiseAbs().maxCoeff()});
      s.velocity += h * a;
      s.angular_velocity += h * alpha;
      s.position += h * s.velocity;
      s.orientation = rotateBy(s.angular_velocity, h, s.orientation);
    }
    if (!std::isfinite(a_max + v_max))
      throw NoSteadyState(format("the settling run diverged at t = %.4g s", t));
    t += h;
    if (v_max < 1e-6 && a_max < 1e-3) break;
  }
  stopDynamicBodies(m, x);
  return t;
}

double maxAbs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

// The direction nothing restrains: the right singular vector of K with the smallest
// singular value, named by the full coordinate it moves most.
std::string freeDirection(const ReducedCoordinates& coords, const Eigen::MatrixXd& k) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(k, Eigen::ComputeFullV);
  const Eigen::VectorXd full = coords.basis() * svd.matrixV().col(k.cols() - 1);
  Eigen::Index i = 0;
  full.cwiseAbs().maxCoeff(&i);
  return coords.fullName(static_cast<int>(i));
}

}  // namespace

SteadyState findSteadyState(Dynamics& dynamics, const SteadyStateOptions& options) {
  const Model& m = dynamics.model();
  SteadyState out;
  State x = dynamics.initialState();
  stopDynamicBodies(m, x);
  if (options.settle) out.settled_for = settle(dynamics, options, x, out.evaluations);
  ConstraintProjection projection(m);
  State trial = x;
  const Eigen::VectorXd none;
  for (int it = 0;; ++it) {
    const ReducedCoordinates coords(m, x);
    const Eigen::VectorXd g = coords.reducedAcceleration(dynamics.evaluate(x));
    ++out.evaluations;
    const double res = maxAbs(g);
    if (!std::isfinite(res)) throw NoSteadyState("the accelerations are not finite");
    if (res <= options.tolerance) {
      out.state = x;
      out.iterations = it;
      out.residual = res;
      return out;
    }
    if (it == options.max_iterations)
      throw NoSteadyState(
          format("Newton's method did not converge in %.0f iterations "
                 "(largest acceleration still %.3g); try --settle",
                 options.max_iterations, res));
    const Linearization lin = linearize(dynamics, coords, x, chooseSteps(dynamics, x), false, 0.0);
    out.evaluations += lin.evaluations + 1;
    const Eigen::MatrixXd& k = lin.stiffness;
    // The least-squares step of least norm (directions nothing stiffens are left alone), by
    // SVD: Eigen 3.4's complete orthogonal decomposition read uninitialised Householder
    // coefficients here (valgrind), which made the step, and the verdict, vary from run to run.
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(k, Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(1e-9);
    const Eigen::VectorXd dq = svd.solve(-g);
    if (maxAbs(k * dq + g) > 1e-6 * res + options.tolerance)
      throw NoSteadyState("no steady state: nothing holds " + freeDirection(coords, k) +
                          format(" against a steady force (acceleration %.3g while the "
                                 "stiffness along it is zero); a spring, a contact or a joint "
                                 "must restrain it",
                                 res));
    bool accepted = false;
    for (double t = 1.0; t >= 1.0 / 1024 && !accepted; t /= 2) {
      coords.perturb(x, t * dq, Eigen::VectorXd::Zero(dq.size()), trial);
      if (projection.hasConstraints()) projection.project(trial, 1e-13, 20);
      stopDynamicBodies(m, trial);
      const double r = maxAbs(coords.reducedAcceleration(dynamics.evaluate(trial)));
      ++out.evaluations;
      if (std::isfinite(r) && r < (1.0 - 1e-4 * t) * res) accepted = true;
    }
    if (!accepted)
      throw NoSteadyState(
          format("Newton's method stalled at a largest acceleration of %.3g "
                 "(iteration %.0f): no steady state near the scene's initial "
                 "pose; try --settle",
                 res, it));
    x = trial;
  }
}

}  // namespace tribo::study
