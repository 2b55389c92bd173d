// The multiplier solve and what surrounds it: the block Cholesky against a dense
// factorization, the dense and sparse constraint solvers against each other, redundant
// constraints (found, named, dropped), and the projection back onto the constraints.
#include <gtest/gtest.h>

#include <random>

#include "core/block_cholesky.hpp"
#include "core/constraint_projection.hpp"
#include "core/constraint_rank.hpp"
#include "core/constraint_solver.hpp"
#include "core/dynamics.hpp"
#include "core/simulator.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

// A random symmetric positive definite matrix on a given block pattern.
Eigen::MatrixXd randomOnPattern(const std::vector<int>& begin,
                                const std::vector<std::pair<int, int>>& block_edges,
                                std::vector<std::pair<int, int>>& entries) {
  const int n = begin.back();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  auto fill = [&](int g, int h) {
    for (int i = begin[g]; i < begin[g + 1]; ++i)
      for (int j = begin[h]; j < begin[h + 1]; ++j) a(i, j) = a(j, i) = u(rng);
  };
  for (std::size_t g = 0; g + 1 < begin.size(); ++g) fill(g, g);
  for (const auto& [g, h] : block_edges) fill(g, h);
  a += n * Eigen::MatrixXd::Identity(n, n);  // diagonally dominant
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      if (a(i, j) != 0.0) entries.emplace_back(i, j);
  return a;
}

TEST(BlockCholesky, SolvesLikeADenseFactorizationWithFillOnALoop) {
  // Groups of 1..6 rows; a cycle 0-1-2-3-4-0 (fill) plus a branch 2-5.
  const std::vector<int> begin{0, 5, 8, 14, 15, 19, 21};
  std::vector<std::pair<int, int>> entries;
  const Eigen::MatrixXd a =
      randomOnPattern(begin, {{1, 0}, {2, 1}, {3, 2}, {4, 3}, {4, 0}, {5, 2}}, entries);
  auto chol = BlockCholesky::create(begin, entries);
  EXPECT_EQ(chol->blockSize(), 6);
  EXPECT_GT(chol->fillCount(), 0);
  chol->setZero();
  for (const auto& [i, j] : entries) chol->values()[chol->slot(i, j)] += a(i, j);
  ASSERT_TRUE(chol->factorize());
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const Eigen::VectorXd expected = a.llt().solve(x);
  chol->solveInPlace(x);
  EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
}

TEST(BlockCholesky, ChainsAndTreesFactorWithoutFill) {
  // A tree: 0-1, 1-2, 1-3, 3-4 (a joint graph's blocks share one body per edge).
  const std::vector<int> begin{0, 5, 10, 15, 20, 25};
  std::vector<std::pair<int, int>> entries;
  const Eigen::MatrixXd a =
      randomOnPattern(begin, {{1, 0}, {2, 1}, {3, 1}, {3, 2}, {4, 3}}, entries);
  auto chol = BlockCholesky::create(begin, entries);
  EXPECT_EQ(chol->blockSize(), 5);
  EXPECT_EQ(chol->fillCount(), 0);
  for (const auto& [i, j] : entries) chol->values()[chol->slot(i, j)] += a(i, j);
  ASSERT_TRUE(chol->factorize());
  Eigen::VectorXd x = Eigen::VectorXd::Ones(a.rows());
  const Eigen::VectorXd expected = a.llt().solve(x);
  chol->solveInPlace(x);
  EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
}

TEST(BlockCholesky, RejectsAnIndefiniteMatrix) {
  const std::vector<int> begin{0, 2};
  auto chol = BlockCholesky::create(begin, {{0, 0}, {1, 0}, {1, 1}});
  chol->values()[chol->slot(0, 0)] = 1.0;
  chol->values()[chol->slot(1, 0)] = 2.0;
  chol->values()[chol->slot(1, 1)] = 1.0;
  EXPECT_FALSE(chol->factorize());
}

// A bent, moving chain state: the chain released horizontally, 0.3 s later.
State movingChainState(const std::shared_ptr<const Model>& model) {
  Simulator sim(model);
  for (int i = 0; i < 300; ++i) EXPECT_TRUE(sim.step().ok);
  return sim.state();
}

TEST(ConstraintSolver, DenseAndSparseGiveTheSameAccelerations) {
  for (int n : {3, 20}) {
    auto dense =
        test::revoluteChain(n, IntegratorType::kRk4, 1e-3, ConstraintSolverKind::kDense).build();
    auto sparse =
        test::revoluteChain(n, IntegratorType::kRk4, 1e-3, ConstraintSolverKind::kSparse).build();
    const State s = movingChainState(dense);
    Dynamics dd(dense), ds(sparse);
    const Workspace& a = dd.evaluate(s);
    const Workspace& b = ds.evaluate(s);
    double scale = 0.0, diff = 0.0;
    for (int i = 0; i < n; ++i) {
      scale = std::max(scale, a.linear_acceleration[i].norm() + a.angular_acceleration[i].norm());
      diff = std::max(diff, (a.linear_acceleration[i] - b.linear_acceleration[i]).norm() +
                                (a.angular_acceleration[i] - b.angular_acceleration[i]).norm());
    }
    EXPECT_LT(diff, 1e-10 * scale) << n << " links";
    EXPECT_FALSE(ConstraintSolver(*dense).isSparse());
    EXPECT_TRUE(ConstraintSolver(*sparse).isSparse());
  }
}

TEST(ConstraintSolver, ChainEnergyErrorVanishesAtTheIntegratorsOrder) {
  // 12 links released horizontally whip around for 2 s; the exact motion keeps its energy.
  // RK4's error must fall by about 2^4 per halving of the step (asked: more than 2^3) and
  // be below 1e-4 of the released potential energy (m g L N^2 / 2 = 0.71 J) at 0.25 ms.
  std::vector<double> error;
  for (double dt : {1e-3, 5e-4, 2.5e-4}) {
    auto model =
        test::revoluteChain(12, IntegratorType::kRk4, dt, ConstraintSolverKind::kSparse).build();
    Simulator sim(model);
    const double e0 = test::mechanicalEnergy(*model, sim.state());
    double worst = 0.0;
    for (long i = 0; i < std::lround(2.0 / dt); ++i) {
      ASSERT_TRUE(sim.step().ok);
      worst = std::max(worst, std::abs(test::mechanicalEnergy(*model, sim.state()) - e0));
    }
    error.push_back(worst);
  }
  EXPECT_LT(error[1], error[0] / 8) << error[0] << " " << error[1];
  EXPECT_LT(error[2], error[1] / 8) << error[1] << " " << error[2];
  EXPECT_LT(error[2], 1e-4 * 0.1 * 9.81 * 0.1 * 144 / 2);
}

// Planar four-bar (a parallelogram) of revolute joints about y: ground pivots at x = 0 and
// x = 0.3, crank and rocker 0.1 m up, coupler 0.3 m across their tops.
ModelBuilder fourBar(RedundancyPolicy policy) {
  ModelBuilder b;
  b.options().constraints.redundant = policy;
  auto link = [&](const std::string& name, const Vec3& centre, double spin = 0.0) {
    Body body;
    body.name = name;
    body.mass = 1.0;
    body.inertia = Mat3::Identity() * 0.01;
    body.position = centre;
    body.angular_velocity = Vec3(0, spin, 0);
    return b.addBody(body);
  };
  // The upright loop is an equilibrium: the crank gets a push (the initial projection makes
  // the other links' velocities consistent with it).
  const BodyIndex crank = link("crank", Vec3(0, 0, 0.05), 2.0);
  const BodyIndex coupler = link("coupler", Vec3(0.15, 0, 0.1));
  const BodyIndex rocker = link("rocker", Vec3(0.3, 0, 0.05));
  const Vec3 y = Vec3::UnitY();
  b.addJoint("ground_crank", JointType::kRevolute, BodyIndex::world(), crank, Vec3::Zero(), y);
  b.addJoint("crank_coupler", JointType::kRevolute, crank, coupler, Vec3(0, 0, 0.1), y);
  b.addJoint("coupler_rocker", JointType::kRevolute, coupler, rocker, Vec3(0.3, 0, 0.1), y);
  b.addJoint("rocker_ground", JointType::kRevolute, BodyIndex::world(), rocker, Vec3(0.3, 0, 0), y);
  return b;
}

TEST(Redundancy, APlanarLoopOfRevolutesIsNamedWithAWayOut) {
  try {
    fourBar(RedundancyPolicy::kError).build();
    FAIL() << "no error";
  } catch (const ModelError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("redundant constraints"), std::string::npos) << m;
    EXPECT_NE(m.find("3 equations"), std::string::npos) << m;
    EXPECT_NE(m.find("joint 'rocker_ground'"), std::string::npos) << m;
    EXPECT_NE(m.find("redundant: remove"), std::string::npos) << m;
  }
}

TEST(Redundancy, RemovedEquationsLeaveAOneDegreeOfFreedomLoopThatMoves) {
  // 4 joints x 5 equations on 3 bodies (18 coordinates) for 1 degree of freedom: 3 of the 20
  // are dependent. Dropped, the rest solves, and the loop stays closed while it falls.
  auto model = fourBar(RedundancyPolicy::kRemove).build();
  int dropped = 0;
  for (const Joint& j : model->joints) dropped += __builtin_popcount(j.dropped_equations);
  EXPECT_EQ(dropped, 3);
  ConstraintSolver solver(*model);
  EXPECT_EQ(solver.equationCount(), 17);
  Simulator sim(model);
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(sim.step().ok);
  EXPECT_LT(sim.stats().max_constraint_error, 1e-6);
  EXPECT_GT(sim.state().bodies[0].angular_velocity.norm(), 0.1);  // it moved
}

TEST(Redundancy, AnOpenChainSkipsTheCheckAndAClosedOneIsChecked) {
  EXPECT_FALSE(needsRankCheck(*test::revoluteChain(5, IntegratorType::kRk4, 1e-3).build()));
  EXPECT_TRUE(needsRankCheck(*fourBar(RedundancyPolicy::kRemove).build()));
}

TEST(Projection, LandsOnTheConstraintsAndOnlyRemovesKineticEnergy) {
  // A chain pulled off its joints (1 mm, 0.01 rad) with velocities across them.
  auto model = test::revoluteChain(4, IntegratorType::kRk4, 1e-3).build();
  State s = movingChainState(model);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (BodyState& b : s.bodies) {
    b.position += 1e-3 * Vec3(u(rng), u(rng), u(rng));
    b.orientation = rotateBy(Vec3(u(rng), u(rng), u(rng)), 0.01, b.orientation);
    b.velocity += Vec3(u(rng), u(rng), u(rng));
  }
  auto kinetic = [&](const State& st) {
    double t = 0.0;
    for (std::size_t i = 0; i < st.bodies.size(); ++i) {
      const Body& body = model->bodies[i];
      const Vec3 w = st.bodies[i].orientation.conjugate() * st.bodies[i].angular_velocity;
      t += 0.5 * body.mass * st.bodies[i].velocity.squaredNorm() + 0.5 * w.dot(body.inertia * w);
    }
    return t;
  };
  ConstraintProjection projection(*model);
  const State before = s;
  const ProjectionReport r = projection.project(s, 1e-12, 10);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.max_phi_before, 1e-4);
  EXPECT_LE(r.max_phi_after, 1e-12);
  EXPECT_TRUE(r.velocities_projected);
  // Evaluate the projected state: on the manifold, J v = 0.
  Dynamics dynamics(model);
  const Workspace& ws = dynamics.evaluate(s);
  EXPECT_LT(ws.max_constraint_error, 1e-12);
  EXPECT_LT(ws.max_constraint_rate_error, 1e-10);
  // The velocity projection is M-orthogonal: it can only take kinetic energy away.
  EXPECT_LT(kinetic(s), kinetic(before));
}

TEST(Projection, AStateOnTheConstraintsIsLeftAlone) {
  auto model = test::revoluteChain(3, IntegratorType::kRk4, 1e-3).build();
  State s = Dynamics(model).initialState();
  const State before = s;
  const ProjectionReport r = ConstraintProjection(*model).project(s, 1e-10, 3);
  EXPECT_EQ(r.position_iterations, 0);
  EXPECT_FALSE(r.velocities_projected);
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    EXPECT_EQ(s.bodies[i].position, before.bodies[i].position);
}

}  // namespace
}  // namespace tribo
