// The few eigenpairs of a large real matrix A (y' = A y, study/linearization.hpp) that decide
// its stability: those with the largest growth rate Re(lambda), found by Arnoldi iteration
// (Spectra's GenEigsSolver, https://spectralib.org) on the Cayley transform
//   C = (A - s I)^-1 (A + s I),   mu = (lambda + s) / (lambda - s),   lambda = s (mu + 1) / (mu -
//   1)
// (Saad, "Numerical Methods for Large Eigenvalue Problems", 2nd ed. 2011, ch. 7; Meerbergen,
// Spence & Roose 1994, BIT 34:409-423). For a real shift s > 0, |mu| > 1 exactly when
// Re(lambda) > 0, so every growing mode outranks every decaying one in magnitude, which is
// what Arnoldi finds first. C is applied as C x = x + 2 s (A - s I)^-1 x through one LU
// factorization of A - s I (Eigen's SparseLU when A has few nonzeros, dense PartialPivLU
// otherwise). The eigenvectors are C's, which are A's; each eigenvalue is the Rayleigh
// quotient v^H A v / v^H v of its vector (more accurate than the mapped mu for modes far from
// s) and each pair must pass ||A v - lambda v|| <= tol ||A||_F ||v||.
// The shift (cayleyShift): the geometric mean over the states of sqrt|(A^2)_ii|, zeros
// skipped. For A = [[0, I], [K, C]] the first half is sqrt|K_ii|, each coordinate's natural
// frequency, so s sits inside the band of the structure's frequencies, where C spreads the
// modes apart; far from s (|lambda| >> s) the modes crowd towards |mu| = 1.
// The guard: a second Arnoldi run from another start vector asking for more modes; the two
// leading growth rates must agree. It catches a run that converged to the wrong set; it does
// not prove that no mode is missed (both runs can miss a mode crowded near |mu| = 1), and
// among more growing modes than asked for the ones returned are those of largest |mu| (largest
// Re(lambda) s / |lambda - s|^2), not necessarily of largest growth rate.
// Not here: mode shapes and sorting (study/modes.hpp), the dense solver (Eigen::EigenSolver in
// study/modes.cpp), generalized problems (M y' = A y), complex shifts.
#pragma once

#include <Eigen/Dense>

namespace tribo::study {

struct SparseEigenOptions {
  int count = 12;                    // eigenvalues wanted, a complex pair counted once
  double residual_tolerance = 1e-8;  // largest ||A v - lambda v|| / (||A||_F ||v||)
  bool guard = true;                 // the second run (see above)
  double shift = 0.0;                // the Cayley shift s; 0: cayleyShift(a)
  double arnoldi_tolerance = 1e-12;  // Spectra's relative tolerance on the Ritz values of C
  int subspace = 0;                  // Arnoldi basis size ncv; 0: max(4 nev + 1, nev + 40)
};

struct SparseEigenpairs {
  Eigen::VectorXcd values;   // one per complex pair (Im >= 0), largest |mu| first
  Eigen::MatrixXcd vectors;  // unit columns
  double shift = 0.0;
  double worst_residual = 0.0;  // of the returned pairs, relative as above
  bool sparse_factorization = false;
  int operations = 0;             // applications of C, both runs
  double guard_difference = 0.0;  // |leading growth rate of run 1 - of run 2| [1/s]
};

// The shift s > 0 described above (1 when A has no nonzero (A^2)_ii).
double cayleyShift(const Eigen::MatrixXd& a);

// Throws LinearizationFailure (study/modes_error.hpp) when A is not finite, A - s I cannot be
// factorized, Arnoldi does not converge, a residual is too large or the guard disagrees;
// ModesError when count < 1 or A has fewer than 2 count + 4 states (use the dense solver).
SparseEigenpairs sparseEigenpairs(const Eigen::MatrixXd& a, const SparseEigenOptions& options);

}  // namespace tribo::study
