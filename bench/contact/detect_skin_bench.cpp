// The skin of the detector's cached pair list (CollisionOptions::broadphase_skin, a Verlet
// list: contact/collision_detector.hpp), measured on real trajectories: a scene runs in a
// Simulator (its own detector at the default skin), and after each step a second detector
// with the skin under test detects on the same geometry poses; only that call is timed
// (manual time). Skin 0 is the baseline: the grid on the tight boxes every call, as before
// the list. Scenes: the 200-sphere pile falling into its box (scenes/sphere_pile_stiff.yaml,
// its first 2 s), the 400 resting boxes (scenes/box_grid20.yaml, 1 s) and a chute of
// 40 x 40 x 5 spheres flowing down a 26 degree slope (bench/peers' chute, smaller; 0.3 s).
// Counters: contact points per call, list builds per call.
// Names: BM_DetectSkin/<scene>/skin:<skin x 100>.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include "chute_scene.hpp"
#include "contact/collision_detector.hpp"
#include "core/automatic_contacts.hpp"
#include "core/model.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

const std::string kScenes = std::string(TRIBO_SOURCE_DIR) + "/scenes/";

// The model's automatic contact rule (core/automatic_contacts.hpp), as the engine asks it.
class Rule : public tribo::contact::PairRule {
 public:
  explicit Rule(std::shared_ptr<const tribo::Model> model) : model_(std::move(model)) {}
  int pairId(int g, int h) const override { return tribo::automaticPairId(*model_, g, h); }
  std::pair<int, int> geometries(int id) const override {
    return tribo::automaticGeometries(*model_, id);
  }

 private:
  std::shared_ptr<const tribo::Model> model_;
};

const tribo::io::Scene& scene(int which) {
  static std::unique_ptr<tribo::io::Scene> cache[3];
  auto& slot = cache[which];
  if (!slot)
    slot = std::make_unique<tribo::io::Scene>(
        which == 0   ? tribo::io::loadScene(kScenes + "sphere_pile_stiff.yaml")
        : which == 1 ? tribo::io::loadScene(kScenes + "box_grid20.yaml")
                     : tribo::io::loadSceneFromString(tribo::bench::chuteYaml(40, 40, 5, 0.3),
                                                      "chute.yaml", {}, {}, {}));
  return *slot;
}

void BM_DetectSkin(benchmark::State& st, int which) {
  const tribo::io::Scene& s = scene(which);
  tribo::contact::CollisionOptions options = s.model->options.collision;
  options.broadphase_skin = static_cast<double>(st.range(0)) / 100.0;
  std::vector<tribo::contact::Shape> shapes;
  for (const auto& g : s.model->geometries) shapes.push_back(g.shape);
  tribo::contact::CollisionDetector detector(std::move(shapes), std::make_unique<Rule>(s.model),
                                             options);
  tribo::Simulator sim(s.model);
  std::vector<tribo::contact::ContactPoint> out;
  double points = 0.0;
  for (auto _ : st) {
    if (!sim.step().ok) {
      st.SkipWithError("diverged");
      return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    detector.detect(sim.current().geometry_poses, out);
    st.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    points += static_cast<double>(out.size());
  }
  const auto calls = static_cast<double>(st.iterations());
  st.counters["points"] = points / calls;
  st.counters["builds_per_call"] = static_cast<double>(detector.skinListBuilds()) / calls;
}

void skins(benchmark::internal::Benchmark* b) {
  b->ArgName("skin");
  for (int s : {0, 2, 5, 10, 20, 40}) b->Arg(s);
}

}  // namespace

BENCHMARK_CAPTURE(BM_DetectSkin, sphere_pile, 0)
    ->Name("BM_DetectSkin/sphere_pile")
    ->Apply(skins)
    ->Iterations(2000)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DetectSkin, box_grid20, 1)
    ->Name("BM_DetectSkin/box_grid20")
    ->Apply(skins)
    ->Iterations(1000)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DetectSkin, chute8000, 2)
    ->Name("BM_DetectSkin/chute8000")
    ->Apply(skins)
    ->Iterations(300)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);
