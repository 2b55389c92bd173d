// Throughput of mu(v) for every law through the virtual interface, over 1024 slip speeds
// spread over [-3, 3] m/s, against an inline, non-virtual mu * tanh(v / v_eps) baseline in
// the same process; and of the shared tangential-force helper.
//
//   BM_FrictionCoefficient/<law>                          one law from the factory
//   BM_FrictionCoefficient/baseline_inline_coulomb_tanh   the baseline
//   BM_TangentialForce/roh_yoo                            tangentialForce per 3D slip
//   BM_DynamicForce/<law>                                 rate + force of a dynamic law per 3D
//                                                         slip (its state reused), the memoryless
//                                                         baseline being BM_TangentialForce/roh_yoo
//
//   BM_TangentialBatch/<law>                              the same slips through the batch
//                                                         (friction/tangential_batch.hpp, 256 a
//                                                         batch, as the engine's friction stage
//                                                         runs it) and point by point,
//                                                         alternately in one
//                                                         iteration: ns a point of each and
//                                                         batch_over_point_by_point (< 1: the
//                                                         batch is faster)
//
// items_per_second counts coefficient (or force) evaluations. The dynamic laws' cost ratio is
// time(BM_DynamicForce/<law>) / time(BM_TangentialForce/roh_yoo).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "friction/dynamic_law.hpp"
#include "friction/friction_law.hpp"
#include "friction/tangential_batch.hpp"
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

// Slips of the speeds above, directions turning in the tangent plane with a small out-of-plane
// part.
std::vector<Eigen::Vector3d> turningSlips() {
  const auto& speeds = slipSpeeds();
  std::vector<Eigen::Vector3d> slips(kSpeeds);
  for (int i = 0; i < kSpeeds; ++i) {
    const double angle = 0.37 * i;
    slips[i] = speeds[i] * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.01).normalized();
  }
  return slips;
}

void BM_TangentialForce(benchmark::State& state, const std::string& name) {
  const auto law = makeFrictionLaw(table1(name));
  const auto slips = turningSlips();
  const double fn = 98.1;
  for (auto _ : state) {
    for (const Eigen::Vector3d& slip : slips) {
      benchmark::DoNotOptimize(tangentialForce(*law, slip, fn));
    }
  }
  state.SetItemsProcessed(state.iterations() * kSpeeds);
}

void BM_TangentialBatch(benchmark::State& state, const std::string& name) {
  const auto law = makeFrictionLaw(table1(name));
  const auto slips = turningSlips();
  const double fn = 98.1;
  std::vector<Eigen::Vector3d> forces(slips.size());
  std::vector<double> mus(slips.size());
  TangentialBatch batch;
  double point_s = 0.0, batch_s = 0.0;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    auto t0 = Clock::now();
    for (std::size_t i = 0; i < slips.size(); ++i)
      forces[i] = tangentialForce(*law, slips[i], fn, &mus[i]);
    benchmark::DoNotOptimize(forces.data());
    auto t1 = Clock::now();
    for (std::size_t first = 0; first < slips.size(); first += TangentialBatch::kCapacity) {
      const std::size_t end = std::min(slips.size(), first + TangentialBatch::kCapacity);
      batch.clear();
      for (std::size_t i = first; i < end; ++i) batch.add(slips[i]);
      batch.evaluate(*law);
      for (std::size_t i = first; i < end; ++i)
        forces[i] = batch.force(i - first, slips[i], fn, &mus[i]);
    }
    benchmark::DoNotOptimize(forces.data());
    auto t2 = Clock::now();
    point_s += std::chrono::duration<double>(t1 - t0).count();
    batch_s += std::chrono::duration<double>(t2 - t1).count();
  }
  const double points = static_cast<double>(state.iterations()) * kSpeeds;
  state.counters["ns_point_by_point"] = 1e9 * point_s / points;
  state.counters["ns_batch"] = 1e9 * batch_s / points;
  state.counters["batch_over_point_by_point"] = batch_s / point_s;
}

// One evaluation as the engine does it per contact and stage: dz/dt at (z, s), then the force
// from z and dz/dt. The states are a settled one per slip (computed once, outside the timing).
void BM_DynamicForce(benchmark::State& state, const std::string& name) {
  const auto owner = makeFrictionLaw({name, {}, {}});
  const DynamicFrictionLaw& law = *owner->dynamic();
  const auto slips = turningSlips();
  const int n = law.stateSize();
  std::vector<double> z(static_cast<std::size_t>(n) * kSpeeds);
  std::vector<double> zdot(static_cast<std::size_t>(n));
  for (int i = 0; i < kSpeeds; ++i) {
    double* zi = z.data() + static_cast<std::size_t>(n) * i;
    law.initialState(zi);
    law.stableStep(zi, slips[i], 98.1, 0.37 * (i % 5));  // a mix of settled and fresh states
  }
  const double fn = 98.1;
  for (auto _ : state) {
    for (int i = 0; i < kSpeeds; ++i) {
      const double* zi = z.data() + static_cast<std::size_t>(n) * i;
      law.rate(zi, slips[i], fn, zdot.data());
      benchmark::DoNotOptimize(law.force(zi, zdot.data(), slips[i], fn, nullptr));
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
  for (const std::string& name : knownFrictionLaws()) {
    benchmark::RegisterBenchmark(("BM_TangentialBatch/" + name).c_str(), BM_TangentialBatch, name);
  }
  for (const std::string& name : knownDynamicFrictionLaws()) {
    benchmark::RegisterBenchmark(("BM_DynamicForce/" + name).c_str(), BM_DynamicForce, name);
  }
  return true;
}();

}  // namespace
}  // namespace tribo::friction

BENCHMARK_MAIN();
