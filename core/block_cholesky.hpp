// Sparse Cholesky factorization A = L L^T of a symmetric positive definite matrix whose rows
// come in small groups (the equations of one joint, at most 6), with dense blocks:
//   - the block graph (groups adjacent when they share a nonzero) is ordered once by
//     approximate minimum degree (Amestoy, Davis & Duff 1996, via Eigen's AMD), and the
//     fill of its elimination is found once (symbolic factorization);
//   - each factorization then runs a fixed schedule of fixed-size kernels,
//     right-looking: L_kk = chol(A_kk), L_ik = A_ik L_kk^-T, A_ij -= L_ik L_jk^T, with B x B
//     blocks, B the largest group (6 at most);
//   - smaller groups are padded with an identity diagonal, which leaves the factorization
//     of the real entries unchanged.
// For the constraint rows of a tree of joints the block graph is the tree's line graph, a
// chordal graph eliminated from the leaves without fill: the factorization and the solves
// are linear in the number of joints (the property Baraff 1996, "Linear-time dynamics
// using Lagrange multipliers", SIGGRAPH, exploits on the augmented system). Closed loops
// add fill blocks. Nothing allocates after create().
// Not here: what the entries are, dense factorizations (core/multiplier_matrix.hpp).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <utility>
#include <vector>

namespace tribo {

class BlockCholesky {
 public:
  static constexpr int kMaxBlock = 6;

  // `group_begin[g]` is the first row of group g (rows of a group are consecutive, groups in
  // row order, 1 to kMaxBlock rows each; group_begin.back() = n). `entries` lists the
  // structurally nonzero (i, j), i >= j. The block size is the largest group's row count,
  // so the kernels are fixed-size for it (5 x 5 for a model of revolute joints).
  static std::unique_ptr<BlockCholesky> create(const std::vector<int>& group_begin,
                                               const std::vector<std::pair<int, int>>& entries);
  virtual ~BlockCholesky() = default;

  virtual int blockSize() const = 0;
  // Index into values() of entry (i, j) (either order); -1 if not in the pattern.
  virtual int slot(int i, int j) const = 0;
  virtual double* values() = 0;
  // Zeroes all blocks (fill included) and sets the padding diagonals to 1.
  virtual void setZero() = 0;
  // False if A is not (numerically) positive definite.
  virtual bool factorize() = 0;
  // x <- A^-1 x.
  virtual void solveInPlace(Eigen::VectorXd& x) = 0;
  // Blocks stored (diagonal, off-diagonal and fill), and of those, fill.
  virtual int blockCount() const = 0;
  virtual int fillCount() const = 0;
};

}  // namespace tribo
