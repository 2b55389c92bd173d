// Joint constraints at acceleration level with Lagrange multipliers and Baumgarte
// stabilization (Baumgarte 1972, Comput. Methods Appl. Mech. Eng. 1:1-16):
//
//   M a = f + J^T lambda,   J a = -J' v - 2 alpha Phi' - beta^2 Phi
//   => (J M^-1 J^T) lambda = -J' v - 2 alpha Phi' - beta^2 Phi - J M^-1 f
//
// over the dynamic bodies' world-frame velocities (v, w) per body, M = diag(m I, I_W).
// Kinematic bodies and the world enter through their known motion only. The multiplier
// system is dense and factorized with Eigen's LDLT: right for the few constraints of the
// validating scenes; sparse and recursive solves are later work.
// Not here: position/velocity projection, limits, redundancy detection.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo {

class ConstraintSolver {
 public:
  explicit ConstraintSolver(const Model& model);

  int equationCount() const { return static_cast<int>(rows_.size()); }

  // Given unconstrained accelerations in ws (from f), adds M^-1 J^T lambda to them, fills
  // ws.constraint_wrench and the constraint error measures.
  void solve(const State& state, Workspace& ws);

 private:
  struct Row {
    ConstraintEquation::Kind kind;
    BodyIndex parent, child;
    Vec3 u_parent;       // parent axis i, parent frame
    Vec3 w_child;        // child axis j, child frame (perpendicular)
    Vec3 anchor_parent;  // parent frame
    Vec3 anchor_child;   // child frame
  };
  const Model& model_;
  std::vector<Row> rows_;
  std::vector<int> dof_;  // body -> offset into the 6n velocity vector, -1 if not dynamic
  int n_dof_ = 0;
  // Preallocated.
  Eigen::MatrixXd jac_, minv_jt_, schur_;
  Eigen::VectorXd rhs_, lambda_;
  std::vector<Mat3> inv_inertia_world_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

}  // namespace tribo
