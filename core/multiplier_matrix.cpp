#include "core/multiplier_matrix.hpp"

#include <algorithm>
#include <cmath>

namespace tribo {

namespace {

// Cholesky A = L L^T in place on the lower triangle of the column-major n x n matrix `a`
// (leading dimension n), 1 / L_ii into `inverse_diagonal`; N > 0 fixes n at compile time
// (the same operations in the same order as N = 0). False if A is not positive definite.
template <int N>
bool smallCholesky(int n_runtime, double* a, double* inverse_diagonal) {
  const int n = N > 0 ? N : n_runtime;
  for (int j = 0; j < n; ++j) {
    double d = a[j * n + j];
    for (int p = 0; p < j; ++p) d -= a[p * n + j] * a[p * n + j];
    if (!(d > 0.0)) return false;
    d = std::sqrt(d);
    a[j * n + j] = d;
    const double r = 1.0 / d;
    inverse_diagonal[j] = r;
    for (int i = j + 1; i < n; ++i) {
      double t = a[j * n + i];
      for (int p = 0; p < j; ++p) t -= a[p * n + i] * a[p * n + j];
      a[j * n + i] = t * r;
    }
  }
  return true;
}

// x <- (L L^T)^-1 x with smallCholesky's factor.
template <int N>
void smallSolve(int n_runtime, const double* l, const double* inverse_diagonal, double* x) {
  const int n = N > 0 ? N : n_runtime;
  for (int i = 0; i < n; ++i) {  // L y = x
    double t = x[i];
    for (int p = 0; p < i; ++p) t -= l[p * n + i] * x[p];
    x[i] = t * inverse_diagonal[i];
  }
  for (int i = n - 1; i >= 0; --i) {  // L^T z = y
    double t = x[i];
    for (int p = i + 1; p < n; ++p) t -= l[i * n + p] * x[p];
    x[i] = t * inverse_diagonal[i];
  }
}

}  // namespace

void MultiplierMatrix::init(int n, const std::vector<std::pair<int, int>>& entries, bool sparse,
                            const std::vector<int>& group_begin) {
  n_ = n;
  sparse_ = sparse;
  if (!sparse) {
    if (n <= kSmall) {
      small_.setZero(n, n);
      values_ = small_.data();
    } else {
      dense_.setZero(n, n);
      values_ = dense_.data();
    }
    value_count_ = n * n;
    return;
  }
  blocks_ = BlockCholesky::create(group_begin, entries);
  values_ = blocks_->values();
  value_count_ = 0;  // setZero() goes through blocks_
}

int MultiplierMatrix::slot(int i, int j) const {
  if (i < 0 || j < 0 || i >= n_ || j >= n_) return -1;
  if (!sparse_) return std::min(i, j) * n_ + std::max(i, j);  // lower triangle, column-major
  return blocks_->slot(i, j);
}

void MultiplierMatrix::setZero() {
  if (sparse_)
    blocks_->setZero();
  else
    std::fill(values_, values_ + value_count_, 0.0);
}

bool MultiplierMatrix::factorize() {
  if (n_ == 0) return true;
  if (!sparse_) {
    if (n_ <= kSmall) {
      double* a = small_.data();
      double* r = small_inverse_diagonal_.data();
      switch (n_) {  // sizes of one joint's equations: loops the compiler unrolls
        case 1:
          return smallCholesky<1>(1, a, r);
        case 2:
          return smallCholesky<2>(2, a, r);
        case 3:
          return smallCholesky<3>(3, a, r);
        case 4:
          return smallCholesky<4>(4, a, r);
        case 5:
          return smallCholesky<5>(5, a, r);
        case 6:
          return smallCholesky<6>(6, a, r);
        default:
          return smallCholesky<0>(n_, a, r);
      }
    }
    dense_llt_.compute(dense_);
    return dense_llt_.info() == Eigen::Success;
  }
  return blocks_->factorize();
}

void MultiplierMatrix::solveInPlace(Eigen::VectorXd& x) {
  if (n_ == 0) return;
  if (!sparse_) {
    if (n_ <= kSmall) {
      const double* l = small_.data();
      const double* r = small_inverse_diagonal_.data();
      switch (n_) {
        case 1:
          smallSolve<1>(1, l, r, x.data());
          break;
        case 2:
          smallSolve<2>(2, l, r, x.data());
          break;
        case 3:
          smallSolve<3>(3, l, r, x.data());
          break;
        case 4:
          smallSolve<4>(4, l, r, x.data());
          break;
        case 5:
          smallSolve<5>(5, l, r, x.data());
          break;
        case 6:
          smallSolve<6>(6, l, r, x.data());
          break;
        default:
          smallSolve<0>(n_, l, r, x.data());
          break;
      }
    } else {
      dense_llt_.solveInPlace(x);
    }
    return;
  }
  blocks_->solveInPlace(x);
}

}  // namespace tribo
