// Cost of the stability analysis (tribo modes, study/modes.hpp) and the baseline it is read
// against in the same process: the belt's in-plane pair from the hand-reduced equation
//   m x'' + N mu'(v_b) x' + k x = 0   (the 2 x 2 companion matrix and its eigenvalues),
// the cheapest possible answer. Names: BM_ModesLinearize/<scene> (basis, steps, central
// differences with their check, eigenvalues; the steady state given), BM_ModesAnalysis/<scene>
// (steady state included, as analyzeModes), BM_ModesLoad/<scene> (reading the scene file:
// parsing its YAML and building the model), BM_ModesBuild/<scene> (building the model from
// the YAML parsed once, io::SceneDocument: what a point of `tribo sweep --analysis modes`
// adds), BM_SweepModesPoint/{reparsed,parsed_once} (a whole sweep point of the belt, with and
// without parsing the text again), BM_ModesChain/<law>/<n> (a chain of n boxes pressed on a
// belt, generated here); BM_Baseline_BeltClosedForm.
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <fstream>
#include <sstream>
#include <string>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/modes.hpp"
#include "study/sweep/sweep_point.hpp"

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

// A chain of n boxes (1 kg, 0.2 x 0.2 x 0.1 m, each on a planar joint) pressed on a belt by
// their weight, joined in a row by springs of 300 N/m and tied to a wall at the first: n
// coupled belt oscillators, 2n coordinates (x and z per box), 4n contact points.
std::string chainScene(int n, const std::string& law) {
  std::ostringstream y;
  y << "simulation: {duration: 1, time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}\n"
       "bodies:\n  - {name: belt, kind: kinematic, surface_velocity: [1.5, 0, 0],\n"
       "     geometry: [{name: surface, shape: halfspace}]}\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: b" << i << ", mass: 1, position: [" << 0.3 * i << ", 0, 0.0499],"
      << " geometry: [{name: g" << i << ", shape: box, size: [0.2, 0.2, 0.1]}]}\n";
  y << "joints:\n";
  for (int i = 0; i < n; ++i)
    y << "  - {name: j" << i << ", type: planar_translation, parent: world, child: b" << i
      << ", anchor: [" << 0.3 * i << ", 0, 0.0499], axis: [0, 1, 0]}\n";
  y << "springs:\n  - {name: s0, a: world, point_a: [-0.3, 0, 0.0499], b: b0,"
       " point_b: [0, 0, 0.0499], stiffness: 300}\n";
  for (int i = 1; i < n; ++i)
    y << "  - {name: s" << i << ", a: b" << i - 1 << ", point_a: [" << 0.3 * (i - 1)
      << ", 0, 0.0499], b: b" << i << ", point_b: [" << 0.3 * i
      << ", 0, 0.0499], stiffness: 300}\n";
  y << "friction_laws:\n  roh_yoo: {mu_s: 0.35, mu_k: 0.3, v_s: 0.01, a: 1.5, beta: 0.3333}\n"
       "  lugre: {sigma0: 1.0e4, sigma1: 30, sigma2: 0, mu_c: 0.3, mu_s: 0.35, v_s: 0.01}\n"
       "materials:\n  - {name: belt_box, normal: {law: linear, stiffness: 2.5e5, damping: 1.5e3},"
       " friction: "
    << law << "}\ncontacts:\n";
  for (int i = 0; i < n; ++i) y << "  - {a: surface, b: g" << i << ", material: belt_box}\n";
  return y.str();
}

// tribo modes on the chain (steady state included); the range argument is n, the law
// roh_yoo (memoryless: 4n coordinates in A) or lugre (plus 12 bristle states per box).
void BM_ModesChain(benchmark::State& st, const std::string& law) {
  const int n = static_cast<int>(st.range(0));
  const auto scene = tribo::io::loadSceneFromString(chainScene(n, law), "chain.yaml");
  for (auto _ : st) {
    const auto r = tribo::study::analyzeModes(scene);
    benchmark::DoNotOptimize(r.leading().growth_rate);
  }
  st.counters["states"] = static_cast<double>(4 * n + (law == "lugre" ? 12 * n : 0));
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
BENCHMARK(BM_Baseline_BeltClosedForm)->Unit(benchmark::kMicrosecond);
