// scenes/dzhanibekov.yaml: a free body spun about its intermediate axis turns over
// periodically. Kinetic energy and angular momentum (world) are conserved; the time between
// flips is 2 K(k) / lambda from the closed-form solution of Euler's equations (Landau &
// Lifshitz, Mechanics, sec. 37: for L^2 < 2 E I2 with axes 1 and 3 exchanged,
// lambda^2 = (I2 - I1)(2 E I3 - L^2) / (I1 I2 I3), k^2 = (I3 - I2)(L^2 - 2 E I1) /
// ((I2 - I1)(2 E I3 - L^2))).
#include <gtest/gtest.h>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/dzhanibekov.yaml";

TEST(DzhanibekovScene, FlipsAtTheEllipticPeriodKeepingEnergyAndMomentum) {
  const io::Scene scene = io::loadScene(kScene);
  ASSERT_EQ(scene.model->joints.size(), 1u);
  EXPECT_EQ(scene.model->joints[0].type, JointType::kFree);
  Simulator sim(scene.model);
  const Mat3& inertia = scene.model->bodies[0].inertia;
  const double i1 = inertia(0, 0), i2 = inertia(1, 1), i3 = inertia(2, 2);
  auto body_w = [&] {
    const BodyState& s = sim.state().bodies[0];
    return Vec3(s.orientation.conjugate() * s.angular_velocity);
  };
  const Vec3 w0 = body_w();
  const double e2 = w0.dot(inertia * w0);  // 2 E
  const double l2 = (inertia * w0).squaredNorm();
  ASSERT_LT(l2, e2 * i2);  // the case the scene is set up for
  const double lambda = std::sqrt((i2 - i1) * (e2 * i3 - l2) / (i1 * i2 * i3));
  const double k = std::sqrt((i3 - i2) * (l2 - e2 * i1) / ((i2 - i1) * (e2 * i3 - l2)));
  const double expected = 2 * test::ellipticK(k) / lambda;  // between sign changes of w2

  const Vec3 momentum0 = sim.state().bodies[0].orientation * (inertia * w0);
  std::vector<double> flips;
  double w2_prev = w0.y(), t_prev = 0.0, energy_error = 0.0, momentum_error = 0.0;
  while (sim.state().time < 20.0 - 1e-9) {
    ASSERT_TRUE(sim.step().ok);
    const Vec3 w = body_w();
    const double t = sim.state().time;
    if ((w2_prev > 0) != (w.y() > 0))
      flips.push_back(t_prev + (t - t_prev) * w2_prev / (w2_prev - w.y()));
    w2_prev = w.y();
    t_prev = t;
    energy_error = std::max(energy_error, std::abs(w.dot(inertia * w) - e2) / e2);
    const Vec3 momentum = sim.state().bodies[0].orientation * (inertia * w);
    momentum_error = std::max(momentum_error, (momentum - momentum0).norm() / momentum0.norm());
  }
  ASSERT_GE(flips.size(), 6u);
  const double measured = (flips.back() - flips.front()) / (flips.size() - 1);
  // Measured: 2e-8 relative, energy 4e-11, momentum 3.5e-10 (RK4, 1 ms).
  EXPECT_NEAR(measured / expected, 1.0, 1e-6) << measured << " vs " << expected;
  EXPECT_LT(energy_error, 1e-8);
  EXPECT_LT(momentum_error, 1e-8);
}

}  // namespace
}  // namespace tribo
