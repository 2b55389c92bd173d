// Contact throughput: resting box grids (10 x 10, 20 x 20, 0.2 m boxes, 1 ms steps) and a
// pile of 200 spheres falling into a box, through the whole engine (Simulator: collision,
// contact forces, integration, checks). Counters: contact points processed per second
// (points per evaluation times evaluations), steps per second, the share of wall time spent
// inside FCL's narrowphase (measured on a separate Dynamics; 0 where every pair has a closed
// form), and for the grids the resting penetration and horizontal drift after the run.
// Stage profile (core/stage_profile.hpp): the belt and the 20 x 20 grid with profiling on,
// each stage's share of the step's wall time and the step in microseconds; the same run
// with profiling off is its baseline (what the clock reads cost).
// Baselines in the same process: FCL's own collide() on a box/half-space and a box/box pair
// (points per second of FCL alone), and the closed-form box/half-space manifold.
// Names: BM_Contact/<scene>, BM_Baseline_<What>.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <string>

#include "contact/collision_detector.hpp"
#include "core/dynamics.hpp"
#include "core/simulator.hpp"
#include "core/stage_profile.hpp"
#include "io/scene_loader.hpp"

namespace {

const std::string kScenes = std::string(TRIBO_SOURCE_DIR) + "/scenes/";

void BM_Contact(benchmark::State& st, const std::string& file, double seconds) {
  const auto scene = tribo::io::loadScene(kScenes + file);
  const double dt = scene.model->options.time_step;
  const long steps = std::lround(seconds / dt);
  double points = 0, evaluations = 0, penetration = 0, drift = 0;
  for (auto _ : st) {
    tribo::Simulator sim(scene.model);
    const tribo::State start = sim.state();
    for (long i = 0; i < steps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
      points += static_cast<double>(sim.current().contacts.size());
    }
    evaluations += static_cast<double>(steps);
    penetration = sim.current().max_penetration;
    drift = 0;
    for (std::size_t b = 0; b < start.bodies.size(); ++b)
      drift = std::max(
          drift, (sim.state().bodies[b].position - start.bodies[b].position).head<2>().norm());
  }
  // FCL's share: the same run's evaluations on a Dynamics with profiling switched on.
  tribo::Dynamics dynamics(scene.model);
  dynamics.setProfiling(true);
  tribo::State s = dynamics.initialState();
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 200; ++i) dynamics.evaluate(s);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  st.counters["points_per_s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  st.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
  st.counters["points_per_step"] = points / evaluations;
  st.counters["fcl_share"] = dynamics.profile().fcl / total;
  st.counters["penetration_um"] = penetration * 1e6;
  st.counters["drift_um"] = drift * 1e6;
}

// A scene's run with profiling on (or off: the baseline): per stage, its share of the step's
// wall time; the step [us]; the stages' sum as a share (the rest is the integrator's own
// work, the checks and the energy guard).
void BM_StageProfile(benchmark::State& st, const std::string& file, double seconds,
                     bool profiling) {
  const auto scene = tribo::io::loadScene(kScenes + file);
  const long steps = std::lround(seconds / scene.model->options.time_step);
  tribo::StageProfile sum;
  for (auto _ : st) {
    tribo::Simulator sim(scene.model);
    sim.setProfiling(profiling);
    for (long i = 0; i < steps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
    }
    const tribo::StageProfile& p = sim.stats().profile;
    for (std::size_t k = 0; k < tribo::kStageCount; ++k) sum.seconds[k] += p.seconds[k];
    sum.step += p.step;
    sum.fcl += p.fcl;
    sum.evaluations += p.evaluations;
  }
  st.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
  if (!profiling) return;
  for (std::size_t k = 0; k < tribo::kStageCount; ++k)
    st.counters[std::string(tribo::stageName(static_cast<tribo::Stage>(k)))] =
        sum.seconds[k] / sum.step;
  st.counters["fcl"] = sum.fcl / sum.step;
  st.counters["stages"] = sum.total() / sum.step;
  st.counters["step_us"] =
      1e6 * sum.step / (static_cast<double>(steps) * static_cast<double>(st.iterations()));
  st.counters["evals_per_step"] =
      static_cast<double>(sum.evaluations) /
      (static_cast<double>(steps) * static_cast<double>(st.iterations()));
}

// One pair's FCL (or closed-form) detection over and over: points per second.
void detectPair(benchmark::State& st, tribo::contact::Shape a, tribo::contact::Shape b,
                const Eigen::Isometry3d& pose_b, bool closed_form) {
  tribo::contact::CollisionOptions options;
  options.closed_form_box_halfspace = options.closed_form_primitives = closed_form;
  tribo::contact::CollisionDetector detector({std::move(a), std::move(b)}, {{0, 1}}, options);
  const std::vector<Eigen::Isometry3d> poses{Eigen::Isometry3d::Identity(), pose_b};
  std::vector<tribo::contact::ContactPoint> out;
  double points = 0;
  for (auto _ : st) {
    detector.detect(poses, out);
    points += static_cast<double>(out.size());
    benchmark::DoNotOptimize(out.data());
  }
  st.counters["points_per_s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  st.counters["points_per_call"] = points / static_cast<double>(st.iterations());
}

Eigen::Isometry3d at(double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(1e-4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.01, 0.02, z);
  return t;
}

void BM_Baseline_FclBoxHalfSpace(benchmark::State& st) {
  detectPair(st, tribo::contact::Shape::halfSpace(), tribo::contact::Shape::box({0.1, 0.1, 0.1}),
             at(0.1 - 3e-5), false);
}
void BM_Baseline_ClosedFormBoxHalfSpace(benchmark::State& st) {
  detectPair(st, tribo::contact::Shape::halfSpace(), tribo::contact::Shape::box({0.1, 0.1, 0.1}),
             at(0.1 - 3e-5), true);
}
void BM_Baseline_FclBoxBox(benchmark::State& st) {
  detectPair(st, tribo::contact::Shape::box({0.1, 0.1, 0.1}),
             tribo::contact::Shape::box({0.1, 0.1, 0.1}), at(0.2 - 3e-5), false);
}

BENCHMARK(BM_Baseline_FclBoxHalfSpace);
BENCHMARK(BM_Baseline_ClosedFormBoxHalfSpace);
BENCHMARK(BM_Baseline_FclBoxBox);
BENCHMARK_CAPTURE(BM_Contact, box_grid10, std::string("box_grid10.yaml"), 1.0)
    ->Name("BM_Contact/box_grid10")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Contact, box_grid20, std::string("box_grid20.yaml"), 1.0)
    ->Name("BM_Contact/box_grid20")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Contact, sphere_pile, std::string("sphere_pile.yaml"), 1.0)
    ->Name("BM_Contact/sphere_pile")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StageProfile, belt, std::string("belt.yaml"), 10.0, true)
    ->Name("BM_StageProfile/belt")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StageProfile, belt_off, std::string("belt.yaml"), 10.0, false)
    ->Name("BM_StageProfile/belt/off")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StageProfile, box_grid20, std::string("box_grid20.yaml"), 0.2, true)
    ->Name("BM_StageProfile/box_grid20")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StageProfile, box_grid20_off, std::string("box_grid20.yaml"), 0.2, false)
    ->Name("BM_StageProfile/box_grid20/off")
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
