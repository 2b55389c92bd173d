// Joint constraints at acceleration level with Lagrange multipliers and Baumgarte
// stabilization (Baumgarte 1972, Comput. Methods Appl. Mech. Eng. 1:1-16):
//
//   M a = f + J^T lambda,   J a = -J' v - 2 alpha Phi' - beta^2 Phi
//   => (J M^-1 J^T) lambda = -J' v - 2 alpha Phi' - beta^2 Phi - J M^-1 f
//
// over the dynamic bodies' world-frame velocities (v, w) per body, M = diag(m I, I_W).
// J is stored sparse (a 1x6 block per body a row touches), so the Schur complement costs
// O(rows^2) small dot products, independent of the number of bodies.
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

  // Given unconstrained accelerations and the kinematics stage in ws, adds
  // M^-1 J^T lambda to the accelerations, fills ws.constraint_wrench and the constraint
  // error measures.
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
  // A row's Jacobian, kept sparse: one 1x6 block per dynamic body it touches (a row
  // touches at most two), and M^-1 applied to each block.
  struct RowJacobian {
    int body[2] = {-1, -1};  // dynamic body index or -1 (world, kinematic)
    Row6 j[2];
    Row6 minv_j[2];
  };
  const Model& model_;
  std::vector<Row> rows_;
  // Preallocated.
  std::vector<RowJacobian> jac_;
  std::vector<double> inv_mass_;  // per body
  // J M^-1 J^T and its factorization. Up to kSmall equations (a few joints) the matrices
  // live on the stack-sized fixed-capacity type and are factorized by Cholesky (LLT):
  // measured 3x cheaper than LDLT at 4 equations. Larger systems use LDLT.
  static constexpr int kSmall = 12;
  using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kSmall, kSmall>;
  using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kSmall, 1>;
  SmallMatrix schur_small_;
  SmallVector rhs_small_;
  Eigen::LLT<SmallMatrix> llt_small_;
  Eigen::MatrixXd schur_;
  Eigen::VectorXd rhs_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  Eigen::VectorXd lambda_;

  template <typename Matrix>
  void fillSchur(Matrix& schur) const;
};

}  // namespace tribo
