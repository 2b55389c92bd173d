// The passes over the contact points that a step merges or skips for speed answer what the
// separate passes answered:
// - the normal force formed in the contact kinematics' pass and, where contacts are the only
//   source of force, the bodies' accelerations in the assemble's pass over the bodies (stage
//   clock off) against the stages run apart (clock on, core/dynamics.hpp): the same states,
//   contact forces and accelerations bit for bit after a run, on scenes of every kind of point
//   (a box grid whose loops split on 2 threads, checked, a pile of spheres and a Hunt-Crossley ball
//   drop through its bounce, whose accelerations are fused; the belt under RK4 on its joint and
//   LuGre stick-slip on its spring, whose are not);
// - the friction formed in the same pass, chunk by chunk, while no dynamic law is in play:
//   besides the scenes above, a grid of sliding boxes whose four materials (a batched
//   Coulomb law, elastic_stick with its anchors, an anisotropic law, rolling and spinning
//   resistance) alternate within each chunk of points, on 2 threads (split, checked);
// - the points' elastic energies formed in the same pass for the evaluation the energy guard
//   reads (Workspace::point_elastic): the energy account summed from that list against the
//   account of the stages apart, summed from the records, bit for bit, on the same scenes
//   (the Hunt-Crossley ball's energy a power of its depth; the belt's points listed but read
//   from the records, for its moving surface adds a power to each; LuGre's not listed);
// - the check's reading of the forces skipped when that pass found them finite: a box driven
//   into the floor so fast in one step that its normal force's damping term overflows (within
//   its half height, so no penetration warning reads the points) still stops the run as a
//   non-finite contact force on that box, merged or apart;
// - the per-step penetration warning (Simulator::check), which measures no width when the
//   deepest point is within every geometry's bound: a heavy box and a thin plate side by side
//   on a half-space, the box sunk to m g / (4 k) at each corner (analytic static depth), so
//   that it is deeper than its half height, deeper than the plate's only, or neither; the
//   count and the geometry named follow from the depths, as the test works them out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "contact/split_count.hpp"
#include "core/energy.hpp"
#include "core/simulator.hpp"
#include "core/stage_threads.hpp"
#include "io/scene_loader.hpp"
#include "support/same_bits.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

using test::sameBits;

std::shared_ptr<const Model> loadScene(const std::string& file, int threads) {
  io::RunSettings settings;
  settings.threads = threads;
  std::string path = TRIBO_SOURCE_DIR;  // appended in place: GCC 12 misreads a chain of +
  path += "/scenes/";
  path += file;
  return io::loadSceneFromString(test::fileText(path), path, {}, {}, settings).model;
}

// The energy accounts of two runs' last evaluations, the merged run's points' elastic energies
// listed in its pass (`listed`), the stages apart's not: the same bits.
void expectSameEnergyAccount(Simulator& merged, Simulator& apart, bool listed) {
  const Workspace &wa = merged.current(), &wb = apart.current();
  EXPECT_EQ(wa.point_elastic.size(), listed ? wa.contacts.size() : 0u);
  EXPECT_TRUE(wb.point_elastic.empty());
  const EnergyAccount x = measureEnergy(merged.model(), merged.state(), wa);
  const EnergyAccount y = measureEnergy(apart.model(), apart.state(), wb);
  EXPECT_TRUE(sameBits(x.elastic, y.elastic)) << x.elastic << " vs " << y.elastic;
  EXPECT_TRUE(sameBits(x.kinetic, y.kinetic)) << x.kinetic << " vs " << y.kinetic;
  EXPECT_TRUE(sameBits(x.gravity, y.gravity)) << x.gravity << " vs " << y.gravity;
  EXPECT_TRUE(sameBits(x.input_power, y.input_power)) << x.input_power << " vs " << y.input_power;
  if (listed && !wa.contacts.empty()) {
    EXPECT_GT(x.elastic, 0.0);  // points in contact
  }
}

TEST(PointPass, MergedPassesGiveTheSeparateStagesBits) {
  struct Case {
    std::string file;
    int steps, threads;
  };
  for (const Case& c :
       {Case{"box_grid20.yaml", 60, 2}, Case{"sphere_pile.yaml", 200, 1}, Case{"belt.yaml", 400, 1},
        Case{"lugre_stick_slip.yaml", 400, 1}, Case{"ball_drop.yaml", 4000, 1}}) {
    SCOPED_TRACE(c.file);
    const auto model = loadScene(c.file, c.threads);
    Simulator fused(model), apart(model);
    apart.setProfiling(true);
    std::size_t most_points = 0;
    const long splits_before = contact::splitLoopCount().load();
    for (int i = 0; i < c.steps; ++i) {
      ASSERT_TRUE(fused.step().ok);
      ASSERT_TRUE(apart.step().ok);
      most_points = std::max(most_points, fused.current().contacts.size());
    }
    ASSERT_GT(most_points, 0u);  // the run touched
    if (c.threads > 1) {         // the points' and bodies' loops were cut for the threads
      EXPECT_GE(most_points, c.threads * kItemsPerThread);
      EXPECT_GT(contact::splitLoopCount().load(), splits_before);
    }
    EXPECT_GT(apart.stats().profile[Stage::kNormalForce], 0.0);
    EXPECT_EQ(fused.stats().profile[Stage::kNormalForce], 0.0);
    const State &a = fused.state(), &b = apart.state();
    ASSERT_EQ(a.bodies.size(), b.bodies.size());
    for (std::size_t k = 0; k < a.bodies.size(); ++k) {
      EXPECT_TRUE(sameBits(a.bodies[k].position, b.bodies[k].position)) << "body " << k;
      EXPECT_TRUE(sameBits(a.bodies[k].velocity, b.bodies[k].velocity)) << "body " << k;
      EXPECT_TRUE(sameBits(a.bodies[k].angular_velocity, b.bodies[k].angular_velocity)) << k;
    }
    const Workspace &wa = fused.current(), &wb = apart.current();
    ASSERT_EQ(wa.contacts.size(), wb.contacts.size());
    for (std::size_t i = 0; i < wa.contacts.size(); ++i) {
      EXPECT_TRUE(sameBits(wa.contacts[i].normal_force, wb.contacts[i].normal_force)) << i;
      EXPECT_TRUE(sameBits(wa.contacts[i].friction_force, wb.contacts[i].friction_force)) << i;
    }
    for (std::size_t k = 0; k < a.bodies.size(); ++k) {
      EXPECT_TRUE(sameBits(wa.linear_acceleration[k], wb.linear_acceleration[k])) << "body " << k;
      EXPECT_TRUE(sameBits(wa.angular_acceleration[k], wb.angular_acceleration[k])) << k;
    }
    EXPECT_TRUE(sameBits(fused.stats().max_penetration, apart.stats().max_penetration));
    expectSameEnergyAccount(fused, apart, c.file != "lugre_stick_slip.yaml");
  }
}

// A side x side grid of 0.1 m boxes sliding on a half-space at 0.3 m/s, box k of surface
// s(k % 4): each surface pair its own material, so that the four kinds of friction point
// alternate every four points.
std::string mixedGrid(int side) {
  std::ostringstream s;
  s << "simulation: {time_step: 1.0e-4, integrator: semi_implicit_euler, gravity: [0, 0, -9.81],"
    << " threads: 2}\n"
    << "friction_laws:\n"
    << "  coulomb: {mu: 0.4, regularization: tanh, v_eps: 0.01}\n"
    << "  elastic_stick: {mu_s: 0.5, mu_k: 0.4, stiffness: 1.0e5, damping: 100}\n"
    << "materials:\n"
    << "  - {name: plain, friction: coulomb, normal: {stiffness: 1.0e5, damping: 200},"
    << " surfaces: [[floor, s0]], default: true}\n"
    << "  - {name: stick, friction: elastic_stick, normal: {stiffness: 1.0e5, damping: 200},"
    << " surfaces: [[floor, s1]]}\n"
    << "  - {name: grain, friction: coulomb, normal: {stiffness: 1.0e5, damping: 200},"
    << " anisotropy: {frame: b, axis: [1, 0, 0], ratio: [0.5, 1.5]}, surfaces: [[floor, s2]]}\n"
    << "  - {name: rolls, friction: coulomb, normal: {stiffness: 1.0e5, damping: 200},"
    << " rolling: {length: 0.002, stiffness: 50, damping: 0.8},"
    << " spinning: {mu: 0.3, radius: 0.005, stiffness: 10, damping: 0.1},"
    << " surfaces: [[floor, s3]]}\n"
    << "bodies:\n"
    << "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace,"
    << " surface: floor}]}\n";
  for (int k = 0; k < side * side; ++k)
    s << "  - {name: b" << k << ", mass: 1, position: [" << 0.15 * (k % side) << ", "
      << 0.15 * (k / side) << ", 0.0499], velocity: [0.3, " << 0.05 * (k % 3) << ", 0],"
      << " geometry: [{name: g" << k << ", shape: box, size: [0.1, 0.1, 0.1], surface: s" << k % 4
      << "}]}\n";
  return s.str();
}

TEST(PointPass, FrictionInTheKinematicsPassGivesTheStageBitsOnMixedMaterials) {
  const auto model = io::loadSceneFromString(mixedGrid(12), "mixed_grid.yaml").model;
  ASSERT_EQ(model->materials.size(), 4u);
  Simulator fused(model), apart(model);
  apart.setProfiling(true);
  const long splits_before = contact::splitLoopCount().load();
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(fused.step().ok);
    ASSERT_TRUE(apart.step().ok);
  }
  EXPECT_GT(contact::splitLoopCount().load(), splits_before);
  const Workspace &wa = fused.current(), &wb = apart.current();
  // 576 points: more than one chunk, and every material within the first.
  ASSERT_EQ(wa.contacts.size(), 4u * 144u);
  ASSERT_EQ(wb.contacts.size(), wa.contacts.size());
  std::vector<int> in_first_chunk(4, 0);
  for (std::size_t i = 0; i < 256; ++i) ++in_first_chunk[wa.contact_pair[i].material];
  for (int count : in_first_chunk) EXPECT_GT(count, 0);
  EXPECT_FALSE(fused.state().stick_anchors.empty());  // elastic_stick and rolling anchors
  EXPECT_TRUE(wa.forces_finite);
  EXPECT_FALSE(wb.forces_finite);  // apart: not screened, the check reads them
  for (std::size_t i = 0; i < wa.contacts.size(); ++i) {
    EXPECT_TRUE(sameBits(wa.contacts[i].normal_force, wb.contacts[i].normal_force)) << i;
    EXPECT_TRUE(sameBits(wa.contacts[i].friction_force, wb.contacts[i].friction_force)) << i;
    EXPECT_TRUE(sameBits(wa.contacts[i].moment, wb.contacts[i].moment)) << i;
    EXPECT_TRUE(sameBits(wa.contacts[i].mu, wb.contacts[i].mu)) << i;
  }
  const State &a = fused.state(), &b = apart.state();
  for (std::size_t k = 0; k < a.bodies.size(); ++k) {
    EXPECT_TRUE(sameBits(a.bodies[k].position, b.bodies[k].position)) << "body " << k;
    EXPECT_TRUE(sameBits(a.bodies[k].velocity, b.bodies[k].velocity)) << "body " << k;
    EXPECT_TRUE(sameBits(a.bodies[k].angular_velocity, b.bodies[k].angular_velocity)) << k;
  }
  // The boxes slid: friction acted (not a grid at rest, where every law gives zero).
  EXPECT_LT(a.bodies[1].velocity.x(), 0.3 - 0.3 * 9.81 * 300 * 1e-4 * 0.5);
  expectSameEnergyAccount(fused, apart, true);
}

TEST(PointPass, AnOverflowingNormalForceStillStopsTheRunNamingTheBox) {
  // A 0.1 m box 10 mm above the floor falling at 3 m/s with a 10 ms step: one step later its
  // corners are 20 mm deep (within its 50 mm half height: no penetration warning, so the check
  // reads the forces only when the points' pass did not screen them) and sinking at 3 m/s, and
  // c d' = 1e308 x 3 overflows; its state is still finite.
  const double gap = 0.01, speed = 3.0, step = 0.01, damping = 1e308;
  ASSERT_TRUE(std::isinf(damping * speed));
  std::ostringstream s;
  s.precision(17);
  s << "simulation: {time_step: " << step
    << ", integrator: semi_implicit_euler, gravity: [0, 0, 0]}\n"
    << "friction_laws: {coulomb: {mu: 0.4, regularization: tanh, v_eps: 0.01}}\n"
    << "materials: [{name: m, friction: coulomb, normal: {stiffness: 1.0e5, damping: " << damping
    << "}, default: true}]\n"
    << "bodies:\n"
    << "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
    << "  - {name: falling, mass: 1, position: [0, 0, " << 0.05 + gap << "], velocity: [0.1, 0, "
    << -speed << "], geometry: [{name: cube, shape: box, size: [0.1, 0.1, 0.1]}]}\n";
  const auto model = io::loadSceneFromString(s.str(), "overflow.yaml").model;
  for (const bool profiling : {false, true}) {
    SCOPED_TRACE(profiling ? "apart" : "merged");
    Simulator sim(model);
    sim.setProfiling(profiling);
    const StepStatus status = sim.step();
    EXPECT_FALSE(status.ok);
    EXPECT_EQ(status.quantity, "contact_force") << status.message;
    EXPECT_EQ(status.body, "falling") << status.message;
    EXPECT_NE(status.message.find("geometry 'cube'"), std::string::npos) << status.message;
    EXPECT_TRUE(sim.state().bodies[1].position.allFinite());  // the last good state, kept
  }
}

// A box of mass `box_mass` (0.2 m cube, half height 0.1 m) and a plate of 0.5 kg (0.2 x 0.2 x
// 0.004 m, half height 2 mm) on a half-space, each placed at its static depth m g / (4 k) at
// rest (damping low enough for the plate's corners at this step).
constexpr double kStiffness = 1e5, kGravity = 9.81;

std::string boxAndPlate(double box_mass) {
  std::ostringstream s;
  s.precision(17);
  auto body = [&](const char* name, double m, double x, double half_height) {
    const double depth = m * kGravity / (4 * kStiffness);
    s << "  - {name: " << name << ", mass: " << m << ", position: [" << x << ", 0, "
      << half_height - depth << "], geometry: [{name: " << name
      << "_shape, shape: box, size: [0.2, 0.2, " << 2 * half_height << "]}]}\n";
  };
  s << "simulation: {time_step: 1.0e-4, integrator: semi_implicit_euler, gravity: [0, 0, "
    << -kGravity << "]}\n"
    << "friction_laws: {coulomb: {mu: 0.4, regularization: tanh, v_eps: 0.01}}\n"
    << "materials:\n"
    << "  - {name: m, normal: {law: linear, stiffness: " << kStiffness
    << ", damping: 200}, friction: coulomb, default: true}\n"
    << "bodies:\n"
    << "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n";
  body("box", box_mass, 0.0, 0.1);
  body("plate", 0.5, 0.5, 0.002);
  return s.str();
}

TEST(PointPass, PenetrationWarningCountsWhatTheDepthsSay) {
  // Static corner depths of the box: 0.25 mm (shallower than both bounds), 4.9 mm (past the
  // plate's 2 mm half height, within the box's 0.1 m) and 0.15 m (past the box's own).
  for (const double box_mass : {10.0, 200.0, 6116.0}) {
    SCOPED_TRACE(box_mass);
    const double depth = box_mass * kGravity / (4 * kStiffness);
    const auto model = io::loadSceneFromString(boxAndPlate(box_mass), "box_and_plate.yaml").model;
    Simulator sim(model);
    const int steps = 50;
    for (int i = 0; i < steps; ++i) ASSERT_TRUE(sim.step().ok);
    ASSERT_EQ(sim.current().contacts.size(), 8u);
    const StepStats& s = sim.stats();
    // The plate's corners sink 12 um: never past its 2 mm. The box's past 0.1 m only when
    // its static depth is; it stays within 1 % of that depth (placed there, damped).
    EXPECT_NEAR(sim.stats().max_penetration, depth, 0.01 * depth);
    if (depth > 0.1) {
      EXPECT_EQ(s.deep_penetrations, 4L * steps);
      ASSERT_GE(s.deepest_geometry, 0);
      EXPECT_EQ(model->geometries[s.deepest_geometry].name, "box_shape");
      EXPECT_NEAR(s.deepest_extent, 0.1, 1e-9);
      EXPECT_NEAR(s.deepest_ratio, depth / 0.1, 0.01 * depth / 0.1);
    } else {
      EXPECT_EQ(s.deep_penetrations, 0);
      EXPECT_EQ(s.deepest_geometry, -1);
    }
  }
}

}  // namespace
}  // namespace tribo
