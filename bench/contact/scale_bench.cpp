// Scale: grids of side x side resting boxes (0.2 m, 8 kg, 0.25 m pitch, as
// scenes/box_grid20.yaml) on a half-space, from 10 x 10 to 142 x 142 (20 164 boxes),
// automatic contacts.
// Times are processor time of the process (one thread).
// - BM_GridSetUp/side: the scene text loaded, the model built, a Dynamics made and its first
//   evaluation: seconds (and the loading's share), heap held afterwards (glibc's mallinfo2, bytes
//   in use in the arena and in chunks mapped apart) in MB and per box, the shares a box of the
//   model, the Dynamics and the initial state, and the process's peak resident set (VmHWM;
//   meaningful when the benchmark runs alone in its process:
//   --benchmark_filter='BM_GridSetUp/70$'); and apart, the seconds to make a Simulator on the
//   loaded model (simulator_s).
// - BM_GridStep/side: semi-implicit Euler steps at 1 ms: microseconds a step and a box.
// - BM_GridGrowth: 10 x 10 and 70 x 70 stepped in the same iteration; the growth exponent
//   log(t_70 / t_10) / log(4900 / 100) of the step's cost (1: linear in the boxes).
// - BM_GridStageGrowth: the same two grids (and 142 x 142) with the stage clock on
//   (core/stage_profile.hpp): each stage's growth exponent between 100 and 20 164 boxes and
//   its nanoseconds a box at each end, so that the stage whose cost a box grows is named
//   (`rest` is the step outside the stages: the integrator's update, the checks, the guard).
//   Wall time of the stage clock, one thread.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "box_grid_scene.hpp"
#include "core/dynamics.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

double peakRssMb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

// Processor time of the process [s]: the figures are taken on a shared machine, where wall
// time counts other jobs too; one thread runs here.
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Bytes allocated and not freed: the arena's chunks in use and the chunks glibc maps apart
// (hblkhd: an allocation above the mmap threshold, 128 kB to 32 MB, such as a vector of
// 20 000 bodies, is not in uordblks).
double heapInUse() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd);
}

void BM_GridSetUp(benchmark::State& st) {
  const int side = static_cast<int>(st.range(0));
  const std::string text = tribo::bench::boxGridYaml(side);
  double seconds = 0, loading = 0, held = 0, model_held = 0, dynamics_held = 0, state_held = 0,
         simulator = 0;
  for (auto _ : st) {
    const double before = heapInUse();
    const double t0 = cpuSeconds();
    const auto scene = tribo::io::loadSceneFromString(text, "grid.yaml");
    const double t1 = cpuSeconds();
    const double after_model = heapInUse();
    tribo::Dynamics dynamics(scene.model);
    const double after_dynamics = heapInUse();
    const tribo::State s = dynamics.initialState();
    const double after_state = heapInUse();
    benchmark::DoNotOptimize(dynamics.evaluate(s).contacts.size());
    seconds += cpuSeconds() - t0;
    loading += t1 - t0;
    held = heapInUse() - before;
    model_held = after_model - before;
    dynamics_held = after_dynamics - after_model;
    state_held = after_state - after_dynamics;
    // What `tribo run` adds: the simulator on the same model (its own Dynamics, its
    // integrator, its energy guard's floor), not counted in the heap above.
    const double t2 = cpuSeconds();
    const tribo::Simulator sim(scene.model);
    benchmark::DoNotOptimize(sim.state().bodies.size());
    simulator += cpuSeconds() - t2;
  }
  const double boxes = side * side;
  st.counters["setup_s"] = seconds / static_cast<double>(st.iterations());
  st.counters["load_s"] = loading / static_cast<double>(st.iterations());
  st.counters["simulator_s"] = simulator / static_cast<double>(st.iterations());
  st.counters["heap_MB"] = held / 1e6;
  st.counters["heap_per_box_kB"] = held / boxes / 1e3;
  // The shares a box: the scene's model; the Dynamics made on it (its workspace, detector,
  // solvers, the contact lists reserved); the initial state; the rest is what the first
  // evaluation made (pair lists, the broadphase, per-point lists).
  st.counters["model_per_box_kB"] = model_held / boxes / 1e3;
  st.counters["dynamics_per_box_kB"] = dynamics_held / boxes / 1e3;
  st.counters["state_per_box_kB"] = state_held / boxes / 1e3;
  st.counters["peak_rss_MB"] = peakRssMb();
}

double stepSeconds(const std::shared_ptr<const tribo::Model>& model, int steps) {
  tribo::Simulator sim(model);
  for (int i = 0; i < 20; ++i) sim.step();  // warm: buffers at their working size
  const double t0 = cpuSeconds();
  for (int i = 0; i < steps; ++i)
    if (!sim.step().ok) return -1.0;
  return (cpuSeconds() - t0) / steps;
}

void BM_GridStep(benchmark::State& st) {
  const int side = static_cast<int>(st.range(0));
  const auto scene = tribo::io::loadSceneFromString(tribo::bench::boxGridYaml(side), "grid.yaml");
  const int steps = std::max(20, 200000 / (side * side));
  double total = 0;
  for (auto _ : st) {
    const double s = stepSeconds(scene.model, steps);
    if (s < 0) {
      st.SkipWithError("diverged");
      return;
    }
    total += s;
  }
  const double per_step = total / static_cast<double>(st.iterations());
  st.counters["step_us"] = 1e6 * per_step;
  st.counters["per_box_us"] = 1e6 * per_step / (side * side);
}

void BM_GridGrowth(benchmark::State& st) {
  const auto small = tribo::io::loadSceneFromString(tribo::bench::boxGridYaml(10), "grid.yaml");
  const auto large = tribo::io::loadSceneFromString(tribo::bench::boxGridYaml(70), "grid.yaml");
  double t_small = 0, t_large = 0;
  for (auto _ : st) {
    t_small += stepSeconds(small.model, 2000);
    t_large += stepSeconds(large.model, 40);
  }
  st.counters["exponent"] = std::log(t_large / t_small) / std::log(4900.0 / 100.0);
  st.counters["per_box_us_100"] = 1e6 * t_small / static_cast<double>(st.iterations()) / 100;
  st.counters["per_box_us_4900"] = 1e6 * t_large / static_cast<double>(st.iterations()) / 4900;
}

// Seconds a step by stage (the last entry: the step outside the stages), stage clock on.
std::vector<double> stageSeconds(const std::shared_ptr<const tribo::Model>& model, int steps) {
  tribo::Simulator sim(model);
  for (int i = 0; i < 20; ++i) sim.step();
  sim.setProfiling(true);
  for (int i = 0; i < steps; ++i)
    if (!sim.step().ok) return {};
  const tribo::StageProfile& p = sim.stats().profile;
  std::vector<double> out(p.seconds.begin(), p.seconds.end());
  out.push_back(p.step - p.total());
  for (double& s : out) s /= steps;
  return out;
}

void BM_GridStageGrowth(benchmark::State& st) {
  const auto small = tribo::io::loadSceneFromString(tribo::bench::boxGridYaml(10), "grid.yaml");
  const auto large = tribo::io::loadSceneFromString(tribo::bench::boxGridYaml(142), "grid.yaml");
  std::vector<double> t_small(tribo::kStageCount + 1, 0.0), t_large = t_small;
  for (auto _ : st) {
    const auto a = stageSeconds(small.model, 2000);
    const auto b = stageSeconds(large.model, 10);
    if (a.empty() || b.empty()) {
      st.SkipWithError("diverged");
      return;
    }
    for (std::size_t k = 0; k < a.size(); ++k) t_small[k] += a[k], t_large[k] += b[k];
  }
  const double n_small = 100.0, n_large = 142.0 * 142.0, it = st.iterations();
  for (std::size_t k = 0; k < t_small.size(); ++k) {
    const std::string name = k < tribo::kStageCount
                                 ? std::string(tribo::stageName(static_cast<tribo::Stage>(k)))
                                 : std::string("rest");
    if (t_small[k] <= 0.0 || t_large[k] <= 0.0) continue;
    st.counters[name + "_exp"] = std::log(t_large[k] / t_small[k]) / std::log(n_large / n_small);
    st.counters[name + "_ns_100"] = 1e9 * t_small[k] / it / n_small;
    st.counters[name + "_ns_20164"] = 1e9 * t_large[k] / it / n_large;
  }
}

}  // namespace

// Grid sides 10, 20, 40, 70 and 142, one iteration each.
void gridSides(benchmark::internal::Benchmark* b) {
  for (int side : {10, 20, 40, 70, 142}) b->Arg(side);
  b->Unit(benchmark::kMillisecond)->Iterations(1);
}

BENCHMARK(BM_GridSetUp)->Apply(gridSides);
BENCHMARK(BM_GridStep)->Apply(gridSides);
BENCHMARK(BM_GridGrowth)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_GridStageGrowth)->Unit(benchmark::kMillisecond)->Iterations(3);
