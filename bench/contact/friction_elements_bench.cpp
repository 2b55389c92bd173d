// What direction-dependent friction and rolling and spinning resistance cost per contact point
// (contact/anisotropy.hpp, contact/rolling_resistance.hpp): the same scene stepped with its
// material as written (the baseline, in the same process), with an anisotropy of ratios 1
// (the wrapper's work on every path, the physics unchanged), and with rolling and spinning
// resistance added (an angular anchor per point, kept across steps); for scale, with
// elastic_stick in place of its tanh law (a linear anchor per point, the same bookkeeping
// the angular anchors use). Scenes: the 10 x 10 box
// grid at rest (400 corner points) and the 200-sphere pile falling into its box.
// Counters: steps and contact points per second; the ratio to the baseline is read between
// the rows (docs/performance.md).
// Names: BM_FrictionElements/<scene>_<variant>.
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

const std::string kScenes = std::string(TRIBO_SOURCE_DIR) + "/scenes/";

enum class Variant { kPlain, kAnisotropic, kResisting, kStick };

// The scene's text with its default material given the variant's element.
std::string sceneText(const std::string& file, const std::string& material_line, Variant v) {
  std::ifstream in(kScenes + file);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::size_t at = yaml.find(material_line);
  if (at == std::string::npos) throw std::runtime_error(file + " has no '" + material_line + "'");
  const std::string indent = "    ";
  std::string element;
  if (v == Variant::kAnisotropic)
    element = indent + "anisotropy: {frame: a, axis: [1, 0, 0], ratio: [1, 1]}\n";
  if (v == Variant::kResisting)
    element = indent + "rolling: {length: 0.001, stiffness: 5, damping: 0.01}\n" + indent +
              "spinning: {mu: 0.3, radius: 0.005, stiffness: 5, damping: 0.01}\n";
  yaml.insert(at + material_line.size(), element);
  if (v == Variant::kStick) {
    const std::size_t laws = yaml.find("friction_laws:\n"), law = yaml.find("friction: coulomb\n");
    if (laws == std::string::npos || law == std::string::npos)
      throw std::runtime_error(file + " has no coulomb material");
    yaml.replace(law, 17, "friction: stick\n");
    yaml.insert(laws + 15,
                "  stick: {law: elastic_stick, mu_s: 0.5, mu_k: 0.5, stiffness: 1.0e4, "
                "damping: 10}\n");
  }
  return yaml;
}

void BM_FrictionElements(benchmark::State& st, const std::string& file,
                         const std::string& material_line, Variant variant, double seconds) {
  const auto scene =
      tribo::io::loadSceneFromString(sceneText(file, material_line, variant), kScenes + file);
  const long steps = std::lround(seconds / scene.model->options.time_step);
  double points = 0;
  for (auto _ : st) {
    tribo::Simulator sim(scene.model);
    for (long i = 0; i < steps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
      points += static_cast<double>(sim.current().contacts.size());
    }
  }
  const double total_steps = static_cast<double>(steps) * static_cast<double>(st.iterations());
  st.counters["steps_per_s"] = benchmark::Counter(total_steps, benchmark::Counter::kIsRate);
  st.counters["points_per_s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  st.counters["points_per_step"] = points / total_steps;
}

const std::string kGridMaterial = "    friction: coulomb\n    default: true\n";

}  // namespace

BENCHMARK_CAPTURE(BM_FrictionElements, box_grid10_plain, std::string("box_grid10.yaml"),
                  kGridMaterial, Variant::kPlain, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, box_grid10_anisotropic, std::string("box_grid10.yaml"),
                  kGridMaterial, Variant::kAnisotropic, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, box_grid10_resisting, std::string("box_grid10.yaml"),
                  kGridMaterial, Variant::kResisting, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, box_grid10_stick, std::string("box_grid10.yaml"),
                  kGridMaterial, Variant::kStick, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, sphere_pile_plain, std::string("sphere_pile.yaml"),
                  kGridMaterial, Variant::kPlain, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, sphere_pile_anisotropic, std::string("sphere_pile.yaml"),
                  kGridMaterial, Variant::kAnisotropic, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, sphere_pile_resisting, std::string("sphere_pile.yaml"),
                  kGridMaterial, Variant::kResisting, 0.5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrictionElements, sphere_pile_stick, std::string("sphere_pile.yaml"),
                  kGridMaterial, Variant::kStick, 0.5)
    ->Unit(benchmark::kMillisecond);
