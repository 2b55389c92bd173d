// GCC 12 reports -Wuse-after-free inside Eigen's aligned_free once it inlines the vector
// temporaries of Spectra's UpperHessenbergEigen::doComputeEigenvectors into this file: a
// false positive of the inlined free-then-reallocate in Eigen's resize. Both are system
// headers, but this warning comes after inlining and is not silenced by that. Off for this
// file alone, and only for GCC (clang has no such warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuse-after-free"
#endif

#include "study/modes/sparse_modes.hpp"

#include <Spectra/GenEigsSolver.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "study/modes/modes_error.hpp"

namespace tribo::study {

namespace {

using Complex = std::complex<double>;
using SparseMatrix = Eigen::SparseMatrix<double>;
using SparseComplex = Eigen::SparseMatrix<Complex>;

// Below this fraction of nonzeros A - sigma I is factorized as a sparse matrix. A chain's A
// has a few nonzeros per row (the differences of unrelated bodies are exact zeros); the
// finite-difference A of a compact assembly is dense and the dense LU is faster there.
constexpr double kSparseDensity = 0.05;

// (A - sigma I)^-1 for Spectra (rows, cols, perform_op): on R^n for a real sigma, on the
// real form R^2n = (Re x, Im x) of C^n for a complex one.
class ShiftInvert {
 public:
  using Scalar = double;

  ShiftInvert(const Eigen::MatrixXd& a, const SparseMatrix* sparse, Complex sigma)
      : n_(a.rows()), real_(sigma.imag() == 0.0) {
    if (sparse) {
      SparseComplex shifted = sparse->cast<Complex>();
      for (Eigen::Index i = 0; i < n_; ++i) shifted.coeffRef(i, i) -= sigma;
      shifted.makeCompressed();
      sparse_lu_ = std::make_unique<Eigen::SparseLU<SparseComplex>>();
      sparse_lu_->compute(shifted);
      ok_ = sparse_lu_->info() == Eigen::Success;
    } else {
      dense_lu_ = std::make_unique<Eigen::PartialPivLU<Eigen::MatrixXcd>>(
          a.cast<Complex>() - sigma * Eigen::MatrixXcd::Identity(n_, n_));
      // rcond is an estimate; below this the solves carry no digits worth iterating on.
      ok_ = dense_lu_->rcond() > 1e-13;
    }
  }

  bool ok() const { return ok_; }
  Eigen::Index rows() const { return real_ ? n_ : 2 * n_; }
  Eigen::Index cols() const { return rows(); }

  void perform_op(const double* x_in, double* y_out) const {
    Eigen::VectorXcd x(n_);
    for (Eigen::Index i = 0; i < n_; ++i) x(i) = Complex(x_in[i], real_ ? 0.0 : x_in[n_ + i]);
    const Eigen::VectorXcd y =
        sparse_lu_ ? Eigen::VectorXcd(sparse_lu_->solve(x)) : Eigen::VectorXcd(dense_lu_->solve(x));
    for (Eigen::Index i = 0; i < n_; ++i) {
      y_out[i] = y(i).real();
      if (!real_) y_out[n_ + i] = y(i).imag();
    }
  }

 private:
  Eigen::Index n_;
  bool real_;
  bool ok_ = false;
  std::unique_ptr<Eigen::SparseLU<SparseComplex>> sparse_lu_;
  std::unique_ptr<Eigen::PartialPivLU<Eigen::MatrixXcd>> dense_lu_;
};

struct Eigenpair {
  Complex value;  // Im >= 0
  Eigen::VectorXcd vector;
};

Eigen::VectorXcd times(const Eigen::MatrixXd& a, const SparseMatrix* sparse,
                       const Eigen::VectorXcd& v) {
  return sparse ? Eigen::VectorXcd(sparse->cast<Complex>() * v)
                : Eigen::VectorXcd(a.cast<Complex>() * v);
}

Eigen::VectorXd startVector(Eigen::Index n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = uniform(random);
  return v;
}

struct ShiftResult {
  std::vector<Eigenpair> pairs;  // folded to Im >= 0, possibly twice (a pair's two halves)
  double radius = 0.0;           // |lambda - sigma| of the farthest eigenvalue found
  int operations = 0;
};

// The `k` eigenvalues of A nearest sigma = i w (both halves of a pair counted when both are
// near, as at w = 0), by Arnoldi on (A - sigma I)^-1.
ShiftResult atShift(const Eigen::MatrixXd& a, const SparseMatrix* sparse, double w, Eigen::Index k,
                    double tolerance, unsigned seed) {
  const Complex sigma(0.0, w);
  ShiftInvert op(a, sparse, sigma);
  if (!op.ok())
    throw LinearizationFailure("the sparse eigensolver cannot factorize A - i w I (w = " +
                               std::to_string(w) + "): use --solver dense");
  const Eigen::Index n = a.rows(), dim = op.rows();
  // On the real form every theta comes with its conjugate, which belongs to no nearby lambda.
  const Eigen::Index nev = w == 0.0 ? k : 2 * k;
  // Spectra's advice is ncv >= 2 nev + 1; nev + 20 more for the small nev.
  const Eigen::Index ncv = std::min(dim, std::max(2 * nev + 1, nev + 20));
  Spectra::GenEigsSolver<ShiftInvert> solver(op, nev, ncv);
  solver.init(startVector(dim, seed).data());
  // Shift-and-invert separates the nearest eigenvalues well: measured tens of products per
  // shift; 300 restarts mean the run is lost.
  constexpr Eigen::Index kMaxRestarts = 300;
  solver.compute(Spectra::SortRule::LargestMagn, kMaxRestarts, tolerance);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw LinearizationFailure("the sparse eigensolver did not converge at shift " +
                               std::to_string(w) + "i (" + std::to_string(n) + " states, " +
                               std::to_string(solver.num_operations()) +
                               " products): use --solver dense");
  const Eigen::VectorXcd theta = solver.eigenvalues();
  const Eigen::MatrixXcd vectors = solver.eigenvectors();
  ShiftResult out;
  out.operations = static_cast<int>(solver.num_operations());
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    Eigen::VectorXcd v = vectors.col(i).head(n);  // the upper half of [v; -i v]
    if (v.norm() == 0.0) continue;
    v.normalize();
    Complex lambda = v.dot(times(a, sparse, v));  // v^H A v, |v| = 1
    if (lambda.imag() < 0) {
      lambda = std::conj(lambda);
      v = v.conjugate().eval();
    }
    // |theta| = 1 / |lambda - sigma| (theta's conjugate on the real form has the same size).
    out.radius = std::max(out.radius, 1.0 / std::abs(theta(i)));
    out.pairs.push_back({lambda, v});
  }
  return out;
}

// Adds `pair` unless an eigenvalue within the relative tolerance is there: true when added.
bool addDistinct(std::vector<Eigenpair>& all, Eigenpair pair, double scale) {
  // Converged eigenvalues agree to ~1e-12 of the spectrum's scale; distinct ones of a chain
  // are ~1e-3 apart relative. 1e-8 between the two.
  const double tolerance = 1e-8 * (std::abs(pair.value) + 1e-3 * scale);
  for (const Eigenpair& p : all)
    if (std::abs(p.value - pair.value) <= tolerance) return false;
  all.push_back(std::move(pair));
  return true;
}

// Half-width of the union of two axis discs (centres c1 < c2 on the imaginary axis, radii)
// where they meet: the strip |Re| < h between the centres is covered.
double halfChord(double c1, double r1, double c2, double r2) {
  const double d = c2 - c1;
  if (d <= 0) return std::min(r1, r2);
  const double x = (d * d + r1 * r1 - r2 * r2) / (2 * d);  // from c1 along the axis
  if (x <= 0 || x >= d) return std::min(r1, r2);           // one disc holds the other's side
  return std::sqrt(std::max(0.0, r1 * r1 - x * x));
}

}  // namespace

double bandBound(const Eigen::MatrixXd& a) {
  double largest = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    // (A^2)_ii; the diagonal added: a 2 x 2 block [[s, w], [-w, s]] has (A^2)_ii = s^2 - w^2
    // and sqrt(w^2 - s^2) + |s| >= w = |Im lambda|.
    const double bound = std::sqrt(std::abs(a.row(i).dot(a.col(i)))) + std::abs(a(i, i));
    if (std::isfinite(bound)) largest = std::max(largest, bound);
  }
  return largest > 0 ? largest : 1.0;
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
  const double nonzeros = static_cast<double>((a.array() != 0.0).count());
  SparseMatrix sparse;
  out.sparse_factorization =
      nonzeros < kSparseDensity * static_cast<double>(n) * static_cast<double>(n);
  if (out.sparse_factorization) sparse = a.sparseView();
  const SparseMatrix* sparse_a = out.sparse_factorization ? &sparse : nullptr;
  const Eigen::Index k = std::clamp<Eigen::Index>(options.per_shift, 2, n - 3);
  const double w_max = bandBound(a);

  std::vector<Eigenpair> all;
  double w = 0.0, previous_w = 0.0, previous_r = 0.0;
  out.strip = HUGE_VAL;
  for (;;) {
    if (out.shifts >= options.max_shifts)
      throw LinearizationFailure("the sparse eigensolver's scan needs more than " +
                                 std::to_string(options.max_shifts) + " shifts (covered up to " +
                                 std::to_string(out.band_top) + " of " + std::to_string(w_max) +
                                 " 1/s): use --solver dense");
    ShiftResult r = atShift(a, sparse_a, w, k, options.arnoldi_tolerance,
                            static_cast<unsigned>(out.shifts + 1));
    out.operations += r.operations;
    bool added = false;
    for (Eigenpair& p : r.pairs) added = addDistinct(all, std::move(p), w_max) || added;
    out.strip = std::min(
        out.strip, out.shifts == 0 ? r.radius : halfChord(previous_w, previous_r, w, r.radius));
    ++out.shifts;
    out.band_top = w + r.radius;
    if (out.band_top >= w_max || (!added && out.shifts > 1)) break;
    previous_w = w;
    previous_r = r.radius;
    // The discs overlap by a tenth of a radius; a shift that found eigenvalues only at its
    // centre (radius 0: cannot happen for k >= 2) would still move.
    w += std::max(0.9 * r.radius, 1e-12 * w_max);
  }

  std::stable_sort(all.begin(), all.end(), [](const Eigenpair& x, const Eigenpair& y) {
    return x.value.real() > y.value.real();
  });
  out.found = static_cast<int>(all.size());
  const auto kept = static_cast<Eigen::Index>(
      std::min<std::size_t>(static_cast<std::size_t>(options.count), all.size()));
  out.values.resize(kept);
  out.vectors.resize(n, kept);
  const double norm = a.norm();
  for (Eigen::Index i = 0; i < kept; ++i) {
    const Eigenpair& p = all[static_cast<std::size_t>(i)];
    out.values(i) = p.value;
    out.vectors.col(i) = p.vector;
    const double residual = (times(a, sparse_a, p.vector) - p.value * p.vector).norm() / norm;
    if (!std::isfinite(residual) || !std::isfinite(std::abs(p.value)))
      throw LinearizationFailure("the sparse eigensolver returned a non-finite eigenpair");
    out.worst_residual = std::max(out.worst_residual, residual);
  }
  if (out.worst_residual > options.residual_tolerance)
    throw LinearizationFailure(
        "the sparse eigensolver's eigenpairs are inaccurate (relative residual " +
        std::to_string(out.worst_residual) + " above " +
        std::to_string(options.residual_tolerance) + "): use --solver dense");
  return out;
}

}  // namespace tribo::study
