// scenes/rolling_sphere.yaml: a solid sphere on a tilted plane rolls without slipping,
// accelerating at 5/7 g sin(theta) (I = 2/5 m r^2), with the centre speed equal to r times
// the spin; friction carries 2/7 m g sin(theta). The penalty contact sits at the midpoint
// of the overlap, r_c = r - d/2 from the centre (d = m g cos(theta) / k): it rolls on r_c,
// a = g sin(theta) / (1 + 2/5 (r / r_c)^2), 2.7e-4 below 5/7 g sin(theta) here.
#include <gtest/gtest.h>

#include <cmath>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/rolling_sphere.yaml";

TEST(RollingSphereScene, RollsWithoutSlippingAtFiveSeventhsGSinTheta) {
  const double theta = 0.2, g = 9.81, r = 0.1;
  const Vec3 down(std::cos(theta), 0, -std::sin(theta));
  const Vec3 normal(std::sin(theta), 0, std::cos(theta));
  for (const std::string law : {"coulomb", "elastic_stick"}) {
    const auto scene = io::loadScene(kScene, {"law=" + law});
    Simulator sim(scene.model);
    double v1 = 0;
    while (sim.state().time < 2.0 - 1e-9) {
      ASSERT_TRUE(sim.step().ok);
      if (std::abs(sim.state().time - 1.0) < 1e-9) v1 = sim.state().bodies[1].velocity.dot(down);
    }
    const BodyState& ball = sim.state().bodies[1];
    const double a = (ball.velocity.dot(down) - v1) / 1.0;
    const double r_c = r - 0.5 * g * std::cos(theta) / 1e5;  // m = 1 kg, k = 1e5 N/m
    const double expected = g * std::sin(theta) / (1 + 0.4 * (r / r_c) * (r / r_c));
    EXPECT_NEAR(a / expected, 1.0, 1e-4) << law;
    EXPECT_NEAR(a / (5.0 / 7.0 * g * std::sin(theta)), 1.0, 1e-3) << law;
    // Rolling: the contact point's velocity v + w x (-r n) is (nearly) zero.
    const Vec3 contact_velocity = ball.velocity + ball.angular_velocity.cross(-r * normal);
    EXPECT_LT(contact_velocity.dot(down), 2e-3) << law;  // tanh creep: v_eps atanh(0.12)
    EXPECT_LT(std::abs(ball.position.y()), 1e-12) << law;
  }
}

}  // namespace
}  // namespace tribo
