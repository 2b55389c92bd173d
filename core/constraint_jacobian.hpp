// The constraint Jacobian J of a model's rows, stored by body: for each dynamic body b the
// rows that touch it form a small dense n_b x 6 matrix J_b over b's world-frame (v, w), with
// M_b^-1 J_b^T beside it (M_b = diag(m I, I_W)). Products then run body by body:
//   A  = J M^-1 J^T = sum_b  S_b^T (J_b M_b^-1 J_b^T) S_b     (S_b selects b's rows)
//   J a,  J^T lambda,  M^-1 J^T lambda,  J M^-1 f
// so assembling A costs sum_b n_b^2 (n_b ~ 10 for a link between two revolute joints),
// linear in the number of bodies for a chain or tree.
// Not here: evaluating rows (core/constraint_rows.hpp), factorizing A
// (core/multiplier_matrix.hpp).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/multiplier_matrix.hpp"
#include "core/workspace.hpp"

namespace tribo {

class ConstraintJacobian {
 public:
  // Sets up storage for `rows` over `body_count` bodies and the pattern of A.
  void init(const std::vector<ConstraintRow>& rows, int body_count);
  // The structurally nonzero entries (i >= j) of A, diagonals included.
  std::vector<std::pair<int, int>> pattern() const;
  // Precomputes where each body's block of A goes in `matrix` (after matrix.init()).
  void bindSlots(const MultiplierMatrix& matrix);

  void setRow(int r, const RowValue& value);
  // M^-1 J^T from inverse masses and inverse world inertias (per body index).
  void computeMassWeighted(const std::vector<double>& inv_mass,
                           const std::vector<Mat3>& inv_inertia_world);

  // matrix.values() += J M^-1 J^T (call matrix.setZero() first).
  void assemble(MultiplierMatrix& matrix) const;
  // out += sign * J x, with x per body (linear, angular) parts.
  void addJx(const std::vector<Vec3>& linear, const std::vector<Vec3>& angular, double sign,
             Eigen::VectorXd& out) const;
  // out += sign * J M^-1 f for body wrenches f.
  void addJMinvF(const std::vector<Wrench>& f, double sign, Eigen::VectorXd& out) const;
  // linear/angular += M^-1 J^T lambda; wrench += J^T lambda (wrench may be null).
  void applyMultipliers(const Eigen::VectorXd& lambda, std::vector<Vec3>& linear,
                        std::vector<Vec3>& angular, std::vector<Wrench>* wrench) const;
  // Row r's block for body b (zero if r does not touch b).
  Row6 block(int r, int body) const;

 private:
  using Blocks = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;
  struct BodyRows {
    int body = -1;
    std::vector<int> rows;   // ascending
    std::vector<int> slots;  // lower triangle of its block of A: (i, j <= i) at i (i + 1) / 2 + j
    Blocks j, minv_j;
  };
  struct Place {
    int slot = -1;  // index in bodies_
    int local = -1;
  };
  std::vector<BodyRows> bodies_;
  std::vector<int> slot_of_body_;  // body index -> index in bodies_ or -1
  std::vector<std::array<Place, ConstraintRow::kMaxBodies>> where_;  // per row, per block
  std::vector<int> block_count_;                                     // per row
};

}  // namespace tribo
