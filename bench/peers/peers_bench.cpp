// Tribo beside Bullet and MuJoCo on the same scenes, in one process (docs/performance.md):
// resting box grids of 10 x 10, 20 x 20, 40 x 40 and 70 x 70 boxes (0.2 m, 8 kg, 0.25 m pitch)
// on a half-space and on a box ground, a pile of 200 spheres falling into a box, and the belt
// (a block on a moving belt held by a spring, Coulomb friction). Tribo runs the scene files
// (scenes/box_grid10.yaml, box_grid20.yaml, box_grid20_box_ground.yaml,
// sphere_pile_stiff.yaml, belt.yaml) or the same scenes generated (peer_scene.hpp); the peers
// are built from the loaded Tribo model, so every engine starts from the same bodies at the
// same poses. Each engine keeps its own contact model and friction (peer_engines.hpp).
// Counters of one run (manual time: the steps only, building the world excluded):
//   us_per_step, us_per_sim_ms (wall time per simulated millisecond: the pile's Tribo step is
//   finer), points (contact points after the last step), points_per_s, penetration_um (deepest
//   contact after the last step), max_speed_mm_s (fastest body after the last step: ~0 at rest;
//   the pile's spheres may still roll), drift_um (largest horizontal displacement, grids),
//   belt_err_um (|x(T) - x_exact(T)|, belt), x_tribo (a peer's us_per_sim_ms over Tribo's on
//   the same scene in this process: > 1 means the peer is slower); cpu_us_per_sim_ms and
//   x_tribo_cpu the same from the process's CPU time (steadier on a loaded machine; a
//   threaded engine's CPU time is the sum over its threads).
// Names: BM_Peers/<scene>/<engine>. Runs once each (--benchmark_repetitions=N for more).
// Granular cases, Tribo beside LAMMPS (lammps_peer.hpp) when LAMMPS was found: the same pile
// (granular_pile) and a chute of 32 000 spheres (granular_chute, generated here), LAMMPS run
// first as the baseline, then Tribo on one thread, on two, and on `threads: auto` (the
// measured choice between one thread and every core: core/thread_choice.hpp). Counters:
// sphere_steps_per_s (moving spheres x steps / wall time), per_core_sphere_steps_per_s (the
// same over the threads stepped on), cpu_sphere_steps_per_s (over the process's CPU time),
// points (contact points after the last step), points_mean (mean over ten samples through
// the run), threads (on the mean over the steps), and for Tribo x_lammps, x_lammps_per_core,
// x_lammps_cpu (Tribo's figure over LAMMPS's in this process: > 1 means Tribo is faster);
// each run's label gives the engine's settings.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "box_grid_scene.hpp"
#include "chute_scene.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "lammps_peer.hpp"
#include "peer_engines.hpp"
#include "peer_scene.hpp"

namespace {

using tribo::peers::PeerRun;

const std::string kScenes = std::string(TRIBO_SOURCE_DIR) + "/scenes/";

struct Case {
  std::string name;
  std::string file;  // under scenes/, or empty: generated
  int grid = 0;      // generated box grid of grid x grid boxes
  bool box_ground = false;
  double seconds = 2.0;                     // simulated per run
  std::vector<std::string> overrides = {};  // the scene's parameters changed (--set)
  bool tribo_only = false;                  // a Tribo setting of a scene the peers ran already
  // MuJoCo's solver: Newton, its default, except for the pile, where the spheres touching
  // each other make Newton's Hessian dense (96 s of CPU for the 2 s against 7.5 s with CG).
  std::string mujoco_solver = "Newton";
};

// Scenes loaded once per process (the 70 x 70 grid takes seconds to parse).
const tribo::io::Scene& scene(const Case& c) {
  static std::map<std::string, std::unique_ptr<tribo::io::Scene>> cache;
  auto& slot = cache[c.name];
  if (!slot) {
    tribo::io::RunSettings settings;
    settings.duration = c.seconds;
    if (c.file == "belt.yaml") {
      // Coulomb friction (the peers' law) and semi-implicit Euler, as in every case here.
      settings.integrator = tribo::IntegratorType::kSemiImplicitEuler;
      slot = std::make_unique<tribo::io::Scene>(
          tribo::io::loadScene(kScenes + c.file, {"friction=coulomb"}, {}, settings));
    } else if (!c.file.empty()) {
      slot = std::make_unique<tribo::io::Scene>(
          tribo::io::loadScene(kScenes + c.file, c.overrides, {}, settings));
    } else {
      slot = std::make_unique<tribo::io::Scene>(tribo::io::loadSceneFromString(
          tribo::bench::boxGridYaml(c.grid, c.box_ground), c.name, c.overrides, {}, settings));
    }
  }
  return *slot;
}

double parameter(const tribo::io::Scene& s, const std::string& name) {
  for (const auto& [key, value] : s.parameters)
    if (key == name) return std::stod(value);
  throw std::invalid_argument("no parameter " + name);
}

tribo::peers::BeltSpec beltSpec(const tribo::io::Scene& s, double seconds) {
  tribo::peers::BeltSpec b;
  b.mass = parameter(s, "m");
  b.spring = parameter(s, "k");
  b.belt_speed = parameter(s, "v_b");
  b.mu = parameter(s, "mu_k");
  b.g = -s.model->options.gravity.z();
  b.dt = 1e-3;
  b.steps = std::lround(seconds / b.dt);
  return b;
}

// Tribo's wall time per simulated millisecond on each case, for the peers' ratios.
struct Baseline {
  double wall = 0.0, cpu = 0.0;  // [s] per simulated millisecond
};
std::map<std::string, Baseline>& triboPerSimMs() {
  static std::map<std::string, Baseline> m;
  return m;
}

void report(benchmark::State& st, const Case& c, const PeerRun& run, double dt, bool tribo) {
  st.SetIterationTime(run.seconds);
  const double per_step = run.seconds / static_cast<double>(run.steps);
  const double per_sim_ms = per_step / (dt * 1e3);
  st.counters["us_per_step"] = per_step * 1e6;
  st.counters["us_per_sim_ms"] = per_sim_ms * 1e6;
  const double cpu_per_sim_ms = run.cpu_seconds / static_cast<double>(run.steps) / (dt * 1e3);
  st.counters["cpu_us_per_sim_ms"] = cpu_per_sim_ms * 1e6;
  st.counters["points"] = run.points;
  st.counters["points_per_s"] = run.points / per_step;
  st.counters["penetration_um"] = run.penetration * 1e6;
  if (c.file == "belt.yaml")
    st.counters["belt_err_um"] = run.belt_error * 1e6;
  else
    st.counters["max_speed_mm_s"] = run.max_speed * 1e3;
  if (c.name.find("grid") != std::string::npos) st.counters["drift_um"] = run.drift * 1e6;
  if (tribo) {
    triboPerSimMs()[c.name] = {per_sim_ms, cpu_per_sim_ms};
  } else if (auto it = triboPerSimMs().find(c.name); it != triboPerSimMs().end()) {
    st.counters["x_tribo"] = per_sim_ms / it->second.wall;
    st.counters["x_tribo_cpu"] = cpu_per_sim_ms / it->second.cpu;
  }
}

PeerRun runTribo(const Case& c, const tribo::io::Scene& s) {
  tribo::Simulator sim(s.model);
  const double dt = s.model->options.time_step;
  PeerRun run;
  run.steps = std::lround(c.seconds / dt);
  const tribo::State start = sim.state();
  const tribo::peers::StepTimer timer;
  for (long i = 0; i < run.steps; ++i) {
    const tribo::StepStatus status = sim.step();
    if (!status.ok) {
      run.error = status.message;
      return run;
    }
  }
  timer.stop(run);
  const tribo::Workspace& w = sim.current();
  run.penetration = w.max_penetration;
  run.points = static_cast<double>(w.contacts.size());
  for (std::size_t b = 0; b < s.model->bodies.size(); ++b)
    if (s.model->bodies[b].kind == tribo::BodyKind::kDynamic)
      run.max_speed = std::max(run.max_speed, sim.state().bodies[b].velocity.norm());
  if (c.file == "belt.yaml") {
    const int box = 1;
    run.belt_error = std::abs(sim.state().bodies[box].position.x() -
                              beltSpec(s, c.seconds).exactX(sim.state().time));
  } else {
    for (std::size_t b = 0; b < start.bodies.size(); ++b)
      if (s.model->bodies[b].kind == tribo::BodyKind::kDynamic)
        run.drift =
            std::max(run.drift,
                     (sim.state().bodies[b].position - start.bodies[b].position).head<2>().norm());
  }
  return run;
}

enum class Engine { kTribo, kBullet, kMujoco };

void BM_Peers(benchmark::State& st, const Case& c, Engine engine) {
  const tribo::io::Scene& s = scene(c);
  for (auto _ : st) {
    PeerRun run;
    double dt = 1e-3;
    if (engine == Engine::kTribo) {
      run = runTribo(c, s);
      dt = s.model->options.time_step;
    } else if (c.file == "belt.yaml") {
      [[maybe_unused]] const tribo::peers::BeltSpec belt = beltSpec(s, c.seconds);
#ifdef TRIBO_PEER_BULLET
      if (engine == Engine::kBullet) run = tribo::peers::runBulletBelt(belt);
#endif
#ifdef TRIBO_PEER_MUJOCO
      if (engine == Engine::kMujoco) run = tribo::peers::runMujocoBelt(belt);
#endif
    } else {
      // Every peer at 1 ms, whatever step Tribo's scene needs.
      [[maybe_unused]] tribo::peers::PeerScene peer =
          tribo::peers::peerSceneFrom(*s.model, parameter(s, "mu"), std::lround(c.seconds / 1e-3));
      peer.dt = 1e-3;
#ifdef TRIBO_PEER_BULLET
      if (engine == Engine::kBullet) run = tribo::peers::runBullet(peer);
#endif
#ifdef TRIBO_PEER_MUJOCO
      if (engine == Engine::kMujoco) run = tribo::peers::runMujoco(peer, 3e9, c.mujoco_solver);
#endif
    }
    if (!run.error.empty()) {
      st.SkipWithError(run.error.c_str());
      return;
    }
    report(st, c, run, dt, engine == Engine::kTribo);
  }
}

const Case kCases[] = {
    {"box_grid10", "box_grid10.yaml", 10, false, 2.0},
    {"box_grid10_box_ground", "", 10, true, 2.0},
    {"box_grid20", "box_grid20.yaml", 20, false, 2.0},
    {"box_grid20_box_ground", "box_grid20_box_ground.yaml", 20, true, 2.0},
    // Stiffer corners (16.4 um static depth, MuJoCo's 17 um here) at the step they need.
    {"box_grid20_stiff", "box_grid20.yaml", 20, false, 2.0, {"k=1.2e6", "dt=5e-4"}, true},
    // The same depth at 1 ms: the damping halved (c 500 N s/m a corner, damping ratio 0.16
    // against the scene's 0.46) keeps the rocking mode's a-priori limit at 1.13 ms (`tribo run
    // scenes/box_grid20.yaml --set k=1.2e6 --set c=500` prints it; c 1000 needs 0.87 ms).
    {"box_grid20_stiff_1ms", "box_grid20.yaml", 20, false, 2.0, {"k=1.2e6", "c=500"}, true},
    {"box_grid20_stiff_rk4",
     "box_grid20.yaml",
     20,
     false,
     2.0,
     {"k=1.2e6", "integrator=rk4"},
     true},
    {"box_grid40", "", 40, false, 0.5},
    {"box_grid40_box_ground", "", 40, true, 0.5},
    {"box_grid70", "", 70, false, 0.2},
    {"box_grid70_box_ground", "", 70, true, 0.2},
    {"sphere_pile_stiff", "sphere_pile_stiff.yaml", 0, false, 2.0, {}, false, "CG"},
    {"sphere_pile_stiff_rk4", "sphere_pile_stiff.yaml", 0, false, 2.0, {"integrator=rk4"}, true},
    {"sphere_pile", "sphere_pile.yaml", 0, false, 2.0, {}, true},
    {"belt", "belt.yaml", 0, false, 2.0},
};

#ifdef TRIBO_PEER_LAMMPS
// Granular cases: every engine on the same spheres (r = 0.05 m, 0.5 kg), the same linear normal
// law (k = 1.5e5 N/m, c = 35 N s/m per point), mu = 0.4, 1 ms steps.
struct GranularCase {
  std::string name;
  std::string file;  // under scenes/, or empty: the 80 x 80 x 5 chute (bench/support)
  double seconds = 2.0;
};

const tribo::io::Scene& granularScene(const GranularCase& c, int threads) {
  static std::map<std::string, std::unique_ptr<tribo::io::Scene>> cache;
  auto& slot = cache[c.name + "/" + std::to_string(threads)];
  if (!slot) {
    tribo::io::RunSettings settings;
    settings.duration = c.seconds;
    settings.threads = threads;
    slot = std::make_unique<tribo::io::Scene>(
        c.file.empty() ? tribo::io::loadSceneFromString(tribo::bench::chuteYaml(80, 80, 5, 0.5),
                                                        "chute.yaml", {}, {}, settings)
                       : tribo::io::loadScene(kScenes + c.file, {}, {}, settings));
  }
  return *slot;
}

constexpr int kSamples = 10;          // contact counts through a run
constexpr double kLammpsSkin = 0.01;  // LAMMPS's neighbour skin [m]: a tenth of a diameter

tribo::peers::GranularRun runTriboGranular(const GranularCase& c, const tribo::io::Scene& s,
                                           int threads) {
  tribo::Simulator sim(s.model);
  const double dt = s.model->options.time_step;
  tribo::peers::GranularRun out;
  out.run.steps = std::lround(c.seconds / dt);
  for (const auto& b : s.model->bodies) out.spheres += b.kind == tribo::BodyKind::kDynamic;
  double points = 0.0;
  long done = 0;
  for (int k = 0; k < kSamples; ++k) {
    const long chunk = (out.run.steps * (k + 1)) / kSamples - done;
    PeerRun part;
    const tribo::peers::StepTimer timer;
    for (long i = 0; i < chunk; ++i) {
      const tribo::StepStatus status = sim.step();
      if (!status.ok) {
        out.run.error = status.message;
        return out;
      }
    }
    timer.stop(part);
    out.run.seconds += part.seconds;
    out.run.cpu_seconds += part.cpu_seconds;
    done += chunk;
    out.run.points = static_cast<double>(sim.current().contacts.size());
    out.run.penetration = sim.current().max_penetration;
    points += out.run.points;
  }
  out.mean_points = points / kSamples;
  // Threads a step ran on, on the mean: `threads: auto` follows its measured choice
  // (core/thread_choice.hpp); a fixed count runs every step on mostThreads().
  out.threads = sim.stats().meanThreads();
  for (std::size_t b = 0; b < s.model->bodies.size(); ++b)
    if (s.model->bodies[b].kind == tribo::BodyKind::kDynamic)
      out.run.max_speed = std::max(out.run.max_speed, sim.state().bodies[b].velocity.norm());
  std::ostringstream set;
  set << "Tribo, " << (threads == tribo::kAutoThreads ? "auto" : std::to_string(threads))
      << " thread(s) (" << out.threads << " on the mean); linear normal law k " << parameter(s, "k")
      << " N/m c " << parameter(s, "c") << " N s/m per point (F_n >= 0); Coulomb mu "
      << parameter(s, "mu") << " tanh-regularized v_eps 0.01 m/s, no tangential spring; "
      << "semi-implicit Euler dt " << dt << " s; grid broadphase, contacts found every step";
  out.settings = set.str();
  return out;
}

// LAMMPS's sphere-steps per second on each granular case (wall, CPU), for Tribo's ratios.
std::map<std::string, std::pair<double, double>>& lammpsSphereSteps() {
  static std::map<std::string, std::pair<double, double>> m;
  return m;
}

// `tribo_threads`: the scene's threads (kAutoThreads: the measured choice), or kLammps.
constexpr int kLammps = -1;

void BM_Granular(benchmark::State& st, const GranularCase& c, int tribo_threads) {
  for (auto _ : st) {
    tribo::peers::GranularRun r;
    if (tribo_threads != kLammps) {
      r = runTriboGranular(c, granularScene(c, tribo_threads), tribo_threads);
    } else {
      const tribo::io::Scene& s = granularScene(c, 1);
      const double dt = s.model->options.time_step;
      const tribo::peers::PeerScene peer =
          tribo::peers::peerSceneFrom(*s.model, parameter(s, "mu"), std::lround(c.seconds / dt));
      r = tribo::peers::runLammps(peer, {parameter(s, "k"), parameter(s, "c")}, kLammpsSkin,
                                  kSamples);
    }
    if (!r.run.error.empty()) {
      st.SkipWithError(r.run.error.c_str());
      return;
    }
    st.SetIterationTime(r.run.seconds);
    const double sphere_steps = static_cast<double>(r.spheres) * static_cast<double>(r.run.steps);
    const double wall = sphere_steps / r.run.seconds, cpu = sphere_steps / r.run.cpu_seconds;
    st.counters["spheres"] = static_cast<double>(r.spheres);
    st.counters["threads"] = r.threads;
    st.counters["us_per_step"] = r.run.seconds / static_cast<double>(r.run.steps) * 1e6;
    st.counters["sphere_steps_per_s"] = wall;
    st.counters["per_core_sphere_steps_per_s"] = wall / r.threads;
    st.counters["cpu_sphere_steps_per_s"] = cpu;
    st.counters["points"] = r.run.points;
    st.counters["points_mean"] = r.mean_points;
    st.counters["penetration_um"] = r.run.penetration * 1e6;
    st.counters["max_speed_mm_s"] = r.run.max_speed * 1e3;
    if (tribo_threads == kLammps) {
      lammpsSphereSteps()[c.name] = {wall, cpu};
    } else if (auto it = lammpsSphereSteps().find(c.name); it != lammpsSphereSteps().end()) {
      st.counters["x_lammps"] = wall / it->second.first;
      st.counters["x_lammps_per_core"] = wall / r.threads / it->second.first;
      st.counters["x_lammps_cpu"] = cpu / it->second.second;
    }
    st.SetLabel(r.settings);
  }
}

const GranularCase kGranularCases[] = {
    {"granular_pile", "sphere_pile_stiff.yaml", 2.0},
    {"granular_chute", "", 0.5},
};
#endif

const bool kRegistered = [] {
  for (const Case& c : kCases) {
    const std::string name = "BM_Peers/" + c.name;
    auto add = [&](const std::string& engine, Engine e) {
      benchmark::RegisterBenchmark((name + "/" + engine).c_str(), BM_Peers, c, e)
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    };
    add("tribo", Engine::kTribo);
    if (c.tribo_only) continue;
#ifdef TRIBO_PEER_BULLET
    add("bullet", Engine::kBullet);
#endif
#ifdef TRIBO_PEER_MUJOCO
    add("mujoco", Engine::kMujoco);
#endif
  }
#ifdef TRIBO_PEER_LAMMPS
  for (const GranularCase& c : kGranularCases)
    for (const auto& [engine, threads] : {std::pair<std::string, int>{"lammps", kLammps},
                                          {"tribo", 1},
                                          {"tribo_2threads", 2},
                                          {"tribo_auto", tribo::kAutoThreads}})
      benchmark::RegisterBenchmark(("BM_Peers/" + c.name + "/" + engine).c_str(), BM_Granular, c,
                                   threads)
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
#endif
  return true;
}();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
#ifdef TRIBO_PEER_BULLET
  benchmark::AddCustomContext("bullet", tribo::peers::bulletVersion());
#endif
#ifdef TRIBO_PEER_MUJOCO
  benchmark::AddCustomContext("mujoco", tribo::peers::mujocoVersion());
#endif
#ifdef TRIBO_PEER_LAMMPS
  benchmark::AddCustomContext("lammps", tribo::peers::lammpsVersion());
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
#ifdef TRIBO_PEER_LAMMPS
  tribo::peers::lammpsFinish();
#endif
  return 0;
}
