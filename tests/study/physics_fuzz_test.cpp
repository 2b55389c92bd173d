// Physics fuzzing: random but valid scenes from a seed (std::mt19937_64), each loaded from
// its YAML text, run for a short time and written to files. Bodies of every primitive shape,
// joints of every type with limits, springs, damping and friction (memoryless and dynamic
// laws), springs, bushings and torsional springs between bodies, every friction law the
// factory knows (memoryless, elastic_stick, every dynamic law, tabulated from a CSV file)
// and every normal law with parameters across their ranges, direction-dependent friction and
// rolling and spinning resistance on a third of the scenes each, values given as expressions
// over parameters, every integrator, 1 to 3 threads or auto, every collision switch, every
// output channel group, and steps from far below to far past the a-priori stability limit.
// The generator takes the lists of laws and channel groups from the engine's own tables, and
// a test fails when a law is added there that it does not know how to write. Each run must
//   - load (the generator only writes valid scenes),
//   - either complete or stop with status diverged and a message naming the quantity and the
//     time (and the body, when one is concerned),
//   - finish within a time cap (a RunMonitor ends runs after 0.5 s of processor time, and a run
//     that overshoots it by far, 20 s, fails the test: a hang),
//   - write files without a non-finite number: no nan or inf anywhere, and every cell of
//     trajectory.csv a finite number.
// Seeds: TRIBO_PHYSICS_FUZZ_SEEDS (default 200) from TRIBO_PHYSICS_FUZZ_FIRST (default 1);
// one seed: TRIBO_PHYSICS_FUZZ_FIRST=1234 TRIBO_PHYSICS_FUZZ_SEEDS=1 (docs/fuzzing.md).
// A failure prints the seed and the scene text.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "friction/friction_law.hpp"
#include "io/output_channels.hpp"
#include "io/scene_loader.hpp"
#include "study/result_writer.hpp"
#include "study/scene_run.hpp"

namespace tribo::study {
namespace {

namespace fs = std::filesystem;

// Caps in processor time, not wall time: the test must judge the engine, not the load of a
// shared machine (a run of 4 s of processor time under ASan took 20 s of wall time on 2 busy
// cores).
constexpr double kTimeCap = 0.5;  // [s] the monitor ends a run after this much stepping
// A run (under sanitizers) taking longer is a hang. The monitor sees the clock only between
// output rows, so one interval of a stiff bdf run counts whole: seed 157 (bdf, a step load,
// 3 threads) spends 24 s of processor time in one interval under ASan + UBSan + coverage on
// this project's 2-core machine, 95% of it in CVODE's difference-quotient Jacobians (perf),
// and 29 ms in the Release build, where its trajectory ends early. A hang never ends.
constexpr double kHangCap = 60.0;  // [s]

// "b3": a prefix letter and an index (appended, not '+': GCC 12's -Wrestrict false positive).
std::string named(char prefix, int i) {
  std::string name(1, prefix);
  name += std::to_string(i);
  return name;
}

long envLong(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? std::strtol(v, nullptr, 10) : fallback;
}

// The YAML text of a random valid scene.
class SceneGenerator {
 public:
  // `elements`: direction-dependent friction and rolling and spinning resistance, drawn from
  // a stream of their own so that every other draw of a seed is what it was before they came
  // (the seeds that once failed stay the scenes they were, with elements off).
  explicit SceneGenerator(std::uint64_t seed, bool elements = true)
      : rng_(seed), elements_rng_(seed ^ 0x9e3779b97f4a7c15ULL), elements_(elements) {}

  std::string scene() {
    std::ostringstream s;
    s.precision(17);
    parameters(s);
    simulation(s);
    const int n = 1 + pick(4);  // dynamic bodies
    bodies(s, n);
    joints(s, n);
    springs(s, n);
    forceElements(s, n);
    frictionLaws(s);
    materials(s);
    output(s);
    loads(s, n);  // last: the sections above stay what they were for each seed
    return s.str();
  }

  // Laws the generator writes: with a test that every law of the factory is among them.
  static const std::vector<std::string>& memorylessLaws() {
    static const std::vector<std::string> laws = {"coulomb", "recurdyn", "adams",
                                                  "roh_yoo", "stribeck", "tabulated"};
    return laws;
  }
  static const std::vector<std::string>& dynamicLaws() {
    static const std::vector<std::string> laws = {"lugre", "dahl", "elasto_plastic", "gms",
                                                  "rate_state"};
    return laws;
  }
  static const std::vector<std::string>& statefulLaws() {
    static const std::vector<std::string> laws = {"elastic_stick"};
    return laws;
  }

 private:
  double uniform(double lo, double hi) { return std::uniform_real_distribution(lo, hi)(rng_); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int pick(int n) { return std::uniform_int_distribution(0, n - 1)(rng_); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  std::string vec(double lo, double hi) {
    std::ostringstream s;
    s.precision(17);
    s << '[' << uniform(lo, hi) << ", " << uniform(lo, hi) << ", " << uniform(lo, hi) << ']';
    return s.str();
  }
  std::string vec(const Eigen::Vector3d& v) {
    std::ostringstream s;
    s.precision(17);
    s << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
    return s.str();
  }
  Eigen::Vector3d unit() {
    Eigen::Vector3d v;
    do v = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    while (v.norm() < 0.1);
    return v.normalized();
  }

  // A few parameters that values below refer to by expression ($scale, $half ...).
  void parameters(std::ostringstream& s) {
    scale_ = logUniform(0.5, 2.0);
    s << "parameters:\n  scale: " << scale_ << "\n  half: '$scale / 2'\n  deg: '30 deg'\n"
      << "  chain: '$half + $half - $scale + 1'\n";  // 1, through a chain of references
  }
  // A number, sometimes written as an expression over the parameters with the same value.
  std::string number(double v) {
    std::ostringstream s;
    s.precision(17);
    if (chance(0.2))
      s << "'" << v / scale_ << " * $scale * $chain'";
    else
      s << v;
    return s.str();
  }

  void simulation(std::ostringstream& s) {
    static const char* const kIntegrators[] = {"rk4", "semi_implicit_euler", "dopri5", "bdf"};
    const std::string integrator = kIntegrators[pick(4)];
    // 1e-5 s (far below any limit here) to 0.05 s (far past the stiff contacts' limit).
    const double dt = logUniform(1e-5, 5e-2);
    const int steps = 5 + pick(150);
    output_interval_ = dt * (1 + pick(3));
    s << "simulation:\n  duration: " << dt * steps << "\n  time_step: " << dt
      << "\n  integrator: " << integrator << "\n  gravity: " << vec(-12, 12) << '\n';
    if (chance(0.3))
      s << "  baumgarte: {alpha: " << uniform(0, 50) << ", beta: " << uniform(0, 500) << "}\n";
    if (integrator == "dopri5" || integrator == "bdf") {
      s << "  rtol: " << logUniform(1e-8, 1e-2) << "\n  atol: " << logUniform(1e-10, 1e-3)
        << "\n  event_location: " << (chance(0.5) ? "true" : "false") << '\n';
      if (chance(0.3)) s << "  max_step: " << dt * uniform(0.1, 2) << '\n';
    }
    if (chance(0.3))
      s << "  constraints: {projection: " << (chance(0.5) ? "true" : "false") << "}\n";
    if (chance(0.4))
      s << "  threads: " << (chance(0.3) ? std::string("auto") : std::to_string(1 + pick(3)))
        << '\n';
    if (chance(0.4))
      s << "  collision: {broadphase: " << flag() << ", closed_form_box_halfspace: " << flag()
        << ", closed_form_primitives: " << flag() << ", polyhedron_manifold: " << flag()
        << ", max_points_per_pair: " << 1 + pick(8) << ", joined_bodies_collide: " << flag()
        << "}\n";
  }
  const char* flag() { return chance(0.5) ? "true" : "false"; }

  void shape(std::ostringstream& s, const std::string& name) {
    static const char* const kShapes[] = {"box", "sphere", "cylinder", "capsule", "cone"};
    const std::string shape = kShapes[pick(5)];
    s << "      - {name: " << name << ", shape: " << shape;
    if (shape == "box")
      s << ", size: " << vec(0.02, 0.5);
    else if (shape == "sphere")
      s << ", radius: " << uniform(0.01, 0.3);
    else
      s << ", radius: " << uniform(0.01, 0.3) << ", length: " << uniform(0.02, 0.6);
    if (chance(0.3)) s << ", position: " << vec(-0.05, 0.05);
    if (chance(0.3)) s << ", rpy: " << vec(-3, 3);
    s << "}\n";
  }

  void bodies(std::ostringstream& s, int n) {
    s << "bodies:\n";
    ground_ = chance(0.8);
    if (ground_) {
      s << "  - name: ground\n    kind: kinematic\n";
      if (chance(0.4)) s << "    surface_velocity: " << vec(-3, 3) << '\n';
      s << "    geometry:\n      - {name: floor, shape: halfspace}\n";
    }
    positions_.clear();
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p(uniform(-1, 1), uniform(-1, 1), uniform(0.0, 0.6));
      positions_.push_back(p);
      s << "  - name: b" << i << "\n    mass: " << number(logUniform(1e-3, 1e3))
        << "\n    position: " << vec(p) << '\n';
      const bool geometry = chance(0.8);
      if (!geometry || chance(0.5)) {
        const double inertia = logUniform(1e-6, 10);
        s << "    inertia: [" << inertia * uniform(1, 1.5) << ", " << inertia * uniform(1, 1.5)
          << ", " << inertia * uniform(1, 1.5) << "]\n";
      }
      if (chance(0.5)) s << "    rpy: " << vec(-3, 3) << '\n';
      if (chance(0.6)) s << "    velocity: " << vec(-5, 5) << '\n';
      if (chance(0.4)) s << "    angular_velocity: " << vec(-20, 20) << '\n';
      if (geometry) {
        s << "    geometry:\n";
        shape(s, named('g', i));
        if (chance(0.2)) shape(s, named('h', i));
      }
    }
  }

  void joints(std::ostringstream& s, int n) {
    static const char* const kTypes[] = {
        "fixed",     "revolute",    "continuous", "prismatic",          "spherical",
        "universal", "cylindrical", "planar",     "planar_translation", "free"};
    bool any = false;
    for (int i = 0; i < n; ++i) {
      if (!chance(0.5)) continue;
      if (!any) s << "joints:\n";
      any = true;
      const std::string type = kTypes[pick(10)];
      const std::string parent = i > 0 && chance(0.5) ? named('b', pick(i)) : "world";
      const Eigen::Vector3d axis = unit();
      const Eigen::Vector3d axis2 = axis.cross(unit()).normalized();
      const Eigen::Vector3d anchor = positions_[i] + Eigen::Vector3d(uniform(-0.3, 0.3), 0, 0);
      s << "  - {name: j" << i << ", type: " << type << ", parent: " << parent << ", child: b" << i
        << ", anchor: " << vec(anchor) << ", axis: " << vec(axis);
      if (type == "universal" || type == "revolute" || type == "cylindrical" || chance(0.2))
        s << ", axis2: " << vec(axis2);
      if (type == "revolute" || type == "prismatic") {
        if (chance(0.5)) {
          const double lower = uniform(-1.5, 0);
          s << ", limit: {lower: " << lower << ", upper: " << lower + uniform(0.01, 2) << '}';
        }
        if (chance(0.3))
          s << ", spring: {stiffness: " << logUniform(1, 1e5) << ", reference: " << uniform(-1, 1)
            << '}';
        if (chance(0.3)) s << ", damping: " << logUniform(1e-3, 1e3);
        if (chance(0.3)) {
          s << ", friction: {law: " << frictionLaw(/*joint=*/true);
          if (chance(0.5))
            s << ", load: constant, normal_force: " << logUniform(0.1, 1e3);
          else
            s << ", load: reaction";
          if (type == "revolute") s << ", radius: " << uniform(0.001, 0.1);
          s << '}';
        }
      }
      s << "}\n";
    }
  }

  void springs(std::ostringstream& s, int n) {
    if (!chance(0.5)) return;
    s << "springs:\n";
    const int count = 1 + pick(2);
    for (int k = 0; k < count; ++k) {
      const int b = pick(n);
      const std::string a = b > 0 && chance(0.5) ? named('b', pick(b)) : "world";
      const Eigen::Vector3d pa = a == "world" ? Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), 1.0)
                                              : positions_[std::stoi(a.substr(1))];
      s << "  - {name: s" << k << ", a: " << a << ", point_a: " << vec(pa) << ", b: b" << b
        << ", point_b: " << vec(positions_[b]) << ", stiffness: " << logUniform(1, 1e6)
        << ", damping: " << (chance(0.5) ? logUniform(1e-3, 1e3) : 0.0)
        << ", rest_length: " << uniform(0, 1) << "}\n";
    }
  }

  // Bushings and torsional springs between a body and the world or another body.
  void forceElements(std::ostringstream& s, int n) {
    if (chance(0.3)) {
      s << "bushings:\n";
      for (int k = 0, count = 1 + pick(2); k < count; ++k) {
        const int b = pick(n);
        const std::string a = b > 0 && chance(0.5) ? named('b', pick(b)) : "world";
        s << "  - {name: u" << k << ", a: " << a << ", b: b" << b
          << ", frame_a: {position: " << vec(-0.5, 0.5) << ", rpy: " << vec(-3, 3) << '}'
          << ", frame_b: {position: " << vec(-0.1, 0.1) << '}' << ", stiffness: " << gains(1, 1e5)
          << ", damping: " << gains(1e-3, 1e2);
        if (chance(0.5))
          s << ", rotational_stiffness: " << gains(1e-2, 1e3)
            << ", rotational_damping: " << gains(1e-4, 10);
        s << "}\n";
      }
    }
    if (chance(0.3)) {
      s << "torsional_springs:\n";
      for (int k = 0, count = 1 + pick(2); k < count; ++k) {
        const int b = pick(n);
        const std::string a = b > 0 && chance(0.5) ? named('b', pick(b)) : "world";
        s << "  - {name: t" << k << ", a: " << a << ", b: b" << b << ", axis: " << vec(unit())
          << ", stiffness: " << logUniform(1e-2, 1e3) << ", damping: " << logUniform(1e-4, 10)
          << ", rest_angle: " << uniform(-3, 3) << "}\n";
      }
    }
  }
  // Applied loads on dynamic bodies, each component a random signal of every kind.
  void loads(std::ostringstream& s, int n) {
    if (!chance(0.3)) return;
    s << "loads:\n";
    for (int k = 0, count = 1 + pick(2); k < count; ++k) {
      s << "  - {name: l" << k << ", body: b" << pick(n) << ", force: " << signals()
        << (chance(0.5) ? ", torque: " + signals() : std::string())
        << ", frame: " << (chance(0.5) ? "world" : "body") << ", point: " << vec(-0.1, 0.1)
        << "}\n";
    }
  }
  std::string signals() {
    std::ostringstream s;
    s.precision(17);
    s << '[';
    for (int i = 0; i < 3; ++i) {
      const double a = (chance(0.5) ? 1 : -1) * logUniform(1e-3, 10);
      s << (i ? ", " : "");
      switch (pick(6)) {
        case 0:
          s << a;
          break;
        case 1:
          s << "{ramp: {rate: " << a << ", start: " << uniform(0, 0.01) << "}}";
          break;
        case 2:
          s << "{step: {time: " << uniform(0, 0.01) << ", before: 0, after: " << a << "}}";
          break;
        case 3:
          s << "{smooth_step: {start: 0, end: " << uniform(1e-3, 0.01)
            << ", before: 0, after: " << a << "}}";
          break;
        case 4:
          s << "{table: [[0, 0], [" << uniform(1e-3, 0.01) << ", " << a << "], [0.02, " << -a
            << "]]}";
          break;
        default:
          s << "{sines: [{amplitude: " << a << ", frequency: " << logUniform(0.1, 1e3) << "}]}";
      }
    }
    s << ']';
    return s.str();
  }
  std::string gains(double lo, double hi) {
    std::ostringstream s;
    s.precision(17);
    s << '[' << logUniform(lo, hi) << ", " << logUniform(lo, hi) << ", " << logUniform(lo, hi)
      << ']';
    return s.str();
  }

  // Any law for a material; for a joint, any but the anchored one (elastic_stick).
  std::string frictionLaw(bool joint = false) {
    std::vector<std::string> laws = memorylessLaws();
    laws.insert(laws.end(), dynamicLaws().begin(), dynamicLaws().end());
    if (!joint) laws.insert(laws.end(), statefulLaws().begin(), statefulLaws().end());
    return laws[static_cast<std::size_t>(pick(static_cast<int>(laws.size())))];
  }

  // The tabulated law's curve: a few points rising to a peak and falling to a plateau.
  static std::string curveFile(double mu_s, double mu_k, double v_s) {
    // One file a process: CTest runs the test cases of this file side by side.
    const fs::path path = fs::temp_directory_path() /
                          ("tribo_physics_fuzz_curve_" + std::to_string(::getpid()) + ".csv");
    std::ofstream out(path);
    out.precision(17);
    out << "v,mu\n0,0\n"
        << v_s << ',' << mu_s << '\n'
        << 3 * v_s << ',' << mu_k << '\n'
        << 100 * v_s + 1 << ',' << mu_k << '\n';
    return path.string();
  }

  void frictionLaws(std::ostringstream& s) {
    static const char* const kRegularizations[] = {"tanh", "linear", "havsin", "none"};
    const double mu_s = uniform(0.05, 1.2);
    const double mu_k = mu_s * uniform(0.1, 0.95);
    const double v_s = logUniform(1e-5, 0.1);
    s << "friction_laws:\n  coulomb: {mu: " << mu_k
      << ", regularization: " << kRegularizations[pick(4)] << ", v_eps: " << v_s << "}\n"
      << "  recurdyn: {mu_s: " << mu_s << ", mu_k: " << mu_k << ", v_s: " << v_s
      << ", v_d: " << v_s * uniform(1.5, 20) << "}\n"
      << "  adams: {mu_s: " << mu_s << ", mu_k: " << mu_k << ", v_s: " << v_s
      << ", v_d: " << v_s * uniform(1.5, 20) << "}\n"
      << "  roh_yoo: {mu_s: " << mu_s << ", mu_k: " << mu_k << ", v_s: " << v_s
      << ", a: " << uniform(1.05, 5) << ", beta: " << uniform(0.1, 2) << "}\n"
      << "  stribeck: {mu_s: " << mu_s << ", mu_k: " << mu_k << ", v_st: " << logUniform(1e-3, 1)
      << ", delta: " << uniform(0.5, 3) << ", viscous: " << (chance(0.5) ? uniform(0, 2) : 0.0)
      << ", v_eps: " << v_s << "}\n"
      << "  elastic_stick: {mu_s: " << mu_s << ", mu_k: " << mu_k
      << ", stiffness: " << logUniform(1e2, 1e7) << ", damping: " << logUniform(1e-2, 1e3)
      << ", stick_speed: " << v_s << "}\n";
    // Dynamic laws: bristle stiffness per newton of load from soft to stiff, the levels above.
    const double sigma0 = logUniform(1e2, 1e6);
    s << "  lugre: {sigma0: " << sigma0 << ", sigma1: " << std::sqrt(sigma0) * uniform(0, 1.5)
      << ", sigma2: " << uniform(0, 0.5) << ", mu_c: " << mu_k << ", mu_s: " << mu_s
      << ", v_s: " << v_s << "}\n"
      << "  dahl: {sigma0: " << sigma0 << ", mu_c: " << mu_k << ", alpha: " << uniform(1, 3)
      << "}\n"
      << "  elasto_plastic: {sigma0: " << sigma0
      << ", sigma1: " << std::sqrt(sigma0) * uniform(0, 1) << ", sigma2: " << uniform(0, 0.5)
      << ", mu_c: " << mu_k << ", mu_s: " << mu_s << ", v_s: " << v_s
      << ", z_ba_fraction: " << uniform(0.1, 0.9) << "}\n"
      << "  gms: {elements: " << 1 + pick(8) << ", stiffness: " << sigma0 << ", mu_c: " << mu_k
      << ", mu_s: " << mu_s << ", v_s: " << v_s << ", delta: " << uniform(0.5, 3)
      << ", attraction: " << logUniform(1, 100) << ", sigma1: " << uniform(0, 1)
      << ", sigma2: " << uniform(0, 0.5) << "}\n";
    const double d_c = logUniform(1e-7, 1e-3);
    const double v0 = logUniform(1e-7, 1e-3);
    s << "  rate_state: {mu0: " << mu_k << ", a: " << logUniform(1e-3, 0.05)
      << ", b: " << logUniform(1e-3, 0.05) << ", d_c: " << d_c << ", v0: " << v0
      << ", theta0: " << d_c / v0 * logUniform(0.1, 10)
      << ", evolution: " << (chance(0.5) ? "aging" : "slip") << "}\n"
      << "  tabulated: {file: " << curveFile(mu_s, mu_k, v_s) << "}\n";
  }

  void output(std::ostringstream& s) {
    s << "output:\n  interval: " << output_interval_ << '\n';
    if (chance(0.6)) {
      s << "  channels: [";
      bool first = true;
      for (const std::string& group : io::knownChannelGroups()) {
        if (!chance(0.5)) continue;
        s << (first ? "" : ", ") << group;
        first = false;
      }
      if (first) s << "position";
      s << "]\n";
    }
    s << "  summary: {body: b0, coordinate: "
      << "xyz"[pick(3)] << "}\n";
  }

  void materials(std::ostringstream& s) {
    static const char* const kNormalLaws[] = {"linear", "hertz", "hunt_crossley", "recurdyn"};
    const std::string law = kNormalLaws[pick(4)];
    const double stiffness = logUniform(1e2, 1e8);
    s << "materials:\n  - name: m\n    default: true\n    friction: " << frictionLaw()
      << "\n    normal: {law: " << law << ", stiffness: " << stiffness;
    if (law == "linear") s << ", damping: " << logUniform(1e-2, 1e4);
    if (law == "hunt_crossley") {
      s << ", exponent: " << uniform(1, 2);
      if (chance(0.5))
        s << ", restitution: " << uniform(0.05, 1) << ", impact_speed: " << logUniform(0.01, 10);
      else
        s << ", damping: " << logUniform(1e-3, 10);
    }
    if (law == "recurdyn")
      s << ", exponent: " << uniform(1, 2) << ", damping: " << logUniform(1e-2, 1e4)
        << ", max_depth: " << logUniform(1e-5, 1e-2);
    s << "}\n";
    if (elements_) contactElements(s);
  }

  // Direction-dependent friction and rolling and spinning resistance (contact/
  // anisotropy.hpp, contact/rolling_resistance.hpp), each on a third of the scenes.
  void contactElements(std::ostringstream& s) {
    std::mt19937_64& r = elements_rng_;
    auto u = [&](double lo, double hi) { return std::uniform_real_distribution(lo, hi)(r); };
    auto log_u = [&](double lo, double hi) { return std::exp(u(std::log(lo), std::log(hi))); };
    if (u(0, 1) < 1.0 / 3.0) {
      s << "    anisotropy: {frame: " << (u(0, 1) < 0.5 ? "a" : "b") << ", axis: [" << u(-1, 1)
        << ", " << u(-1, 1) << ", " << u(-1, 1) << "], ratio: [" << log_u(0.1, 10) << ", "
        << log_u(0.1, 10) << "]";
      if (u(0, 1) < 0.5) s << ", backward: [" << log_u(0.1, 10) << ", " << log_u(0.1, 10) << "]";
      s << "}\n";
    }
    if (u(0, 1) < 1.0 / 3.0)
      s << "    rolling: {length: " << log_u(1e-5, 1e-1) << ", stiffness: " << log_u(1e-2, 1e4)
        << ", damping: " << log_u(1e-4, 10) << "}\n";
    if (u(0, 1) < 1.0 / 3.0)
      s << "    spinning: {mu: " << log_u(0.01, 2) << ", radius: " << log_u(1e-4, 0.1)
        << ", stiffness: " << log_u(1e-2, 1e4) << ", damping: " << log_u(1e-4, 10)
        << ", stick_speed: " << log_u(1e-6, 1) << "}\n";
  }

  std::mt19937_64 rng_;
  std::mt19937_64 elements_rng_;
  bool elements_ = true;
  double scale_ = 1.0;
  bool ground_ = false;
  double output_interval_ = 1e-3;
  std::vector<Eigen::Vector3d> positions_;
};

// Is `token` a spelling of a non-finite number (nan, inf, infinity; any case, any sign)?
bool nonFiniteWord(std::string token) {
  while (!token.empty() && (token.front() == '-' || token.front() == '+')) token.erase(0, 1);
  std::transform(token.begin(), token.end(), token.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return token == "nan" || token == "inf" || token == "infinity" || token.starts_with("nan(");
}

// What is wrong with the files in `dir`, "" when nothing is.
std::string checkFiles(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::ifstream in(entry.path());
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    std::string token;
    for (const char c : text + "\n") {
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.' ||
          c == '(' || c == ')') {
        token += c;
        continue;
      }
      if (nonFiniteWord(token)) return entry.path().filename().string() + ": '" + token + "'";
      token.clear();
    }
    if (entry.path().filename() != "trajectory.csv") continue;
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);  // header
    for (int row = 2; std::getline(lines, line); ++row) {
      std::istringstream cells(line);
      std::string cell;
      while (std::getline(cells, cell, ',')) {
        char* end = nullptr;
        const double v = std::strtod(cell.c_str(), &end);
        if (cell.empty() || *end != '\0' || !std::isfinite(v))
          return "trajectory.csv row " + std::to_string(row) + ": cell '" + cell + "'";
      }
      if (!line.empty() && line.back() == ',')
        return "trajectory.csv row " + std::to_string(row) + ": empty last cell";
    }
  }
  return "";
}

// Runs seeds [first, first + seeds) and checks each as the header says.
void runSeeds(long first, long seeds, bool elements = true) {
  // The process id keeps two builds' runs at once (Release and sanitized) out of each other's
  // folder.
  const fs::path dir = fs::temp_directory_path() / ("tribo_physics_fuzz_" + std::to_string(first) +
                                                    "_" + std::to_string(::getpid()));
  int complete = 0, diverged = 0, capped = 0;
  for (long seed = first; seed < first + seeds; ++seed) {
    const std::string yaml = SceneGenerator(static_cast<std::uint64_t>(seed), elements).scene();
    SCOPED_TRACE("seed " + std::to_string(seed) + ", scene:\n" + yaml);
    io::Scene scene;
    try {
      scene = io::loadSceneFromString(yaml, "physics_fuzz_" + std::to_string(seed) + ".yaml");
    } catch (const io::SceneError& e) {
      ADD_FAILURE() << "the generator wrote a scene that does not load: " << e.what();
      continue;
    }
    const std::clock_t start = std::clock();
    const auto elapsed = [&] { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; };
    bool stopped = false;
    RunOptions options;
    options.monitor = {scene.output.interval, [&](const TrajectoryRecorder&) {
                         stopped = elapsed() > kTimeCap;
                         return stopped;
                       }};
    // And within a row: a watchdog raises the stop request, which the step sees at every
    // right-hand-side evaluation (a stiff bdf interval can take a minute under sanitizers).
    std::atomic<bool> stop{false}, done{false};
    options.stop = &stop;
    std::thread watchdog([&] {
      while (!done.load()) {
        if (elapsed() > kTimeCap) stop.store(true);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    });
    const RunResult result = runScene(scene, options);
    done.store(true);
    watchdog.join();
    EXPECT_LT(elapsed(), kHangCap) << "a run took longer than the hang cap";
    if (result.complete || result.interrupted) {
      ++(stopped || result.interrupted ? capped : complete);
    } else {
      ++diverged;
      EXPECT_FALSE(result.message.empty());
      EXPECT_FALSE(result.stop.quantity.empty()) << result.message;
      EXPECT_TRUE(std::isfinite(result.stop.time)) << result.message;
      // The message words the quantity as the simulator does ("contact_force" as "contact
      // force", "angular_velocity" as "angular velocity"; core/simulator.cpp).
      std::string words = result.stop.quantity;
      std::replace(words.begin(), words.end(), '_', ' ');
      EXPECT_NE(result.message.find(words), std::string::npos) << result.message;
      if (!result.stop.body.empty()) {
        EXPECT_NE(result.message.find(result.stop.body), std::string::npos) << result.message;
      }
    }
    fs::remove_all(dir);
    fs::create_directories(dir);
    writeResults(dir, scene, result);
    const std::string bad = checkFiles(dir);
    EXPECT_EQ(bad, "") << "a non-finite number in the output";
    if (::testing::Test::HasFailure()) break;  // one failing seed is enough to read
  }
  fs::remove_all(dir);
  std::cout << "physics fuzz: seeds " << first << ".." << first + seeds - 1 << ": " << complete
            << " complete, " << diverged << " diverged, " << capped << " ended at the " << kTimeCap
            << " s cap\n";
}

TEST(PhysicsFuzz, TheGeneratorWritesEveryLawOfTheFactory) {
  const auto covers = [](const std::vector<std::string>& known,
                         const std::vector<std::string>& written) {
    for (const std::string& law : known)
      EXPECT_NE(std::find(written.begin(), written.end(), law), written.end())
          << "the physics fuzz does not write law '" << law << "'";
  };
  covers(friction::knownFrictionLaws(), SceneGenerator::memorylessLaws());
  covers(friction::knownDynamicFrictionLaws(), SceneGenerator::dynamicLaws());
  covers(friction::knownStatefulFrictionLaws(), SceneGenerator::statefulLaws());
  // Over 2000 seeds every law, channel group and integrator is written.
  std::string all;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) all += SceneGenerator(seed).scene();
  for (const auto* list : {&SceneGenerator::memorylessLaws(), &SceneGenerator::dynamicLaws(),
                           &SceneGenerator::statefulLaws()})
    for (const std::string& law : *list)
      EXPECT_NE(all.find("friction: " + law), std::string::npos) << law << " in a material";
  for (const std::string& group : io::knownChannelGroups())
    EXPECT_NE(all.find(group), std::string::npos) << group;
  for (const char* word :
       {"bushings:", "torsional_springs:", "loads:", "{smooth_step:", "frame: body",
        "threads: auto", "threads: 2", "integrator: bdf", "integrator: dopri5", "$scale",
        "load: reaction", "law: lugre", "law: rate_state", "anisotropy: {frame: a",
        "anisotropy: {frame: b", "backward:", "rolling: {", "spinning: {"})
    EXPECT_NE(all.find(word), std::string::npos) << word;
}

TEST(PhysicsFuzz, RandomValidScenesCompleteOrStopWithANamedReason) {
  runSeeds(envLong("TRIBO_PHYSICS_FUZZ_FIRST", 1), envLong("TRIBO_PHYSICS_FUZZ_SEEDS", 200));
}

// Seeds that once failed (with the contact elements: 375, whose rate_state law's state
// overflowed under a 42 ms step and whose message did not word its quantity, "friction
// state"); without them: 1019 stopped on energy with "rose by -nan J" in its message (the
// energy balance had overflowed; core/simulator.cpp now says so in words); 100 (once the
// generator wrote every channel group) had a finite friction force of 4e168 N whose norm
// overflowed in its square, written as an empty field (study/trajectory_recorder.cpp now
// takes stable norms).
TEST(PhysicsFuzz, SeedsThatOnceFailed) {
  for (const long seed : {1019L, 100L}) runSeeds(seed, 1, false);
  runSeeds(375, 1);
}

}  // namespace
}  // namespace tribo::study
