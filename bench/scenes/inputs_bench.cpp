// What inputs cost a step (issue: loads, actuators and signals pay only where used): the belt
// scenes as shipped against the same scenes with inputs added, in the same process, read as
// ratios of steps per second:
//   BM_BeltInputs/0  scenes/belt.yaml as shipped (contact belt, constant surface speed)
//   BM_BeltInputs/1  + a ramped load on the box
//   BM_BeltInputs/2  + the surface speed a sum of sines (the belt_modulated experiment)
//   BM_JointBeltInputs/0  scenes/belt_joint_friction.yaml as shipped (no contact: the cheapest
//                         step, where any overhead shows most)
//   BM_JointBeltInputs/1  + a ramped load on the box and a position servo on its joint
// RK4 at 1 ms, 10 s simulated per iteration.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

std::string text(const std::string& file) {
  std::ifstream in(std::string(TRIBO_SOURCE_DIR) + "/scenes/" + file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

void runSteps(benchmark::State& st, const std::string& yaml) {
  const auto scene = tribo::io::loadSceneFromString(yaml, "inputs_bench.yaml", {"duration=10"});
  constexpr long kSteps = 10000;
  for (auto _ : st) {
    tribo::Simulator sim(scene.model);
    for (long i = 0; i < kSteps; ++i)
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
    benchmark::DoNotOptimize(sim.state().bodies.back().position.x());
  }
  st.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(kSteps) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
}

const std::string kLoad =
    "\nloads:\n  - {name: push, body: box, force: [{ramp: {rate: 0.5}}, 0, 0]}\n";

void BM_BeltInputs(benchmark::State& st) {
  std::string yaml = text("belt.yaml");
  if (st.range(0) >= 1) yaml += kLoad;
  if (st.range(0) >= 2)
    yaml = replaced(yaml, "surface_velocity: [$v_b, 0, 0]",
                    "surface_velocity: [{sines: [{offset: $v_b, amplitude: 0.2, frequency: 0.4}]}, "
                    "0, 0]");
  runSteps(st, yaml);
}
BENCHMARK(BM_BeltInputs)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_JointBeltInputs(benchmark::State& st) {
  std::string yaml = text("belt_joint_friction.yaml");
  if (st.range(0) >= 1)
    yaml += kLoad +
            "actuators:\n  - {name: servo, joint: box_on_belt, type: position, target: "
            "{ramp: {rate: 0.01}}, kp: 5, kd: 0.5}\n";
  runSteps(st, yaml);
}
BENCHMARK(BM_JointBeltInputs)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
