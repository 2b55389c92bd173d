// Set-up cost of a URDF robot as `tribo run` and `tribo info` pay it, against the size of its
// tree: generated chains and wide trees of N links with a 5 cm collision box each
// (tests/support/urdf_tree_text.hpp), N = 1 000 to 16 000. BM_UrdfScene/<chain|wide>/N is
// io::sceneFromUrdf (read, assemble, the model built three times with automatic contacts
// between the links and the ground, the a-priori stable step); its baseline in the same
// process, BM_UrdfRead/<chain|wide>/N, reads the same file alone. Both report the time per
// link and Google Benchmark's fit of time against N (`_BigO`, `_RMS`): set-up linear in the
// links shows as the same us_per_link at every N (docs/urdf.md). Part of tribo_bench_core:
//   build/bench/core/tribo_bench_core --benchmark_filter=Urdf
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>

#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "support/urdf_tree_text.hpp"

namespace {

namespace fs = std::filesystem;

// The generated file for (shape, n), written once per process.
std::string robotFile(bool wide, int n) {
  const fs::path folder = fs::temp_directory_path() / "tribo_robot_setup_bench";
  fs::create_directories(folder);
  const fs::path file = folder / ((wide ? "wide" : "chain") + std::to_string(n) + ".urdf");
  if (!fs::exists(file)) {
    std::ofstream out(file);
    out << (wide ? tribo::test::urdfWide(n, true) : tribo::test::urdfChain(n, true));
  }
  return file.string();
}

void perLink(benchmark::State& st, int n) {
  st.counters["us_per_link"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * n * 1e-6,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.SetComplexityN(n);
}

void BM_UrdfRead(benchmark::State& st, bool wide) {
  const int n = static_cast<int>(st.range(0));
  const std::string file = robotFile(wide, n);
  for (auto _ : st) benchmark::DoNotOptimize(tribo::io::readUrdf(file).links.size());
  perLink(st, n);
}

void BM_UrdfScene(benchmark::State& st, bool wide) {
  const int n = static_cast<int>(st.range(0));
  const std::string file = robotFile(wide, n);
  for (auto _ : st)
    benchmark::DoNotOptimize(tribo::io::sceneFromUrdf(file, {}, {}).model->bodies.size());
  perLink(st, n);
}

#define TRIBO_SETUP_SIZES \
  RangeMultiplier(4)->Range(1000, 16000)->Unit(benchmark::kMillisecond)->Complexity()
BENCHMARK_CAPTURE(BM_UrdfRead, chain, false)->TRIBO_SETUP_SIZES;
BENCHMARK_CAPTURE(BM_UrdfScene, chain, false)->TRIBO_SETUP_SIZES;
BENCHMARK_CAPTURE(BM_UrdfRead, wide, true)->TRIBO_SETUP_SIZES;
BENCHMARK_CAPTURE(BM_UrdfScene, wide, true)->TRIBO_SETUP_SIZES;

}  // namespace
