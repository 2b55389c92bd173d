#include "core/block_cholesky.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace tribo {

namespace {

// The block structure and elimination schedule, independent of the block size.
struct Symbolic {
  struct Update {
    int ik, jk, target;  // block indices: target -= blocks[ik] * blocks[jk]^T
  };
  int n = 0, groups = 0, blocks = 0, fill = 0, block_size = 1;
  std::vector<int> group_of_row, local_of_row;
  std::vector<int> position;               // group -> elimination position
  std::vector<int> rows_at, first_row_at;  // per position
  // Column k (a position) of L below the diagonal: entries col_start[k] .. col_start[k+1] of
  // col_row (row positions, ascending) and col_block (block indices). Diagonal block of
  // position k: block k.
  std::vector<int> col_start, col_row, col_block;
  std::vector<int> update_start;  // per position: its range in updates
  std::vector<Update> updates;

  Symbolic(const std::vector<int>& group_begin, const std::vector<std::pair<int, int>>& entries);
  int slot(int i, int j) const;  // within blocks of block_size^2 values, column-major
};

Symbolic::Symbolic(const std::vector<int>& group_begin,
                   const std::vector<std::pair<int, int>>& entries) {
  groups = static_cast<int>(group_begin.size()) - 1;
  n = groups > 0 ? group_begin.back() : 0;
  group_of_row.assign(n, 0);
  local_of_row.assign(n, 0);
  for (int g = 0; g < groups; ++g) {
    const int rows = group_begin[g + 1] - group_begin[g];
    if (rows > BlockCholesky::kMaxBlock || rows <= 0)
      throw std::invalid_argument("BlockCholesky: groups must have 1 to 6 rows");
    block_size = std::max(block_size, rows);
    for (int r = group_begin[g]; r < group_begin[g + 1]; ++r) {
      group_of_row[r] = g;
      local_of_row[r] = r - group_begin[g];
    }
  }
  // Block graph and its fill-reducing order (Eigen's orderings return P^-1).
  std::vector<std::set<int>> adjacent(groups);
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (int g = 0; g < groups; ++g) triplets.emplace_back(g, g, 1.0);
  for (const auto& [i, j] : entries) {
    const int a = group_of_row[i], b = group_of_row[j];
    if (a == b) continue;
    adjacent[a].insert(b);
    adjacent[b].insert(a);
    triplets.emplace_back(std::max(a, b), std::min(a, b), 1.0);
  }
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> pattern(groups, groups);
  pattern.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::AMDOrdering<int>::PermutationType inverse;
  Eigen::AMDOrdering<int>()(pattern, inverse);
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p = inverse.inverse();
  position.assign(p.indices().data(), p.indices().data() + groups);
  rows_at.assign(groups, 0);
  first_row_at.assign(groups, 0);
  for (int g = 0; g < groups; ++g) {
    rows_at[position[g]] = group_begin[g + 1] - group_begin[g];
    first_row_at[position[g]] = group_begin[g];
  }
  // Eliminating position k joins its later neighbours pairwise (the fill).
  std::vector<std::set<int>> later(groups);
  for (int g = 0; g < groups; ++g)
    for (int h : adjacent[g])
      if (position[h] > position[g]) later[position[g]].insert(position[h]);
  std::map<std::pair<int, int>, int> block_of;  // (row position, column position) -> block
  blocks = groups;
  col_start.assign(1, 0);
  for (int k = 0; k < groups; ++k) {
    for (int i : later[k]) {
      col_row.push_back(i);
      col_block.push_back(blocks);
      block_of[{i, k}] = blocks++;
    }
    col_start.push_back(static_cast<int>(col_row.size()));
    for (auto a = later[k].begin(); a != later[k].end(); ++a)
      for (auto b = std::next(a); b != later[k].end(); ++b)
        if (later[*a].insert(*b).second) ++fill;  // *a < *b: *b comes after *a
  }
  update_start.assign(1, 0);
  for (int k = 0; k < groups; ++k) {
    for (int a = col_start[k]; a < col_start[k + 1]; ++a)
      for (int b = col_start[k]; b <= a; ++b) {
        const int i = col_row[a], j = col_row[b];  // i >= j
        updates.push_back({col_block[a], col_block[b], i == j ? i : block_of.at({i, j})});
      }
    update_start.push_back(static_cast<int>(updates.size()));
  }
}

int Symbolic::slot(int i, int j) const {
  if (i < 0 || j < 0 || i >= n || j >= n) return -1;
  int pi = position[group_of_row[i]], pj = position[group_of_row[j]];
  int li = local_of_row[i], lj = local_of_row[j];
  const int area = block_size * block_size;
  if (pi == pj) {
    if (li < lj) std::swap(li, lj);
    return pi * area + lj * block_size + li;
  }
  if (pi < pj) {
    std::swap(pi, pj);
    std::swap(li, lj);
  }
  const auto begin = col_row.begin() + col_start[pj], end = col_row.begin() + col_start[pj + 1];
  const auto hit = std::lower_bound(begin, end, pi);
  if (hit == end || *hit != pi) return -1;
  return col_block[hit - col_row.begin()] * area + lj * block_size + li;
}

template <int B>
class BlockCholeskyOf final : public BlockCholesky {
 public:
  using Block = Eigen::Matrix<double, B, B>;
  using Vector = Eigen::Matrix<double, B, 1>;

  explicit BlockCholeskyOf(Symbolic symbolic)
      : s_(std::move(symbolic)),
        blocks_(s_.blocks, Block::Zero()),
        inverse_(s_.groups, Block::Identity()),
        y_(s_.groups, Vector::Zero()) {
    setZero();
  }

  int blockSize() const override { return B; }
  int slot(int i, int j) const override { return s_.slot(i, j); }
  double* values() override { return blocks_.empty() ? nullptr : blocks_.data()->data(); }
  int blockCount() const override { return s_.blocks; }
  int fillCount() const override { return s_.fill; }

  void setZero() override {
    for (Block& b : blocks_) b.setZero();
    for (int k = 0; k < s_.groups; ++k)
      for (int d = s_.rows_at[k]; d < B; ++d) blocks_[k](d, d) = 1.0;
  }

  bool factorize() override {
    for (int k = 0; k < s_.groups; ++k) {
      Block& d = blocks_[k];
      Vector reciprocal;             // 1 / L_jj
      for (int j = 0; j < B; ++j) {  // in-place Cholesky of the lower triangle
        double sum = d(j, j);
        for (int p = 0; p < j; ++p) sum -= d(j, p) * d(j, p);
        if (!(sum > 0.0)) return false;
        sum = std::sqrt(sum);
        d(j, j) = sum;
        reciprocal(j) = 1.0 / sum;
        for (int i = j + 1; i < B; ++i) {
          double t = d(i, j);
          for (int p = 0; p < j; ++p) t -= d(i, p) * d(j, p);
          d(i, j) = t * reciprocal(j);
        }
      }
      Block& inv = inverse_[k];  // L_kk^-1 by forward substitution, column by column
      inv.setZero();
      for (int c = 0; c < B; ++c) {
        inv(c, c) = reciprocal(c);
        for (int i = c + 1; i < B; ++i) {
          double t = 0.0;
          for (int p = c; p < i; ++p) t -= d(i, p) * inv(p, c);
          inv(i, c) = t * reciprocal(i);
        }
      }
      for (int e = s_.col_start[k]; e < s_.col_start[k + 1]; ++e) {
        const Block l = blocks_[s_.col_block[e]] * inv.transpose();  // L_ik = A_ik L_kk^-T
        blocks_[s_.col_block[e]] = l;
      }
      for (int u = s_.update_start[k]; u < s_.update_start[k + 1]; ++u) {
        const Symbolic::Update& up = s_.updates[u];
        blocks_[up.target].noalias() -= blocks_[up.ik] * blocks_[up.jk].transpose();
      }
    }
    return true;
  }

  void solveInPlace(Eigen::VectorXd& x) override {
    for (int k = 0; k < s_.groups; ++k) {
      y_[k].setZero();
      for (int l = 0; l < s_.rows_at[k]; ++l) y_[k](l) = x(s_.first_row_at[k] + l);
    }
    for (int k = 0; k < s_.groups; ++k) {  // L z = b
      const Vector yk = inverse_[k] * y_[k];
      y_[k] = yk;
      for (int e = s_.col_start[k]; e < s_.col_start[k + 1]; ++e)
        y_[s_.col_row[e]].noalias() -= blocks_[s_.col_block[e]] * yk;
    }
    for (int k = s_.groups - 1; k >= 0; --k) {  // L^T x = z
      for (int e = s_.col_start[k]; e < s_.col_start[k + 1]; ++e)
        y_[k].noalias() -= blocks_[s_.col_block[e]].transpose() * y_[s_.col_row[e]];
      const Vector yk = inverse_[k].transpose() * y_[k];
      y_[k] = yk;
    }
    for (int k = 0; k < s_.groups; ++k)
      for (int l = 0; l < s_.rows_at[k]; ++l) x(s_.first_row_at[k] + l) = y_[k](l);
  }

 private:
  Symbolic s_;
  std::vector<Block, Eigen::aligned_allocator<Block>> blocks_;
  std::vector<Block, Eigen::aligned_allocator<Block>> inverse_;  // per position: L_kk^-1
  std::vector<Vector, Eigen::aligned_allocator<Vector>> y_;      // per position: scratch
};

}  // namespace

std::unique_ptr<BlockCholesky> BlockCholesky::create(
    const std::vector<int>& group_begin, const std::vector<std::pair<int, int>>& entries) {
  Symbolic s(group_begin, entries);
  switch (s.block_size) {
    case 1:
      return std::make_unique<BlockCholeskyOf<1>>(std::move(s));
    case 2:
      return std::make_unique<BlockCholeskyOf<2>>(std::move(s));
    case 3:
      return std::make_unique<BlockCholeskyOf<3>>(std::move(s));
    case 4:
      return std::make_unique<BlockCholeskyOf<4>>(std::move(s));
    case 5:
      return std::make_unique<BlockCholeskyOf<5>>(std::move(s));
    default:
      return std::make_unique<BlockCholeskyOf<6>>(std::move(s));
  }
}

}  // namespace tribo
