// The box/half-space corners (contact/primitive_contacts.hpp boxHalfSpaceContacts), formed
// from the three column products once per box, against the plain corner `box_pose * s` of
// Eigen bit for bit (this build's order), over random poses, half sizes from 0.1 mm to 11 m
// and tilted planes; and against the analytic depths of a box tilted about one axis. The
// other order of the sums, x + (y + z), tried by hand, fails the first test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "contact/primitive_contacts.hpp"
#include "support/same_bits.hpp"

namespace tribo::contact {
namespace {

// The corners below the plane as the plain expression gives them (the reference).
std::vector<ContactPoint> plainCorners(const Eigen::Isometry3d& box, const Eigen::Vector3d& half,
                                       const Eigen::Isometry3d& plane, int pair) {
  const Eigen::Vector3d n = plane.linear().col(2);
  const double offset = n.dot(plane.translation());
  std::vector<ContactPoint> out;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d s((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(),
                            (k & 4) ? half.z() : -half.z());
    const Eigen::Vector3d corner = box * s;
    const double depth = offset - n.dot(corner);
    if (depth <= 0.0) continue;
    ContactPoint cp;
    cp.pair = pair;
    cp.feature = k;
    cp.position = corner + 0.5 * depth * n;
    cp.normal = n;
    cp.depth = depth;
    out.push_back(cp);
  }
  return out;
}

Eigen::Isometry3d pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  t.translation() = p;
  return t;
}

using test::sameBits;

TEST(BoxHalfSpaceCorners, SameBitsAsThePlainCornersOverRandomPoses) {
  std::mt19937 rng(2026);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> decade(-3.0, 1.0), u(-1.0, 1.0);
  int points = 0, boxes_touching = 0;
  for (int i = 0; i < 50000; ++i) {
    const double scale = std::pow(10.0, decade(rng));  // 1 mm to 10 m, half sizes 0.1-1.1 of it
    const Eigen::Vector3d half(scale * (0.1 + std::abs(u(rng))), scale * (0.1 + std::abs(u(rng))),
                               scale * (0.1 + std::abs(u(rng))));
    // Resting boxes (tilts of 1e-6) and boxes in any orientation; planes level or tilted.
    const Eigen::Quaterniond q =
        i % 2 == 0 ? Eigen::Quaterniond(1.0, 1e-6 * g(rng), 1e-6 * g(rng), g(rng)).normalized()
                   : Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
    const Eigen::Isometry3d plane =
        i % 3 == 0 ? Eigen::Isometry3d::Identity()
                   : pose(Eigen::Vector3d(u(rng), u(rng), u(rng)) * 10.0 * scale,
                          Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized());
    const Eigen::Vector3d n = plane.linear().col(2);
    // The box's centre near the plane: from a corner's depth of a tenth of its size above.
    const Eigen::Vector3d centre = plane.translation() + u(rng) * half.norm() * 1.1 * n +
                                   scale * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Isometry3d box = pose(centre, q);
    std::vector<ContactPoint> out(3);  // appended after what is there
    const int added = boxHalfSpaceContacts(box, half, plane, i, out);
    const std::vector<ContactPoint> expected = plainCorners(box, half, plane, i);
    ASSERT_EQ(added, static_cast<int>(expected.size())) << i;
    ASSERT_EQ(out.size(), 3 + expected.size()) << i;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const ContactPoint& a = out[3 + k];
      const ContactPoint& b = expected[k];
      ASSERT_EQ(a.pair, b.pair);
      ASSERT_EQ(a.feature, b.feature) << i;
      ASSERT_TRUE(sameBits(a.position, b.position)) << i << " corner " << b.feature;
      ASSERT_TRUE(sameBits(a.normal, b.normal)) << i;
      ASSERT_EQ(std::memcmp(&a.depth, &b.depth, sizeof(double)), 0) << i;
    }
    points += added;
    boxes_touching += added > 0;
  }
  // Both sides of the test were reached: boxes with no corner, some and most corners below.
  EXPECT_GT(boxes_touching, 10000);
  EXPECT_LT(boxes_touching, 45000);
  EXPECT_GT(points, 4 * 10000);
}

TEST(BoxHalfSpaceCorners, TiltedAboutOneAxisGivesTheAnalyticDepths) {
  // A box (half sizes a, b, c) tilted by theta about x, its centre at height z: the corners
  // (y, z) = (+-b, -c) sit at z -+ b sin(theta) - c cos(theta), so with the lower pair at depth
  // d < 2 b sin(theta) only those two corners touch, at depth d.
  for (double scale : {1e-3, 1.0, 10.0})
    for (double theta : {1e-6, 0.01, 0.3}) {
      const double a = 0.3 * scale, b = 0.2 * scale, c = 0.1 * scale;
      const double d = 0.5 * b * std::sin(theta);
      const double z = c * std::cos(theta) + b * std::sin(theta) - d;
      const Eigen::Isometry3d box =
          pose({0.5 * scale, -0.25 * scale, z},
               Eigen::Quaterniond(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX())));
      std::vector<ContactPoint> out;
      ASSERT_EQ(boxHalfSpaceContacts(box, {a, b, c}, Eigen::Isometry3d::Identity(), 7, out), 2)
          << scale << " " << theta;
      for (const ContactPoint& p : out) {
        const double sy = (p.feature & 2) ? 1.0 : -1.0, sz = (p.feature & 4) ? 1.0 : -1.0;
        EXPECT_EQ(sy, -1.0);
        EXPECT_EQ(sz, -1.0);
        const double corner_z = z + sy * b * std::sin(theta) + sz * c * std::cos(theta);
        EXPECT_NEAR(p.depth, -corner_z, 1e-13 * scale);
        EXPECT_NEAR(p.depth, d, 1e-13 * scale);
        EXPECT_NEAR(p.position.z(), -0.5 * p.depth, 1e-13 * scale);
        EXPECT_NEAR(std::abs(p.position.x() - 0.5 * scale), a, 1e-13 * scale);
        EXPECT_EQ(p.pair, 7);
      }
    }
}

}  // namespace
}  // namespace tribo::contact
