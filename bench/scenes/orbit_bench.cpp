// Cost of periodic orbits (study/orbit/) read against what a user would otherwise run: the
// settled simulation of one sweep point (the scene's own duration, `tribo run`), measured
// first in the same process. Names: BM_Baseline_SettledRun/belt; BM_Orbit/belt_newton_only
// and BM_Orbit/belt (one orbit, `tribo orbit`: its settling run, shooting with the Jacobian's
// columns on the cores, the Floquet multipliers; without and with the return-map iterations
// before Newton's, study/orbit/picard.hpp; counters over_settled_run, flows,
// periods_to_converge and over_newton_only); BM_OrbitBranch/belt_newton_only and
// BM_OrbitBranch/belt (the branch from v_b = 1 to 4 in steps of 0.1, `tribo orbit
// --continue`, without and with the return map's steps, study/orbit/branch_return_map.hpp;
// BM_OrbitBranch/belt_100 the 100 points in steps of 0.03: counters points,
// by_return_map, per_point_over_settled_run (wall time), per_point_cpu_over_settled_run
// (processor time of every thread) and over_newton_only). What a branch point costs against a
// sweep point is the question a user of `--continue` asks.
// BM_OrbitLanes/<dense|krylov>/N: the orbit of N belt oscillators side by side
// (tests/support/belt_lanes.hpp, 12 N unknowns) by dense shooting (2 (12 N + 1) flows a Newton
// iteration, on the cores) and by matrix-free Krylov shooting (GMRES and Arnoldi, a flow a
// product); counters unknowns, flows, krylov_products and, for Krylov, over_dense (its time over
// dense shooting's at the same N, measured before it).
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <map>
#include <string>

#include "io/scene_loader.hpp"
#include "study/orbit/orbit_branch.hpp"
#include "study/orbit/periodic_orbit.hpp"
#include "study/scene_run.hpp"
#include "support/belt_lanes.hpp"

namespace {

const std::string kBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

double& settledSeconds() {
  static double seconds = 0.0;
  return seconds;
}
double& settledCpuSeconds() {
  static double seconds = 0.0;
  return seconds;
}

// The process's processor time, every thread's [s].
double processCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Wall time per iteration; `cpu`, if given, gets the process's processor time per iteration
// (every thread: the shooting's flows run on both cores).
template <class Work>
double timed(benchmark::State& st, Work work, double* cpu = nullptr) {
  double total = 0.0, cpu_total = 0.0;
  for (auto _ : st) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = processCpuSeconds();
    work();
    cpu_total += processCpuSeconds() - cpu_start;
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (cpu != nullptr) *cpu = cpu_total / static_cast<double>(st.iterations());
  return total / static_cast<double>(st.iterations());
}

void BM_Baseline_SettledRun(benchmark::State& st) {
  const auto scene = tribo::io::loadScene(kBelt);
  settledSeconds() = timed(
      st,
      [&] {
        const auto r = tribo::study::runScene(scene, tribo::study::RunOptions{});
        benchmark::DoNotOptimize(r.summary.period);
      },
      &settledCpuSeconds());
}

double& newtonOnlySeconds() {
  static double seconds = 0.0;
  return seconds;
}

// One orbit; `return_map` false is Newton's method alone (the baseline of the return map's
// gain, measured first).
void BM_Orbit(benchmark::State& st, bool return_map) {
  const auto scene = tribo::io::loadScene(kBelt);
  tribo::study::OrbitSpec spec;
  spec.return_map = return_map;
  tribo::study::OrbitResult r;
  const double each = timed(st, [&] { r = tribo::study::findPeriodicOrbit(scene, spec); });
  if (settledSeconds() > 0.0) st.counters["over_settled_run"] = each / settledSeconds();
  st.counters["flows"] = static_cast<double>(r.flows);
  st.counters["periods_to_converge"] = r.periods_to_converge;
  if (!return_map)
    newtonOnlySeconds() = each;
  else if (newtonOnlySeconds() > 0.0)
    st.counters["over_newton_only"] = each / newtonOnlySeconds();
}

// Newton alone's branch time, by step.
std::map<double, double>& newtonOnlyBranchSeconds() {
  static std::map<double, double> seconds;
  return seconds;
}

// The belt's branch from v_b = 1 to 4 in steps of 0.1 (about 30 points); `return_map` false
// is the arclength corrector at every point (the baseline, measured first). `step` 0.03: the
// issue's 100 points (`tribo orbit scenes/belt.yaml --continue v_b=1:4 --step 0.03 --max-step
// 0.03 --max-points 100`); per_point_over_settled_run is then the branch's time over that of the
// settled sweep of the same 100 values.
void BM_OrbitBranch(benchmark::State& st, bool return_map, double step) {
  tribo::study::BranchSpec spec;
  spec.parameter = "v_b";
  spec.from = 1.0;
  spec.to = 4.0;
  spec.step = step;
  spec.max_step = step;
  spec.max_points = 100;
  spec.orbit.return_map = return_map;
  std::size_t points = 0, by_return_map = 0;
  double cpu = 0.0;
  const double each = timed(
      st,
      [&] {
        const auto r = tribo::study::continueOrbit(kBelt, {}, spec);
        points = r.points.size();
        by_return_map = 0;
        for (const auto& p : r.points) by_return_map += p.by_return_map ? 1 : 0;
      },
      &cpu);
  st.counters["points"] = static_cast<double>(points);
  st.counters["by_return_map"] = static_cast<double>(by_return_map);
  if (settledSeconds() > 0.0 && points > 0) {
    // Wall time on the cores against a settled run on one, and processor time against
    // processor time: a sweep runs its points side by side on the cores (`tribo sweep
    // --jobs`), so the second is what the branch saves against a sweep on the same machine.
    st.counters["per_point_over_settled_run"] =
        each / static_cast<double>(points) / settledSeconds();
    st.counters["per_point_cpu_over_settled_run"] =
        cpu / static_cast<double>(points) / settledCpuSeconds();
  }
  if (!return_map)
    newtonOnlyBranchSeconds()[step] = each;
  else if (const auto it = newtonOnlyBranchSeconds().find(step);
           it != newtonOnlyBranchSeconds().end())
    st.counters["over_newton_only"] = each / it->second;
}

std::map<long, double>& denseSeconds() {
  static std::map<long, double> seconds;
  return seconds;
}

void BM_OrbitLanes(benchmark::State& st, tribo::study::OrbitSolver solver) {
  const long lanes = st.range(0);
  const auto scene =
      tribo::io::loadSceneFromString(tribo::test::beltLanes(static_cast<int>(lanes)), "lanes.yaml");
  tribo::study::OrbitSpec spec;
  spec.solver = solver;
  tribo::study::OrbitResult r;
  const double each = timed(st, [&] { r = tribo::study::findPeriodicOrbit(scene, spec); });
  st.counters["unknowns"] = static_cast<double>(r.start.size());
  st.counters["flows"] = static_cast<double>(r.flows);
  st.counters["krylov_products"] = static_cast<double>(r.krylov_products);
  st.counters["newton_iterations"] = r.iterations;
  if (solver == tribo::study::OrbitSolver::kDense) {
    denseSeconds()[lanes] = each;
  } else if (denseSeconds().count(lanes)) {
    st.counters["over_dense"] = each / denseSeconds()[lanes];
  }
}

}  // namespace

BENCHMARK_CAPTURE(BM_OrbitLanes, dense, tribo::study::OrbitSolver::kDense)
    ->Arg(4)
    ->Arg(10)
    ->Arg(25)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_OrbitLanes, krylov, tribo::study::OrbitSolver::kKrylov)
    ->Arg(4)
    ->Arg(10)
    ->Arg(25)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_Baseline_SettledRun)
    ->Name("BM_Baseline_SettledRun/belt")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orbit, belt_newton_only, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Orbit, belt, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_OrbitBranch, belt_newton_only, false, 0.1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_OrbitBranch, belt, true, 0.1)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(BM_OrbitBranch, belt_100, true, 0.03)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);
