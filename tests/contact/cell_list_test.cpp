// The cell list (contact/cell_list.hpp) against a brute-force O(n^2) overlap test: boxes of
// about one size from 1 mm to 10 m, packed as a pile and spread thin (dense and hashed cells),
// far from the origin, moving between calls; boxes touching at exactly the cell edge; boxes
// of many sizes (correct, if slow); far, NaN and point boxes; 1, 2 and 3 threads. Then the
// detector's skin list, which uses it for fat boxes of one size, against every pair listed.
#include "contact/cell_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

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

// n boxes with sides `size` times a factor in [1, spread] (per axis), centres uniform in a
// cube of side `region` about `centre`.
std::vector<Aabb> boxesOfOneSize(std::mt19937& rng, int n, double size, double spread,
                                 double region, const Eigen::Vector3d& centre) {
  std::uniform_real_distribution<double> factor(1.0, spread);
  std::uniform_real_distribution<double> at(-0.5 * region, 0.5 * region);
  std::vector<Aabb> boxes(static_cast<std::size_t>(n));
  for (Aabb& b : boxes) {
    const Eigen::Vector3d c = centre + Eigen::Vector3d(at(rng), at(rng), at(rng));
    const Eigen::Vector3d side(size * factor(rng), size * factor(rng), size * factor(rng));
    b.lo = c - 0.5 * side;
    b.hi = c + 0.5 * side;
  }
  return boxes;
}

TEST(CellList, EqualsBruteForceForBoxesOfOneSizePackedAndSpreadMovingBetweenCalls) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> log_size(std::log(1e-3), std::log(10.0));
  std::normal_distribution<double> step;
  long pairs_total = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const double size = std::exp(log_size(rng));
    const int n = 300 + 100 * (scene % 4);
    // Packed as a pile (about one box a box volume: dense cells) or spread over a thousand
    // box volumes each (hashed cells); about the origin or 1e4 sizes away from it.
    const bool packed = scene % 2 == 0;
    const double region = size * std::cbrt(static_cast<double>(n)) * (packed ? 1.0 : 10.0);
    const Eigen::Vector3d centre = scene % 3 == 2
                                       ? Eigen::Vector3d(1e4 * size, -3e4 * size, 7e3 * size)
                                       : Eigen::Vector3d::Zero();
    std::vector<Aabb> boxes = boxesOfOneSize(rng, n, size, 1.5, region, centre);
    const std::vector<int> members = allMembers(boxes.size());
    CellList cells;
    for (int call = 0; call < 5; ++call) {
      Pairs pairs;
      cells.overlappingPairs(boxes, members, pairs);
      const Pairs expected = bruteForcePairs(boxes, members);
      EXPECT_EQ(sortedPairs(pairs), expected)
          << "scene " << scene << " (size " << size << "), call " << call;
      double largest = 0.0;
      for (const Aabb& b : boxes) largest = std::max(largest, (b.hi - b.lo).maxCoeff());
      EXPECT_GE(cells.cellSize(), largest);
      EXPECT_LE(cells.cellSize(), largest * (1.0 + 2e-6));
      pairs_total += static_cast<long>(expected.size());
      for (Aabb& b : boxes) {  // each box moves by up to about half its size
        const Eigen::Vector3d d = 0.2 * size * Eigen::Vector3d(step(rng), step(rng), step(rng));
        b.lo += d;
        b.hi += d;
      }
    }
  }
  EXPECT_GT(pairs_total, 10000) << "the packed scenes overlap";
}

TEST(CellList, TheCellEdgeIsTheLargestExtent) {
  std::vector<Aabb> boxes(3);
  boxes[0].hi = Eigen::Vector3d(0.1, 0.2, 0.3);
  boxes[1].lo = Eigen::Vector3d(1, 1, 1);
  boxes[1].hi = Eigen::Vector3d(1.25, 1.1, 1.1);
  boxes[2].lo = boxes[2].hi = Eigen::Vector3d(5, 5, 5);
  CellList cells;
  Pairs pairs;
  cells.overlappingPairs(boxes, allMembers(3), pairs);
  EXPECT_LE(cells.cellSize(), 0.3 * (1.0 + 2e-6));
  EXPECT_GE(cells.cellSize(), 0.3);
  EXPECT_TRUE(pairs.empty());
}

TEST(CellList, BoxesTouchingAtTheCellEdgeArePairs) {
  // Cubes of side s side by side at spacing s, each face the very coordinate of its
  // neighbour's (touching faces, edges and corners), a 5 x 5 x 5 block, for sides that are and
  // are not powers of two and lower corners at and off multiples of the side: the centre has
  // 26 neighbours, the rest as brute force says.
  for (const double side : {1.0, 0.1, 0.3, 1e-3, 7.0}) {
    for (const double offset : {0.0, 0.5, -1e3}) {
      double x[6];
      for (int i = 0; i < 6; ++i) x[i] = side * (i + offset);
      std::vector<Aabb> boxes;
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
          for (int k = 0; k < 5; ++k) {
            Aabb b;
            b.lo = Eigen::Vector3d(x[i], x[j], x[k]);
            b.hi = Eigen::Vector3d(x[i + 1], x[j + 1], x[k + 1]);
            boxes.push_back(b);
          }
      const std::vector<int> members = allMembers(boxes.size());
      CellList cells;
      Pairs pairs;
      cells.overlappingPairs(boxes, members, pairs);
      const Pairs expected = bruteForcePairs(boxes, members);
      EXPECT_EQ(sortedPairs(pairs), expected) << "side " << side << ", offset " << offset;
      const int centre = 2 * 25 + 2 * 5 + 2;
      EXPECT_EQ(
          std::count_if(expected.begin(), expected.end(),
                        [&](const auto& p) { return p.first == centre || p.second == centre; }),
          26)
          << "side " << side << ", offset " << offset;
    }
  }
}

TEST(CellList, BoxesOfManySizesAreStillPairedRight) {
  // Sizes from 1 mm to 10 m: the cell is the largest, so the list degenerates towards all
  // pairs (the detector gives such boxes to the grid), but stays exact.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> log_size(std::log(1e-3), std::log(10.0));
  std::uniform_real_distribution<double> at(-20.0, 20.0);
  std::vector<Aabb> boxes(400);
  for (Aabb& b : boxes) {
    const Eigen::Vector3d c(at(rng), at(rng), at(rng));
    const Eigen::Vector3d half(std::exp(log_size(rng)), std::exp(log_size(rng)),
                               std::exp(log_size(rng)));
    b.lo = c - half;
    b.hi = c + half;
  }
  const std::vector<int> members = allMembers(boxes.size());
  CellList cells;
  Pairs pairs;
  cells.overlappingPairs(boxes, members, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForcePairs(boxes, members));
  EXPECT_FALSE(pairs.empty());
}

TEST(CellList, FarNanInfiniteAndPointBoxesAreStillFound) {
  std::mt19937 rng(11);
  std::vector<Aabb> boxes = boxesOfOneSize(rng, 150, 0.1, 1.2, 1.0, Eigen::Vector3d::Zero());
  Aabb far_a, far_b;  // beyond 2^30 cells of about 0.1 m, overlapping each other
  far_a.lo = Eigen::Vector3d(2e8, -2e8, 2e8);
  far_a.hi = far_a.lo + Eigen::Vector3d::Constant(0.05);
  far_b.lo = far_a.lo + Eigen::Vector3d::Constant(0.02);
  far_b.hi = far_b.lo + Eigen::Vector3d::Constant(0.05);
  boxes.push_back(far_a);
  boxes.push_back(far_b);
  Aabb nan_box;  // paired with everything rather than lost
  nan_box.lo.setConstant(std::numeric_limits<double>::quiet_NaN());
  nan_box.hi = nan_box.lo;
  boxes.push_back(nan_box);
  Aabb slab;  // infinite: kept aside, meets what lies in it
  slab.lo = Eigen::Vector3d(-std::numeric_limits<double>::infinity(), -1, -0.05);
  slab.hi = Eigen::Vector3d(std::numeric_limits<double>::infinity(), 1, 0.05);
  boxes.push_back(slab);
  Aabb point;  // a zero-size box inside the crowd
  point.lo = point.hi = Eigen::Vector3d(0.01, 0.02, 0.03);
  boxes.push_back(point);
  const std::vector<int> members = allMembers(boxes.size());
  CellList cells;
  Pairs pairs;
  cells.overlappingPairs(boxes, members, pairs);
  const Pairs expected = bruteForcePairs(boxes, members);
  EXPECT_EQ(sortedPairs(pairs), expected);
  const int n = static_cast<int>(boxes.size());
  EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), std::make_pair(n - 5, n - 4)));
  EXPECT_EQ(std::count_if(expected.begin(), expected.end(),
                          [&](const auto& p) { return p.first == n - 3 || p.second == n - 3; }),
            n - 1);

  // Boxes that are all points: a cell of 1 m, coincident points paired.
  std::vector<Aabb> points(6);
  for (int k = 0; k < 6; ++k) points[k].lo = points[k].hi = Eigen::Vector3d(k / 2, 0, 0);
  Pairs point_pairs;
  cells.overlappingPairs(points, allMembers(6), point_pairs);
  EXPECT_EQ(sortedPairs(point_pairs), (Pairs{{0, 1}, {2, 3}, {4, 5}}));
  EXPECT_EQ(cells.cellSize(), 1.0);
}

TEST(CellList, OnlyTheMembersAreLookedAt) {
  std::mt19937 rng(7);
  const std::vector<Aabb> boxes = boxesOfOneSize(rng, 300, 0.2, 1.3, 2.0, Eigen::Vector3d::Zero());
  std::vector<int> members;
  for (int g = 1; g < 300; g += 3) members.push_back(g);
  CellList cells;
  Pairs pairs;
  cells.overlappingPairs(boxes, members, pairs);
  EXPECT_EQ(sortedPairs(pairs), bruteForcePairs(boxes, members));
  EXPECT_FALSE(pairs.empty());
}

TEST(CellList, TheSameListInTheSameOrderForAnyThreadCountAndTheWorkIsSplit) {
  for (const bool packed : {true, false}) {  // dense and hashed cells
    std::mt19937 rng(5);
    const double region = packed ? 18.0 : 400.0;
    const std::vector<Aabb> boxes =
        boxesOfOneSize(rng, 6000, 1.0, 1.4, region, Eigen::Vector3d::Zero());
    const std::vector<int> members = allMembers(boxes.size());
    Pairs one;
    CellList single;
    single.overlappingPairs(boxes, members, one);
    ASSERT_EQ(sortedPairs(one), bruteForcePairs(boxes, members));
    ASSERT_FALSE(one.empty());
    for (const int threads : {2, 3}) {
      CellList cells;
      cells.setThreads(threads);
      const long before = splitLoopCount().load();
      Pairs pairs;
      cells.overlappingPairs(boxes, members, pairs);
      EXPECT_EQ(pairs, one) << threads << " threads, packed " << packed;
      EXPECT_GT(splitLoopCount().load(), before) << "the pair search was cut for a team";
    }
  }
}

using test::EveryPair;

// The skin list of a pile of spheres or turning cubes of one size (so its fat boxes go to the
// cell list) finds the points every pair listed finds, bit for bit and in the same order.
TEST(CellList, TheSkinListOfSpheresAndCubesOfOneSizeGivesWhatEveryPairGives) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> log_size(std::log(1e-3), std::log(10.0));
  std::normal_distribution<double> nd;
  for (int scene = 0; scene < 6; ++scene) {
    const double r = std::exp(log_size(rng));
    const bool cubes = scene % 2 == 1;
    const int n = 120;
    std::vector<Shape> shapes;
    std::vector<Eigen::Isometry3d> poses;
    const double side = 2.0 * r * std::cbrt(static_cast<double>(n)) * 0.95;
    std::uniform_real_distribution<double> at(0.0, side);
    for (int g = 0; g < n; ++g) {
      shapes.push_back(cubes ? Shape::box(Eigen::Vector3d::Constant(0.8 * r)) : Shape::sphere(r));
      Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
      t.translation() = Eigen::Vector3d(at(rng), at(rng), at(rng));
      t.linear() =
          Eigen::Quaterniond(nd(rng), nd(rng), nd(rng), nd(rng)).normalized().toRotationMatrix();
      poses.push_back(t);
    }
    std::vector<std::pair<int, int>> all;
    for (int g = 0; g < n; ++g)
      for (int h = g + 1; h < n; ++h) all.emplace_back(g, h);
    CollisionOptions skin;
    skin.broadphase = true;
    skin.broadphase_skin = 0.1;
    CollisionDetector skinned(shapes, std::make_unique<EveryPair>(n), skin);
    CollisionDetector brute(shapes, all);  // no broadphase: every pair to the narrowphase
    std::size_t points = 0;
    for (int call = 0; call < 12; ++call) {
      std::vector<ContactPoint> got, want;
      skinned.detect(poses, got);
      brute.detect(poses, want);
      const std::string where = "scene " + std::to_string(scene) + ", call " + std::to_string(call);
      ASSERT_EQ(got.size(), want.size()) << where;
      for (std::size_t i = 0; i < got.size(); ++i) {
        const auto [g, h] = all[static_cast<std::size_t>(want[i].pair)];
        EXPECT_EQ(got[i].pair, g * n + h) << where;
        EXPECT_EQ(got[i].position, want[i].position) << where;
        EXPECT_EQ(got[i].depth, want[i].depth) << where;
      }
      points += got.size();
      for (Eigen::Isometry3d& t : poses) {  // moves by up to about a tenth of r, and turns
        t.translation() += 0.05 * r * Eigen::Vector3d(nd(rng), nd(rng), nd(rng));
        t.linear() =
            (Eigen::AngleAxisd(0.1, Eigen::Vector3d(nd(rng), nd(rng), nd(rng)).normalized()) *
             Eigen::Quaterniond(t.linear()))
                .normalized()
                .toRotationMatrix();
      }
    }
    EXPECT_GT(points, 50U) << "scene " << scene << " has contacts to find";
    EXPECT_GT(skinned.skinListBuilds(), 1) << "scene " << scene << ": the list was rebuilt";
    EXPECT_EQ(skinned.cellListBuilds(), skinned.skinListBuilds())
        << "scene " << scene << ": fat boxes of one size go to the cell list";
  }
}

TEST(CellList, TheSkinListOfManySizesStaysWithTheGrid) {
  std::vector<Shape> shapes;
  std::vector<Eigen::Isometry3d> poses;
  for (int g = 0; g < 40; ++g) {
    shapes.push_back(Shape::sphere(g % 4 == 0 ? 1.0 : 0.1));  // one in four ten times larger
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(0.15 * g, 0.0, 0.0);
    poses.push_back(t);
  }
  CollisionOptions skin;
  skin.broadphase = true;
  skin.broadphase_skin = 0.1;
  CollisionDetector skinned(shapes, std::make_unique<EveryPair>(40), skin);
  std::vector<ContactPoint> got;
  skinned.detect(poses, got);
  EXPECT_FALSE(got.empty());
  EXPECT_EQ(skinned.skinListBuilds(), 1);
  EXPECT_EQ(skinned.cellListBuilds(), 0);
}

}  // namespace
}  // namespace tribo::contact
