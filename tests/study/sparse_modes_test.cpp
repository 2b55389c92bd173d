// The sparse eigensolver (study/modes/sparse_modes.hpp) against what is known independently:
//  - a block-diagonal A built here from 2 x 2 blocks [[s, w], [-w, s]] (eigenvalues s +- i w
//    by construction), one growing pair buried among many decaying ones: the solver must
//    find that pair, its frequency, its eigenvector on its block, and exactly the 12
//    eigenvalues of largest growth rate (ranked here from the known ones); the same after an
//    orthogonal change of basis (a dense A with the same eigenvalues: the dense-LU path);
//    and modes spread over four decades of frequency with damping ratio 0.001 (the case a
//    single real Cayley shift could not converge on);
//  - a chain of boxes on a belt (tests/support/chain_on_belt.hpp, 240 states): the modes of
//    the sparse solver against Eigen's dense solver on the same A;
//  - refusals: too few states, a non-finite A.
#include "study/modes/sparse_modes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "study/modes/modes.hpp"
#include "support/chain_on_belt.hpp"

namespace tribo::study {
namespace {

struct Pair {
  double s, w;  // eigenvalues s +- i w
};

// 200 decaying pairs (frequencies w 1..100 rad/s, damping ratios 0.05..0.5, both spread
// log-uniformly, deterministic: s = -zeta w, as a structure's modes) and one growing pair
// (0.03 + 41.7 i) at block 137.
std::vector<Pair> knownPairs() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Pair> pairs;
  for (int k = 0; k < 200; ++k) {
    const double w = std::pow(100.0, unit(random)), zeta = 0.05 * std::pow(10.0, unit(random));
    pairs.push_back({-zeta * w, w});
  }
  pairs[137] = {0.03, 41.7};
  return pairs;
}

Eigen::MatrixXd blockDiagonal(const std::vector<Pair>& pairs) {
  const auto n = static_cast<Eigen::Index>(2 * pairs.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(2 * k);
    a(i, i) = a(i + 1, i + 1) = pairs[k].s;
    a(i, i + 1) = pairs[k].w;
    a(i + 1, i) = -pairs[k].w;
  }
  return a;
}

// The known eigenvalues (Im >= 0), the `count` of largest growth rate.
std::vector<std::complex<double>> largestGrowth(const std::vector<Pair>& pairs, std::size_t count) {
  std::vector<std::complex<double>> values;
  for (const Pair& p : pairs) values.emplace_back(p.s, p.w);
  std::sort(values.begin(), values.end(), [](auto x, auto y) { return x.real() > y.real(); });
  values.resize(count);
  return values;
}

// Each found eigenvalue within `tolerance` |lambda| of a distinct expected one.
void expectSameSet(const Eigen::VectorXcd& found, std::vector<std::complex<double>> expected,
                   double tolerance) {
  ASSERT_EQ(static_cast<std::size_t>(found.size()), expected.size());
  for (const auto& f : found) {
    auto near = std::min_element(expected.begin(), expected.end(),
                                 [&](auto x, auto y) { return std::abs(x - f) < std::abs(y - f); });
    EXPECT_LE(std::abs(*near - f), tolerance * std::abs(f)) << f << " against " << *near;
    expected.erase(near);
  }
}

// Relative eigenvalue tolerance 1e-9: the blocks are normal, so an eigenvalue's error is at
// most its residual ||A v - lambda v|| / ||v||, which the solver bounds by 1e-8 ||A||_F
// relative; in practice Arnoldi converges to 1e-12 (Spectra's tolerance), far inside 1e-9
// of |lambda| >= 0.5 here.
constexpr double kValueTolerance = 1e-9;

TEST(SparseModes, FindsTheOneGrowingPairAmongTwoHundredDecaying) {
  const std::vector<Pair> pairs = knownPairs();
  const Eigen::MatrixXd a = blockDiagonal(pairs);
  SparseEigenOptions options;
  options.count = 12;
  const SparseEigenpairs r = sparseEigenpairs(a, options);
  EXPECT_TRUE(r.sparse_factorization);  // 2 nonzeros a row of 402
  ASSERT_EQ(r.values.size(), 12);
  // The growing pair comes first.
  EXPECT_NEAR(r.values(0).real(), 0.03, kValueTolerance * 41.7);
  EXPECT_NEAR(r.values(0).imag(), 41.7, kValueTolerance * 41.7);
  EXPECT_NEAR(std::abs(r.values(0).imag()) / (2 * std::numbers::pi), 41.7 / (2 * std::numbers::pi),
              1e-9);
  int growing = 0;
  for (const auto& v : r.values) growing += v.real() > 0 ? 1 : 0;
  EXPECT_EQ(growing, 1);
  // Its eigenvector lives on block 137 (entries 274, 275) alone.
  EXPECT_NEAR(r.vectors.col(0).segment(274, 2).norm(), 1.0, 1e-9);
  // The other eleven: the next growth rates of the known set.
  expectSameSet(r.values, largestGrowth(pairs, 12), kValueTolerance);
  EXPECT_GE(r.band_top, 100.0);  // the band 1..100 rad/s is scanned whole
  EXPECT_LE(r.worst_residual, 1e-8);
}

TEST(SparseModes, SameEigenvaluesAfterAnOrthogonalChangeOfBasis) {
  const std::vector<Pair> pairs = knownPairs();
  const Eigen::MatrixXd d = blockDiagonal(pairs);
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd g(d.rows(), d.cols());
  for (Eigen::Index i = 0; i < g.size(); ++i) g(i) = normal(random);
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(g).householderQ();
  const Eigen::MatrixXd a = q * d * q.transpose();  // dense, same eigenvalues
  SparseEigenOptions options;
  options.count = 12;
  const SparseEigenpairs r = sparseEigenpairs(a, options);
  EXPECT_FALSE(r.sparse_factorization);
  // The rotation's round-off (~1e-15 ||A||_F per entry, ||A||_F ~ 5e2) moves the normal
  // matrix's eigenvalues by ~1e-12 absolute; 1e-7 relative of |lambda| >= 1 is ample.
  expectSameSet(r.values, largestGrowth(pairs, 12), 1e-7);
  EXPECT_NEAR(r.values(0).real(), 0.03, 1e-7 * 41.7);
}

// 300 pairs with w log-spaced over 0.1..1000 rad/s and damping ratio 0.001 (s = -0.001 w),
// and the pair at block 150 (w ~ 10 rad/s) growing at s = +0.002 w: the scan must cover
// the whole band, find every eigenvalue, the growing pair first and its frequency to 1e-9
// relative (the error of a normal matrix's eigenvalue is at most its residual, ~1e-12 of
// ||A||_F ~ 1e4 absolute, 1e-9 of w ~ 10 leaves a factor 100).
TEST(SparseModes, ScansLightlyDampedModesOverFourDecades) {
  std::vector<Pair> pairs;
  for (int k = 0; k < 300; ++k) {
    const double w = 0.1 * std::pow(1e4, k / 299.0);
    pairs.push_back({-0.001 * w, w});
  }
  pairs[150].s = 0.002 * pairs[150].w;
  const SparseEigenpairs r = sparseEigenpairs(blockDiagonal(pairs), {});
  ASSERT_EQ(r.values.size(), 12);
  EXPECT_EQ(r.found, 300);
  EXPECT_GE(r.band_top, 1000.0);
  EXPECT_GT(r.values(0).real(), 0.0);
  EXPECT_LT(r.values(1).real(), 0.0);
  EXPECT_LE(std::abs(r.values(0).imag() - pairs[150].w), 1e-9 * pairs[150].w);
  EXPECT_LE(std::abs(r.values(0).real() - pairs[150].s), 1e-9 * pairs[150].w);
  expectSameSet(r.values, largestGrowth(pairs, 12), kValueTolerance);
  EXPECT_LE(r.worst_residual, 1e-8);
}

TEST(SparseModes, RefusesTooFewStatesAndANonFiniteMatrix) {
  EXPECT_THROW(sparseEigenpairs(Eigen::MatrixXd::Identity(10, 10), {}), ModesError);
  Eigen::MatrixXd a = blockDiagonal(knownPairs());
  a(3, 5) = std::nan("");
  EXPECT_THROW(sparseEigenpairs(a, {}), LinearizationFailure);
  SparseEigenOptions none;
  none.count = 0;
  EXPECT_THROW(sparseEigenpairs(blockDiagonal(knownPairs()), none), ModesError);
}

// A chain of 60 boxes (240 states); damped springs between them make the in-phase modes lead
// and some 9 of the 60 in-plane pairs grow (fewer than the 12 asked for, so the sparse solver
// must return every growing mode). The dense solver on the same A is the reference: the
// growing modes must agree one to one to 1e-8 relative (both solvers' backward errors are
// ~1e-13 ||A|| with ||A|| ~ 1e6 and the chain's pairs are well separated).
TEST(SparseModes, ChainAgreesWithTheDenseSolver) {
  const auto scene = io::loadSceneFromString(test::chainOnBelt(60, "roh_yoo", 0.5), "chain.yaml");
  ModesSpec dense_spec, sparse_spec;
  dense_spec.solver = EigenSolverChoice::kDense;
  sparse_spec.solver = EigenSolverChoice::kSparse;
  const ModesResult dense = analyzeModes(scene, dense_spec);
  const ModesResult sparse = analyzeModes(scene, sparse_spec);
  EXPECT_EQ(dense.solver.method, "dense");
  EXPECT_EQ(sparse.solver.method, "sparse");
  EXPECT_GE(dense.modes.size(), 120u);  // every pair (overdamped contact pairs split in two)
  EXPECT_EQ(sparse.modes.size(), 12u);
  ASSERT_GT(dense.unstable_count, 0);
  ASSERT_LT(dense.unstable_count, 12);
  EXPECT_EQ(sparse.unstable_count, dense.unstable_count);
  for (int i = 0; i < dense.unstable_count; ++i) {
    const auto d = dense.modes[static_cast<std::size_t>(i)].eigenvalue;
    const auto s = sparse.modes[static_cast<std::size_t>(i)].eigenvalue;
    EXPECT_LE(std::abs(d - s), 1e-8 * std::abs(d)) << "mode " << i + 1 << ": " << d << " " << s;
  }
  // The leading mode's shape: the same magnitudes (1e-6: the eigenvector of a pair separated
  // by delta from the next is accurate to residual / delta).
  const Mode& ld = dense.leading();
  const Mode& ls = sparse.leading();
  ASSERT_EQ(ld.shape.size(), ls.shape.size());
  for (std::size_t k = 0; k < ld.shape.size(); ++k)
    EXPECT_NEAR(ld.shape[k].magnitude, ls.shape[k].magnitude, 1e-6) << ld.shape[k].coordinate;
  for (const auto& w : sparse.warnings) EXPECT_EQ(w.find("sparse"), std::string::npos) << w;
}

}  // namespace
}  // namespace tribo::study
