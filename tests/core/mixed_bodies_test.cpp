// Dynamic and kinematic bodies listed in any order, of masses from 1 mg to 1 t, isotropic or
// not, against the sums worked out here from the bodies' initial records:
// - each body's unconstrained acceleration in zero contact: a dynamic body's g and, turning,
//   its gyroscopic term I_W^-1 (-w x I_W w); a kinematic body's zero (it keeps its velocity);
// - the energy account: kinetic energy m |v|^2 / 2 + w . I_W w / 2 and gravity -m g . x summed
//   over the dynamic bodies alone, each body's share (zero for a kinematic body), and no
//   input power without a contact, joint or load.
// The evaluation and the account read each body's mass and kind from lists of their own
// (Dynamics, EnergyTerms), not from the model's records; a list out of step with the bodies
// would give a kinematic body a share or a dynamic body another's mass.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/dynamics.hpp"
#include "core/energy.hpp"
#include "core/model_builder.hpp"

namespace tribo {
namespace {

Vec3 randomVector(std::mt19937& rng, double magnitude) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Vec3(n(rng), n(rng), n(rng)).normalized() * magnitude;
}

// A symmetric positive definite inertia with principal moments in [moment, 3 moment], turned
// by a random rotation; or moment times the identity.
Mat3 randomInertia(std::mt19937& rng, double moment, bool isotropic) {
  if (isotropic) return moment * Mat3::Identity();
  std::uniform_real_distribution<double> u(1.0, 3.0);
  std::normal_distribution<double> n(0.0, 1.0);
  const Mat3 q = Quat(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
  const Vec3 moments(moment * u(rng), moment * u(rng), moment * u(rng));
  const Mat3 inertia = q * moments.asDiagonal() * q.transpose();
  return 0.5 * (inertia + inertia.transpose());
}

TEST(MixedBodies, AccelerationsAndEnergyFollowEachBodysKindAndMassInAnyOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> exponent(-6.0, 3.0);  // 1 mg to 1 t
  std::bernoulli_distribution coin(0.5);
  const Vec3 gravity(0.3, -1.2, -9.81);
  for (int scene = 0; scene < 12; ++scene) {
    ModelBuilder builder;
    std::vector<Body> bodies;
    const int count = 1 + scene % 7;
    for (int i = 0; i < count; ++i) {
      Body body;
      body.name = "body" + std::to_string(i);
      // The first scenes put a kinematic body first, then last, then interleave at random.
      const bool kinematic = scene == 0 ? i == 0 : scene == 1 ? i == count - 1 : coin(rng);
      body.kind = kinematic ? BodyKind::kKinematic : BodyKind::kDynamic;
      body.mass = std::pow(10.0, exponent(rng));
      body.inertia = randomInertia(rng, 0.1 * body.mass, coin(rng));
      body.position = randomVector(rng, 0.01 + 10.0 * i);
      std::normal_distribution<double> n(0.0, 1.0);
      body.orientation = Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
      body.velocity = randomVector(rng, 2.0);
      body.angular_velocity = randomVector(rng, 5.0);
      builder.addBody(body);
      bodies.push_back(body);
    }
    builder.options().gravity = gravity;
    Dynamics dynamics(builder.build());
    const State state = dynamics.initialState();
    const Workspace& ws = dynamics.evaluate(state);
    std::vector<double> share;
    const EnergyAccount account = measureEnergy(dynamics.model(), state, ws, &share);
    ASSERT_EQ(share.size(), bodies.size());
    long double kinetic = 0.0L, potential = 0.0L;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const Body& body = bodies[b];
      const std::string where = "scene " + std::to_string(scene) + ", " + body.name;
      if (body.kind == BodyKind::kKinematic) {
        EXPECT_EQ(ws.linear_acceleration[b], Vec3::Zero()) << where;
        EXPECT_EQ(ws.angular_acceleration[b], Vec3::Zero()) << where;
        EXPECT_EQ(share[b], 0.0) << where;
        continue;
      }
      // Free of contact: gravity alone moves the centre; the spin turns by Euler's equations.
      EXPECT_LT((ws.linear_acceleration[b] - gravity).norm(), 1e-15 * gravity.norm()) << where;
      const Mat3 r = body.orientation.toRotationMatrix();
      const Mat3 world_inertia = r * body.inertia * r.transpose();
      const Vec3& w = body.angular_velocity;
      const Vec3 euler = world_inertia.inverse() * (-w.cross(world_inertia * w));
      EXPECT_LT((ws.angular_acceleration[b] - euler).norm(), 1e-12 * (1.0 + euler.norm())) << where;
      const double e_kinetic =
          0.5 * body.mass * body.velocity.squaredNorm() + 0.5 * w.dot(world_inertia * w);
      const double e_gravity = -body.mass * gravity.dot(body.position);
      EXPECT_NEAR(share[b], e_kinetic + e_gravity,
                  1e-14 * (std::abs(e_kinetic) + std::abs(e_gravity)))
          << where;
      kinetic += e_kinetic;
      potential += e_gravity;
    }
    const double k = static_cast<double>(kinetic), p = static_cast<double>(potential);
    EXPECT_NEAR(account.kinetic, k, 1e-14 * std::abs(k)) << scene;
    EXPECT_NEAR(account.gravity, p, 1e-14 * (std::abs(p) + std::abs(k))) << scene;
    EXPECT_EQ(account.elastic, 0.0) << scene;
    EXPECT_EQ(account.input_power, 0.0) << scene;
  }
}

}  // namespace
}  // namespace tribo
