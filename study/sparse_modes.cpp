// GCC 12 reports -Wuse-after-free inside Eigen's aligned_free once it inlines the vector
// temporaries of Spectra's UpperHessenbergEigen::doComputeEigenvectors into this file: a
// false positive of the inlined free-then-reallocate in Eigen's resize. Both are system
// headers, but this warning comes after inlining and is not silenced by that. Off for this
// file alone, and only for GCC (clang has no such warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuse-after-free"
#endif

#include "study/sparse_modes.hpp"

#include <Spectra/GenEigsSolver.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "study/modes_error.hpp"

namespace tribo::study {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// Below this fraction of nonzeros A - s I is factorized as a sparse matrix. A chain's A has
// a few nonzeros per row (the differences of unrelated bodies are exact zeros); the
// finite-difference A of a compact assembly is dense and the dense LU is faster there.
constexpr double kSparseDensity = 0.05;

// The Cayley transform C x = x + 2 s (A - s I)^-1 x, for Spectra (rows, cols, perform_op).
class CayleyOperator {
 public:
  using Scalar = double;

  CayleyOperator(const Eigen::MatrixXd& a, const SparseMatrix* sparse, double shift)
      : n_(a.rows()), shift_(shift) {
    if (sparse) {
      SparseMatrix identity(n_, n_);
      identity.setIdentity();
      sparse_lu_ = std::make_unique<Eigen::SparseLU<SparseMatrix>>();
      sparse_lu_->compute(*sparse - shift * identity);
      ok_ = sparse_lu_->info() == Eigen::Success;
    } else {
      dense_lu_ = std::make_unique<Eigen::PartialPivLU<Eigen::MatrixXd>>(
          a - shift * Eigen::MatrixXd::Identity(n_, n_));
      // rcond is an estimate; below this the solves carry no digits worth iterating on.
      ok_ = dense_lu_->rcond() > 1e-13;
    }
  }

  bool ok() const { return ok_; }
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }

  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Eigen::VectorXd> x(x_in, n_);
    Eigen::Map<Eigen::VectorXd> y(y_out, n_);
    if (sparse_lu_)
      y = x + 2 * shift_ * sparse_lu_->solve(x);
    else
      y = x + 2 * shift_ * dense_lu_->solve(x);
  }

 private:
  Eigen::Index n_;
  double shift_;
  bool ok_ = false;
  std::unique_ptr<Eigen::SparseLU<SparseMatrix>> sparse_lu_;
  std::unique_ptr<Eigen::PartialPivLU<Eigen::MatrixXd>> dense_lu_;
};

struct Run {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
  int operations = 0;
};

// One Arnoldi run for the `nev` eigenvalues of C of largest magnitude from start vector v0;
// its pairs folded to Im >= 0 (a pair once), the eigenvalues Rayleigh quotients of A.
Run arnoldi(CayleyOperator& op, const Eigen::MatrixXd& a, const SparseMatrix* sparse,
            Eigen::Index nev, const Eigen::VectorXd& v0, double tolerance, int subspace) {
  const Eigen::Index n = a.rows();
  // Spectra's advice is ncv >= 2 nev + 1; a basis four times nev (at least nev + 40) keeps
  // the restarts few when many modes crowd near |mu| = 1 (measured: on 200 lightly damped
  // pairs 2 nev + 1 needed thousands of restarts, 4 nev + 1 a few hundred products).
  const Eigen::Index ncv = std::min(n, subspace > 0 ? std::max<Eigen::Index>(subspace, nev + 2)
                                                    : std::max(4 * nev + 1, nev + 40));
  Spectra::GenEigsSolver<CayleyOperator> solver(op, nev, ncv);
  solver.init(v0.data());
  // Enough for the chains of docs/stability.md (tens of restarts); a spectrum spread around
  // |mu| = 1 needs thousands and is refused instead (auto then takes the dense solver).
  constexpr Eigen::Index kMaxRestarts = 500;
  solver.compute(Spectra::SortRule::LargestMagn, kMaxRestarts, tolerance);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw LinearizationFailure("the sparse eigensolver did not converge (" + std::to_string(n) +
                               " states, " + std::to_string(nev) + " eigenvalues asked for, " +
                               std::to_string(solver.num_operations()) +
                               " products): use --solver dense");
  const Eigen::VectorXcd mu = solver.eigenvalues();
  const Eigen::MatrixXcd vectors = solver.eigenvectors();
  Run run;
  run.operations = static_cast<int>(solver.num_operations());
  std::vector<std::complex<double>> values;
  std::vector<Eigen::VectorXcd> kept;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    Eigen::VectorXcd v = vectors.col(i);
    v.normalize();
    const Eigen::VectorXcd av = sparse ? Eigen::VectorXcd(sparse->cast<std::complex<double>>() * v)
                                       : Eigen::VectorXcd(a.cast<std::complex<double>>() * v);
    std::complex<double> lambda = v.dot(av);  // v^H A v, |v| = 1
    if (lambda.imag() < 0) {
      // The conjugate pair's other half: skip it when its partner is in the set.
      const std::complex<double> mirror = std::conj(mu(i));
      bool partner = false;
      for (Eigen::Index j = 0; j < mu.size(); ++j)
        partner = partner || (j != i && std::abs(mu(j) - mirror) <= 1e-8 * std::abs(mu(i)));
      if (partner) continue;
      lambda = std::conj(lambda);
      v = v.conjugate().eval();
    }
    values.push_back(lambda);
    kept.push_back(v);
  }
  run.values.resize(static_cast<Eigen::Index>(values.size()));
  run.vectors.resize(n, run.values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    run.values(static_cast<Eigen::Index>(k)) = values[k];
    run.vectors.col(static_cast<Eigen::Index>(k)) = kept[k];
  }
  return run;
}

double leadingGrowth(const Eigen::VectorXcd& values) {
  double lead = -HUGE_VAL;
  for (const auto& v : values) lead = std::max(lead, v.real());
  return lead;
}

Eigen::VectorXd startVector(Eigen::Index n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform(random);
  return v;
}

}  // namespace

double cayleyShift(const Eigen::MatrixXd& a) {
  double log_sum = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const double square = std::abs(a.row(i).dot(a.col(i)));  // (A^2)_ii
    if (square > 0 && std::isfinite(square)) {
      log_sum += 0.5 * std::log(square);
      ++count;
    }
  }
  return count > 0 ? std::exp(log_sum / count) : 1.0;
}

SparseEigenpairs sparseEigenpairs(const Eigen::MatrixXd& a, const SparseEigenOptions& options) {
  const Eigen::Index n = a.rows();
  if (options.count < 1) throw ModesError("the sparse eigensolver needs at least one mode");
  if (n < 2 * options.count + 4)
    throw ModesError("the sparse eigensolver needs at least 2 x " + std::to_string(options.count) +
                     " + 4 states for " + std::to_string(options.count) +
                     " modes; the system has " + std::to_string(n) + ": use --solver dense");
  if (!a.allFinite())
    throw LinearizationFailure(
        "the linearized system is not finite (a force is not differentiable here)");
  SparseEigenpairs out;
  out.shift = options.shift > 0 ? options.shift : cayleyShift(a);
  const double nonzeros = static_cast<double>((a.array() != 0.0).count());
  SparseMatrix sparse;
  out.sparse_factorization =
      nonzeros < kSparseDensity * static_cast<double>(n) * static_cast<double>(n);
  if (out.sparse_factorization) sparse = a.sparseView();
  const SparseMatrix* sparse_a = out.sparse_factorization ? &sparse : nullptr;
  std::unique_ptr<CayleyOperator> op;
  // A real eigenvalue at s makes A - s I singular: move the shift off it once.
  for (const double factor : {1.0, 1.37}) {
    op = std::make_unique<CayleyOperator>(a, sparse_a, factor * out.shift);
    if (op->ok()) {
      out.shift *= factor;
      break;
    }
  }
  if (!op->ok())
    throw LinearizationFailure("the sparse eigensolver cannot factorize A - s I (s = " +
                               std::to_string(out.shift) + "): use --solver dense");
  // Eigenvalues of C, a conjugate pair counting twice.
  const Eigen::Index nev = std::min<Eigen::Index>(2 * options.count, n - 3);
  Run run = arnoldi(*op, a, sparse_a, nev, startVector(n, 1), options.arnoldi_tolerance,
                    options.subspace);
  out.operations = run.operations;
  const Eigen::Index kept = std::min<Eigen::Index>(options.count, run.values.size());
  out.values = run.values.head(kept);
  out.vectors = run.vectors.leftCols(kept);
  const double norm = a.norm();
  for (Eigen::Index k = 0; k < kept; ++k) {
    const Eigen::VectorXcd& v = out.vectors.col(k);
    const Eigen::VectorXcd av = sparse_a ? Eigen::VectorXcd(sparse.cast<std::complex<double>>() * v)
                                         : Eigen::VectorXcd(a.cast<std::complex<double>>() * v);
    const double residual = (av - out.values(k) * v).norm() / (norm * v.norm());
    if (!std::isfinite(residual) || !std::isfinite(std::abs(out.values(k))))
      throw LinearizationFailure("the sparse eigensolver returned a non-finite eigenpair");
    out.worst_residual = std::max(out.worst_residual, residual);
  }
  if (out.worst_residual > options.residual_tolerance)
    throw LinearizationFailure(
        "the sparse eigensolver's eigenpairs are inaccurate (relative "
        "residual " +
        std::to_string(out.worst_residual) + " above " +
        std::to_string(options.residual_tolerance) + "): use --solver dense");
  if (options.guard) {
    const Eigen::Index more =
        std::min<Eigen::Index>(nev + std::max<Eigen::Index>(4, nev / 2), n - 3);
    const Run check = arnoldi(*op, a, sparse_a, more, startVector(n, 2), options.arnoldi_tolerance,
                              options.subspace);
    out.operations += check.operations;
    out.guard_difference = std::abs(leadingGrowth(out.values) - leadingGrowth(check.values));
    // Two converged runs find the same leading eigenvalue to about its residual (measured:
    // 1e-15 to 1e-9 1/s); a gap above 1e-7 of the spectrum's scale means one of them settled
    // on another mode.
    double lead = 0.0;
    for (const auto& v : out.values) lead = std::max(lead, std::abs(v));
    const double allowed = 1e-7 * (out.shift + lead);
    if (!(out.guard_difference <= allowed))
      throw LinearizationFailure(
          "the sparse eigensolver's two runs disagree on the largest growth rate (" +
          std::to_string(leadingGrowth(out.values)) + " against " +
          std::to_string(leadingGrowth(check.values)) + " 1/s): use --solver dense");
  }
  return out;
}

}  // namespace tribo::study
