#include "study/linearization.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tribo::study {

DifferenceSteps chooseSteps(Dynamics& dynamics, const State& at) {
  DifferenceSteps steps;
  const Workspace& ws = dynamics.evaluate(at);
  const Model& m = dynamics.model();
  for (const contact::ContactRecord& rec : ws.contacts) {
    if (rec.point.depth > 0) steps.position = std::min(steps.position, rec.point.depth / 100);
    const double v_stick =
        m.materials[m.contact_pairs[rec.point.pair].material].friction->stickSpeed();
    if (v_stick > 0) steps.velocity = std::min(steps.velocity, v_stick / 100);
  }
  return steps;
}

namespace {

// Central difference of the reduced accelerations along coordinate j (configuration when
// !velocity) with step h.
Eigen::VectorXd column(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at, int j,
                       bool velocity, double h, State& scratch) {
  const int n = coords.size();
  Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  step(j) = h;
  coords.perturb(at, velocity ? zero : step, velocity ? step : zero, scratch);
  const Eigen::VectorXd plus = coords.reducedAcceleration(dynamics.evaluate(scratch));
  coords.perturb(at, velocity ? zero : Eigen::VectorXd(-step),
                 velocity ? Eigen::VectorXd(-step) : zero, scratch);
  const Eigen::VectorXd minus = coords.reducedAcceleration(dynamics.evaluate(scratch));
  return (plus - minus) / (2 * h);
}

// Which full coordinates reduced coordinate j moves most (for messages).
std::string coordinateLabel(const ReducedCoordinates& coords, int j) {
  Eigen::Index i = 0;
  coords.basis().col(j).cwiseAbs().maxCoeff(&i);
  std::string label = coords.fullName(static_cast<int>(i));
  if (coords.size() == coords.fullSize()) return label;
  std::string text = "independent coordinate ";
  text.append(std::to_string(j)).append(" (mostly ").append(label).append(")");
  return text;
}

}  // namespace

Linearization linearize(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at,
                        const DifferenceSteps& steps, bool velocities, double check_tolerance) {
  const int n = coords.size();
  Linearization lin;
  lin.stiffness.resize(n, n);
  if (velocities) lin.damping.resize(n, n);
  State scratch = at;
  struct Check {
    Eigen::VectorXd coarse;
    int j;
    bool velocity;
  };
  std::vector<Check> checks;
  for (const bool velocity : {false, true}) {
    if (velocity && !velocities) break;
    const double h = velocity ? steps.velocity : steps.position;
    Eigen::MatrixXd& out = velocity ? lin.damping : lin.stiffness;
    for (int j = 0; j < n; ++j) {
      out.col(j) = column(dynamics, coords, at, j, velocity, h, scratch);
      lin.evaluations += 2;
      if (check_tolerance > 0) {
        checks.push_back({column(dynamics, coords, at, j, velocity, 4 * h, scratch), j, velocity});
        lin.evaluations += 2;
      }
    }
  }
  // A column's difference is measured against its own size, or a small share of the
  // largest entry of its matrix when it is (nearly) zero.
  for (const Check& c : checks) {
    const Eigen::MatrixXd& mat = c.velocity ? lin.damping : lin.stiffness;
    const double scale =
        std::max({mat.col(c.j).cwiseAbs().maxCoeff(), 1e-6 * mat.cwiseAbs().maxCoeff(), 1e-300});
    const double d = (mat.col(c.j) - c.coarse).cwiseAbs().maxCoeff() / scale;
    lin.worst_disagreement = std::max(lin.worst_disagreement, d);
    if (d > check_tolerance) {
      char text[256];
      std::snprintf(text, sizeof text,
                    "finite differences along %s (%s) disagree between steps %.3g and %.3g by "
                    "%.2g (relative): a kink or a contact opening within the step?",
                    coordinateLabel(coords, c.j).c_str(), c.velocity ? "velocity" : "position",
                    c.velocity ? steps.velocity : steps.position,
                    4 * (c.velocity ? steps.velocity : steps.position), d);
      lin.warnings.push_back(text);
    }
  }
  return lin;
}

Eigen::MatrixXd firstOrderMatrix(const Linearization& lin) {
  const Eigen::Index n = lin.stiffness.rows();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).setIdentity();
  a.bottomLeftCorner(n, n) = lin.stiffness;
  if (lin.damping.size() > 0) a.bottomRightCorner(n, n) = lin.damping;
  return a;
}

}  // namespace tribo::study
