// scenes/ball_drop.yaml: a sphere on a Hunt-Crossley contact whose damping was set from a
// restitution e. Thrown down without gravity it must leave at exactly e times its impact
// speed (the exact Hunt-Crossley relation, contact/normal_law.hpp; independent of mass,
// stiffness and exponent), and with gravity its mechanical energy (kinetic + potential +
// elastic) must never rise from one step to the next at any step the engine allows.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/normal_law.hpp"
#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/ball_drop.yaml";
constexpr double kR = 0.1, kM = 1.0;

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

// Kinetic + potential + elastic energy of the ball [J].
double energy(const Model& model, const State& s, const Workspace& ws) {
  const BodyState& b = s.bodies[1];
  const Mat3 r = b.orientation.toRotationMatrix();
  double e = 0.5 * kM * b.velocity.squaredNorm() +
             0.5 * b.angular_velocity.dot(r * model.bodies[1].inertia * r.transpose() *
                                          b.angular_velocity) -
             kM * model.options.gravity.dot(b.position);
  for (const auto& c : ws.contacts)
    e += model.materials[model.contactPair(c.point.pair).material].normal.energy(c.point.depth);
  return e;
}

TEST(BallDropScene, ThrownDownItLeavesAtTheRestitutionOfTheExactHuntCrossleyRelation) {
  for (double e : {0.5, 0.8, 0.95}) {
    const double v_in = 2.0;
    const auto scene =
        io::loadScene(kScene, {"gz=0", set("v0", -v_in), set("h0", kR + 1e-4), set("e", e),
                               set("v_impact", v_in), "dt=1e-5", "duration=0.02"});
    Simulator sim(scene.model);
    double v_out = NAN;
    while (sim.state().time < 0.02) {
      const double z0 = sim.state().bodies[1].position.z();
      const double v0 = sim.state().bodies[1].velocity.z();
      ASSERT_TRUE(sim.step().ok);
      const double z1 = sim.state().bodies[1].position.z();
      if (v0 > 0 && z0 < kR && z1 >= kR) {  // leaves the ground within this step
        v_out = sim.state().bodies[1].velocity.z();
        break;
      }
    }
    ASSERT_TRUE(std::isfinite(v_out)) << "no rebound for e = " << e;
    // Measured against the analytic relation; the integration error at 1e-5 s is ~1e-7.
    EXPECT_NEAR(v_out / v_in, e, 1e-5) << "e " << e;
  }
}

TEST(BallDropScene, DroppedTheEnergyNeverRisesAtAnyAllowedStep) {
  // The engine's stability limit for this contact (Hunt-Crossley linearized at the static
  // depth) is far above the impact's needs; steps from 1e-5 s up to 4e-4 s (12 steps per
  // contact) are all allowed. The damping only dissipates: E(n+1) <= E(n), up to
  // round-off of E (1e-12 J).
  for (double dt : {1e-5, 1e-4, 4e-4}) {
    const auto scene = io::loadScene(kScene, {set("dt", dt), "duration=1.0"});
    Simulator sim(scene.model);
    double previous = energy(*scene.model, sim.state(), sim.current());
    const double initial = previous;
    double worst_rise = -INFINITY;
    int bounces = 0;
    bool in_contact = false;
    while (sim.state().time < 1.0 - 0.5 * dt) {
      ASSERT_TRUE(sim.step().ok) << "dt " << dt;
      const Workspace& ws = sim.current();
      const double now = energy(*scene.model, sim.state(), ws);
      worst_rise = std::max(worst_rise, now - previous);
      previous = now;
      if (!ws.contacts.empty() && !in_contact) ++bounces;
      in_contact = !ws.contacts.empty();
    }
    EXPECT_GE(bounces, 2) << "dt " << dt;
    EXPECT_LE(worst_rise, 1e-12 * initial) << "dt " << dt;
    EXPECT_LT(previous, initial) << "dt " << dt;
  }
}

}  // namespace
}  // namespace tribo
