// The work of a step outside the force evaluation, split across threads: the energy account
// (core/energy.hpp: each body's and contact point's terms in parallel, summed in index order)
// and the energy guard built on it; and the simulator's deep-penetration books, which now
// measure a half width only past the shape's thinnest (core/simulator.cpp). The integrators'
// per-body updates split too; their
// trajectories are compared in tests/core/threaded_evaluation_test.cpp. Here, on 1, 2 and 3
// threads, over box fields of several sizes and masses on a moving belt with applied loads:
//   - the account is the same bit for bit, and equals sums the test forms on its own
//     (kinetic energy with the world-frame inertia, gravity, 1/2 k d^2 per corner, the loads'
//     power F . v_point + T . w and the belt's -F_belt . s from the contact wrench on it);
//   - a field stepped by semi-implicit Euler beyond its stability limit h w > 2 (w the
//     vertical contact frequency, sqrt(4 k / m)) is stopped, at the same step, with the same
//     words, body and quantity on every thread count; one within the limit is never stopped;
//   - boxes heavy enough to rest deeper than their half width (the static depth m g / (4 k)
//     against 0.1 m) are booked as deep the same way on every thread count, at the ratio of
//     the force balance.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

#include "contact/split_count.hpp"
#include "core/energy.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/same_bits.hpp"

namespace tribo {
namespace {

constexpr double kStiffness = 6.0e5;  // per corner [N/m]
constexpr double kGravity = 9.81;
const Vec3 kBelt(0.3, -0.1, 0.0);  // the belt's surface velocity [m/s]

struct Field {
  int n = 30;               // n x n boxes of 0.2 m at a pitch of 0.25 m
  double mass = 6.0;        // [kg]
  double damping = 0.0;     // per corner [N s/m]
  double dt = 5e-4;         // [s]
  double sink_speed = 0.0;  // initial downward speed [m/s]
  std::string integrator = "rk4";
};

std::string fieldYaml(const Field& f) {
  std::ostringstream s;
  s.precision(17);
  const double z = 0.1 - f.mass * kGravity / (4 * kStiffness);  // the static depth of 4 corners
  s << "simulation: {time_step: " << f.dt << ", integrator: " << f.integrator
    << ", gravity: [0, 0, " << -kGravity << "]}\n"
    << "friction_laws: {coulomb: {mu: 0.4, regularization: tanh, v_eps: 0.1}}\n"
    << "materials:\n"
    << "  - {name: m, normal: {law: linear, stiffness: " << kStiffness << ", damping: " << f.damping
    << "}, friction: coulomb, default: true}\n"
    << "bodies:\n"
    << "  - {name: belt, kind: kinematic, surface_velocity: [" << kBelt.x() << ", " << kBelt.y()
    << ", 0], geometry: [{name: floor, shape: halfspace}]}\n"
    << "  - {name: box, mass: " << f.mass << ", position: [0, 0, " << z << "], velocity: [0.02, "
    << "-0.01, " << -f.sink_speed << "], angular_velocity: [0, 0, 0.3], geometry: [{name: s, "
    << "shape: box, size: [0.2, 0.2, 0.2]}], pattern: {grid: [" << f.n << ", " << f.n
    << ", 1], spacing: [0.25, 0.25, 0]}}\n"
    << "loads:\n"
    << "  - {name: push, body: box_0_0_0, force: [{ramp: {rate: 40}}, 0, 0], point: [0, 0, "
       "-0.05]}\n"
    << "  - {name: twist, body: box_2_1_0, torque: [0, 0, 1.5]}\n";
  return s.str();
}

std::shared_ptr<const Model> load(const std::string& yaml, int threads) {
  io::RunSettings settings;
  settings.threads = threads;
  return io::loadSceneFromString(yaml, "field.yaml", {}, {}, settings).model;
}

using test::sameBits;

// The account formed by the test: world-frame inertia, and the sources' power from the loads'
// definitions and the contact wrench on the belt.
EnergyAccount expectedAccount(const Model& m, const State& state, const Workspace& ws) {
  EnergyAccount a;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Body& body = m.bodies[b];
    if (body.kind != BodyKind::kDynamic) continue;
    const BodyState& s = state.bodies[b];
    const Mat3 r = s.orientation.toRotationMatrix();
    const Mat3 inertia_world = r * body.inertia * r.transpose();
    a.kinetic += 0.5 * body.mass * s.velocity.dot(s.velocity) +
                 0.5 * s.angular_velocity.dot(inertia_world * s.angular_velocity);
    a.gravity += body.mass * kGravity * s.position.z();
  }
  for (const contact::ContactRecord& c : ws.contacts)
    a.elastic += 0.5 * kStiffness * c.point.depth * c.point.depth;
  // push: F = (40 t, 0, 0) at (0, 0, -0.05) in the body frame; twist: T = (0, 0, 1.5).
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const BodyState& s = state.bodies[b];
    if (m.bodies[b].name == "box_0_0_0") {
      const Vec3 arm = s.orientation.toRotationMatrix() * Vec3(0, 0, -0.05);
      a.input_power += Vec3(40 * state.time, 0, 0).dot(s.velocity + s.angular_velocity.cross(arm));
    } else if (m.bodies[b].name == "box_2_1_0") {
      a.input_power += Vec3(0, 0, 1.5).dot(s.angular_velocity);
    }
  }
  a.input_power -= ws.contact_wrench[0].force.dot(kBelt);  // the belt is body 0
  return a;
}

TEST(ThreadedStepChecks, EnergyAccountSameOnThreadsAndEqualToTheTestsSums) {
  for (const auto& [n, mass] : {std::pair{16, 0.5}, std::pair{30, 6.0}, std::pair{40, 80.0}}) {
    Field f;
    f.n = n;
    f.mass = mass;
    f.damping = 0.4 * std::sqrt(kStiffness * mass);  // 0.2 of a corner's critical damping
    const std::string yaml = fieldYaml(f);
    EnergyAccount reference;
    for (int threads : {1, 2, 3}) {
      Simulator sim(load(yaml, threads));
      for (int i = 0; i < 15; ++i) ASSERT_TRUE(sim.step().ok) << n << " boxes, step " << i;
      const Workspace& ws = sim.current();
      ASSERT_EQ(ws.contacts.size(), static_cast<std::size_t>(4 * n * n));
      const long split_before = contact::splitLoopCount().load();
      const EnergyAccount a = measureEnergy(sim.model(), sim.state(), ws, nullptr, threads);
      const long split = contact::splitLoopCount().load() - split_before;
      // 4 n^2 points always pay for a second thread; n^2 bodies from 512 on.
      if (threads > 1) {
        EXPECT_GE(split, n * n >= 512 ? 2 : 1) << n << " boxes, " << threads << " threads";
      } else {
        EXPECT_EQ(split, 0);
      }
      // The same state on one thread gives the same bits (the terms' sums keep their order).
      const EnergyAccount serial = measureEnergy(sim.model(), sim.state(), ws, nullptr, 1);
      for (auto [x, y] : {std::pair{a.kinetic, serial.kinetic},
                          {a.gravity, serial.gravity},
                          {a.elastic, serial.elastic},
                          {a.input_power, serial.input_power}})
        EXPECT_TRUE(sameBits(x, y))
            << n << " boxes, " << threads << " threads: " << x << " vs " << y;
      if (threads == 1) {
        reference = a;
      } else {  // and the run on more threads reached the same state
        EXPECT_TRUE(sameBits(a.kinetic, reference.kinetic)) << n << " boxes, " << threads;
        EXPECT_TRUE(sameBits(a.input_power, reference.input_power)) << n << " boxes, " << threads;
      }
      const EnergyAccount e = expectedAccount(sim.model(), sim.state(), ws);
      EXPECT_NEAR(a.kinetic, e.kinetic, 1e-12 * std::abs(e.kinetic)) << n << " boxes";
      EXPECT_NEAR(a.gravity, e.gravity, 1e-12 * std::abs(e.gravity) + 1e-12) << n << " boxes";
      EXPECT_NEAR(a.elastic, e.elastic, 1e-12 * e.elastic) << n << " boxes";
      // The belt's power is the large term (its friction on every box); the loads' are small.
      EXPECT_NEAR(a.input_power, e.input_power, 1e-11 * std::abs(e.input_power)) << n << " boxes";
      EXPECT_GT(std::abs(e.input_power), 0.1 * mass * n * n) << "the belt must drive the boxes";
    }
  }
}

struct Ending {
  StepStatus status;
  long steps = 0;
};

Ending runUntilStopped(const std::string& yaml, int threads, int max_steps) {
  Simulator sim(load(yaml, threads));
  Ending e;
  for (int i = 0; i < max_steps && e.status.ok; ++i) e.status = sim.step();
  e.steps = sim.stats().steps;
  return e;
}

TEST(ThreadedStepChecks, DivergingFieldStopsAtTheSameStepOnEveryThreadCount) {
  // w = sqrt(4 k / m): h w = 2.4 and 3.0 diverge under semi-implicit Euler; 1.6 does not.
  for (const auto& [n, mass, hw] : {std::tuple{24, 4.0, 2.4}, std::tuple{30, 20.0, 3.0}}) {
    Field f;
    f.n = n;
    f.mass = mass;
    f.sink_speed = 0.01;
    f.integrator = "semi_implicit_euler";
    f.dt = hw / std::sqrt(4 * kStiffness / mass);
    const std::string yaml = fieldYaml(f);
    const Ending one = runUntilStopped(yaml, 1, 400);
    ASSERT_FALSE(one.status.ok) << n << " boxes at h w = " << hw << ": not stopped";
    EXPECT_FALSE(one.status.body.empty());
    for (int threads : {2, 3}) {
      const Ending many = runUntilStopped(yaml, threads, 400);
      EXPECT_EQ(many.steps, one.steps) << threads << " threads";
      EXPECT_EQ(many.status.message, one.status.message) << threads << " threads";
      EXPECT_EQ(many.status.body, one.status.body) << threads << " threads";
      EXPECT_EQ(many.status.quantity, one.status.quantity) << threads << " threads";
      EXPECT_TRUE(sameBits(many.status.time, one.status.time)) << threads << " threads";
    }
  }
  Field stable;
  stable.n = 24;
  stable.mass = 4.0;
  stable.sink_speed = 0.01;
  stable.integrator = "semi_implicit_euler";
  stable.dt = 1.6 / std::sqrt(4 * kStiffness / stable.mass);
  for (int threads : {1, 2}) {
    const Ending e = runUntilStopped(fieldYaml(stable), threads, 300);
    EXPECT_TRUE(e.status.ok) << threads << " threads: " << e.status.message;
    EXPECT_EQ(e.steps, 300);
  }
}

TEST(ThreadedStepChecks, DeepPenetrationBooksSameOnEveryThreadCount) {
  // Depth m g / (4 k) = ratio x 0.1 m at rest: deeper than the box's half width.
  for (const auto& [n, ratio] : {std::pair{24, 1.5}, std::pair{32, 3.0}}) {
    Field f;
    f.n = n;
    f.mass = ratio * 0.1 * 4 * kStiffness / kGravity;
    f.damping = 2.0 * std::sqrt(kStiffness * f.mass);  // critically damped per corner
    f.dt = 1e-3;
    const std::string yaml = fieldYaml(f);
    StepStats reference;
    for (int threads : {1, 2, 3}) {
      Simulator sim(load(yaml, threads));
      for (int i = 0; i < 20; ++i) ASSERT_TRUE(sim.step().ok) << threads << " threads";
      const StepStats& s = sim.stats();
      EXPECT_EQ(s.deep_penetrations, 20L * 4 * n * n) << threads << " threads";
      EXPECT_NEAR(s.deepest_extent, 0.1, 1e-4);  // a box tilted a little by friction
      EXPECT_NEAR(s.deepest_ratio, ratio, 1e-3 * ratio) << threads << " threads";
      EXPECT_NEAR(s.deepest_depth, ratio * 0.1, 1e-3 * ratio);
      if (threads == 1) {
        reference = s;
        continue;
      }
      EXPECT_EQ(s.deepest_geometry, reference.deepest_geometry) << threads << " threads";
      EXPECT_TRUE(sameBits(s.deepest_ratio, reference.deepest_ratio)) << threads << " threads";
      EXPECT_TRUE(sameBits(s.first_deep_time, reference.first_deep_time)) << threads;
    }
  }
}

}  // namespace
}  // namespace tribo
