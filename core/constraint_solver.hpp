// Joint constraints at acceleration level with Lagrange multipliers and Baumgarte
// stabilization (Baumgarte 1972, Comput. Methods Appl. Mech. Eng. 1:1-16):
//
//   M a = f + J^T lambda,   J a = -(J' v - f'') - 2 alpha Phi' - beta^2 Phi
//   => (J M^-1 J^T) lambda = -(J' v - f'') - 2 alpha Phi' - beta^2 Phi - J M^-1 f
//
// over the dynamic bodies' world-frame velocities (v, w) per body, M = diag(m I, I_W); f'
// and f'' are the prescribed rates of drive rows (zero for the others). Rows come from
// core/constraint_rows.hpp (joint equations, drives, couplings), J is stored by body
// (core/constraint_jacobian.hpp) and J M^-1 J^T is factorized dense or sparse by size
// (core/multiplier_matrix.hpp; ConstraintOptions::solver), or, under kAuto when every row
// belongs to a joint holding one body to the world with its rotations locked, solved in
// closed form (core/locked_rotation_solve.hpp). Kinematic bodies and the world
// enter through their known motion only.
// Not here: projection (core/constraint_projection.hpp), redundancy detection
// (core/constraint_rank.hpp), joint forces (core/joint_forces.hpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "core/constraint_jacobian.hpp"
#include "core/constraint_rows.hpp"
#include "core/locked_rotation_solve.hpp"
#include "core/model.hpp"
#include "core/multiplier_matrix.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo {

// Whether a system of `equations` rows is factorized sparse under `options`.
bool useSparseFactorization(const ConstraintOptions& options, int equations);

class ConstraintSolver {
 public:
  explicit ConstraintSolver(const Model& model);

  int equationCount() const { return static_cast<int>(rows_.size()); }
  bool isSparse() const { return matrix_.isSparse(); }
  // Whether the last solve() was in closed form (core/locked_rotation_solve.hpp).
  bool lastSolveClosedForm() const { return closed_form_; }
  const std::vector<ConstraintRow>& rows() const { return rows_; }

  // Given unconstrained accelerations and the kinematics stage in ws, adds
  // M^-1 J^T lambda to the accelerations, fills ws.constraint_wrench and the constraint
  // error measures. If J M^-1 J^T cannot be factorized (a singular configuration) the
  // accelerations become NaN, which the simulator reports.
  void solve(const State& state, Workspace& ws);

  // After solve(): the applied forces change by `delta` (per body, world, at the origin);
  // updates lambda, the accelerations and the constraint wrenches with the same
  // factorization (one back-substitution), or after a closed-form solve the same projection
  // again.
  void addForcesAndResolve(const std::vector<Wrench>& delta, Workspace& ws);

  // After solve(): the multipliers, one per row in rows()' order.
  const Eigen::VectorXd& multipliers() const { return lambda_; }
  // After solve(): the force the joint's own equations exert on its child [N, world].
  Vec3 reactionForce(int joint) const;

 private:
  const Model& model_;
  std::vector<ConstraintRow> rows_;
  std::vector<RowGroup> groups_;
  std::vector<std::vector<int>> joint_rows_;  // per joint, its equation rows
  ConstraintJacobian jacobian_;
  MultiplierMatrix matrix_;
  std::vector<RowValue> values_;
  std::vector<double> inv_mass_;  // per body
  Eigen::VectorXd rhs_;
  Eigen::VectorXd lambda_;
  Eigen::VectorXd delta_lambda_;
  std::optional<LockedRotationSolve> locked_;  // under kAuto, when every row allows it
  bool closed_form_ = false;
};

}  // namespace tribo
