// Throughput of mu(v) for every law through the virtual interface, over 1024 slip speeds
// spread over [-3, 3] m/s, against an inline, non-virtual mu * tanh(v / v_eps) baseline in
// the same process; and of the shared tangential-force helper.
//
//   BM_FrictionCoefficient/<law>                          one law from the factory
//   BM_FrictionCoefficient/baseline_inline_coulomb_tanh   the baseline
//   BM_TangentialForce/roh_yoo                            tangentialForce per 3D slip
//
// items_per_second counts coefficient (or force) evaluations.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <string>

#include "friction/friction_law.hpp"
#include "support/table1_laws.hpp"

namespace tribo::friction {
namespace {

constexpr int kSpeeds = 1024;

const std::array<double, kSpeeds>& slipSpeeds() {
  static const std::array<double, kSpeeds> speeds = [] {
    std::array<double, kSpeeds> v{};
    for (int i = 0; i < kSpeeds; ++i) v[i] = -3.0 + 6.0 * i / (kSpeeds - 1);
    return v;
  }();
  return speeds;
}

using tribo::test::table1;

void BM_FrictionCoefficient(benchmark::State& state, const std::string& name) {
  const auto law = makeFrictionLaw(table1(name));
  const auto& speeds = slipSpeeds();
  for (auto _ : state) {
    for (const double v : speeds) benchmark::DoNotOptimize(law->coefficient(v));
  }
  state.SetItemsProcessed(state.iterations() * kSpeeds);
}

inline double inlineCoulombTanh(double v, double mu, double inv_v_eps) {
  return mu * std::tanh(v * inv_v_eps);
}

void BM_BaselineInlineCoulombTanh(benchmark::State& state) {
  const double mu = 0.3;
  const double inv_v_eps = 1.0 / 1e-4;
  const auto& speeds = slipSpeeds();
  for (auto _ : state) {
    for (const double v : speeds) benchmark::DoNotOptimize(inlineCoulombTanh(v, mu, inv_v_eps));
  }
  state.SetItemsProcessed(state.iterations() * kSpeeds);
}

void BM_TangentialForce(benchmark::State& state, const std::string& name) {
  const auto law = makeFrictionLaw(table1(name));
  const auto& speeds = slipSpeeds();
  std::array<Eigen::Vector3d, kSpeeds> slips;
  for (int i = 0; i < kSpeeds; ++i) {
    // Slip directions turning in the tangent plane, with a small out-of-plane part.
    const double angle = 0.37 * i;
    slips[i] = speeds[i] * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.01).normalized();
  }
  const double fn = 98.1;
  for (auto _ : state) {
    for (const Eigen::Vector3d& slip : slips) {
      benchmark::DoNotOptimize(tangentialForce(*law, slip, fn));
    }
  }
  state.SetItemsProcessed(state.iterations() * kSpeeds);
}

const bool registered = [] {
  benchmark::RegisterBenchmark("BM_FrictionCoefficient/baseline_inline_coulomb_tanh",
                               BM_BaselineInlineCoulombTanh);
  for (const std::string& name : knownFrictionLaws()) {
    benchmark::RegisterBenchmark(("BM_FrictionCoefficient/" + name).c_str(), BM_FrictionCoefficient,
                                 name);
  }
  benchmark::RegisterBenchmark("BM_TangentialForce/roh_yoo", BM_TangentialForce,
                               std::string("roh_yoo"));
  return true;
}();

}  // namespace
}  // namespace tribo::friction

BENCHMARK_MAIN();
