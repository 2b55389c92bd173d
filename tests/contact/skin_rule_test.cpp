// The skin list's margin rule (contact/collision_detector.hpp): a list that lasted fewer than
// 24 calls is rebuilt with twice the margin, up to 4 times the first; one that has lasted 48
// calls with a margin wider than the first is rebuilt with half. Checked on a sphere moving
// at a constant speed among resting ones, where a list lasts until the sphere has moved
// farther than the margin, so its life in calls is margin / speed, worked out here:
// - moving at a tenth of the first margin a call, the lists come to last 2.5 to 4 tenths of
//   the first margin over the speed (24 to 44 calls), never shorter, as the rule says;
// - at rest afterwards, the list is rebuilt exactly twice (4 -> 2 -> 1 times the first
//   margin) and then kept;
// - moving again, the next list lasts the first margin's life (10 calls), not the widest's;
// - a scene whose lists last long from the start keeps the first margin (no build but the
//   first while it rests);
// for spheres of 1 mm, 1 m and 100 m. The points themselves do not depend on the margin
// (tests/contact/skin_list_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/collision_detector.hpp"

namespace tribo::contact {
namespace {

struct Row {
  std::vector<Shape> shapes;
  std::vector<Eigen::Isometry3d> poses;
  std::vector<std::pair<int, int>> pairs;
};

// Five spheres of radius r in a row 4 r apart (no two touch), every pair listed.
Row rowOfSpheres(double r) {
  Row row;
  for (int g = 0; g < 5; ++g) {
    row.shapes.push_back(Shape::sphere(r));
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(4.0 * r * g, 0.0, 0.0);
    row.poses.push_back(t);
  }
  for (int g = 0; g < 5; ++g)
    for (int h = g + 1; h < 5; ++h) row.pairs.emplace_back(g, h);
  return row;
}

CollisionOptions skinOptions() {
  CollisionOptions o;
  o.broadphase = true;
  o.broadphase_skin = 0.1;  // the first margin: a tenth of the spheres' diameter
  return o;
}

// The calls of each list, ended by a build, while sphere 2 moves by `step` along y a call
// (0: at rest), over `calls` calls.
struct Lives {
  std::vector<long> lives;  // each list's calls, from its build to the next build
  long calls_since_build = 0;
};

void run(CollisionDetector& d, Row& row, double step, int calls, Lives& lives) {
  std::vector<ContactPoint> out;
  for (int k = 0; k < calls; ++k) {
    row.poses[2].translation().y() += step;
    const long before = d.skinListBuilds();
    d.detect(row.poses, out);
    ASSERT_TRUE(out.empty());
    if (d.skinListBuilds() > before) {
      lives.lives.push_back(lives.calls_since_build);
      lives.calls_since_build = 0;
    }
    ++lives.calls_since_build;
  }
}

TEST(SkinRule, AMovingSphereWidensTheSkinAndRestNarrowsItBack) {
  for (const double r : {1e-3, 1.0, 100.0}) {
    SCOPED_TRACE(r);
    Row row = rowOfSpheres(r);
    CollisionDetector d(row.shapes, row.pairs, skinOptions());
    const double first_margin = 0.1 * 2.0 * r;
    // 9.3 calls to cross the first margin: its lists last 10 calls.
    const double step = first_margin / 9.3;
    Lives lives;
    run(d, row, step, 1000, lives);
    ASSERT_GE(lives.lives.size(), 4u);
    EXPECT_EQ(lives.lives[0], 0);   // the first build, on the first call
    EXPECT_EQ(lives.lives[1], 10);  // the first margin's life: then twice the margin
    EXPECT_EQ(lives.lives[2], 19);  // twice the first margin's: then four times
    // From then on the widest margin: lists of 4 x 9.3 calls, rounded up; within [24, 48).
    for (std::size_t i = 3; i < lives.lives.size(); ++i) {
      EXPECT_EQ(lives.lives[i], 38) << i;
      EXPECT_GE(lives.lives[i], 24);
      EXPECT_LT(lives.lives[i], 48);
    }
    // At rest: two builds (48 calls each at four, then twice the first margin), then none.
    const long builds = d.skinListBuilds();
    Lives rest;
    rest.calls_since_build = lives.calls_since_build;
    run(d, row, 0.0, 400, rest);
    EXPECT_EQ(d.skinListBuilds() - builds, 2);
    ASSERT_EQ(rest.lives.size(), 2u);
    EXPECT_EQ(rest.lives[0], 48);
    EXPECT_EQ(rest.lives[1], 48);
    // Moving again: the first margin's life, 9.3 steps crossed on the 10th call (twice the
    // margin would take 19).
    Lives again;
    again.calls_since_build = rest.calls_since_build;
    run(d, row, step, 12, again);
    ASSERT_EQ(again.lives.size(), 1u);
    EXPECT_EQ(again.lives[0], rest.calls_since_build + 9);  // the resting list's calls
    EXPECT_EQ(again.calls_since_build, 3);                  // calls 10, 11 and 12
  }
}

TEST(SkinRule, ASlowSceneKeepsTheFirstMargin) {
  for (const double r : {1e-3, 1.0, 100.0}) {
    SCOPED_TRACE(r);
    Row row = rowOfSpheres(r);
    CollisionDetector d(row.shapes, row.pairs, skinOptions());
    // 60.5 calls to cross the first margin: lists of 61 calls, past 24, so no widening;
    // no narrowing either, the margin being the first.
    const double step = 0.1 * 2.0 * r / 60.5;
    Lives lives;
    run(d, row, step, 1000, lives);
    ASSERT_GE(lives.lives.size(), 10u);
    for (std::size_t i = 1; i < lives.lives.size(); ++i) EXPECT_EQ(lives.lives[i], 61) << i;
  }
}

}  // namespace
}  // namespace tribo::contact
