// Belt scene speed: simulated seconds per wall second for each integrator and step, and the
// baseline it is read against in the same process: the hand-reduced one-degree-of-freedom
// RK4 loop (tests/support/one_dof_belt.hpp), the cheapest possible simulation of the scene.
// Names: BM_BeltScene/<integrator>/<step in us>, BM_Baseline_OneDofRk4/<step in us>.
#include <benchmark/benchmark.h>

#include <string>

#include "core/simulator.hpp"
#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "support/one_dof_belt.hpp"

namespace {

constexpr double kSimulated = 10.0;  // [s] per iteration
const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

void BM_BeltScene(benchmark::State& st, const std::string& integrator) {
  const double dt = static_cast<double>(st.range(0)) * 1e-6;
  const auto scene = tribo::io::loadScene(
      kBelt, {"integrator=" + integrator, "dt=" + std::to_string(dt), "duration=10"});
  const long steps = std::lround(kSimulated / dt);
  for (auto _ : st) {
    tribo::Simulator sim(scene.model);
    for (long i = 0; i < steps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
    }
    benchmark::DoNotOptimize(sim.state().bodies.back().position.x());
  }
  st.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kSimulated * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
}

// A long run whose quantities decay to subnormal numbers unless flushed (mu_s = 0.31 settles
// into a cycle where the box's rocking and the joint drift decay for tens of seconds;
// core/flush_denormals.hpp): 100 s of RK4 at 4 ms, per step, against mu_s = 0.35. The two
// take the same instructions a step; without flushing the first took 7 times as long.
void BM_BeltLongRun(benchmark::State& st) {
  const std::string mu_s = st.range(0) == 31 ? "0.31" : "0.35";
  const auto scene = tribo::io::loadScene(kBelt, {"dt=0.004", "duration=100", "mu_s=" + mu_s});
  constexpr long kSteps = 25000;
  for (auto _ : st) {
    tribo::Simulator sim(scene.model);
    for (long i = 0; i < kSteps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
    }
    benchmark::DoNotOptimize(sim.state().bodies.back().position.x());
  }
  st.counters["us_per_step"] = benchmark::Counter(
      static_cast<double>(kSteps) * static_cast<double>(st.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}

void BM_Baseline_OneDofRk4(benchmark::State& st) {
  const double dt = static_cast<double>(st.range(0)) * 1e-6;
  const auto law = tribo::friction::makeFrictionLaw(
      {"roh_yoo",
       {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3}},
       {}});
  const tribo::test::OneDofBelt belt{10.0, 300.0, 1.5, 9.81, law.get()};
  const long steps = std::lround(kSimulated / dt);
  for (auto _ : st) {
    double x = 0.0, v = 0.0;
    belt.run(x, v, dt, steps, [](double, double, double) {});
    benchmark::DoNotOptimize(x);
  }
  st.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kSimulated * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
}

BENCHMARK(BM_BeltLongRun)
    ->Name("BM_BeltLongRun/mu_s_x100")
    ->Arg(35)
    ->Arg(31)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Baseline_OneDofRk4)
    ->Name("BM_Baseline_OneDofRk4")
    ->Arg(1000)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BeltScene, rk4, std::string("rk4"))
    ->Name("BM_BeltScene/rk4")
    ->Arg(8000)
    ->Arg(4000)
    ->Arg(2000)
    ->Arg(1000)
    ->Arg(500)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BeltScene, semi_implicit_euler, std::string("semi_implicit_euler"))
    ->Name("BM_BeltScene/semi_implicit_euler")
    ->Arg(2000)
    ->Arg(1000)
    ->Arg(500)
    ->Arg(250)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
