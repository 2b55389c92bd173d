#include "study/modes/linearization.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tribo::study {

Eigen::VectorXd reducedResponse(Dynamics& dynamics, const ReducedCoordinates& coords,
                                const State& x, bool with_states) {
  const Workspace& ws = dynamics.evaluate(x);
  const Eigen::VectorXd a = coords.reducedAcceleration(ws);
  if (!with_states) return a;
  Eigen::VectorXd out(a.size() + static_cast<Eigen::Index>(x.friction_values.size()));
  out.head(a.size()) = a;
  for (std::size_t i = 0; i < x.friction_values.size(); ++i)
    out(a.size() + static_cast<Eigen::Index>(i)) = ws.friction_state_rate[i];
  return out;
}

DifferenceSteps chooseSteps(Dynamics& dynamics, const State& at) {
  DifferenceSteps steps;
  const Workspace& ws = dynamics.evaluate(at);
  const Model& m = dynamics.model();
  for (const contact::ContactRecord& rec : ws.contacts) {
    if (rec.point.depth > 0) steps.position = std::min(steps.position, rec.point.depth / 100);
    const double v_stick =
        m.materials[m.contactPair(rec.point.pair).material].friction->stickSpeed();
    if (v_stick > 0) steps.velocity = std::min(steps.velocity, v_stick / 100);
  }
  return steps;
}

namespace {

// Central difference of the response along coordinate j (configuration when !velocity) with
// step h.
Eigen::VectorXd column(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at, int j,
                       bool velocity, double h, State& scratch, bool with_states) {
  const int n = coords.size();
  Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  step(j) = h;
  coords.perturb(at, velocity ? zero : step, velocity ? step : zero, scratch);
  const Eigen::VectorXd plus = reducedResponse(dynamics, coords, scratch, with_states);
  coords.perturb(at, velocity ? zero : Eigen::VectorXd(-step),
                 velocity ? Eigen::VectorXd(-step) : zero, scratch);
  const Eigen::VectorXd minus = reducedResponse(dynamics, coords, scratch, with_states);
  return (plus - minus) / (2 * h);
}

// The same along internal state value i.
Eigen::VectorXd stateColumn(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at,
                            std::size_t i, double h, State& scratch) {
  scratch = at;
  scratch.friction_values[i] = at.friction_values[i] + h;
  const Eigen::VectorXd plus = reducedResponse(dynamics, coords, scratch, true);
  scratch.friction_values[i] = at.friction_values[i] - h;
  const Eigen::VectorXd minus = reducedResponse(dynamics, coords, scratch, true);
  scratch = at;
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
  const bool with_states = velocities && !at.friction_values.empty();
  const auto nz = static_cast<Eigen::Index>(at.friction_values.size());
  if (with_states) {
    lin.state_force.resize(n, nz);
    lin.state_from_position.resize(nz, n);
    lin.state_from_velocity.resize(nz, n);
    lin.state_rate.resize(nz, nz);
  }
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
      const Eigen::VectorXd col =
          column(dynamics, coords, at, j, velocity, h, scratch, with_states);
      out.col(j) = col.head(n);
      if (with_states)
        (velocity ? lin.state_from_velocity : lin.state_from_position).col(j) = col.tail(nz);
      lin.evaluations += 2;
      if (check_tolerance > 0) {
        checks.push_back(
            {column(dynamics, coords, at, j, velocity, 4 * h, scratch, false), j, velocity});
        lin.evaluations += 2;
      }
    }
  }
  for (Eigen::Index i = 0; i < nz && with_states; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double h = 1e-4 * std::abs(at.friction_values[k]) + 1e-12;
    const Eigen::VectorXd col = stateColumn(dynamics, coords, at, k, h, scratch);
    lin.state_force.col(i) = col.head(n);
    lin.state_rate.col(i) = col.tail(nz);
    lin.evaluations += 2;
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
  const Eigen::Index nz = lin.state_rate.rows();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n + nz, 2 * n + nz);
  a.block(0, n, n, n).setIdentity();
  a.block(n, 0, n, n) = lin.stiffness;
  if (lin.damping.size() > 0) a.block(n, n, n, n) = lin.damping;
  if (nz > 0) {
    a.block(n, 2 * n, n, nz) = lin.state_force;
    a.block(2 * n, 0, nz, n) = lin.state_from_position;
    a.block(2 * n, n, nz, n) = lin.state_from_velocity;
    a.block(2 * n, 2 * n, nz, nz) = lin.state_rate;
  }
  return a;
}

}  // namespace tribo::study
