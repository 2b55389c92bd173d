// Contact identity between steps and the anchors of stateful friction: keys by pair and
// feature, nearest-point matching for feature-less points, elongation from the anchored
// material points (including a belt's surface drift), and rebasing that keeps it.
#include "contact/stick_anchor.hpp"

#include <gtest/gtest.h>

#include "support/contact_point_at.hpp"

namespace tribo::contact {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

ContactPoint point(int pair, int feature, const Vector3d& p) {
  return test::contactPointAt(pair, feature, p);
}

TEST(StickAnchor, FeaturePointsKeepTheirKeyAndOthersMatchTheNearestWithinTheRadius) {
  const Isometry3d id = Isometry3d::Identity();
  const AnchorFrames frames{&id, &id};
  std::vector<StickAnchor> anchors{
      anchorAt(contactKey(0, 3), point(0, 3, {0, 0, 0}), frames, 0.0, {}),
      anchorAt(contactKey(1, kFreshSlot), point(1, -1, {1, 0, 0}), frames, 0.0, {}),
      anchorAt(contactKey(1, kFreshSlot + 1), point(1, -1, {1.5, 0, 0}), frames, 0.0, {})};
  EXPECT_EQ(findAnchor(anchors, point(0, 3, {9, 9, 9}), 0.01), &anchors[0]);  // by feature
  EXPECT_EQ(findAnchor(anchors, point(0, 2, {0, 0, 0}), 0.01), nullptr);      // other corner
  EXPECT_EQ(findAnchor(anchors, point(1, -1, {1.004, 0, 0}), 0.01), &anchors[1]);
  EXPECT_EQ(findAnchor(anchors, point(1, -1, {1.496, 0, 0}), 0.01), &anchors[2]);
  EXPECT_EQ(findAnchor(anchors, point(1, -1, {1.2, 0, 0}), 0.01), nullptr);  // too far
  EXPECT_EQ(findAnchor(anchors, point(2, -1, {1.0, 0, 0}), 0.01), nullptr);  // other pair

  // Two points claiming one anchor: the first keeps it, the second gets a fresh slot above
  // every slot of the pair.
  AnchorBook book;
  book.begin(anchors);
  EXPECT_EQ(book.claim(point(1, -1, {1, 0, 0}), &anchors[1]), anchors[1].key);
  EXPECT_EQ(book.claim(point(1, -1, {1, 0, 0}), &anchors[1]), contactKey(1, kFreshSlot + 2));
  EXPECT_EQ(book.claim(point(0, 5, {0, 0, 0}), nullptr), contactKey(0, 5));
}

TEST(StickAnchor, ElongationFollowsTheMaterialPointsAndTheBeltSurface) {
  Isometry3d a = Isometry3d::Identity(), b = Isometry3d::Identity();
  b.translation() = Vector3d(0, 0, 0.05);
  const ContactPoint cp = point(0, 0, {0.1, 0.2, 0.0});
  friction::StickUpdate hold;
  hold.elongation = Vector3d(1e-5, 0, 3.0);  // the normal part is dropped
  const StickAnchor anchor = anchorAt(contactKey(0, 0), cp, {&a, &b}, 2.0, hold);
  // Rounding of p +- u/2 at p ~ 0.2 m: 1e-17 m on 1e-5 m.
  EXPECT_TRUE(
      stickView(&anchor, cp, {&a, &b}, 2.0).elongation.isApprox(Vector3d(1e-5, 0, 0), 1e-9));
  // B moves 3 mm along y and rotates a little about z: u grows by its material point's
  // displacement.
  Isometry3d b2 = b;
  b2.translation() += Vector3d(0, 3e-3, 0);
  b2.linear() = Eigen::AngleAxisd(1e-3, Vector3d::UnitZ()).toRotationMatrix();
  const Vector3d moved = b2 * anchor.anchor_b - b * anchor.anchor_b;
  EXPECT_TRUE(stickView(&anchor, cp, {&a, &b2}, 2.0)
                  .elongation.isApprox(Vector3d(1e-5 + moved.x(), moved.y(), 0), 1e-12));
  // A belt surface moving at 1.5 m/s along x carries A's material point 1.5 mm in 1 ms.
  AnchorFrames belt{&a, &b, Vector3d(1.5, 0, 0), Vector3d::Zero()};
  EXPECT_TRUE(
      stickView(&anchor, cp, belt, 2.001).elongation.isApprox(Vector3d(1e-5 - 1.5e-3, 0, 0), 1e-9));
  EXPECT_FALSE(stickView(nullptr, cp, belt, 2.0).anchored);
}

}  // namespace
}  // namespace tribo::contact
