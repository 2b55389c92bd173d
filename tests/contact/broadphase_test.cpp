// The grid broadphase (contact/broadphase.hpp) against a brute-force O(n^2) overlap test
// over random boxes of sizes from 1 mm to 10 m moving between calls, far and huge boxes,
// NaN, thread counts; and the whole detector with it against every pair listed, over
// random scenes of every shape kind.
#include "contact/broadphase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "contact/collision_detector.hpp"
#include "contact/split_count.hpp"
#include "support/box_pairs.hpp"
#include "support/every_pair_rule.hpp"

namespace tribo::contact {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

using test::allMembers;
using test::bruteForcePairs;
using test::sortedPairs;

// n boxes of sizes log-uniform in [1 mm, 10 m], centres uniform in a cube of side `region`.
std::vector<Aabb> randomBoxes(std::mt19937& rng, int n, double region) {
  std::uniform_real_distribution<double> log_size(std::log(1e-3), std::log(10.0));
  std::uniform_real_distribution<double> at(-0.5 * region, 0.5 * region);
  std::vector<Aabb> boxes(static_cast<std::size_t>(n));
  for (Aabb& b : boxes) {
    const Eigen::Vector3d c(at(rng), at(rng), at(rng));
    const Eigen::Vector3d half(std::exp(log_size(rng)), std::exp(log_size(rng)),
                               std::exp(log_size(rng)));
    b.lo = c - 0.5 * half;
    b.hi = c + 0.5 * half;
  }
  return boxes;
}

TEST(GridBroadphase, EqualsBruteForceOverRandomBoxesMovingBetweenCalls) {
  std::mt19937 rng(20261127);
  for (const double region : {0.05, 1.0, 20.0, 400.0}) {
    for (const int n : {2, 17, 300}) {
      std::vector<Aabb> boxes = randomBoxes(rng, n, region);
      const std::vector<int> members = allMembers(boxes.size());
      GridBroadphase grid;
      std::normal_distribution<double> move(0.0, 0.02 * region);
      std::size_t found = 0;
      for (int call = 0; call < 6; ++call) {
        Pairs pairs;
        grid.overlappingPairs(boxes, members, pairs);
        const Pairs expected = bruteForcePairs(boxes, members);
        EXPECT_EQ(pairs.size(), expected.size()) << "no pair twice";
        EXPECT_EQ(sortedPairs(pairs), expected)
            << "region " << region << ", n " << n << ", call " << call;
        found += expected.size();
        for (Aabb& b : boxes) {  // every box moves, the cell edge stays that of the first call
          const Eigen::Vector3d d(move(rng), move(rng), move(rng));
          b.lo += d;
          b.hi += d;
        }
      }
      if (n == 300 && region <= 20.0) {
        EXPECT_GT(found, 0U) << "the case has overlaps to find";
      }
    }
  }
}

TEST(GridBroadphase, BoxesMovingInsideTheirCellsKeepTheBucketsAndTheAnswerFollowsThem) {
  // Pairs of boxes 1 um apart or 1 um overlapping, moved by 2 um back and forth: their cells
  // stay the same (the buckets are kept), their overlap flips every call.
  std::vector<Aabb> boxes;
  for (int k = 0; k < 50; ++k) {
    Aabb a, b;
    a.lo = Eigen::Vector3d(0.5 * k + 0.1, 0.1, 0.1);
    a.hi = a.lo + Eigen::Vector3d::Constant(0.2);
    b.lo = a.lo + Eigen::Vector3d(0.2 + 1e-6, 0.0, 0.0);
    b.hi = b.lo + Eigen::Vector3d::Constant(0.2);
    boxes.push_back(a);
    boxes.push_back(b);
  }
  const std::vector<int> members = allMembers(boxes.size());
  GridBroadphase grid;
  for (int call = 0; call < 4; ++call) {
    Pairs pairs;
    grid.overlappingPairs(boxes, members, pairs);
    const Pairs expected = bruteForcePairs(boxes, members);
    EXPECT_EQ(sortedPairs(pairs), expected) << "call " << call;
    EXPECT_EQ(expected.size(), call % 2 == 0 ? 0U : 50U) << "the case flips";
    const double shift = call % 2 == 0 ? -2e-6 : 2e-6;
    for (std::size_t k = 1; k < boxes.size(); k += 2) {
      boxes[k].lo.x() += shift;
      boxes[k].hi.x() += shift;
    }
  }
}

TEST(GridBroadphase, OnlyTheMembersAreLookedAt) {
  std::mt19937 rng(7);
  const std::vector<Aabb> boxes = randomBoxes(rng, 200, 2.0);
  std::vector<int> members;
  for (int g = 0; g < 200; g += 3) members.push_back(g);
  GridBroadphase grid;
  Pairs pairs;
  grid.overlappingPairs(boxes, members, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForcePairs(boxes, members));
  EXPECT_FALSE(pairs.empty());
}

TEST(GridBroadphase, TouchingFacesEdgesAndCornersArePairs) {
  // Unit cubes side by side at spacing exactly 1 (touching faces, edges and corners), a
  // 3 x 3 x 3 block: 26 neighbours of the centre, and the brute-force count in all.
  std::vector<Aabb> boxes;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        Aabb b;
        b.lo = Eigen::Vector3d(i, j, k);
        b.hi = b.lo + Eigen::Vector3d::Ones();
        boxes.push_back(b);
      }
  const std::vector<int> members = allMembers(boxes.size());
  GridBroadphase grid;
  Pairs pairs;
  grid.overlappingPairs(boxes, members, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForcePairs(boxes, members));
  EXPECT_EQ(std::count_if(pairs.begin(), pairs.end(),
                          [](const auto& p) { return p.first == 13 || p.second == 13; }),
            26);
}

TEST(GridBroadphase, HugeFarAndPointBoxesAreStillFound) {
  std::mt19937 rng(11);
  std::vector<Aabb> boxes = randomBoxes(rng, 120, 1.0);
  Aabb ground;  // covers millions of cells: kept aside
  ground.lo = Eigen::Vector3d(-1e5, -1e5, -0.6);
  ground.hi = Eigen::Vector3d(1e5, 1e5, -0.2);
  boxes.push_back(ground);
  Aabb beam;  // long and thin across the region
  beam.lo = Eigen::Vector3d(-50, -0.01, -0.01);
  beam.hi = Eigen::Vector3d(50, 0.01, 0.01);
  boxes.push_back(beam);
  Aabb far_a, far_b;  // beyond 2^30 cells (of about 0.1 m here), overlapping each other
  far_a.lo = Eigen::Vector3d(2e8, -2e8, 2e8);
  far_a.hi = far_a.lo + Eigen::Vector3d::Constant(1e-3);
  far_b.lo = far_a.lo + Eigen::Vector3d::Constant(5e-4);
  far_b.hi = far_b.lo + Eigen::Vector3d::Constant(1e-3);
  boxes.push_back(far_a);
  boxes.push_back(far_b);
  Aabb point;  // a zero-size box (a contact point sphere) inside the ground
  point.lo = point.hi = Eigen::Vector3d(3, 4, -0.3);
  boxes.push_back(point);
  const std::vector<int> members = allMembers(boxes.size());
  GridBroadphase grid;
  Pairs pairs;
  grid.overlappingPairs(boxes, members, pairs);
  const Pairs expected = bruteForcePairs(boxes, members);
  EXPECT_EQ(sortedPairs(pairs), expected);
  const int n = static_cast<int>(boxes.size());
  EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), std::make_pair(n - 3, n - 2)));
  EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), std::make_pair(n - 5, n - 1)));
}

TEST(GridBroadphase, ANanBoxIsPairedWithEveryBoxRatherThanLost) {
  std::mt19937 rng(3);
  std::vector<Aabb> boxes = randomBoxes(rng, 40, 1.0);
  boxes[5].lo.setConstant(std::numeric_limits<double>::quiet_NaN());
  boxes[5].hi.setConstant(std::numeric_limits<double>::quiet_NaN());
  GridBroadphase grid;
  Pairs pairs;
  grid.overlappingPairs(boxes, allMembers(boxes.size()), pairs);
  EXPECT_EQ(std::count_if(pairs.begin(), pairs.end(),
                          [](const auto& p) { return p.first == 5 || p.second == 5; }),
            39);
  // Every pair among the others is the brute force's.
  Pairs others;
  for (const auto& p : pairs)
    if (p.first != 5 && p.second != 5) others.push_back(p);
  std::vector<int> rest;
  for (int g = 0; g < 40; ++g)
    if (g != 5) rest.push_back(g);
  EXPECT_EQ(sortedPairs(others), bruteForcePairs(boxes, rest));
}

TEST(GridBroadphase, TheSameListInTheSameOrderForAnyThreadCountAndTheWorkIsSplit) {
  std::mt19937 rng(5);
  const std::vector<Aabb> boxes = randomBoxes(rng, 6000, 60.0);
  const std::vector<int> members = allMembers(boxes.size());
  Pairs one;
  GridBroadphase single;
  single.overlappingPairs(boxes, members, one);
  ASSERT_EQ(sortedPairs(one), bruteForcePairs(boxes, members));
  for (const int threads : {2, 3}) {
    GridBroadphase grid;
    grid.setThreads(threads);
    const long before = splitLoopCount().load();
    Pairs pairs;
    grid.overlappingPairs(boxes, members, pairs);
    EXPECT_EQ(pairs, one) << threads << " threads";
    EXPECT_GT(splitLoopCount().load(), before) << "the pair tests were cut for a team";
  }
}

Eigen::Isometry3d randomPose(std::mt19937& rng, double region) {
  std::uniform_real_distribution<double> at(-0.5 * region, 0.5 * region);
  Eigen::Quaterniond q(
      std::normal_distribution<double>()(rng), std::normal_distribution<double>()(rng),
      std::normal_distribution<double>()(rng), std::normal_distribution<double>()(rng));
  q.normalize();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  t.translation() = Eigen::Vector3d(at(rng), at(rng), at(rng));
  return t;
}

Shape randomShape(std::mt19937& rng, int kind, double scale) {
  std::uniform_real_distribution<double> f(0.3, 1.0);
  switch (kind % 7) {
    case 0:
      return Shape::box(scale * Eigen::Vector3d(f(rng), f(rng), f(rng)));
    case 1:
      return Shape::sphere(scale * f(rng));
    case 2:
      return Shape::cylinder(scale * f(rng), scale * f(rng));
    case 3:
      return Shape::capsule(scale * f(rng), scale * f(rng));
    case 4:
      return Shape::cone(scale * f(rng), scale * f(rng));
    default: {
      // A tetrahedron: convex mesh (5) or triangle mesh (6).
      auto mesh = std::make_shared<MeshData>();
      mesh->vertices = {scale * Eigen::Vector3d(0, 0, 0), scale * Eigen::Vector3d(f(rng), 0, 0),
                        scale * Eigen::Vector3d(0, f(rng), 0),
                        scale * Eigen::Vector3d(0, 0, f(rng))};
      mesh->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
      Shape s;
      s.type = kind % 7 == 5 ? ShapeType::kConvexMesh : ShapeType::kTriangleMesh;
      s.mesh = mesh;
      return s;
    }
  }
}

using test::EveryPair;

TEST(GridBroadphase, TheDetectorFindsEveryContactOfEveryShapeKindAsTheFullPairListDoes) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> log_scale(std::log(1e-3), std::log(10.0));
  for (int scene = 0; scene < 6; ++scene) {
    const double scale = std::exp(log_scale(rng));
    const int n = 40;
    std::vector<Shape> shapes;
    for (int g = 0; g < n; ++g) shapes.push_back(randomShape(rng, g, scale));
    std::vector<std::pair<int, int>> all;
    for (int g = 0; g < n; ++g)
      for (int h = g + 1; h < n; ++h) all.emplace_back(g, h);
    CollisionDetector by_rule(shapes, std::make_unique<EveryPair>(n));
    CollisionDetector listed(shapes, all);  // no broadphase: every pair to the narrowphase
    std::size_t points = 0;
    for (int call = 0; call < 3; ++call) {
      std::vector<Eigen::Isometry3d> poses;
      for (int g = 0; g < n; ++g) poses.push_back(randomPose(rng, 6.0 * scale));
      std::vector<ContactPoint> a, b;
      by_rule.detect(poses, a);
      listed.detect(poses, b);
      ASSERT_EQ(a.size(), b.size())
          << "scene " << scene << " (scale " << scale << "), call " << call;
      for (std::size_t i = 0; i < a.size(); ++i) {
        const auto [g, h] = all[static_cast<std::size_t>(b[i].pair)];
        EXPECT_EQ(a[i].pair, g * n + h);
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].depth, b[i].depth);
      }
      points += a.size();
    }
    EXPECT_GT(points, 0U) << "scene " << scene << " has contacts to find";
  }
}

}  // namespace
}  // namespace tribo::contact
