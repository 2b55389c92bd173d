// Collision detection: the closed-form box/half-space manifold against geometry and
// against FCL's own answer, and FCL box/box contacts (normal from A into B).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/collision_detector.hpp"
#include "contact/contact_force.hpp"
#include "contact/normal_law.hpp"
#include "friction/friction_law.hpp"

namespace tribo::contact {
namespace {

Eigen::Isometry3d pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  t.translation() = p;
  return t;
}

TEST(BoxHalfSpace, FlatBoxHasFourCornersAtTheSameDepth) {
  std::vector<ContactPoint> out;
  const Eigen::Vector3d half(0.1, 0.2, 0.05);
  const int n = boxHalfSpaceContacts(pose({0.3, -0.2, 0.05 - 1e-4}, Eigen::Quaterniond::Identity()),
                                     half, Eigen::Isometry3d::Identity(), 0, out);
  ASSERT_EQ(n, 4);
  for (const auto& c : out) {
    EXPECT_NEAR(c.depth, 1e-4, 1e-15);
    EXPECT_TRUE(c.normal.isApprox(Eigen::Vector3d::UnitZ()));
    EXPECT_NEAR(std::abs(c.position.x() - 0.3), 0.1, 1e-15);
    EXPECT_NEAR(std::abs(c.position.y() + 0.2), 0.2, 1e-15);
    EXPECT_NEAR(c.position.z(), -0.5e-4, 1e-15);  // midway between corner and plane
  }
}

TEST(BoxHalfSpace, TiltedPlaneAndBoxAgreeWithFclDeepestPoint) {
  // Closed form against FCL's single deepest point for a range of poses.
  const Eigen::Vector3d half(0.1, 0.15, 0.05);
  const Eigen::Quaterniond plane_q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 0).normalized()));
  const Eigen::Isometry3d plane = pose({0.1, 0.2, -0.3}, plane_q);
  const Eigen::Vector3d n = plane_q * Eigen::Vector3d::UnitZ();
  CollisionOptions closed, fcl_only;
  fcl_only.closed_form_box_halfspace = false;
  CollisionDetector a({Shape::halfSpace(), Shape::box(half)}, {{0, 1}}, closed);
  CollisionDetector b({Shape::halfSpace(), Shape::box(half)}, {{0, 1}}, fcl_only);
  int compared = 0;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.17 * i, Eigen::Vector3d(1, -1, 2).normalized()));
    const Eigen::Isometry3d box = pose(plane * Eigen::Vector3d(0, 0, 0.02 + 0.003 * i), q);
    const std::vector<Eigen::Isometry3d> poses{plane, box};
    std::vector<ContactPoint> pa, pb;
    a.detect(poses, pa);
    b.detect(poses, pb);
    ASSERT_EQ(pa.empty(), pb.empty()) << i;
    if (pa.empty()) continue;
    double deepest = 0;
    for (const auto& c : pa) {
      deepest = std::max(deepest, c.depth);
      EXPECT_TRUE(c.normal.isApprox(n, 1e-12));
    }
    EXPECT_NEAR(deepest, pb[0].depth, 1e-9) << i;
    EXPECT_NEAR(std::abs(pb[0].normal.dot(n)), 1.0, 1e-9) << i;
    ++compared;
  }
  EXPECT_GT(compared, 5);
}

TEST(BoxHalfSpace, PairOrderFlipsTheNormal) {
  const Eigen::Vector3d half(0.1, 0.1, 0.1);
  CollisionDetector d({Shape::box(half), Shape::halfSpace()}, {{0, 1}});
  std::vector<ContactPoint> out;
  const std::vector<Eigen::Isometry3d> poses{pose({0, 0, 0.09}, Eigen::Quaterniond::Identity()),
                                             Eigen::Isometry3d::Identity()};
  d.detect(poses, out);
  ASSERT_EQ(out.size(), 4u);
  for (const auto& c : out) EXPECT_TRUE(c.normal.isApprox(-Eigen::Vector3d::UnitZ()));
}

TEST(BoxBox, FclContactsPointFromAIntoB) {
  const Eigen::Vector3d half(0.5, 0.5, 0.5);
  CollisionDetector d({Shape::box(half), Shape::box(half)}, {{0, 1}});
  std::vector<ContactPoint> out;
  // B sits on A, overlapping by 1 mm.
  const std::vector<Eigen::Isometry3d> poses{
      pose({0, 0, 0}, Eigen::Quaterniond::Identity()),
      pose({0.2, 0.1, 0.999}, Eigen::Quaterniond::Identity())};
  d.detect(poses, out);
  ASSERT_FALSE(out.empty());
  for (const auto& c : out) {
    EXPECT_NEAR(c.normal.z(), 1.0, 1e-9);
    EXPECT_NEAR(c.depth, 1e-3, 1e-9);
  }
  // Separated: no contact.
  const std::vector<Eigen::Isometry3d> apart{pose({0, 0, 0}, Eigen::Quaterniond::Identity()),
                                             pose({0, 0, 1.01}, Eigen::Quaterniond::Identity())};
  d.detect(apart, out);
  EXPECT_TRUE(out.empty());
}

TEST(Broadphase, FindsTheSameContactsAsTheDirectPairList) {
  const Eigen::Vector3d half(0.1, 0.1, 0.1);
  std::vector<Shape> shapes{Shape::halfSpace()};
  std::vector<std::pair<int, int>> pairs;
  std::vector<Eigen::Isometry3d> poses{Eigen::Isometry3d::Identity()};
  for (int i = 0; i < 6; ++i) {
    shapes.push_back(Shape::box(half));
    pairs.emplace_back(0, i + 1);
    // Every other box touches the ground.
    poses.push_back(pose({0.5 * i, 0, (i % 2) ? 0.099 : 0.3}, Eigen::Quaterniond::Identity()));
  }
  // A seventh box overlapping box 2 (at x = 0.5) by 5 mm; all box pairs are candidates.
  shapes.push_back(Shape::box(half));
  poses.push_back(pose({0.695, 0, 0.099}, Eigen::Quaterniond::Identity()));
  pairs.emplace_back(0, 7);
  for (int i = 1; i <= 7; ++i)
    for (int j = i + 1; j <= 7; ++j) pairs.emplace_back(i, j);
  CollisionOptions with_bp;
  with_bp.broadphase = true;
  CollisionDetector direct(shapes, pairs), culled(shapes, pairs, with_bp);
  std::vector<ContactPoint> a, b;
  direct.detect(poses, a);
  culled.detect(poses, b);
  ASSERT_GT(a.size(), 16u);  // 4 ground pairs x 4 corners, plus the overlapping boxes
  int box_box = 0;
  for (const auto& c : a) box_box += pairs[c.pair].first != 0;
  EXPECT_GT(box_box, 0);
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].pair, b[i].pair);
    EXPECT_TRUE(a[i].position.isApprox(b[i].position));
  }
}

TEST(CollisionDetector, RejectsTwoHalfSpaces) {
  EXPECT_THROW(CollisionDetector({Shape::halfSpace(), Shape::halfSpace()}, {{0, 1}}),
               std::invalid_argument);
}

TEST(NormalLaw, LinearAndHuntCrossleyNeverPull) {
  NormalLaw linear{NormalLawType::kLinear, 1e5, 1e3, 1.5};
  EXPECT_DOUBLE_EQ(linear.force(1e-3, 0.0), 100.0);
  EXPECT_DOUBLE_EQ(linear.force(1e-3, 0.05), 150.0);
  EXPECT_EQ(linear.force(1e-3, -1.0), 0.0);  // separating fast: no adhesion
  EXPECT_EQ(linear.force(-1e-3, 1.0), 0.0);  // not in contact
  NormalLaw hc{NormalLawType::kHuntCrossley, 1e7, 0.2, 1.5};
  EXPECT_NEAR(hc.force(1e-4, 0.5), 1e7 * std::pow(1e-4, 1.5) * 1.1, 1e-9);
  EXPECT_EQ(hc.force(1e-4, -10.0), 0.0);
  EXPECT_THROW(normalLawFromName("hertzian"), std::invalid_argument);
}

TEST(ContactForce, BeltSurfaceVelocityEntersSlipButNotDepthRate) {
  Material m;
  m.normal = {NormalLawType::kLinear, 1e5, 0.0, 1.5};
  m.friction = friction::makeFrictionLaw({"coulomb", {{"mu", 0.3}}, {{"regularization", "none"}}});
  ContactPoint cp;
  cp.position = Eigen::Vector3d(0, 0, 0);
  cp.normal = Eigen::Vector3d::UnitZ();
  cp.depth = 1e-3;
  GeometryMotion belt, box;
  belt.surface_velocity = Eigen::Vector3d(1.5, 0, 0);
  box.origin = Eigen::Vector3d(0, 0, 0.05);
  box.velocity = Eigen::Vector3d(0.5, 0, 0);
  ContactRecord rec;
  evaluateContact(cp, belt, box, m, rec);
  EXPECT_NEAR(rec.depth_rate, 0.0, 1e-15);
  EXPECT_TRUE(rec.slip.isApprox(Eigen::Vector3d(-1.0, 0, 0)));
  EXPECT_NEAR(rec.normal_force, 100.0, 1e-9);
  // The belt drags the slower box forward with mu * N.
  EXPECT_TRUE(rec.friction_force.isApprox(Eigen::Vector3d(30.0, 0, 0)));
}

}  // namespace
}  // namespace tribo::contact
