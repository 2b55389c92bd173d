// What each integrator setting costs on the belt scene and on the three-box chain, read
// against the hand-reduced one-degree-of-freedom RK4 loop run in the same process
// (BM_Baseline_OneDofRk4, belt_bench.cpp), and what the run guards cost: the same RK4 steps
// with and without the Simulator's checks (finite state, penetration, energy account).
// Names: BM_Integrator/<scene>/<integrator>/<setting>, setting = step in us (fixed) or
// -log10(rtol) (adaptive, 10 ms communication interval); BM_Guards/belt/{checked,unchecked}.
// Accuracy for the same settings: tribo tradeoff (docs/speed-accuracy.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/integrator.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

constexpr double kSimulated = 10.0;  // [s] per iteration

std::shared_ptr<const tribo::Model> model(const std::string& scene, tribo::IntegratorType type,
                                          long setting) {
  const auto loaded =
      tribo::io::loadScene(std::string(TRIBO_SOURCE_DIR) + "/scenes/" + scene + ".yaml");
  auto m = std::make_shared<tribo::Model>(*loaded.model);
  m->options.integrator = type;
  if (tribo::isAdaptive(type)) {
    m->options.time_step = 0.01;
    m->options.relative_tolerance = std::pow(10.0, -static_cast<double>(setting));
    m->options.absolute_tolerance = 1e-3 * m->options.relative_tolerance;
  } else {
    m->options.time_step = static_cast<double>(setting) * 1e-6;
  }
  return m;
}

void rates(benchmark::State& st, long steps) {
  st.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kSimulated * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
}

void BM_Integrator(benchmark::State& st, const std::string& scene, tribo::IntegratorType type) {
  const auto m = model(scene, type, st.range(0));
  const long steps = std::lround(kSimulated / m->options.time_step);
  long evaluations = 0;
  for (auto _ : st) {
    tribo::Simulator sim(m);
    for (long i = 0; i < steps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
    }
    evaluations = sim.stats().evaluations;
    benchmark::DoNotOptimize(sim.state().bodies.back().position.x());
  }
  rates(st, steps);
  st.counters["evaluations"] = static_cast<double>(evaluations);
}

// RK4 at 8 ms on the belt, through the Simulator (checked) or the bare integrator
// (unchecked): the price of the divergence guards.
void BM_Guards(benchmark::State& st, bool checked) {
  const auto m = model("belt", tribo::IntegratorType::kRk4, 8000);
  const long steps = std::lround(kSimulated / m->options.time_step);
  for (auto _ : st) {
    if (checked) {
      tribo::Simulator sim(m);
      for (long i = 0; i < steps; ++i) benchmark::DoNotOptimize(sim.step().ok);
      benchmark::DoNotOptimize(sim.state().bodies.back().position.x());
    } else {
      tribo::Dynamics dynamics(m);
      auto integrator = tribo::makeIntegrator(m->options.integrator, *m);
      tribo::State state = dynamics.initialState();
      for (long i = 0; i < steps; ++i)
        integrator->step(dynamics, state, m->options.time_step, false);
      benchmark::DoNotOptimize(state.bodies.back().position.x());
    }
  }
  rates(st, steps);
}

using tribo::IntegratorType;

BENCHMARK_CAPTURE(BM_Integrator, belt_rk4, std::string("belt"), IntegratorType::kRk4)
    ->Name("BM_Integrator/belt/rk4")
    ->Arg(8000)
    ->Arg(4000)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Integrator, belt_dopri5, std::string("belt"), IntegratorType::kDopri5)
    ->Name("BM_Integrator/belt/dopri5")
    ->Arg(3)
    ->Arg(5)
    ->Arg(7)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Integrator, belt_bdf, std::string("belt"), IntegratorType::kBdf)
    ->Name("BM_Integrator/belt/bdf")
    ->Arg(4)
    ->Arg(6)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Integrator, boxes_rk4, std::string("boxes_on_belt"), IntegratorType::kRk4)
    ->Name("BM_Integrator/boxes_on_belt/rk4")
    ->Arg(2000)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Integrator, boxes_dopri5, std::string("boxes_on_belt"),
                  IntegratorType::kDopri5)
    ->Name("BM_Integrator/boxes_on_belt/dopri5")
    ->Arg(5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Integrator, boxes_bdf, std::string("boxes_on_belt"), IntegratorType::kBdf)
    ->Name("BM_Integrator/boxes_on_belt/bdf")
    ->Arg(6)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Guards, checked, true)
    ->Name("BM_Guards/belt/checked")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Guards, unchecked, false)
    ->Name("BM_Guards/belt/unchecked")
    ->Unit(benchmark::kMillisecond);

}  // namespace
