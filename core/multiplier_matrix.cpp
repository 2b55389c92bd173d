#include "core/multiplier_matrix.hpp"

#include <algorithm>
#include <cmath>

namespace tribo {

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
      double* a = small_.data();  // column-major, leading dimension n_
      for (int j = 0; j < n_; ++j) {
        double d = a[j * n_ + j];
        for (int p = 0; p < j; ++p) d -= a[p * n_ + j] * a[p * n_ + j];
        if (!(d > 0.0)) return false;
        d = std::sqrt(d);
        a[j * n_ + j] = d;
        const double r = 1.0 / d;
        small_inverse_diagonal_(j) = r;
        for (int i = j + 1; i < n_; ++i) {
          double t = a[j * n_ + i];
          for (int p = 0; p < j; ++p) t -= a[p * n_ + i] * a[p * n_ + j];
          a[j * n_ + i] = t * r;
        }
      }
      return true;
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
      for (int i = 0; i < n_; ++i) {  // L y = x
        double t = x(i);
        for (int p = 0; p < i; ++p) t -= l[p * n_ + i] * x(p);
        x(i) = t * small_inverse_diagonal_(i);
      }
      for (int i = n_ - 1; i >= 0; --i) {  // L^T z = y
        double t = x(i);
        for (int p = i + 1; p < n_; ++p) t -= l[i * n_ + p] * x(p);
        x(i) = t * small_inverse_diagonal_(i);
      }
    } else {
      dense_llt_.solveInPlace(x);
    }
    return;
  }
  blocks_->solveInPlace(x);
}

}  // namespace tribo
