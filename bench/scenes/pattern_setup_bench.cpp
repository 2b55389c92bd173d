// Set-up cost of a scene that generates its bodies (`bodies[].pattern`, docs/scene-format.md):
// a field of N boxes on a half-space from one pattern entry, N = 1 250 to 20 000.
// BM_PatternScene/N is io::loadSceneFromString as `tribo run` pays it (parse, expand the
// pattern, build the model with its automatic contacts, the a-priori stable step); its
// baseline in the same process, BM_PatternYaml/N, parses the same text with yaml-cpp alone
// (io::SceneDocument), the part no scene reader can skip. Both report the time per body and
// the fit of time against N. Issue target: 20 000 bodies set up in under 50 ms
// (docs/performance.md). Part of tribo_bench_scenes:
//   build/bench/scenes/tribo_bench_scenes --benchmark_filter=Pattern
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "io/scene_loader.hpp"

namespace {

std::string fieldOf(int n) {
  const int nx = static_cast<int>(std::lround(std::sqrt(2.0 * n))), ny = n / nx;
  return "simulation: {duration: 1, time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}\n"
         "friction_laws:\n  coulomb: {mu: 0.4, regularization: tanh, v_eps: 0.01}\n"
         "materials:\n  - {name: m, normal: {law: linear, stiffness: 1.0e5, damping: 100}, "
         "friction: coulomb, default: true}\n"
         "bodies:\n"
         "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
         "  - {name: box, mass: 8, position: [0, 0, 0.1], geometry: [{name: s, shape: box, "
         "size: [0.2, 0.2, 0.2]}], pattern: {grid: [" +
         std::to_string(nx) + ", " + std::to_string(ny) +
         ", 1], spacing: [0.25, 0.25, 0], jitter: 0.01, seed: 3}}\n";
}

void perBody(benchmark::State& st, int n) {
  st.counters["us_per_body"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * n * 1e-6,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.SetComplexityN(n);
}

void BM_PatternYaml(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const std::string text = fieldOf(n);
  for (auto _ : st) {
    const tribo::io::SceneDocument document(text, "field.yaml");
    benchmark::DoNotOptimize(&document);
  }
  perBody(st, n);
}

void BM_PatternScene(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const std::string text = fieldOf(n);
  for (auto _ : st)
    benchmark::DoNotOptimize(
        tribo::io::loadSceneFromString(text, "field.yaml").model->bodies.size());
  perBody(st, n);
}

#define TRIBO_PATTERN_SIZES \
  Arg(1250)->Arg(5000)->Arg(20000)->Unit(benchmark::kMillisecond)->Complexity()
BENCHMARK(BM_PatternYaml)->TRIBO_PATTERN_SIZES;
BENCHMARK(BM_PatternScene)->TRIBO_PATTERN_SIZES;

}  // namespace
