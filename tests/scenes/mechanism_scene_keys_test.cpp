// Every joint type and every joint key is reachable from a scene file, lands in the model as
// written, and a mistake in them is an error located at its key.
#include <gtest/gtest.h>

#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

const std::string kAllJoints = R"(
simulation:
  constraints: {projection: true, tolerance: 1e-9, iterations: 2, project_initial: false,
                redundant: remove, solver: sparse, sparse_threshold: 10}
bodies:
  - {name: a, mass: 1, inertia: [0.1, 0.1, 0.1]}
  - {name: b, mass: 1, inertia: [0.1, 0.1, 0.1], position: [1, 0, 0]}
  - {name: c, mass: 1, inertia: [0.1, 0.1, 0.1], position: [2, 0, 0]}
  - {name: d, mass: 1, inertia: [0.1, 0.1, 0.1], position: [3, 0, 0]}
  - {name: e, mass: 1, inertia: [0.1, 0.1, 0.1], position: [4, 0, 0]}
  - {name: f, mass: 1, inertia: [0.1, 0.1, 0.1], position: [5, 0, 0]}
  - {name: g, mass: 1, inertia: [0.1, 0.1, 0.1], position: [6, 0, 0]}
  - {name: h, mass: 1, inertia: [0.1, 0.1, 0.1], position: [7, 0, 0]}
  - {name: i, mass: 1, inertia: [0.1, 0.1, 0.1], position: [8, 0, 0]}
  - {name: k, mass: 1, inertia: [0.1, 0.1, 0.1], position: [9, 0, 0]}
joints:
  - {name: weld, type: fixed, child: a}
  - name: hinge
    type: revolute
    child: b
    anchor: [1, 0, 0.5]
    axis: [0, 1, 0]
    limit: {lower: -1, upper: 1, stiffness: 100, damping: 2}
    spring: {stiffness: 5, reference: 0.1}
    damping: 0.3
    effort: 0.2
    friction: {law: coulomb, load: constant, normal_force: 3, radius: 0.02}
  - {name: wheel, type: continuous, parent: world, child: c, axis: [0, 0, 1],
     drive: {mode: velocity, constant: 2, slope: 0.1, amplitude: 0.5, frequency: 3, phase: 0.1}}
  - {name: slide, type: prismatic, child: d, axis: [1, 0, 0], friction: {law: roh_yoo},
     mimic: {joint: hinge, multiplier: 0.5, offset: 0.01}}
  - {name: ball, type: spherical, child: e}
  - {name: cardan, type: universal, child: f, axis: [0, 0, 1], axis2: [1, 0, 0]}
  - {name: sleeve, type: cylindrical, child: g, axis: [0, 0, 1]}
  - {name: table, type: planar, child: h, axis: [0, 0, 1]}
  - {name: belt, type: planar_translation, child: i, axis: [0, 1, 0]}
  - {name: floating, type: free, child: k}
friction_laws:
  coulomb: {mu: 0.4}
  roh_yoo: {mu_s: 0.35, mu_k: 0.3, v_s: 0.01, a: 1.5, beta: 0.5}
)";

using test::replaced;

std::string errorOf(const std::string& yaml) { return test::sceneErrorOf(yaml, "joints.yaml"); }

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(MechanismSceneKeys, EveryJointTypeAndKeyLandsInTheModel) {
  const io::Scene scene = io::loadSceneFromString(kAllJoints, "joints.yaml");
  const Model& m = *scene.model;
  const JointType types[] = {
      JointType::kFixed,       JointType::kRevolute,  JointType::kRevolute,
      JointType::kPrismatic,   JointType::kSpherical, JointType::kUniversal,
      JointType::kCylindrical, JointType::kPlanar,    JointType::kPlanarTranslation,
      JointType::kFree};
  ASSERT_EQ(m.joints.size(), 10u);
  for (int j = 0; j < 10; ++j) EXPECT_EQ(m.joints[j].type, types[j]) << m.joints[j].name;

  const JointElements& hinge = m.joints[1].elements;
  ASSERT_TRUE(hinge.limit && hinge.spring && hinge.friction);
  EXPECT_EQ(hinge.limit->lower, -1.0);
  EXPECT_EQ(hinge.limit->upper, 1.0);
  EXPECT_EQ(hinge.limit->stiffness, 100.0);
  EXPECT_EQ(hinge.limit->damping, 2.0);
  EXPECT_EQ(hinge.spring->stiffness, 5.0);
  EXPECT_EQ(hinge.spring->reference, 0.1);
  EXPECT_EQ(hinge.damping, 0.3);
  EXPECT_EQ(hinge.effort, 0.2);
  EXPECT_EQ(hinge.friction->law->name(), "coulomb");
  EXPECT_EQ(hinge.friction->load, JointFrictionLoad::kConstant);
  EXPECT_EQ(hinge.friction->normal_force, 3.0);
  EXPECT_EQ(hinge.friction->radius, 0.02);
  // The anchor is where the frames sit: 0.5 m above the child's centre.
  EXPECT_TRUE(m.joints[1].anchor_in_child.isApprox(Vec3(0, 0, 0.5)));

  const auto& drive = m.joints[2].elements.drive;
  ASSERT_TRUE(drive);
  EXPECT_EQ(drive->mode, DriveMode::kVelocity);
  EXPECT_EQ(drive->function.constant, 2.0);
  EXPECT_EQ(drive->function.slope, 0.1);
  EXPECT_EQ(drive->function.amplitude, 0.5);
  EXPECT_EQ(drive->function.frequency, 3.0);
  EXPECT_EQ(drive->function.phase, 0.1);

  ASSERT_TRUE(m.joints[3].elements.friction);
  EXPECT_EQ(m.joints[3].elements.friction->law->name(), "roh_yoo");
  EXPECT_EQ(m.joints[3].elements.friction->load, JointFrictionLoad::kReaction);
  ASSERT_EQ(m.couplings.size(), 1u);
  EXPECT_EQ(m.couplings[0].leader, 1);
  EXPECT_EQ(m.couplings[0].follower, 3);
  EXPECT_EQ(m.couplings[0].multiplier, 0.5);
  EXPECT_EQ(m.couplings[0].offset, 0.01);

  // The universal joint's second axis is its frame's x, in the child.
  EXPECT_TRUE(m.joints[5].axes_in_child.col(0).isApprox(Vec3::UnitX()));

  const ConstraintOptions& c = m.options.constraints;
  EXPECT_TRUE(c.projection);
  EXPECT_EQ(c.projection_tolerance, 1e-9);
  EXPECT_EQ(c.projection_iterations, 2);
  EXPECT_FALSE(c.project_initial);
  EXPECT_EQ(c.redundant, RedundancyPolicy::kRemove);
  EXPECT_EQ(c.solver, ConstraintSolverKind::kSparse);
  EXPECT_EQ(c.sparse_threshold, 10);
}

TEST(MechanismSceneKeys, MistakesAreLocatedAtTheirKey) {
  EXPECT_HAS(errorOf(replaced(kAllJoints, "type: spherical", "type: ball")),
             "joints[4].type: unknown joint type 'ball' (expected one of: fixed, revolute, "
             "continuous, prismatic, planar_translation, spherical, universal, cylindrical, "
             "planar, free)");
  EXPECT_HAS(
      errorOf(replaced(kAllJoints, "{name: ball, type: spherical, child: e}",
                       "{name: ball, type: spherical, child: e, limit: {lower: 0, upper: 1}}")),
      "joints[4].limit: joint 'ball': a limit needs a revolute or prismatic joint");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "friction: {law: roh_yoo}", "friction: {law: stick}")),
             "joints[3].friction.law: friction law 'stick' is not defined in friction_laws "
             "(defined: coulomb, roh_yoo)");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "joint: hinge", "joint: elbow")),
             "joints[3].mimic.joint: unknown joint 'elbow' (known joints: weld, hinge");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "{law: roh_yoo}", "{law: roh_yoo, normal_force: 2}")),
             "joints[3].friction.normal_force: normal_force applies to load: constant only");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "lower: -1", "min: -1")),
             "joints[1].limit.min: unknown key 'min'");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "lower: -1", "lower: 2")),
             "joints[1].limit: joint 'hinge' limit: expected finite lower <= upper");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "axis2: [1, 0, 0]", "axis2: [1, 0, 1]")),
             "joints[5]: joint 'cardan': axis2 must be normal to axis");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "mode: velocity", "mode: torque")),
             "joints[2].drive.mode: expected one of position, velocity, found 'torque'");
  EXPECT_HAS(errorOf(replaced(kAllJoints, "solver: sparse", "solver: fast")),
             "simulation.constraints.solver: unknown constraint solver 'fast'");
}

}  // namespace
}  // namespace tribo
