// Cost of the stability analysis (tribo modes, study/modes.hpp) and the baseline it is read
// against in the same process: the belt's in-plane pair from the hand-reduced equation
//   m x'' + N mu'(v_b) x' + k x = 0   (the 2 x 2 companion matrix and its eigenvalues),
// the cheapest possible answer. Names: BM_ModesLinearize/<scene> (basis, steps, central
// differences with their check, eigenvalues; the steady state given), BM_ModesAnalysis/<scene>
// (steady state included, as analyzeModes), BM_ModesLoad/<scene> (reading the scene: what a
// point of `tribo sweep --analysis modes` adds); BM_Baseline_BeltClosedForm.
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <string>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/modes.hpp"

namespace {

std::string scenePath(const std::string& name) {
  return std::string(TRIBO_SOURCE_DIR) + "/scenes/" + name + ".yaml";
}

void BM_ModesLinearize(benchmark::State& st, const std::string& name) {
  const auto scene = tribo::io::loadScene(scenePath(name));
  tribo::Dynamics dynamics(scene.model);
  const tribo::State steady = tribo::study::findSteadyState(dynamics).state;
  for (auto _ : st) {
    const tribo::study::ReducedCoordinates coords(*scene.model, steady);
    const auto steps = tribo::study::chooseSteps(dynamics, steady);
    const auto lin = tribo::study::linearize(dynamics, coords, steady, steps, true, 1e-4);
    const auto modes = tribo::study::modesOf(tribo::study::firstOrderMatrix(lin), coords, 1e-6);
    benchmark::DoNotOptimize(modes.front().growth_rate);
  }
}

void BM_ModesAnalysis(benchmark::State& st, const std::string& name) {
  const auto scene = tribo::io::loadScene(scenePath(name));
  for (auto _ : st) {
    const auto r = tribo::study::analyzeModes(scene);
    benchmark::DoNotOptimize(r.leading().growth_rate);
  }
}

void BM_ModesLoad(benchmark::State& st, const std::string& name) {
  for (auto _ : st) {
    const auto scene = tribo::io::loadScene(scenePath(name));
    benchmark::DoNotOptimize(scene.model.get());
  }
}

void BM_Baseline_BeltClosedForm(benchmark::State& st) {
  const auto law = tribo::friction::makeFrictionLaw(
      {"roh_yoo",
       {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3}},
       {}});
  const double m = 10, k = 300, n = m * 9.81;
  for (auto _ : st) {
    Eigen::Matrix2d a;
    a << 0, 1, -k / m, -n * law->slope(1.5) / m;
    const Eigen::Vector2cd ev = a.eigenvalues();
    benchmark::DoNotOptimize(ev(0).real());
  }
}

}  // namespace

BENCHMARK_CAPTURE(BM_ModesLinearize, belt, std::string("belt"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesAnalysis, belt, std::string("belt"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesLoad, belt, std::string("belt"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesLinearize, mode_coupling, std::string("mode_coupling"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesAnalysis, mode_coupling, std::string("mode_coupling"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Baseline_BeltClosedForm)->Unit(benchmark::kMicrosecond);
