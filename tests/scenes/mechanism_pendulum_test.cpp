// scenes/pendulum.yaml: a pendulum released at 170 degrees. Its period against the exact
// elliptic-integral value, and its energy per integrator: RK4 conserves it to its order,
// semi-implicit Euler drifts at first order (it gains energy through the centripetal
// constraint acceleration applied explicitly), projection pins the drift of the joint.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/pendulum.yaml";
constexpr double kG = 9.81, kL = 1.0, kM = 1.0, kIBob = 1e-4;

struct Swing {
  double period = 0.0;     // from downward zero crossings of the angle [s]
  double max_drift = 0.0;  // max |E - E0| / (m g L)
  double max_phi = 0.0;    // max |Phi| over the run
};

Swing swing(const std::vector<std::string>& overrides) {
  const io::Scene scene = io::loadScene(kScene, overrides);
  Simulator sim(scene.model);
  const double e0 = test::mechanicalEnergy(*scene.model, sim.state());
  Swing out;
  std::vector<double> crossings;
  double th_prev =
      std::atan2(sim.state().bodies[0].position.x(), -sim.state().bodies[0].position.z());
  double t_prev = 0.0;
  while (sim.state().time < scene.model->options.duration - 1e-9) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) break;
    const Vec3 p = sim.state().bodies[0].position;
    const double th = std::atan2(p.x(), -p.z()), t = sim.state().time;
    if (th_prev > 0 && th <= 0 && th_prev < 1.0)  // through the bottom, not through the top
      crossings.push_back(t_prev + (t - t_prev) * th_prev / (th_prev - th));
    th_prev = th;
    t_prev = t;
    out.max_drift =
        std::max(out.max_drift,
                 std::abs(test::mechanicalEnergy(*scene.model, sim.state()) - e0) / (kM * kG * kL));
  }
  if (crossings.size() >= 2)
    out.period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  out.max_phi = sim.stats().max_constraint_error;
  return out;
}

TEST(PendulumScene, PeriodAt170DegreesIsTheEllipticIntegralValue) {
  // T = 4 sqrt(I_O / (m g L)) K(sin(theta0 / 2)), I_O = I_bob + m L^2: 4.89377 s.
  const double expected = 4 * std::sqrt((kIBob + kM * kL * kL) / (kM * kG * kL)) *
                          test::ellipticK(std::sin(170.0 / 360.0 * std::numbers::pi));
  const Swing s = swing({});
  // Measured 4e-9 (RK4, 1 ms); the crossing interpolation alone allows a few 1e-9.
  EXPECT_NEAR(s.period / expected, 1.0, 2e-8) << s.period << " vs " << expected;
  EXPECT_GT(s.period, 2.4 * 2 * std::numbers::pi * std::sqrt(kL / kG));  // far from small-angle
}

TEST(PendulumScene, Rk4KeepsTheEnergyToItsOrder) {
  // Measured 1.1e-9 m g L at 1 ms over 20 s; halving the step must gain about 2^4.
  const Swing h1 = swing({"dt=0.001"}), h2 = swing({"dt=0.0005"});
  EXPECT_LT(h1.max_drift, 1e-8);
  EXPECT_LT(h2.max_drift, h1.max_drift / 8);
  EXPECT_LT(h1.max_phi, 1e-9);
}

TEST(PendulumScene, SemiImplicitEulerDriftsAtFirstOrder) {
  // 0.12 m g L at 1 ms over 20 s (the explicit velocity update of a body on a circle adds
  // h^2 (v^2 / L)^2 per step); its drift halves with the step: first order.
  const Swing h1 = swing({"integrator=semi_implicit_euler", "dt=0.001"});
  const Swing h2 = swing({"integrator=semi_implicit_euler", "dt=0.0005"});
  EXPECT_GT(h1.max_drift / h2.max_drift, 1.6);
  EXPECT_LT(h1.max_drift / h2.max_drift, 2.8);
  EXPECT_GT(h1.max_phi, 1e-4);  // and the joint drifts: mm
}

TEST(PendulumScene, ProjectionHoldsTheJointWhateverTheIntegrator) {
  for (const char* integrator : {"rk4", "semi_implicit_euler"}) {
    const Swing s = swing({std::string("integrator=") + integrator, "projection=true"});
    EXPECT_LE(s.max_phi, 1.0000001e-10) << integrator;
  }
}

}  // namespace
}  // namespace tribo
