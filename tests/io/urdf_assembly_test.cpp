// Forward kinematics and fixed-joint lumping of URDF trees against hand-computed values.
#include "io/urdf_assembly.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tribo::io {
namespace {

UrdfLink link(const std::string& name, double mass, const Eigen::Vector3d& com,
              const Eigen::Vector3d& principal) {
  UrdfLink l;
  l.name = name;
  l.has_inertial = mass > 0.0;
  l.mass = mass;
  l.inertial_origin.translation() = com;
  l.inertia = principal.asDiagonal();
  return l;
}

UrdfJoint joint(const std::string& name, const std::string& type, const std::string& parent,
                const std::string& child, const Eigen::Vector3d& xyz,
                const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ()) {
  UrdfJoint j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  j.origin.translation() = xyz;
  j.axis = axis;
  return j;
}

TEST(UrdfAssembly, RevoluteAndPrismaticForwardKinematics) {
  UrdfRobot r;
  r.links = {link("base", 1, {0, 0, 0}, {1, 1, 1}), link("arm", 1, {0, 0, 0}, {1, 1, 1}),
             link("slider", 1, {0, 0, 0}, {1, 1, 1})};
  r.joints = {joint("shoulder", "revolute", "base", "arm", {0, 0, 1}),
              joint("rail", "prismatic", "arm", "slider", {1, 0, 0}, {1, 0, 0})};
  const double q = std::numbers::pi / 2;
  const UrdfAssembly a =
      assembleUrdf(r, Eigen::Isometry3d::Identity(), {{"shoulder", q}, {"rail", 0.5}});
  // Arm frame at (0,0,1) turned 90 deg about z; the slider 1 + 0.5 m along the arm's x = world y.
  EXPECT_TRUE(a.link_world[1].translation().isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(a.link_world[2].translation().isApprox(Eigen::Vector3d(0, 1.5, 1)));
  EXPECT_EQ(a.groups.size(), 3u);
  EXPECT_EQ(a.groups[2].parent_joint, 1);
  EXPECT_THROW(assembleUrdf(r, Eigen::Isometry3d::Identity(), {{"elbow", 1.0}}),
               std::invalid_argument);
}

TEST(UrdfAssembly, FixedJointsLumpMassComAndInertia) {
  // Two point-like masses 2 kg at x = -1 and 1 kg at x = +2 (in the top frame) plus their own
  // inertias: M = 3, com = 0, I_yy = 0.1 + 0.2 + 2*1 + 1*4 = 6.3.
  UrdfRobot r;
  r.links = {link("a", 2, {-1, 0, 0}, {0.1, 0.1, 0.1}), link("b", 1, {0, 0, 0}, {0.2, 0.2, 0.2})};
  r.joints = {joint("weld", "fixed", "a", "b", {2, 0, 0})};
  const UrdfAssembly a = assembleUrdf(r, Eigen::Isometry3d::Identity());
  ASSERT_EQ(a.groups.size(), 1u);
  const UrdfBodyGroup& g = a.groups[0];
  EXPECT_DOUBLE_EQ(g.mass, 3.0);
  EXPECT_TRUE(g.com.isZero(1e-15));
  EXPECT_NEAR(g.inertia(0, 0), 0.3, 1e-12);
  EXPECT_NEAR(g.inertia(1, 1), 6.3, 1e-12);
  EXPECT_NEAR(g.inertia(2, 2), 6.3, 1e-12);
  EXPECT_EQ(a.group_of_link[1], 0);
}

TEST(UrdfAssembly, RotatedInertialFrameOfADiagonalTensorByPiIsUnchanged) {
  // kdl_parser's testInertiaRPYmodel pair: rpy = (pi, 0, 0) on a diagonal inertia.
  UrdfRobot r1, r2;
  r1.links = {link("l", 1, {1, 2, 3}, {5, 15, 25})};
  r2 = r1;
  r2.links[0].inertial_origin.linear() =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const auto g1 = assembleUrdf(r1, Eigen::Isometry3d::Identity()).groups[0];
  const auto g2 = assembleUrdf(r2, Eigen::Isometry3d::Identity()).groups[0];
  EXPECT_TRUE(g1.inertia.isApprox(g2.inertia, 1e-12));
  EXPECT_TRUE(g1.com.isApprox(Eigen::Vector3d(1, 2, 3)));
}

}  // namespace
}  // namespace tribo::io
