// The belt scene's RK4 step against a hand-written one-degree-of-freedom RK4 loop of the
// same physics, both run in the same process and in the same benchmark iteration:
//   m x'' = -k x - c x' + mu(v_b - x') m g       (Roh & Yoo 2007, Fig. 3, Table 1)
// with m, k, c, v_b and g read from the loaded scene and mu the scene's own friction-law
// object (the model's material), so both pay the same cost per law evaluation. The loop is
// the cheapest simulation of the scene; Tribo's step carries a full rigid body on a
// planar_translation joint with four penalty contact points (docs/belt-scene.md).
// Counters: us per step of each (thread CPU time, so time the thread spends preempted on a
// shared machine counts for neither; sums over the iterations), their ratio (and the ratio
// of the fastest iteration of each), and the largest difference
// of the box's x between the two trajectories over the run (whole run and first 5 s).
// Name: BM_BeltStepVsLoop/<step in us>, 60 simulated seconds per iteration.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace {

const std::string kBeltScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

// The scene's numbers for the hand-written loop.
struct OneDof {
  double m = 0.0, k = 0.0, c = 0.0, v_b = 0.0, g = 0.0;
  const tribo::friction::FrictionLaw* law = nullptr;
  double acceleration(double x, double v) const {
    return (-k * x - c * v + law->coefficient(v_b - v) * m * g) / m;
  }
};

OneDof oneDofOf(const tribo::Model& model) {
  OneDof p;
  for (const tribo::Body& b : model.bodies) {
    if (b.kind == tribo::BodyKind::kDynamic) p.m = b.mass;
    if (b.kind == tribo::BodyKind::kKinematic) p.v_b = b.surface_velocity.x();
  }
  p.k = model.springs.front().stiffness;
  p.c = model.springs.front().damping;
  p.g = -model.options.gravity.z();
  p.law = model.materials.front().friction.get();
  return p;
}

// n RK4 steps of h from (x, v); x after each step into xs.
void handLoop(const OneDof& p, double h, long n, std::vector<double>& xs) {
  double x = 0.0, v = 0.0;
  for (long i = 0; i < n; ++i) {
    const double a1 = p.acceleration(x, v);
    const double x2 = x + 0.5 * h * v, v2 = v + 0.5 * h * a1;
    const double a2 = p.acceleration(x2, v2);
    const double x3 = x + 0.5 * h * v2, v3 = v + 0.5 * h * a2;
    const double a3 = p.acceleration(x3, v3);
    const double x4 = x + h * v3, v4 = v + h * a3;
    const double a4 = p.acceleration(x4, v4);
    x += h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
    v += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    xs[static_cast<std::size_t>(i)] = x;
  }
}

double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_BeltStepVsLoop(benchmark::State& st) {
  constexpr double kDuration = 60.0;  // [s]
  const double dt = static_cast<double>(st.range(0)) * 1e-6;
  const auto scene = tribo::io::loadScene(
      kBeltScene, {"integrator=rk4", "dt=" + std::to_string(dt), "duration=60"});
  const OneDof p = oneDofOf(*scene.model);
  const long steps = std::lround(kDuration / dt);
  std::vector<double> hand(static_cast<std::size_t>(steps)), engine(hand.size());
  double hand_s = 0.0, engine_s = 0.0;
  double hand_min = std::numeric_limits<double>::infinity(), engine_min = hand_min;
  for (auto _ : st) {
    const double t0 = threadSeconds();
    handLoop(p, dt, steps, hand);
    const double t1 = threadSeconds();
    tribo::Simulator sim(scene.model);
    const double x0 = sim.state().bodies.back().position.x();
    for (long i = 0; i < steps; ++i) {
      if (!sim.step().ok) {
        st.SkipWithError("diverged");
        return;
      }
      engine[static_cast<std::size_t>(i)] = sim.state().bodies.back().position.x() - x0;
    }
    const double t2 = threadSeconds();
    benchmark::DoNotOptimize(hand.data());
    benchmark::DoNotOptimize(engine.data());
    const double a = t1 - t0, b = t2 - t1;
    hand_s += a;
    engine_s += b;
    hand_min = std::min(hand_min, a);
    engine_min = std::min(engine_min, b);
  }
  double max_dx = 0.0, max_dx_5s = 0.0;
  for (std::size_t i = 0; i < hand.size(); ++i) {
    const double d = std::abs(hand[i] - engine[i]);
    max_dx = std::max(max_dx, d);
    if (static_cast<double>(i + 1) * dt <= 5.0) max_dx_5s = std::max(max_dx_5s, d);
  }
  const double n = static_cast<double>(steps) * static_cast<double>(st.iterations());
  st.counters["loop_us_per_step"] = 1e6 * hand_s / n;
  st.counters["tribo_us_per_step"] = 1e6 * engine_s / n;
  st.counters["ratio"] = engine_s / hand_s;
  st.counters["ratio_of_fastest"] = engine_min / hand_min;
  st.counters["max_dx_m"] = max_dx;
  st.counters["max_dx_5s_m"] = max_dx_5s;
}

BENCHMARK(BM_BeltStepVsLoop)->Arg(8000)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
