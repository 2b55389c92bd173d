// Step cost of a chain of N revolute-jointed links (N = 1..256, no contacts), to show how it
// grows with N for the dense and the sparse factorization of J M^-1 J^T, and what share of
// an evaluation the constraint solve takes. Read against baselines run in the same process:
// the same N links without joints (everything but the constraints) and the solver alone.
// Names: BM_ChainStep/<dense|sparse>/<integrator>/N (one step, 1 ms), BM_ChainEvaluate/
// <dense|sparse>/N (one force evaluation), BM_ChainSolve/<dense|sparse>/N (the constraint
// solve of one evaluation), BM_ChainFree/N (an evaluation of N unjointed links), and for
// closed loops (fill in the sparse factorization) BM_LoopSolve/<scene>/<dense|sparse>.
#include <benchmark/benchmark.h>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/joint_test_models.hpp"

namespace {

using tribo::ConstraintSolverKind;
using tribo::IntegratorType;

constexpr int kStepsPerRestart = 500;  // the chain falls; restart before it folds up tightly

void BM_ChainStep(benchmark::State& st, ConstraintSolverKind solver, IntegratorType integrator) {
  const int n = static_cast<int>(st.range(0));
  auto model = tribo::test::revoluteChain(n, integrator, 1e-3, solver).build();
  tribo::Simulator sim(model);
  const tribo::State start = sim.state();
  int steps = 0;
  for (auto _ : st) {
    if (++steps == kStepsPerRestart) {
      steps = 0;
      sim.setState(start);
    }
    if (!sim.step().ok) {
      st.SkipWithError("diverged");
      return;
    }
  }
  st.counters["us_per_link"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * n * 1e-6,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["sparse"] = tribo::ConstraintSolver(*model).isSparse() ? 1 : 0;
}

tribo::State fallingState(const tribo::Model& model) {
  // A generic configuration: advance the chain 0.2 s so that it moves and bends.
  tribo::Simulator sim(std::make_shared<tribo::Model>(model));
  for (int i = 0; i < 200; ++i) sim.step();
  return sim.state();
}

void BM_ChainEvaluate(benchmark::State& st, ConstraintSolverKind solver) {
  const int n = static_cast<int>(st.range(0));
  auto model = tribo::test::revoluteChain(n, IntegratorType::kRk4, 1e-3, solver).build();
  tribo::Dynamics dynamics(model);
  const tribo::State s = fallingState(*model);
  for (auto _ : st) benchmark::DoNotOptimize(dynamics.evaluate(s).linear_acceleration.data());
}

void BM_ChainSolve(benchmark::State& st, ConstraintSolverKind solver) {
  const int n = static_cast<int>(st.range(0));
  auto model = tribo::test::revoluteChain(n, IntegratorType::kRk4, 1e-3, solver).build();
  tribo::Dynamics dynamics(model);
  const tribo::State s = fallingState(*model);
  tribo::Workspace ws = dynamics.evaluate(s);  // kinematics and free accelerations
  const tribo::Workspace free = ws;
  tribo::ConstraintSolver constraint_solver(*model);
  for (auto _ : st) {
    ws.linear_acceleration = free.linear_acceleration;
    ws.angular_acceleration = free.angular_acceleration;
    constraint_solver.solve(s, ws);
    benchmark::DoNotOptimize(ws.linear_acceleration.data());
  }
}

void BM_ChainFree(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  tribo::ModelBuilder b = tribo::test::revoluteChain(n, IntegratorType::kRk4, 1e-3);
  tribo::ModelBuilder free;
  for (const auto& body : b.bodies()) free.addBody(body);
  auto model = free.build();
  tribo::Dynamics dynamics(model);
  const tribo::State s = dynamics.initialState();
  for (auto _ : st) benchmark::DoNotOptimize(dynamics.evaluate(s).linear_acceleration.data());
}

void BM_LoopSolve(benchmark::State& st, const std::string& scene, const std::string& solver) {
  const auto loaded =
      tribo::io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/" + scene + ".yaml");
  auto model = std::make_shared<tribo::Model>(*loaded.model);
  model->options.constraints.solver = tribo::constraintSolverFromName(solver);
  tribo::Simulator sim(model);
  for (int i = 0; i < 100; ++i) sim.step();
  const tribo::State s = sim.state();
  tribo::Dynamics dynamics(model);
  tribo::Workspace ws = dynamics.evaluate(s);
  const tribo::Workspace free = ws;
  tribo::ConstraintSolver constraint_solver(*model);
  for (auto _ : st) {
    ws.linear_acceleration = free.linear_acceleration;
    ws.angular_acceleration = free.angular_acceleration;
    constraint_solver.solve(s, ws);
    benchmark::DoNotOptimize(ws.linear_acceleration.data());
  }
  st.counters["equations"] = constraint_solver.equationCount();
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {1, 2, 4, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256}) b->Arg(n);
  b->Unit(benchmark::kMicrosecond);
}

BENCHMARK_CAPTURE(BM_ChainStep, dense_sie, ConstraintSolverKind::kDense,
                  IntegratorType::kSemiImplicitEuler)
    ->Name("BM_ChainStep/dense/semi_implicit_euler")
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ChainStep, sparse_sie, ConstraintSolverKind::kSparse,
                  IntegratorType::kSemiImplicitEuler)
    ->Name("BM_ChainStep/sparse/semi_implicit_euler")
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ChainStep, auto_rk4, ConstraintSolverKind::kAuto, IntegratorType::kRk4)
    ->Name("BM_ChainStep/auto/rk4")
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ChainEvaluate, dense, ConstraintSolverKind::kDense)
    ->Name("BM_ChainEvaluate/dense")
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ChainEvaluate, sparse, ConstraintSolverKind::kSparse)
    ->Name("BM_ChainEvaluate/sparse")
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ChainSolve, dense, ConstraintSolverKind::kDense)
    ->Name("BM_ChainSolve/dense")
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ChainSolve, sparse, ConstraintSolverKind::kSparse)
    ->Name("BM_ChainSolve/sparse")
    ->Apply(sizes);
BENCHMARK(BM_ChainFree)->Name("BM_ChainFree")->Apply(sizes);
BENCHMARK_CAPTURE(BM_LoopSolve, andrews_dense, "andrews_squeezer", "dense")
    ->Name("BM_LoopSolve/andrews_squeezer/dense")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_LoopSolve, andrews_sparse, "andrews_squeezer", "sparse")
    ->Name("BM_LoopSolve/andrews_squeezer/sparse")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_LoopSolve, crank_dense, "slider_crank", "dense")
    ->Name("BM_LoopSolve/slider_crank/dense")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_LoopSolve, crank_sparse, "slider_crank", "sparse")
    ->Name("BM_LoopSolve/slider_crank/sparse")
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
