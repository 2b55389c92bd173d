// Bodies whose inertia is a multiple of the identity (spheres, cubes: the isotropic bodies of
// core/dynamics.hpp) against Euler's equations, I dw/dt = T - w x (I w) in the body frame:
// - torque-free, in any orientation and at any spin, no angular acceleration at all (I w is
//   parallel to w, so w x I w = 0) and a world inverse inertia of exactly 1 / I;
// - a torque T about any axis: dw/dt = T / I, and over a run w(t) = w0 + T t / I;
// - a body almost isotropic (one moment off by 1e-12 to 1e-3 of the others) keeps the
//   general formulas: its angular acceleration is the gyroscopic term worked out here in the
//   body frame, not zero;
// - the energy account's kinetic energy of a spinning sphere, I |w|^2 / 2;
// - spheres and cubes given by their geometry (the solid formulas) are isotropic bodies; a box
//   with one edge longer is not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/energy.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

struct Spin {
  Mat3 inertia;
  Quat orientation;
  Vec3 angular_velocity;
  Vec3 torque = Vec3::Zero();
};

// One free body in zero gravity, no contacts; a constant torque when given.
std::shared_ptr<const Model> spinningBody(const Spin& s, IntegratorType integrator) {
  ModelBuilder b;
  Body body;
  body.name = "spinner";
  body.mass = 3.0;
  body.inertia = s.inertia;
  body.orientation = s.orientation;
  body.angular_velocity = s.angular_velocity;
  const BodyIndex index = b.addBody(body);
  if (s.torque != Vec3::Zero()) {
    AppliedLoad load;
    load.name = "twist";
    load.body = index;
    for (int i = 0; i < 3; ++i) load.torque[i] = Signal::constant(s.torque[i]);
    b.addLoad(load);
  }
  b.options().gravity = Vec3::Zero();
  b.options().integrator = integrator;
  b.options().time_step = 1e-3;
  b.options().duration = 1.0;
  return b.build();
}

Quat randomOrientation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

Vec3 randomVector(std::mt19937& rng, double magnitude) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Vec3(n(rng), n(rng), n(rng)).normalized() * magnitude;
}

TEST(IsotropicBody, TorqueFreeHasNoAngularAccelerationInAnyOrientation) {
  std::mt19937 rng(7);
  int cases = 0;
  for (const double moment : {1e-9, 2.5e-3, 1.0, 40.0, 1e6})
    for (const double spin : {1e-6, 1.0, 300.0, 1e4})
      for (int k = 0; k < 4; ++k) {
        const Spin s{moment * Mat3::Identity(), randomOrientation(rng), randomVector(rng, spin)};
        Dynamics dynamics(spinningBody(s, IntegratorType::kSemiImplicitEuler));
        const Workspace& ws = dynamics.evaluate(dynamics.initialState());
        // Exact: I w parallel to w leaves no gyroscopic term, and R I R^T = I.
        EXPECT_EQ(ws.angular_acceleration[0], Vec3::Zero()) << moment << " " << spin;
        EXPECT_EQ(ws.inv_inertia_world[0], Mat3((1.0 / moment) * Mat3::Identity())) << moment;
        ++cases;
      }
  EXPECT_EQ(cases, 80);
}

TEST(IsotropicBody, TorqueGivesTorqueOverMoment) {
  std::mt19937 rng(11);
  for (const double moment : {1e-6, 0.02, 5.0, 1e4})
    for (const double torque : {1e-4, 1.0, 1e3}) {
      const Spin s{moment * Mat3::Identity(), randomOrientation(rng), randomVector(rng, 2.0),
                   randomVector(rng, torque)};
      const auto model = spinningBody(s, IntegratorType::kRk4);
      Dynamics dynamics(model);
      const Workspace& ws = dynamics.evaluate(dynamics.initialState());
      const Vec3 want = s.torque / moment;
      EXPECT_LT((ws.angular_acceleration[0] - want).norm(), 1e-15 * want.norm())
          << moment << " " << torque;
      Simulator sim(model);
      for (int i = 0; i < 500; ++i) ASSERT_TRUE(sim.step().ok);
      // w(t) = w0 + T t / I: linear in time, which RK4 integrates to rounding.
      const Vec3 w = s.angular_velocity + want * sim.state().time;
      EXPECT_LT((sim.state().bodies[0].angular_velocity - w).norm(), 1e-12 * w.norm())
          << moment << " " << torque;
    }
}

TEST(IsotropicBody, AlmostIsotropicBodyKeepsItsGyroscopicTerm) {
  std::mt19937 rng(3);
  for (const double off : {1e-12, 1e-9, 1e-6, 1e-3})
    for (int k = 0; k < 5; ++k) {
      const double moment = 0.7;
      Mat3 inertia = moment * Mat3::Identity();
      inertia(2, 2) = moment * (1.0 + off);
      const Spin s{inertia, randomOrientation(rng), randomVector(rng, 50.0)};
      Dynamics dynamics(spinningBody(s, IntegratorType::kSemiImplicitEuler));
      const Workspace& ws = dynamics.evaluate(dynamics.initialState());
      // Euler's equations in the body frame, in long double: I a = -w x (I w).
      const Mat3 r = s.orientation.toRotationMatrix();
      const Vec3 wb = r.transpose() * s.angular_velocity;
      const long double i_xy = moment, i_z = moment * (1.0 + off);
      const long double ax = -(static_cast<long double>(wb.y()) * wb.z() * (i_z - i_xy)) / i_xy;
      const long double ay = -(static_cast<long double>(wb.z()) * wb.x() * (i_xy - i_z)) / i_xy;
      const Vec3 want_body(static_cast<double>(ax), static_cast<double>(ay), 0.0);
      const Vec3 got_body = r.transpose() * ws.angular_acceleration[0];
      // The gyroscopic term is off * |w|^2 in size; the general formulas' rounding is that of
      // |w|^2 (the two nearly equal products it subtracts).
      const double scale = 50.0 * 50.0;
      ASSERT_GT(want_body.norm(), 0.0);
      EXPECT_LT((got_body - want_body).norm(), 1e-14 * scale + 1e-9 * want_body.norm())
          << off << " " << k;
      if (off >= 1e-9) {
        EXPECT_GT(got_body.norm(), 0.5 * want_body.norm()) << off;
      }
    }
}

TEST(IsotropicBody, KineticEnergyIsHalfMomentTimesSpinSquared) {
  std::mt19937 rng(5);
  for (const double moment : {1e-8, 0.3, 2e5})
    for (const double spin : {1e-3, 7.0, 2e3}) {
      const Spin s{moment * Mat3::Identity(), randomOrientation(rng), randomVector(rng, spin)};
      Dynamics dynamics(spinningBody(s, IntegratorType::kSemiImplicitEuler));
      const State state = dynamics.initialState();
      const Workspace& ws = dynamics.evaluate(state);
      std::vector<double> body_energy;
      const EnergyAccount account = measureEnergy(dynamics.model(), state, ws, &body_energy);
      // At rest in zero gravity, spinning: E = I |w|^2 / 2, whatever the orientation.
      const double want = 0.5 * moment * spin * spin;
      ASSERT_EQ(body_energy.size(), 1u);
      EXPECT_NEAR(body_energy[0], want, 4e-16 * want) << moment << " " << spin;
      EXPECT_NEAR(account.kinetic, want, 4e-16 * want) << moment << " " << spin;
    }
}

TEST(IsotropicBody, SpheresAndCubesFromTheirGeometryAreIsotropic) {
  const std::string yaml = R"(
simulation: {duration: 0.01, time_step: 0.001, integrator: semi_implicit_euler, gravity: [0, 0, 0]}
bodies:
  - {name: ball, mass: 2.0, position: [0, 0, 0], orientation: [0.3, -0.2, 0.9, 0.1],
     angular_velocity: [3, -70, 11], geometry: [{name: g1, shape: sphere, radius: 0.037}]}
  - {name: cube, mass: 0.4, position: [1, 0, 0], orientation: [0.5, 0.5, -0.5, 0.5],
     angular_velocity: [-4, 9, 25], geometry: [{name: g2, shape: box, size: [0.13, 0.13, 0.13]}]}
  - {name: brick, mass: 0.4, position: [2, 0, 0], orientation: [0.5, 0.5, -0.5, 0.5],
     angular_velocity: [-4, 9, 25], geometry: [{name: g3, shape: box, size: [0.13, 0.13, 0.26]}]}
)";
  const io::Scene scene = io::loadSceneFromString(yaml, "spin.yaml");
  Dynamics dynamics(scene.model);
  const Workspace& ws = dynamics.evaluate(dynamics.initialState());
  const double ball = 0.4 * 2.0 * 0.037 * 0.037;
  const double cube = 0.4 * (0.13 * 0.13 + 0.13 * 0.13) / 12.0;
  EXPECT_NEAR(scene.model->bodies[0].inertia(0, 0), ball, 1e-15 * ball);
  EXPECT_NEAR(scene.model->bodies[1].inertia(1, 1), cube, 1e-15 * cube);
  EXPECT_EQ(ws.angular_acceleration[0], Vec3::Zero());
  EXPECT_EQ(ws.angular_acceleration[1], Vec3::Zero());
  EXPECT_EQ(ws.inv_inertia_world[0](1, 2), 0.0);
  // The brick precesses: |I a| = |w x I w| > 0.
  EXPECT_GT(ws.angular_acceleration[2].norm(), 1.0);
}

}  // namespace
}  // namespace tribo
