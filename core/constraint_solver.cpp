#include "core/constraint_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tribo {

bool useSparseFactorization(const ConstraintOptions& options, int equations) {
  switch (options.solver) {
    case ConstraintSolverKind::kDense:
      return false;
    case ConstraintSolverKind::kSparse:
      return true;
    case ConstraintSolverKind::kAuto:
      break;
  }
  return equations >= options.sparse_threshold;
}

ConstraintSolver::ConstraintSolver(const Model& model)
    : model_(model), rows_(constraintRows(model)), groups_(rowGroups(rows_)) {
  const int m = equationCount();
  const int nb = static_cast<int>(model.bodies.size());
  joint_rows_.resize(model.joints.size());
  for (int r = 0; r < m; ++r)
    if (rows_[r].equation >= 0) joint_rows_[rows_[r].joint].push_back(r);
  jacobian_.init(rows_, nb);
  matrix_.init(m, jacobian_.pattern(), useSparseFactorization(model.options.constraints, m),
               groupBegins(groups_, m));
  jacobian_.bindSlots(matrix_);
  values_.resize(m);
  for (const Body& b : model.bodies) inv_mass_.push_back(1.0 / b.mass);
  rhs_.setZero(m);
  lambda_.setZero(m);
  delta_lambda_.setZero(m);
  if (model.options.constraints.solver == ConstraintSolverKind::kAuto)
    locked_ = LockedRotationSolve::plan(model, rows_);
}

void ConstraintSolver::solve(const State& state, Workspace& ws) {
  ws.max_constraint_error = 0.0;
  ws.max_constraint_rate_error = 0.0;
  ws.max_constraint_joint = -1;
  for (auto& w : ws.constraint_wrench) w.setZero();
  const int m = equationCount();
  if (m == 0) return;
  const double alpha = model_.options.baumgarte_alpha;
  const double beta = model_.options.baumgarte_beta;

  evaluateRows(rows_, groups_, MotionView(state, ws.rotation), state.time, values_);
  for (int r = 0; r < m; ++r) {
    const RowValue& v = values_[r];
    rhs_(r) = -v.bias - 2.0 * alpha * v.phi_dot - beta * beta * v.phi;
    if (std::abs(v.phi) > ws.max_constraint_error) {
      ws.max_constraint_error = std::abs(v.phi);
      ws.max_constraint_joint = rows_[r].joint;
    }
    ws.max_constraint_rate_error = std::max(ws.max_constraint_rate_error, std::abs(v.phi_dot));
  }
  // Bodies each held to the world with their rotations locked: in closed form.
  closed_form_ = false;
  if (locked_) {
    lambda_.setZero();
    closed_form_ = locked_->project(values_, rhs_, ws, lambda_);
    if (closed_form_) return;
  }
  for (int r = 0; r < m; ++r) jacobian_.setRow(r, values_[r]);
  jacobian_.computeMassWeighted(inv_mass_, ws.inv_inertia_world);
  jacobian_.addJx(ws.linear_acceleration, ws.angular_acceleration, -1.0, rhs_);

  matrix_.setZero();
  jacobian_.assemble(matrix_);
  if (!matrix_.factorize()) {
    lambda_.setConstant(std::numeric_limits<double>::quiet_NaN());
  } else {
    lambda_ = rhs_;
    matrix_.solveInPlace(lambda_);
  }
  jacobian_.applyMultipliers(lambda_, ws.linear_acceleration, ws.angular_acceleration,
                             &ws.constraint_wrench);
}

void ConstraintSolver::addForcesAndResolve(const std::vector<Wrench>& delta, Workspace& ws) {
  for (std::size_t b = 0; b < delta.size(); ++b) {
    if (model_.bodies[b].kind != BodyKind::kDynamic) continue;
    ws.linear_acceleration[b] += delta[b].force * inv_mass_[b];
    ws.angular_acceleration[b] += ws.inv_inertia_world[b] * delta[b].torque;
  }
  const int m = equationCount();
  if (m == 0) return;
  if (closed_form_) {  // the same projection: J a = b again for the changed accelerations
    locked_->project(values_, rhs_, ws, lambda_);
    return;
  }
  delta_lambda_.setZero();
  jacobian_.addJMinvF(delta, -1.0, delta_lambda_);
  matrix_.solveInPlace(delta_lambda_);
  lambda_ += delta_lambda_;
  jacobian_.applyMultipliers(delta_lambda_, ws.linear_acceleration, ws.angular_acceleration,
                             &ws.constraint_wrench);
}

Vec3 ConstraintSolver::reactionForce(int joint) const {
  Vec3 f = Vec3::Zero();
  const int child = model_.joints[joint].child.value;
  for (int r : joint_rows_[joint]) {
    const Row6 block = closed_form_ ? values_[r].j[0] : jacobian_.block(r, child);
    f += lambda_(r) * block.head<3>().transpose();
  }
  return f;
}

}  // namespace tribo
