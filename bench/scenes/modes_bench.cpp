// Cost of the stability analysis (tribo modes, study/modes/modes.hpp) and the baseline it is read
// against in the same process: the belt's in-plane pair from the hand-reduced equation
//   m x'' + N mu'(v_b) x' + k x = 0   (the 2 x 2 companion matrix and its eigenvalues),
// the cheapest possible answer. Names: BM_ModesLinearize/<scene> (basis, steps, central
// differences with their check, eigenvalues; the steady state given), BM_ModesAnalysis/<scene>
// (steady state included, as analyzeModes), BM_ModesLoad/<scene> (reading the scene file:
// parsing its YAML and building the model), BM_ModesBuild/<scene> (building the model from
// the YAML parsed once, io::SceneDocument: what a point of `tribo sweep --analysis modes`
// adds), BM_SweepModesPoint/{reparsed,parsed_once} (a whole sweep point of the belt, with and
// without parsing the text again), BM_ModesChain/<law>/<n> (a chain of n boxes pressed on a
// belt, tests/support/chain_on_belt.hpp), BM_ModesSolver/<dense|sparse>/<n> (the
// eigensolvers alone on the chain's A, linearized once per n: every mode by Eigen's dense
// solver against the 12 of largest growth rate by study/modes/sparse_modes.hpp's band scan; the
// sparse case reports dense_over_sparse, the ratio to the dense case's time measured just before in
// the same process); BM_Baseline_BeltClosedForm.
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "study/sweep/sweep_point.hpp"
#include "support/chain_on_belt.hpp"

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

std::string sceneText(const std::string& name) {
  std::ifstream in(scenePath(name));
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void BM_ModesBuild(benchmark::State& st, const std::string& name) {
  const tribo::io::SceneDocument document(sceneText(name), scenePath(name));
  for (auto _ : st) {
    const auto scene = document.load({"v_b=1.2"});
    benchmark::DoNotOptimize(scene.model.get());
  }
}

void BM_SweepModesPoint(benchmark::State& st, bool parsed_once) {
  tribo::study::SweepSetup setup;
  setup.scene_path = scenePath("belt");
  setup.scene_text = sceneText("belt");
  setup.analysis = tribo::study::SweepAnalysis::kModes;
  const tribo::io::SceneDocument document(setup.scene_text, setup.scene_path);
  const std::vector<std::string> point{"v_b=1.2", "mu_s=0.4"};
  for (auto _ : st) {
    const auto o = tribo::study::runPoint(setup, point, nullptr, parsed_once ? &document : nullptr);
    benchmark::DoNotOptimize(o.max_growth_rate);
  }
}

// tribo modes on the chain (steady state included); the range argument is n, the law
// roh_yoo (memoryless: 4n coordinates in A) or lugre (plus 12 bristle states per box).
void BM_ModesChain(benchmark::State& st, const std::string& law) {
  const int n = static_cast<int>(st.range(0));
  const auto scene = tribo::io::loadSceneFromString(tribo::test::chainOnBelt(n, law), "chain.yaml");
  for (auto _ : st) {
    const auto r = tribo::study::analyzeModes(scene);
    benchmark::DoNotOptimize(r.leading().growth_rate);
  }
  st.counters["states"] = static_cast<double>(4 * n + (law == "lugre" ? 12 * n : 0));
}

// The chain (damped springs of 0.5 N s/m between the boxes, so that a few in-phase modes
// grow rather than all of them at one tied rate): its steady state, coordinates and A as
// analyzeModes makes them, once per n.
struct ChainSystem {
  tribo::io::Scene scene;  // the coordinates refer to its model
  std::unique_ptr<tribo::study::ReducedCoordinates> coords;
  Eigen::MatrixXd a;
};

const ChainSystem& chainSystem(int n) {
  static std::map<int, ChainSystem> cache;
  auto found = cache.find(n);
  if (found != cache.end()) return found->second;
  ChainSystem system;
  system.scene =
      tribo::io::loadSceneFromString(tribo::test::chainOnBelt(n, "roh_yoo", 0.5), "chain.yaml");
  const tribo::io::Scene& scene = system.scene;
  tribo::Dynamics dynamics(scene.model);
  dynamics.setSteadyFriction(true);
  const tribo::State steady = tribo::study::findSteadyState(dynamics).state;
  dynamics.setSteadyFriction(false);
  system.coords = std::make_unique<tribo::study::ReducedCoordinates>(*scene.model, steady);
  const auto steps = tribo::study::chooseSteps(dynamics, steady);
  system.a = tribo::study::firstOrderMatrix(
      tribo::study::linearize(dynamics, *system.coords, steady, steps, true, 1e-4));
  return cache.emplace(n, std::move(system)).first->second;
}

// Seconds per dense solve by n, left by the dense case for the sparse one's ratio.
std::map<int, double>& denseSeconds() {
  static std::map<int, double> seconds;
  return seconds;
}

void BM_ModesSolver(benchmark::State& st, bool sparse) {
  const int n = static_cast<int>(st.range(0));
  const ChainSystem& system = chainSystem(n);
  double total = 0.0;
  for (auto _ : st) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<tribo::study::Mode> modes;
    try {
      modes = sparse ? tribo::study::sparseModesOf(system.a, *system.coords, 1e-6, {})
                     : tribo::study::modesOf(system.a, *system.coords, 1e-6);
    } catch (const std::exception& e) {
      st.SkipWithError(e.what());
      return;
    }
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(modes.front().growth_rate);
  }
  const double each = total / static_cast<double>(st.iterations());
  st.counters["states"] = static_cast<double>(system.a.rows());
  if (!sparse) denseSeconds()[n] = each;
  if (sparse && denseSeconds().count(n))
    st.counters["dense_over_sparse"] = denseSeconds()[n] / each;
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
BENCHMARK_CAPTURE(BM_ModesBuild, belt, std::string("belt"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SweepModesPoint, reparsed, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SweepModesPoint, parsed_once, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesLinearize, mode_coupling, std::string("mode_coupling"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesAnalysis, mode_coupling, std::string("mode_coupling"))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ModesChain, roh_yoo, std::string("roh_yoo"))
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModesChain, lugre, std::string("lugre"))
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Unit(benchmark::kMillisecond);
// Boxes 25..500: 100..2000 states. Each dense case runs before its sparse one.
BENCHMARK_CAPTURE(BM_ModesSolver, dense, false)
    ->Name("BM_ModesSolver/dense")
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModesSolver, sparse, true)
    ->Name("BM_ModesSolver/sparse")
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Baseline_BeltClosedForm)->Unit(benchmark::kMicrosecond);
