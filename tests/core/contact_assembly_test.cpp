// The contact wrenches a body (Workspace::contact_wrench, Dynamics::assemble) against a sum
// written here over the contact records, point by point in contact order: on B the point's
// force F = F_n n + F_t and (p - o_B) x F + M, on A -F and (p - o_A) x (-F) - M
// (contact/contact_force.hpp), for 1, 2 and 3 threads, on scenes where bodies touch each
// other, so that a body is B at some points and A at others, beside the ground and kinematic
// bodies: a settled pile of 200 spheres, a box stack, two boxes on a belt (each too small for
// a stage to split: one thread whatever the setting), and 12 x 12 stacks of two boxes on a
// kinematic ground, whose 1 152 points (2 304 body entries) split the per-body sums on 2 and
// 3 threads (checked: the entries reach kItemsPerThread a thread, and loops were split). The sums
// are compared within 4e-16 of the sum of the terms' magnitudes (the same additions in the same
// order agree bit for bit; the bound leaves the compiler room to order a product's roundings).
// Newton's third law on top: the contact forces on all bodies add up to those of the points with a
// world side.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "contact/split_count.hpp"
#include "core/dynamics.hpp"
#include "core/simulator.hpp"
#include "core/stage_threads.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

// n x n stacks of two 0.2 m boxes on the ground, each box at its static depth.
std::string stacks(int n) {
  std::ostringstream s;
  s.precision(17);
  const double k = 6.0e5, m = 4.0, g = 9.81;
  s << "simulation: {time_step: 2.0e-4, integrator: semi_implicit_euler}\n"
    << "friction_laws:\n  coulomb: {mu: 0.5, regularization: tanh, v_eps: 0.01}\n"
    << "materials:\n  - {name: m, normal: {law: linear, stiffness: " << k
    << ", damping: 1000}, friction: coulomb, default: true}\n"
    << "bodies:\n  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: "
       "halfspace}]}\n";
  for (int i = 0; i < n * n; ++i) {
    const double x = 0.3 * (i / n), y = 0.3 * (i % n), vx = 0.01 * (i % 7 - 3);
    const double z0 = 0.1 - 2 * m * g / (4 * k), z1 = z0 + 0.2 - m * g / (4 * k);
    for (int level = 0; level < 2; ++level)
      s << "  - {name: b" << i << "_" << level << ", mass: " << m << ", position: [" << x << ", "
        << y << ", " << (level == 0 ? z0 : z1) << "], velocity: [" << vx * level
        << ", 0, 0], geometry: [{name: s" << i << "_" << level
        << ", shape: box, size: [0.2, 0.2, 0.2]}]}\n";
  }
  return s.str();
}

std::shared_ptr<const Model> load(const std::string& file, int threads) {
  io::RunSettings settings;
  settings.threads = threads;
  if (file.rfind("stacks", 0) == 0)
    return io::loadSceneFromString(stacks(12), "stacks.yaml", {}, {}, settings).model;
  const std::string path = std::string(TRIBO_SOURCE_DIR) + "/scenes/" + file;
  return io::loadSceneFromString(test::fileText(path), path, {}, {}, settings).model;
}

struct Sum {
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double scale = 0.0;  // sum of the terms' magnitudes
  void add(const Vec3& f, const Vec3& t) {
    force += f;
    torque += t;
    scale += f.norm() + t.norm();
  }
};

// `split`: the scene's body entries must reach kItemsPerThread a thread, and loops split.
void expectAssembledAsSummed(const std::string& file, int steps, bool split = false) {
  SCOPED_TRACE(file);
  const auto model = load(file, 1);
  Simulator sim(model);
  for (int i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok) << "step " << i;
  const State state = sim.state();
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    const auto threaded = load(file, threads);
    Dynamics dynamics(threaded);
    const long splits_before = contact::splitLoopCount().load();
    const Workspace& ws = dynamics.evaluate(state);
    const long splits = contact::splitLoopCount().load() - splits_before;
    const Model& m = *threaded;
    std::vector<Sum> sums(m.bodies.size());
    Vec3 on_world = Vec3::Zero();
    int between_bodies = 0;
    std::size_t entries = 0;  // a point's sides that are bodies
    for (std::size_t i = 0; i < ws.contacts.size(); ++i) {
      const contact::ContactRecord& rec = ws.contacts[i];
      const ContactPair& pair = ws.contact_pair[i];
      const BodyIndex a = m.geometries[pair.geometry_a].body;
      const BodyIndex b = m.geometries[pair.geometry_b].body;
      const Vec3 f = rec.normal_force * rec.point.normal + rec.friction_force;
      if (!b.isWorld()) {
        const Vec3 r = rec.point.position - state.bodies[b.value].position;
        sums[b.value].add(f, r.cross(f) + rec.moment);
      } else {
        on_world += f;
      }
      if (!a.isWorld()) {
        const Vec3 r = rec.point.position - state.bodies[a.value].position;
        sums[a.value].add(-f, r.cross(-f) - rec.moment);
      } else {
        on_world -= f;
      }
      between_bodies += !a.isWorld() && !b.isWorld();
      entries += static_cast<std::size_t>(!a.isWorld()) + static_cast<std::size_t>(!b.isWorld());
    }
    if (split && threads > 1) {
      EXPECT_GE(entries, kItemsPerThread * static_cast<std::size_t>(threads));
      EXPECT_GT(splits, 0);
    }
    EXPECT_GT(between_bodies, 0) << "no point between two bodies: the scene checks too little";
    Vec3 on_bodies = Vec3::Zero();
    double total_scale = 0.0;
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      const Wrench& w = ws.contact_wrench[b];
      const double tol = 4e-16 * sums[b].scale;
      EXPECT_LE((w.force - sums[b].force).norm(), tol) << "body " << m.bodies[b].name;
      EXPECT_LE((w.torque - sums[b].torque).norm(), tol) << "body " << m.bodies[b].name;
      on_bodies += w.force;
      total_scale += sums[b].scale;
    }
    // What the bodies get from each other cancels: the rest came from the world's side.
    EXPECT_LE((on_bodies + on_world).norm(), 1e-14 * total_scale);
  }
}

TEST(ContactAssembly, SettledSpherePile) { expectAssembledAsSummed("sphere_pile.yaml", 1500); }

TEST(ContactAssembly, BoxStack) { expectAssembledAsSummed("box_stack.yaml", 300); }

TEST(ContactAssembly, TwoBoxesOnABelt) { expectAssembledAsSummed("two_boxes_on_belt.yaml", 300); }

TEST(ContactAssembly, StacksOfTwoBoxesSplitAcrossThreads) {
  expectAssembledAsSummed("stacks", 20, true);
}

}  // namespace
}  // namespace tribo
