// Matrix-free linear algebra for shooting on large states: Newton's step by GMRES and the
// leading Floquet multipliers by Arnoldi, both from products of a matrix with a vector that
// the caller computes with flows, so a state of n unknowns costs a flow per Krylov vector
// instead of 2 n flows for a dense Jacobian (Telichevesky, Kundert & White, "Efficient
// steady-state analysis based on matrix-free Krylov-subspace methods", DAC 1995: the
// monodromy of a dissipative system is the identity's shift by a matrix of few large
// eigenvalues, so GMRES on M - I converges in about as many products as M has eigenvalues
// away from 0). GMRES is Eigen's (unsupported/Eigen/IterativeSolvers: Saad & Schultz, SIAM J.
// Sci. Stat. Comput. 7, 1986; restarted every 60 vectors); Arnoldi is Spectra's implicitly
// restarted GenEigsSolver (Lehoucq & Sorensen, SIAM J. Matrix Anal. Appl. 17, 1996).
// Internal to study/orbit/. Not here: the products themselves (periodic_orbit.cpp scales the
// unknowns and differences the flow), preconditioning.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <functional>
#include <vector>

namespace tribo::study::krylov {

// y = A x for the caller's A.
using Product = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct Solution {
  Eigen::VectorXd x;
  int products = 0;        // A x evaluations
  double error = 0.0;      // |A x - b| / |b| as GMRES estimates it
  bool converged = false;  // error <= tolerance within max_products
};

// x with A x = b (A of size b.size()), from x = 0.
Solution gmres(const Product& a, const Eigen::VectorXd& b, double tolerance, int max_products);

struct Leading {
  std::vector<std::complex<double>> values;  // by decreasing modulus
  int products = 0;
};

// The `count` eigenvalues of largest modulus of the n x n matrix A (count <= n - 2); throws
// std::runtime_error when Arnoldi does not converge.
Leading leadingEigenvalues(const Product& a, Eigen::Index n, Eigen::Index count, double tolerance);

}  // namespace tribo::study::krylov
