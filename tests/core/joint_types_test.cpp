// Each joint type removes exactly the motions it should: a body given an arbitrary velocity
// is projected (ConstraintOptions::project_initial) onto the velocities the joint allows,
// whose form is known in closed form; then typical motions against closed forms (a slider
// on an incline, a spinning drop along a cylindrical joint, a puck on a planar joint, the
// Cardan velocity ratio of a universal joint, a spherical pendulum's energy).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/constraint_solver.hpp"
#include "core/simulator.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;
const Vec3 kCentre(0.3, -0.2, 0.5);
const Vec3 kAnchor(0.1, 0.1, 0.2);
const Vec3 kAxis = Vec3(1, 2, 2).normalized();
const Vec3 kAxis2 = Vec3(2, 0, -1).normalized();  // normal to kAxis
const Vec3 kV0(0.4, -1.1, 0.7), kW0(1.3, 0.2, -0.9);

std::shared_ptr<const Model> oneJoint(JointType type, const Vec3& gravity = Vec3::Zero()) {
  ModelBuilder b;
  b.options().gravity = gravity;
  Body body;
  body.name = "b";
  body.mass = 2.0;
  body.inertia = Vec3(0.1, 0.2, 0.25).asDiagonal();
  body.position = kCentre;
  body.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3(1, -1, 2).normalized()));
  body.velocity = kV0;
  body.angular_velocity = kW0;
  const BodyIndex i = b.addBody(body);
  b.addJoint("j", type, BodyIndex::world(), i, kAnchor, kAxis, kAxis2);
  return b.build();
}

struct Allowed {
  JointType type;
  int dof;
};

class JointTypeVelocities : public ::testing::TestWithParam<Allowed> {};

TEST_P(JointTypeVelocities, ProjectOntoTheMotionsTheJointAllows) {
  const auto [type, dof] = GetParam();
  const auto model = oneJoint(type);
  EXPECT_EQ(ConstraintSolver(*model).equationCount(), 6 - dof) << jointTypeName(type);
  const BodyState s = Simulator(model).state().bodies[0];
  const Vec3 r = kCentre - kAnchor;  // centre of mass from the anchor
  const Vec3& v = s.velocity;
  const Vec3& w = s.angular_velocity;
  const Vec3 anchor_velocity = v - w.cross(r);
  auto along = [](const Vec3& x) { return x - x.dot(kAxis) * kAxis; };  // part normal to axis
  constexpr double kTol = 1e-12;
  switch (type) {
    case JointType::kFixed:
      EXPECT_LT(v.norm() + w.norm(), kTol);
      break;
    case JointType::kRevolute:
      EXPECT_LT(along(w).norm(), kTol);
      EXPECT_LT(anchor_velocity.norm(), kTol);
      EXPECT_GT(w.norm(), 0.1);
      break;
    case JointType::kPrismatic:
      EXPECT_LT(w.norm(), kTol);
      EXPECT_LT(along(v).norm(), kTol);
      EXPECT_GT(v.norm(), 0.1);
      break;
    case JointType::kSpherical:
      EXPECT_LT(anchor_velocity.norm(), kTol);
      EXPECT_GT(w.norm(), 0.1);
      break;
    case JointType::kUniversal:
      EXPECT_LT(std::abs(w.dot(kAxis.cross(kAxis2))), kTol);
      EXPECT_LT(anchor_velocity.norm(), kTol);
      EXPECT_GT(std::abs(w.dot(kAxis)), 0.1);
      EXPECT_GT(std::abs(w.dot(kAxis2)), 0.1);
      break;
    case JointType::kCylindrical:
      EXPECT_LT(along(w).norm(), kTol);
      EXPECT_LT(along(anchor_velocity).norm(), kTol);
      EXPECT_GT(std::abs(anchor_velocity.dot(kAxis)), 0.1);
      break;
    case JointType::kPlanar:
      EXPECT_LT(along(w).norm(), kTol);
      EXPECT_LT(std::abs(anchor_velocity.dot(kAxis)), kTol);
      EXPECT_GT(anchor_velocity.norm(), 0.1);
      break;
    case JointType::kPlanarTranslation:
      EXPECT_LT(w.norm(), kTol);
      EXPECT_LT(std::abs(v.dot(kAxis)), kTol);
      EXPECT_GT(v.norm(), 0.1);
      break;
    case JointType::kFree:
      EXPECT_EQ(v, kV0);
      EXPECT_EQ(w, kW0);
      break;
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllTypes, JointTypeVelocities,
    ::testing::Values(Allowed{JointType::kFixed, 0}, Allowed{JointType::kRevolute, 1},
                      Allowed{JointType::kPrismatic, 1}, Allowed{JointType::kSpherical, 3},
                      Allowed{JointType::kUniversal, 2}, Allowed{JointType::kCylindrical, 2},
                      Allowed{JointType::kPlanar, 3}, Allowed{JointType::kPlanarTranslation, 2},
                      Allowed{JointType::kFree, 6}),
    [](const auto& info) { return jointTypeName(info.param.type); });

void run(Simulator& sim, double t) {
  const long n = std::lround(t / sim.model().options.time_step);
  for (long i = 0; i < n; ++i) ASSERT_TRUE(sim.step().ok);
}

TEST(JointTypes, PrismaticSlidesDownItsInclineAtGravityAlongTheAxis) {
  Simulator sim(oneJoint(JointType::kPrismatic, Vec3(0, 0, -kG)));
  const Vec3 p0 = sim.state().bodies[0].position;
  const double v0 = sim.state().bodies[0].velocity.dot(kAxis);
  run(sim, 1.0);
  const double a = -kG * kAxis.z();
  EXPECT_NEAR((sim.state().bodies[0].position - p0).dot(kAxis), v0 + 0.5 * a, 1e-9);
  EXPECT_LT((sim.state().bodies[0].position - p0).cross(kAxis).norm(), 1e-9);
  EXPECT_LT(sim.state().bodies[0].angular_velocity.norm(), 1e-9);
}

TEST(JointTypes, CylindricalLetsAVerticalSpinnerFallAndKeepsItsSpin) {
  ModelBuilder b;
  Body body;
  body.name = "spinner";
  body.inertia = Vec3(0.2, 0.2, 0.3).asDiagonal();
  body.position = Vec3(0, 0, 1);
  body.angular_velocity = Vec3(0, 0, 7.0);
  const BodyIndex i = b.addBody(body);
  b.addJoint("shaft", JointType::kCylindrical, BodyIndex::world(), i, Vec3(0, 0, 1), Vec3::UnitZ());
  Simulator sim(b.build());
  run(sim, 1.0);
  EXPECT_NEAR(sim.state().bodies[0].position.z(), 1.0 - 0.5 * kG, 1e-9);
  EXPECT_NEAR(sim.state().bodies[0].angular_velocity.z(), 7.0, 1e-9);
  EXPECT_LT(sim.state().bodies[0].position.head<2>().norm(), 1e-9);
}

TEST(JointTypes, PlanarCarriesGravityAndLeavesInPlaneMotionFree) {
  ModelBuilder b;
  Body body;
  body.name = "puck";
  body.inertia = Vec3(0.1, 0.1, 0.2).asDiagonal();
  body.velocity = Vec3(0.5, -0.3, 0);
  body.angular_velocity = Vec3(0, 0, 2.0);
  const BodyIndex i = b.addBody(body);
  b.addJoint("table", JointType::kPlanar, BodyIndex::world(), i, Vec3::Zero(), Vec3::UnitZ());
  Simulator sim(b.build());
  run(sim, 2.0);
  const BodyState& s = sim.state().bodies[0];
  EXPECT_NEAR(s.position.x(), 1.0, 1e-9);
  EXPECT_NEAR(s.position.y(), -0.6, 1e-9);
  EXPECT_NEAR(s.position.z(), 0.0, 1e-9);
  EXPECT_NEAR(s.angular_velocity.z(), 2.0, 1e-9);
}

TEST(JointTypes, UniversalJointFollowsTheCardanVelocityRatio) {
  // Input shaft along x driven at w1; output shaft at beta = 30 deg in the x-y plane; the
  // cross's arms: z on the input, (-sin beta, cos beta, 0) on the output. With theta1 from
  // there: tan theta2 = cos(beta) tan theta1, w2 / w1 = cos(beta) / (1 - sin^2 beta sin^2 theta1).
  const double beta = std::numbers::pi / 6, w1 = 3.0;
  ModelBuilder b;
  b.options().time_step = 1e-3;
  b.options().constraints.redundant = RedundancyPolicy::kRemove;  // shared centre
  const Vec3 s2(std::cos(beta), std::sin(beta), 0), arm2(-std::sin(beta), std::cos(beta), 0);
  auto shaft = [&](const std::string& name, const Vec3& axis) {
    Body body;
    body.name = name;
    body.inertia = Mat3::Identity() * 0.01;
    body.position = 0.2 * axis;
    return b.addBody(body);
  };
  const BodyIndex in = shaft("input", Vec3::UnitX()), out = shaft("output", s2);
  const int drive = b.addJoint("in_bearing", JointType::kRevolute, BodyIndex::world(), in,
                               Vec3::Zero(), Vec3::UnitX(), Vec3::UnitZ());
  b.setJointDrive(drive, {DriveMode::kVelocity, {w1, 0, 0, 0, 0}});
  b.addJoint("out_bearing", JointType::kRevolute, BodyIndex::world(), out, Vec3::Zero(), s2, arm2);
  b.addJoint("cross", JointType::kUniversal, in, out, Vec3::Zero(), Vec3::UnitZ(), arm2);
  Simulator sim(b.build());
  double worst_rate = 0.0, worst_angle = 0.0;
  for (int i = 0; i < 3000; ++i) {
    ASSERT_TRUE(sim.step().ok);
    const double t = sim.state().time, theta1 = w1 * t;
    const double w2 = sim.state().bodies[1].angular_velocity.dot(s2);
    const double expected_w2 =
        w1 * std::cos(beta) / (1 - std::pow(std::sin(beta) * std::sin(theta1), 2));
    worst_rate = std::max(worst_rate, std::abs(w2 - expected_w2));
    // theta2: the output arm's angle about s2 from arm2 towards z (the output body starts
    // unrotated, so its arm is q * arm2).
    const Vec3 arm = sim.state().bodies[1].orientation * arm2;
    const double theta2 = std::atan2(arm.dot(Vec3::UnitZ()), arm.dot(arm2));
    const double expected_theta2 = std::atan2(std::sin(theta1) * std::cos(beta), std::cos(theta1));
    worst_angle = std::max(worst_angle, std::abs(wrapAngle(theta2 - expected_theta2)));
  }
  EXPECT_LT(worst_rate, 1e-6 * w1);
  EXPECT_LT(worst_angle, 1e-7);
  EXPECT_LT(sim.stats().max_constraint_error, 1e-8);
}

TEST(JointTypes, SphericalPendulumConservesEnergyAndHoldsItsPivot) {
  ModelBuilder b;
  b.options().time_step = 1e-3;
  Body bob;
  bob.name = "bob";
  bob.inertia = Mat3::Identity() * 0.01;
  bob.position = Vec3(0.6, 0, -0.8);
  bob.velocity = Vec3(0, 1.5, 0);
  const BodyIndex i = b.addBody(bob);
  b.addJoint("ball", JointType::kSpherical, BodyIndex::world(), i, Vec3::Zero(), Vec3::UnitZ());
  const auto model = b.build();
  Simulator sim(model);
  const double e0 = test::mechanicalEnergy(*model, sim.state());
  run(sim, 3.0);
  EXPECT_LT(std::abs(test::mechanicalEnergy(*model, sim.state()) - e0), 1e-6 * kG);
  const BodyState& s = sim.state().bodies[0];
  const Vec3 pivot = s.position + s.orientation * (Vec3(0, 0, 0) - bob.position);
  EXPECT_LT(pivot.norm(), 1e-8);
}

TEST(JointTypes, UrdfFramesGiveTheSameJointAsTheWorldForm) {
  // URDF style: joint frame 0.5 m above the parent's origin, child frame at the joint, axis
  // (0, 1, 0) in it; the child's centre 0.2 m below its link frame.
  ModelBuilder b;
  Body body;
  body.name = "link";
  body.position = Vec3(0, 0, 0.3);
  const BodyIndex i = b.addBody(body);
  Eigen::Isometry3d joint_in_parent = Eigen::Isometry3d::Identity();
  joint_in_parent.translation() = Vec3(0, 0, 0.5);
  Eigen::Isometry3d joint_in_child = Eigen::Isometry3d::Identity();
  joint_in_child.translation() = Vec3(0, 0, 0.2);
  b.addJointInFrames("urdf", JointType::kRevolute, BodyIndex::world(), i, joint_in_parent,
                     joint_in_child, Vec3::UnitY());
  b.addJoint("world_form", JointType::kRevolute, BodyIndex::world(), i, Vec3(0, 0, 0.5),
             Vec3::UnitY());
  b.options().constraints.redundant = RedundancyPolicy::kRemove;
  const auto model = b.build();
  const Joint& u = model->joints[0];
  const Joint& w = model->joints[1];
  EXPECT_TRUE(u.anchor_in_parent.isApprox(w.anchor_in_parent));
  EXPECT_TRUE(u.anchor_in_child.isApprox(w.anchor_in_child));
  EXPECT_TRUE(u.axes_in_parent.col(2).isApprox(w.axes_in_parent.col(2)));
  EXPECT_TRUE(u.axes_in_child.col(2).isApprox(w.axes_in_child.col(2)));
  // The two are the same joint: the second one's equations are all redundant.
  EXPECT_EQ(__builtin_popcount(model->joints[1].dropped_equations), 5);
}

}  // namespace
}  // namespace tribo
