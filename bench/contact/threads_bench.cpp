// Two threads against one in the same process (SimulationOptions::threads): resting box
// grids of 20 x 20 (on a half-space and on a box ground), 40 x 40 (1600 boxes) and more,
// generated like scenes/box_grid20.yaml (bench/support/box_grid_scene.hpp: 0.2 m boxes of 8 kg
// at a 0.25 m pitch at their static depth, Coulomb friction, semi-implicit Euler at 1 ms).
// Each iteration steps a one-thread simulator and a two-thread one by the same steps,
// alternately in short runs so a change of the machine's load hits both; counters: the step
// [us] of each, their ratio (speedup, > 1: two threads faster) and the contact points per
// step. The trajectories are the same bit for bit (tests/core/threaded_evaluation_test.cpp).
// Names: BM_Threads/grid<N>[_box_ground].
#include <benchmark/benchmark.h>

#include <chrono>
#include <sstream>
#include <string>

#include "box_grid_scene.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

std::shared_ptr<const tribo::Model> grid(int n, bool box_ground, int threads) {
  tribo::io::RunSettings settings;
  settings.threads = threads;
  return tribo::io::loadSceneFromString(tribo::bench::boxGridYaml(n, box_ground), "grid.yaml", {},
                                        {}, settings)
      .model;
}

void BM_Threads(benchmark::State& st, int n, bool box_ground) {
  tribo::Simulator one(grid(n, box_ground, 1)), two(grid(n, box_ground, 2));
  constexpr int kRun = 10;  // steps per turn
  double seconds[2] = {0, 0};
  long steps = 0;
  for (auto _ : st) {
    tribo::Simulator* sims[2] = {&one, &two};
    for (int k = 0; k < 2; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = 0; i < kRun; ++i)
        if (!sims[k]->step().ok) {
          st.SkipWithError("diverged");
          return;
        }
      seconds[k] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    steps += kRun;
  }
  st.counters["step_us_1"] = 1e6 * seconds[0] / static_cast<double>(steps);
  st.counters["step_us_2"] = 1e6 * seconds[1] / static_cast<double>(steps);
  st.counters["speedup"] = seconds[0] / seconds[1];
  st.counters["points_per_step"] = static_cast<double>(one.current().contacts.size());
}

}  // namespace

BENCHMARK_CAPTURE(BM_Threads, grid20, 20, false)
    ->Name("BM_Threads/grid20")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Threads, grid20_box_ground, 20, true)
    ->Name("BM_Threads/grid20_box_ground")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Threads, grid40, 40, false)
    ->Name("BM_Threads/grid40")
    ->Unit(benchmark::kMillisecond);
// 70 x 70 (4900 boxes): set-up needs the pair bookkeeping without its O(n^2) memory first.
// BENCHMARK_CAPTURE(BM_Threads, grid70,
// 70)->Name("BM_Threads/grid70")->Unit(benchmark::kMillisecond);
