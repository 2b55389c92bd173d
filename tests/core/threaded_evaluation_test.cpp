// Threads of one force evaluation (SimulationOptions::threads, core/thread_count.hpp): a run
// on 2 or 3 threads must give the one-thread run's trajectory bit for bit (every body's
// position, orientation, velocity and angular velocity compared byte for byte, and the
// friction states), on scenes large enough that the stages and the narrowphase do split
// (each multi-thread run must have cut loops for a team of threads; how many of them another
// thread ran part of is printed: contact/split_count.hpp):
// box grids of 16 x 16 and 30 x 30 resting and sliding on a half-space (closed-form
// corners), boxes colliding with each other (FCL's box/box), stateful (elastic_stick) and
// dynamic (LuGre) friction, boxes hinged to the world by revolute joints, the pile of
// 200 spheres (its narrowphase splits), and boxes sliding so slowly that their squared slip
// speed is subnormal (flushed to zero in a step, on every thread). A 7 x 7 grid, below every
// stage's threshold, is checked to stay on one thread. The reference is the one-thread run of the
// same scene in the same process. Also: the scene key and its errors, and the sweep's limit of one
// thread per point.
#include <gtest/gtest.h>
#include <sched.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contact/split_count.hpp"
#include "contact/work_team.hpp"
#include "core/dynamics.hpp"
#include "core/simulator.hpp"
#include "core/thread_choice.hpp"
#include "core/thread_count.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

// n x n boxes of 0.2 m at `pitch` on the ground, each with its own small sliding velocity
// and spin; columns alternately approach each other at `closing` [m/s] (they collide when
// pitch - 0.2 < closing * t).
std::string boxGrid(int n, double pitch, const std::string& law, const std::string& integrator,
                    double closing = 0.0, bool hinged = false, double dt = 1e-3) {
  std::ostringstream s;
  s.precision(17);
  s << "simulation: {time_step: " << dt << ", integrator: " << integrator << "}\n"
    << "friction_laws:\n"
    << "  coulomb: {mu: 0.5, regularization: tanh, v_eps: 0.01}\n"
    << "  elastic_stick: {mu_s: 0.5, mu_k: 0.4, stiffness: 1.0e5, damping: 100}\n"
    << "  lugre: {sigma0: 1.0e4, sigma1: 100, sigma2: 0, mu_c: 0.4, mu_s: 0.5, v_s: 0.01}\n"
    << "materials:\n"
    << "  - {name: m, normal: {law: linear, stiffness: 6.0e5, damping: 1000}, friction: " << law
    << ", default: true}\n"
    << "bodies:\n"
    << "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int k = i * n + j;
      const double vx = (i % 2 == 0 ? closing : -closing) + 0.01 * ((k * 7) % 11 - 5);
      const double vy = 0.01 * ((k * 5) % 13 - 6);
      const double wz = 0.1 * ((k * 3) % 7 - 3);
      const double mass = 4.0 + (k % 5);
      const double z = 0.1 - mass * 9.81 / (4 * 6.0e5);  // at the static depth of 4 corners
      s << "  - {name: b" << k << ", mass: " << mass << ", position: [" << i * pitch << ", "
        << j * pitch << ", " << z << "], velocity: [" << vx << ", " << vy
        << ", 0], angular_velocity: [0, 0, " << wz << "], geometry: [{name: s" << k
        << ", shape: box, size: [0.2, 0.2, 0.2]}]}\n";
    }
  if (hinged) {  // each box on a revolute joint about y through its lower front edge
    s << "joints:\n";
    for (int k = 0; k < n * n; ++k)
      s << "  - {name: j" << k << ", type: revolute, parent: world, child: b" << k << ", anchor: ["
        << (k / n) * pitch + 0.1 << ", " << (k % n) * pitch << ", 0.0], axis: [0, 1, 0]}\n";
  }
  return s.str();
}

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::shared_ptr<const Model> load(const std::string& yaml, int threads) {
  io::RunSettings settings;
  settings.threads = threads;
  return io::loadSceneFromString(yaml, "threads_test.yaml", {}, {}, settings).model;
}

struct RunEnd {
  State state;
  std::size_t contacts = 0;        // contact points of the last evaluation
  std::size_t between_bodies = 0;  // of them, not on the ground (geometry 0)
  bool ok = true;
};

RunEnd run(const std::string& yaml, int threads, int steps) {
  Simulator sim(load(yaml, threads));
  RunEnd r;
  for (int i = 0; i < steps && r.ok; ++i) {
    const StepStatus status = sim.step();
    r.ok = status.ok;
    if (!r.ok) ADD_FAILURE() << status.message;
  }
  r.contacts = sim.current().contacts.size();
  for (const contact::ContactRecord& c : sim.current().contacts) {
    const ContactPair pair = sim.model().contactPair(c.point.pair);
    if (pair.geometry_a != 0 && pair.geometry_b != 0) ++r.between_bodies;
  }
  r.state = sim.state();
  return r;
}

template <class T>
bool sameBytes(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Byte-for-byte equal body states and friction states; names the first difference.
::testing::AssertionResult identical(const State& a, const State& b) {
  if (a.bodies.size() != b.bodies.size()) return ::testing::AssertionFailure() << "body count";
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyState& x = a.bodies[i];
    const BodyState& y = b.bodies[i];
    if (!sameBytes(x.position, y.position) || !sameBytes(x.velocity, y.velocity) ||
        !sameBytes(x.angular_velocity, y.angular_velocity) ||
        !sameBytes(x.orientation.coeffs(), y.orientation.coeffs()))
      return ::testing::AssertionFailure()
             << "body " << i << " differs: position " << x.position.transpose() << " vs "
             << y.position.transpose() << ", velocity " << x.velocity.transpose() << " vs "
             << y.velocity.transpose();
  }
  if (a.friction_values.size() != b.friction_values.size() ||
      (!a.friction_values.empty() && std::memcmp(a.friction_values.data(), b.friction_values.data(),
                                                 a.friction_values.size() * sizeof(double)) != 0))
    return ::testing::AssertionFailure() << "friction values differ";
  if (a.stick_anchors.size() != b.stick_anchors.size())
    return ::testing::AssertionFailure() << "stick anchor count differs";
  for (std::size_t i = 0; i < a.stick_anchors.size(); ++i)
    if (!sameBytes(a.stick_anchors[i].position, b.stick_anchors[i].position) ||
        a.stick_anchors[i].key != b.stick_anchors[i].key)
      return ::testing::AssertionFailure() << "stick anchor " << i << " differs";
  return ::testing::AssertionSuccess();
}

// The scene on 1, 2 and 3 threads: the same state after `steps`, a run that moved, at least
// `min_contacts` contact points, and (iff `splits`) loops run on a team of threads in at
// least half as many as the steps (the sphere pile: 429 in 600 steps, as it settles).
void expectSameOnThreads(const std::string& yaml, int steps, std::size_t min_contacts,
                         bool splits = true) {
  const RunEnd one = run(yaml, 1, steps);
  ASSERT_TRUE(one.ok);
  EXPECT_GE(one.contacts, min_contacts);
  const State start = Simulator(load(yaml, 1)).state();
  double moved = 0.0;
  for (std::size_t b = 0; b < start.bodies.size(); ++b)
    moved = std::max(moved, (one.state.bodies[b].position - start.bodies[b].position).norm());
  EXPECT_GT(moved, 1e-6) << "nothing moved: the comparison would be empty";
  for (int threads : {2, 3}) {
    EXPECT_EQ(Dynamics(load(yaml, threads)).threads(), threads);
    const long split_before = contact::splitLoopCount().load();
    const long helped_before = contact::helpedLoopCount().load();
    const RunEnd many = run(yaml, threads, steps);
    const long split = contact::splitLoopCount().load() - split_before;
    const long helped = contact::helpedLoopCount().load() - helped_before;
    if (splits) {
      EXPECT_GE(split, steps / 2) << threads << " threads: the work was split in few steps";
      // Whether a helper took part depends on the machine's load (a helper not scheduled in
      // time is not waited for: contact/work_team.hpp), so it is reported, not asserted;
      // work_team_test asserts that helpers do take part.
      std::printf("%d threads: %ld chunks runs by helpers over %ld split loops\n", threads, helped,
                  split);
    } else {
      EXPECT_EQ(split, 0) << threads << " threads: below the threshold, yet split";
    }
    ASSERT_TRUE(many.ok) << threads << " threads";
    EXPECT_EQ(many.contacts, one.contacts) << threads << " threads";
    EXPECT_TRUE(identical(one.state, many.state)) << threads << " threads";
  }
}

// Two threads start only when each has 256 contact points (or bodies) to work on
// (core/dynamics.cpp); these scenes have at least this many.
constexpr std::size_t kSplits = 2 * 256;

TEST(ThreadedEvaluation, BoxGridsOfSeveralSizesSlidingOnTheGround) {
  // 49 boxes, 196 corners: below the 256 items a thread needs, so it stays on one.
  expectSameOnThreads(boxGrid(7, 0.25, "coulomb", "semi_implicit_euler"), 40, 2 * 49, false);
  expectSameOnThreads(boxGrid(16, 0.25, "coulomb", "rk4"), 20, kSplits);
  expectSameOnThreads(boxGrid(30, 0.25, "coulomb", "semi_implicit_euler"), 20, kSplits);
}

TEST(ThreadedEvaluation, BoxesCollidingWithEachOther) {
  // Columns 1 mm apart closing at 1 m/s: box/box contacts (FCL) from the sixth 0.2 ms step.
  const std::string yaml = boxGrid(16, 0.201, "coulomb", "semi_implicit_euler", 0.5, false, 2e-4);
  const RunEnd r = run(yaml, 1, 12);
  ASSERT_TRUE(r.ok);
  EXPECT_GT(r.between_bodies, 100u);
  expectSameOnThreads(yaml, 12, kSplits);
}

TEST(ThreadedEvaluation, SpherePile) {
  const std::string yaml = fileText(std::string(TRIBO_SOURCE_DIR) + "/scenes/sphere_pile.yaml");
  expectSameOnThreads(yaml, 600, 200);  // its narrowphase splits (128 pairs a thread)
}

TEST(ThreadedEvaluation, StatefulFriction) {
  expectSameOnThreads(boxGrid(16, 0.25, "elastic_stick", "rk4"), 20, kSplits);
}

TEST(ThreadedEvaluation, DynamicFriction) {
  expectSameOnThreads(boxGrid(16, 0.25, "lugre", "semi_implicit_euler", 0.0, false, 2e-4), 30,
                      kSplits);
}

TEST(ThreadedEvaluation, BoxesOnRevoluteJoints) {
  expectSameOnThreads(boxGrid(12, 0.25, "coulomb", "rk4", 0.0, true), 20, 2 * 144);
}

// Every box sliding at 1e-160 m/s along x and y: the squared slip speed, 2e-320, is
// subnormal, which a step flushes to zero (core/flush_denormals.hpp), so a step from there
// finds a slip speed of 0 and no friction force, and leaves the x velocity as it was. A
// thread that did not flush would find a slip speed of 1.4e-160 and a friction force of about
// 1e-157 N. (Steps after that slide at normal numbers: the boxes settle and rock by about
// 1e-13 m/s.) The helper threads are started here by a loop outside any step, in the
// default floating-point mode (as a loop of a study or of another library in the process
// would start them: a thread starts in its creator's mode). The step from the slow state is
// taken 50 times on each simulator, after a few steps have woken its helpers, so that helpers
// run chunks of it.
TEST(ThreadedEvaluation, SubnormalSquaredSlipSpeedIsFlushedOnEveryThread) {
  std::vector<int> started(64, 0);
  auto mark = [&](std::size_t c) { started[c] = 1; };
  contact::runChunks(started.size(), 3, mark);  // starts two helpers
  const std::string yaml = boxGrid(16, 0.25, "coulomb", "semi_implicit_euler");
  const std::shared_ptr<const Model> model = load(yaml, 1);
  State slow = Simulator(model).state();
  std::size_t boxes = 0;
  for (std::size_t b = 0; b < slow.bodies.size(); ++b) {
    if (model->bodies[b].kind != BodyKind::kDynamic) continue;  // the ground
    slow.bodies[b].velocity = Vec3(1e-160, -1e-160, 0.0);
    slow.bodies[b].angular_velocity.setZero();
    ++boxes;
  }
  ASSERT_EQ(boxes, 256u);
  State reference;
  for (int threads : {1, 2, 3}) {
    Simulator sim(load(yaml, threads));
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(sim.step().ok);
    const long split_before = contact::splitLoopCount().load();
    const long helped_before = contact::helpedLoopCount().load();
    for (int trial = 0; trial < 50; ++trial) {
      sim.setState(slow);
      ASSERT_TRUE(sim.step().ok);
      const State& after = sim.state();
      for (std::size_t b = 0; b < after.bodies.size(); ++b)
        if (model->bodies[b].kind == BodyKind::kDynamic) {
          ASSERT_EQ(after.bodies[b].velocity.x(), 1e-160) << threads << " threads, body " << b;
        }
      if (threads == 1 && trial == 0) reference = after;
      ASSERT_TRUE(identical(reference, after)) << threads << " threads, trial " << trial;
    }
    if (threads > 1) {
      EXPECT_GE(contact::splitLoopCount().load() - split_before, 50) << threads << " threads";
      std::printf("%d threads: helpers took part in %ld split loops\n", threads,
                  contact::helpedLoopCount().load() - helped_before);
    }
  }
}

TEST(ThreadedEvaluation, AutoIsTheEnvironmentsCountElseTheCores) {
  // kAutoThreads: OMP_NUM_THREADS's first number, else the CPUs this process may run on (its
  // affinity mask), whatever OpenMP's own setting has been changed to in the process.
  const char* saved = std::getenv("OMP_NUM_THREADS");
  const std::string before = saved != nullptr ? saved : "";
  ::setenv("OMP_NUM_THREADS", "3,2", 1);
  EXPECT_EQ(autoThreads(), 3);
  EXPECT_EQ(resolveThreads(kAutoThreads), 3);
  {
    const ScopedThreadLimit two(2);
    EXPECT_EQ(resolveThreads(kAutoThreads), 2);
  }
  ::setenv("OMP_NUM_THREADS", "none", 1);  // not a number: the cores
  cpu_set_t cpus;
  CPU_ZERO(&cpus);
  ASSERT_EQ(sched_getaffinity(0, sizeof(cpus), &cpus), 0);
  EXPECT_EQ(autoThreads(), CPU_COUNT(&cpus));
  ::unsetenv("OMP_NUM_THREADS");
  EXPECT_EQ(autoThreads(), CPU_COUNT(&cpus));
  if (saved != nullptr) ::setenv("OMP_NUM_THREADS", before.c_str(), 1);
}

TEST(ThreadedEvaluation, ThreadsChangedBetweenStepsGiveTheSameRun) {
  // The threads of a run changed between steps (as `threads: auto`'s measured choice does):
  // the one-thread run's trajectory bit for bit, each step counted on the threads it ran on.
  const std::string yaml = boxGrid(16, 0.25, "elastic_stick", "rk4");
  const int steps = 24;
  const RunEnd one = run(yaml, 1, steps);
  ASSERT_TRUE(one.ok);
  Simulator sim(load(yaml, 3));
  ASSERT_EQ(sim.mostThreads(), 3);
  long threaded = 0;
  const long split_before = contact::splitLoopCount().load();
  for (int i = 0; i < steps; ++i) {
    const int threads = 1 + (i * 7 / 3) % 3;  // 1, 3, 2, 2, 1, 3, 3, 2, 1, ...
    sim.pinThreads(threads);
    ASSERT_EQ(sim.threads(), threads);
    threaded += threads > 1;
    ASSERT_TRUE(sim.step().ok);
  }
  EXPECT_GE(contact::splitLoopCount().load() - split_before, threaded);
  EXPECT_EQ(sim.stats().threaded_steps, threaded);
  EXPECT_TRUE(identical(one.state, sim.state()));
  sim.pinThreads(7);  // held within 1 and the most
  EXPECT_EQ(sim.threads(), 3);
  sim.pinThreads(0);
  EXPECT_EQ(sim.threads(), 1);
}

TEST(ThreadedEvaluation, AutoThreadsMeasuredChoiceKeepsTheRun) {
  // `threads: auto`: the steps' threads follow the measured choice (core/thread_choice.hpp),
  // whichever it is on this machine, and the run is the one-thread run bit for bit. The first
  // trial window (ThreadChoice::kWindowSteps steps and the uncounted first) runs on every
  // thread; a fixed count is never changed.
  const std::string yaml = boxGrid(30, 0.25, "coulomb", "semi_implicit_euler");
  const int steps = 300;
  const RunEnd one = run(yaml, 1, steps);
  ASSERT_TRUE(one.ok);
  Simulator sim(load(yaml, kAutoThreads));
  for (int i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok);
  EXPECT_TRUE(identical(one.state, sim.state()));
  if (sim.mostThreads() > 1) {
    EXPECT_GE(sim.stats().threaded_steps, 1 + ThreadChoice::kWindowSteps);
    EXPECT_LE(sim.stats().threaded_steps, steps);
  } else {
    EXPECT_EQ(sim.stats().threaded_steps, 0);  // a one-core machine: nothing to choose
  }
  Simulator fixed(load(yaml, 2));
  for (int i = 0; i < 40; ++i) ASSERT_TRUE(fixed.step().ok);
  EXPECT_EQ(fixed.threads(), 2);
  EXPECT_EQ(fixed.stats().threaded_steps, 40);
}

TEST(ThreadedEvaluation, SmallScenesKeepOneThread) {
  // One box: no stage has enough items for a second thread, whatever the setting.
  EXPECT_EQ(Dynamics(load(boxGrid(1, 0.25, "coulomb", "rk4"), 4)).threads(), 1);
  const std::string belt = fileText(std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml");
  EXPECT_EQ(Dynamics(load(belt, 2)).threads(), 1);
  EXPECT_EQ(Dynamics(load(belt, kAutoThreads)).threads(), 1);
}

TEST(ThreadedEvaluation, ThreadLimitOfTheConstructingThread) {
  const std::string yaml = boxGrid(30, 0.25, "coulomb", "rk4");
  {
    const ScopedThreadLimit one(1);
    EXPECT_EQ(Dynamics(load(yaml, 3)).threads(), 1);
    {
      const ScopedThreadLimit two(2);
      EXPECT_EQ(Dynamics(load(yaml, 3)).threads(), 2);
    }
    EXPECT_EQ(ScopedThreadLimit::limit(), 1);
  }
  EXPECT_EQ(ScopedThreadLimit::limit(), 0);
  EXPECT_EQ(Dynamics(load(yaml, 3)).threads(), 3);
}

TEST(ThreadedEvaluation, SceneKey) {
  const std::string base = boxGrid(2, 0.25, "coulomb", "rk4");
  auto with = [&](const std::string& value) {
    return test::replaced(base, "integrator: rk4}", "integrator: rk4, threads: " + value + "}");
  };
  EXPECT_EQ(io::loadSceneFromString(with("3"), "t.yaml").model->options.threads, 3);
  EXPECT_EQ(io::loadSceneFromString(with("auto"), "t.yaml").model->options.threads, kAutoThreads);
  EXPECT_EQ(io::loadSceneFromString(base, "t.yaml").model->options.threads, 1);  // default
  for (const std::string bad : {"0", "-1", "2.5", "x"}) {
    const std::string message = test::sceneErrorOf(with(bad), "t.yaml");
    EXPECT_NE(message.find("t.yaml:1:"), std::string::npos) << message;
    EXPECT_NE(message.find("simulation.threads"), std::string::npos) << message;
    EXPECT_NE(message.find("expected auto or a whole number >= 1, found '" + bad + "'"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace tribo
