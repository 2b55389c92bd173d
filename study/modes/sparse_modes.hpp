// The few eigenpairs of a large real matrix A (y' = A y, study/modes/linearization.hpp) that decide
// its stability: those of largest growth rate Re(lambda) among the eigenvalues near the
// imaginary axis, found by scanning the frequency band with shift-and-invert Arnoldi at
// shifts sigma_k = i w_k (Saad, "Numerical Methods for Large Eigenvalue Problems", 2nd ed.,
// SIAM 2011, ch. 7, shift-and-invert; Ericsson & Ruhe 1980, Math. Comp. 35:1251-1268, the
// spectral transformation; Arnoldi by Spectra's GenEigsSolver, https://spectralib.org).
// One shift: (A - sigma I)^-1 by one LU factorization (Eigen's SparseLU when A has few
// nonzeros, dense PartialPivLU otherwise; complex for sigma != 0). Its eigenvalues
// theta = 1 / (lambda - sigma) are largest for the lambda nearest sigma, so Arnoldi finds the
// `per_shift` eigenvalues of A nearest sigma quickly and reliably, however spread the rest
// (a mechanical structure's lightly damped modes over decades of frequency, which defeat a
// single real shift). Spectra wants a real operator: for complex sigma it runs on the real
// 2n x 2n form of (A - sigma I)^-1 ([[Re, -Im], [Im, Re]]), whose eigenvalues are the theta
// and their conjugates, the eigenvector's upper half an eigenvector of A. Each eigenvalue is
// the Rayleigh quotient v^H A v / v^H v of its vector and each pair must pass
// ||A v - lambda v|| <= tol ||A||_F ||v||.
// The scan: w_0 = 0 (real, covers the low band and real eigenvalues near 0); after shift k,
// r_k = the distance from sigma_k to the farthest of its eigenvalues, and w_{k+1} = w_k +
// 0.9 r_k, so consecutive discs overlap and their union covers the segment [0, top] of the
// imaginary axis. It stops when top reaches w_max = max_i (sqrt|(A^2)_ii| + |A_ii|) (for
// A = [[0, I], [K, C]] about the largest coordinate's natural frequency or damping rate: a
// heuristic bound of the band, not a proof) or when a shift finds nothing new.
//
// What it certifies: when every Arnoldi run converged, every eigenvalue inside the union of
// the discs |lambda - i w_k| < r_k is found (and its conjugate). Not: eigenvalues outside
// the discs (far left of the axis, stiff heavily damped or real ones, or above `top`),
// multiplicities (eigenvalues within the deduplication tolerance are reported once).
//
// Not here: mode shapes and sorting (study/modes/modes.hpp), the dense solver (Eigen::EigenSolver
// in study/modes/modes.cpp), generalized problems (M y' = A y).
#pragma once

#include <Eigen/Dense>

namespace tribo::study {

struct SparseEigenOptions {
  int count = 12;                    // eigenvalues returned, a complex pair counted once
  double residual_tolerance = 1e-8;  // largest ||A v - lambda v|| / (||A||_F ||v||)
  int per_shift = 20;                // eigenvalues of A (both of a pair) sought at each shift
  double arnoldi_tolerance = 1e-12;  // Spectra's relative tolerance on the Ritz values
  int max_shifts = 400;              // the scan fails beyond this many shifts
};

struct SparseEigenpairs {
  Eigen::VectorXcd values;      // one per complex pair (Im >= 0), decreasing growth rate
  Eigen::MatrixXcd vectors;     // unit columns
  int shifts = 0;               // shifts of the scan (factorizations)
  int found = 0;                // distinct eigenvalues (Im >= 0) the scan found in all
  double band_top = 0.0;        // the discs cover the imaginary axis from 0 to i band_top [1/s]
  double strip = 0.0;           // and the strip |Re lambda| < strip along it [1/s]
  double worst_residual = 0.0;  // of the returned pairs, relative as above
  bool sparse_factorization = false;
  int operations = 0;  // applications of a shifted inverse, all shifts
};

// w_max above: max_i (sqrt|(A^2)_ii| + |A_ii|) (1 when that is 0).
double bandBound(const Eigen::MatrixXd& a);

// Throws LinearizationFailure (study/modes/modes_error.hpp) when A is not finite, A - sigma I
// cannot be factorized, an Arnoldi run does not converge, the scan needs more than max_shifts
// shifts or a residual is too large; ModesError when count < 1 or A has fewer than 2 per_shift + 4
// states (use the dense solver).
SparseEigenpairs sparseEigenpairs(const Eigen::MatrixXd& a, const SparseEigenOptions& options);

}  // namespace tribo::study
