// The world inverse inertia of every body, as Dynamics::updatePoses forms it once an
// evaluation: the rotation from the orientation, then R I^-1 R^T, over 400 bodies (the
// 400-box grid) with Eigen's product `r * t * r.transpose()` (the code before) and with
// rotatedTensor (core/math.hpp: the same bits on components). Each iteration runs both over
// the same bodies, alternately, so a change of the machine's load hits both; counters: each
// one's time a body [ns] and their ratio (speedup, > 1: rotatedTensor faster).
// Names: BM_RotatedTensor.
#include <benchmark/benchmark.h>

#include <chrono>
#include <random>
#include <vector>

#include "core/math.hpp"

namespace {

void BM_RotatedTensor(benchmark::State& st) {
  constexpr int kBodies = 400;
  std::vector<tribo::Quat> orientation(kBodies);
  std::vector<tribo::Mat3> inverse(kBodies), rotation(kBodies), world(kBodies);
  std::mt19937 rng(400);
  std::normal_distribution<double> g;
  for (int b = 0; b < kBodies; ++b) {
    orientation[b] = tribo::Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
    inverse[b] = tribo::Vec3(1.0 / 0.053, 1.0 / 0.053, 1.0 / 0.053).asDiagonal();  // 8 kg box
  }
  double seconds[2] = {0, 0};
  long turns = 0;
  for (auto _ : st) {
    for (int k = 0; k < 2; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      for (int b = 0; b < kBodies; ++b) {
        const tribo::Mat3 r = orientation[b].toRotationMatrix();
        rotation[b] = r;
        world[b] = k == 0 ? tribo::Mat3(r * inverse[b] * r.transpose())
                          : tribo::rotatedTensor(r, inverse[b]);
      }
      benchmark::DoNotOptimize(world.data());
      benchmark::ClobberMemory();
      seconds[k] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    ++turns;
  }
  const double bodies = static_cast<double>(turns) * kBodies;
  st.counters["eigen_ns_per_body"] = 1e9 * seconds[0] / bodies;
  st.counters["components_ns_per_body"] = 1e9 * seconds[1] / bodies;
  st.counters["speedup"] = seconds[0] / seconds[1];
}

}  // namespace

BENCHMARK(BM_RotatedTensor)->Unit(benchmark::kMicrosecond);
