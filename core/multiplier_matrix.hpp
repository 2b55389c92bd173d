// The symmetric positive definite multiplier matrix A = J M^-1 J^T of a model's constraint
// rows with a pattern fixed at construction (entry (i, j) is structurally nonzero when rows
// i and j touch a common dynamic body), filled through precomputed slots, factorized and
// solved. Three storages:
//   small dense  (n <= 12): fixed-capacity matrix on the object, Cholesky by plain loops
//                           (Eigen's general LLT and triangular solves cost more at these
//                           sizes: the belt scene's 4 equations);
//   dense:                  Eigen::MatrixXd, Cholesky (LLT), O(n^3);
//   sparse:                 blocks of each joint's equations, block Cholesky in an
//                           approximate-minimum-degree order (core/block_cholesky.hpp):
//                           linear in the number of joints for chains and trees.
// Nothing allocates after the first factorization. Bench: bench/core/chain_bench.cpp (dense vs
// sparse).
// Not here: what the entries are (core/constraint_jacobian.hpp), redundancy.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <utility>
#include <vector>

#include "core/block_cholesky.hpp"

namespace tribo {

class MultiplierMatrix {
 public:
  // n equations; `entries` lists the structurally nonzero (i, j), i >= j, and must include
  // every diagonal (i, i). Sparse storage needs the row groups: group_begin[g] is the first
  // row of group g (at most 6 rows each), group_begin.back() = n.
  void init(int n, const std::vector<std::pair<int, int>>& entries, bool sparse,
            const std::vector<int>& group_begin = {});

  int size() const { return n_; }
  bool isSparse() const { return sparse_; }
  // Index into values() of entry (i, j) (either order); -1 if not in the pattern.
  int slot(int i, int j) const;
  double* values() { return values_; }
  int valueCount() const { return value_count_; }
  void setZero();

  // Factorizes the current values; false if A is not (numerically) positive definite.
  bool factorize();
  // x <- A^-1 x with the last factorization.
  void solveInPlace(Eigen::VectorXd& x);

 private:
  static constexpr int kSmall = 12;
  using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kSmall, kSmall>;

  int n_ = 0;
  bool sparse_ = false;
  double* values_ = nullptr;
  int value_count_ = 0;
  SmallMatrix small_;                                        // lower triangle: A, then L
  Eigen::Matrix<double, kSmall, 1> small_inverse_diagonal_;  // 1 / L_ii
  Eigen::MatrixXd dense_;
  Eigen::LLT<Eigen::MatrixXd> dense_llt_;
  std::unique_ptr<BlockCholesky> blocks_;
};

}  // namespace tribo
