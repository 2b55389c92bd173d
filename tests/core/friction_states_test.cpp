// Friction memory's one owner (core/friction_states.hpp): the layout of
// State::friction_values (the joints' slices first, then one slice per contact record in key
// order, each of its law's size), the point that drives each record, the shared explicit
// update, and the message for a state that is not finite. The scene: scenes/belt.yaml (a
// box on a belt, four corners under a dynamic law) with a second body on a prismatic joint
// whose friction is rate-and-state under a constant load.
#include "core/friction_states.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

const std::string kScene = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";

io::Scene beltWithJointSlider(const std::string& law) {
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = test::replaced(text.str(), "  - name: box\n", R"(  - name: slider
    mass: 2.0
    inertia: [0.01, 0.01, 0.01]
    position: [0, 3, 1]
    velocity: [0.02, 0, 0]
  - name: box
)");
  yaml = test::replaced(yaml, "joints:\n", R"(joints:
  - {name: slide, type: prismatic, parent: world, child: slider, anchor: [0, 3, 1],
     axis: [1, 0, 0], friction: {law: rate_state, load: constant, normal_force: 19.62}}
)");
  return io::loadSceneFromString(yaml, kScene,
                                 {"friction=" + law, "dt=1e-5", "integrator=semi_implicit_euler"});
}

class FrictionMemory : public testing::TestWithParam<std::string> {};

TEST_P(FrictionMemory, ValuesHoldTheJointSliceThenOneSlicePerContactRecordInKeyOrder) {
  const io::Scene scene = beltWithJointSlider(GetParam());
  Simulator sim(scene.model);
  Dynamics dynamics(scene.model);
  const FrictionStates& memory = dynamics.frictionMemory();
  ASSERT_TRUE(memory.dynamic());
  EXPECT_FALSE(memory.stateful());
  const int joint_values = memory.jointValues();
  const int contact_size = scene.model->materials[0].friction->dynamic()->stateSize();
  EXPECT_GE(joint_values, 1);  // rate-and-state: one state variable
  EXPECT_EQ(std::ssize(sim.state().friction_values), joint_values);  // no contact yet
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(sim.step().ok);
  const State& s = sim.state();
  ASSERT_EQ(s.friction_states.size(), 4u);  // the box's four corners on the belt
  int next = joint_values;
  for (std::size_t r = 0; r < s.friction_states.size(); ++r) {
    const contact::FrictionStateRecord& record = s.friction_states[r];
    if (r > 0) {
      EXPECT_LT(s.friction_states[r - 1].key, record.key);
    }
    EXPECT_EQ(record.state, next);
    EXPECT_EQ(record.state_size, contact_size);
    next += record.state_size;
  }
  EXPECT_EQ(std::ssize(s.friction_values), next);
  // Each record is driven by the one contact point (a corner) that continues it, and its
  // rate slice is that point's.
  const Workspace& ws = dynamics.evaluate(s);
  ASSERT_EQ(ws.friction_state_contact.size(), 4u);
  for (std::size_t r = 0; r < 4; ++r) {
    const int i = ws.friction_state_contact[r];
    ASSERT_GE(i, 0);
    EXPECT_EQ(contact::contactKey(ws.contact_points[i].pair,
                                  static_cast<std::uint64_t>(ws.contact_points[i].feature)),
              s.friction_states[r].key);
  }
  // The shared explicit update: z + dt dz/dt, value by value.
  State next_state = s;
  addRates(s, ws.friction_state_rate, 1e-6, next_state);
  for (std::size_t k = 0; k < s.friction_values.size(); ++k)
    EXPECT_EQ(next_state.friction_values[k],
              s.friction_values[k] + 1e-6 * ws.friction_state_rate[k]);
}

TEST_P(FrictionMemory, AStateThatIsNotFiniteIsNamedByItsLawAndBody) {
  const io::Scene scene = beltWithJointSlider(GetParam());
  Simulator sim(scene.model);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(sim.step().ok);
  const Dynamics dynamics(scene.model);
  const FrictionStates& memory = dynamics.frictionMemory();
  std::string body = "unset";
  EXPECT_EQ(memory.nonFinite(sim.state(), body), "");
  EXPECT_EQ(body, "");

  State joint_nan = sim.state();
  joint_nan.friction_values[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(memory.nonFinite(joint_nan, body).find("joint"), std::string::npos);
  EXPECT_EQ(body, "");

  State contact_inf = sim.state();
  ASSERT_FALSE(contact_inf.friction_states.empty());
  contact_inf.friction_values[static_cast<std::size_t>(contact_inf.friction_states[2].state)] =
      std::numeric_limits<double>::infinity();
  const std::string what = memory.nonFinite(contact_inf, body);
  EXPECT_NE(what.find("'" + GetParam() + "'"), std::string::npos) << what;
  EXPECT_EQ(body, "box");
}

INSTANTIATE_TEST_SUITE_P(ContactLaws, FrictionMemory,
                         testing::Values("lugre", "gms", "rate_state", "elasto_plastic"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tribo
