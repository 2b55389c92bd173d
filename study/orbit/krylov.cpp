// GCC 12 reports -Wuse-after-free inside Eigen's aligned_free once it inlines Spectra's
// UpperHessenbergEigen::doComputeEigenvectors here, the false positive
// study/modes/sparse_modes.cpp describes; off for this file alone, and only for GCC.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuse-after-free"
#endif
#include "study/orbit/krylov.hpp"

#include <Spectra/GenEigsSolver.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <unsupported/Eigen/IterativeSolvers>

namespace tribo::study::krylov {
class ProductMatrix;
}

// Eigen's iterative solvers take a matrix-free operator as a type with Eigen's matrix traits
// and a product rule (the pattern of Eigen's documentation, "Matrix-free solvers").
namespace Eigen::internal {
template <>
struct traits<tribo::study::krylov::ProductMatrix>
    : public Eigen::internal::traits<Eigen::SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace tribo::study::krylov {

class ProductMatrix : public Eigen::EigenBase<ProductMatrix> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };

  ProductMatrix(const Product& a, Eigen::Index n) : a_(a), n_(n) {}
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  template <typename Rhs>
  Eigen::Product<ProductMatrix, Rhs, Eigen::AliasFreeProduct> operator*(
      const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<ProductMatrix, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }
  Eigen::VectorXd apply(const Eigen::VectorXd& x) const {
    ++products_;
    return a_(x);
  }
  int products() const { return products_; }

 private:
  const Product& a_;
  Eigen::Index n_;
  mutable int products_ = 0;
};

}  // namespace tribo::study::krylov

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<tribo::study::krylov::ProductMatrix, Rhs, SparseShape, DenseShape,
                            GemvProduct>
    : generic_product_impl_base<tribo::study::krylov::ProductMatrix, Rhs,
                                generic_product_impl<tribo::study::krylov::ProductMatrix, Rhs>> {
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const tribo::study::krylov::ProductMatrix& lhs,
                            const Rhs& rhs, const double& alpha) {
    dst.noalias() += alpha * lhs.apply(Eigen::VectorXd(rhs));
  }
};
}  // namespace Eigen::internal

namespace tribo::study::krylov {

namespace {

// Krylov vectors kept before GMRES restarts.
constexpr int kRestart = 60;

// A x for Spectra (rows, cols, perform_op).
class SpectraProduct {
 public:
  using Scalar = double;
  SpectraProduct(const Product& a, Eigen::Index n) : a_(a), n_(n) {}
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::VectorXd y = a_(Eigen::Map<const Eigen::VectorXd>(x_in, n_));
    Eigen::Map<Eigen::VectorXd>(y_out, n_) = y;
  }

 private:
  const Product& a_;
  Eigen::Index n_;
};

}  // namespace

Solution gmres(const Product& a, const Eigen::VectorXd& b, double tolerance, int max_products) {
  const ProductMatrix op(a, b.size());
  Eigen::GMRES<ProductMatrix, Eigen::IdentityPreconditioner> solver;
  solver.set_restart(kRestart);
  solver.setTolerance(tolerance);
  solver.setMaxIterations(max_products);
  solver.compute(op);
  Solution s;
  s.x = solver.solve(b);
  s.products = op.products();
  s.error = solver.error();
  s.converged = solver.info() == Eigen::Success;
  return s;
}

Leading leadingEigenvalues(const Product& a, Eigen::Index n, Eigen::Index count, double tolerance) {
  if (count < 1 || count > n - 2)
    throw std::invalid_argument("leadingEigenvalues: count must be 1 .. n - 2");
  SpectraProduct op(a, n);
  // Spectra asks ncv > nev + 1; twice nev plus a margin converges in a few restarts.
  const Eigen::Index ncv = std::min(n, std::max(2 * count + 1, count + 12));
  Spectra::GenEigsSolver<SpectraProduct> solver(op, count, ncv);
  // A fixed start vector: the same multipliers from run to run.
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  Eigen::VectorXd start(n);
  for (Eigen::Index i = 0; i < n; ++i) start(i) = uniform(random);
  solver.init(start.data());
  constexpr Eigen::Index kMaxRestarts = 100;
  solver.compute(Spectra::SortRule::LargestMagn, kMaxRestarts, tolerance);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("Arnoldi did not converge on the " + std::to_string(count) +
                             " leading multipliers in " + std::to_string(solver.num_operations()) +
                             " products");
  Leading out;
  const Eigen::VectorXcd values = solver.eigenvalues();
  for (Eigen::Index i = 0; i < values.size(); ++i) out.values.push_back(values(i));
  std::sort(out.values.begin(), out.values.end(),
            [](auto x, auto y) { return std::abs(x) > std::abs(y); });
  out.products = static_cast<int>(solver.num_operations());
  return out;
}

}  // namespace tribo::study::krylov
