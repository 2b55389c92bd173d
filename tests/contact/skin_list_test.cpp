// The detector's cached pair list (CollisionOptions::broadphase_skin, a Verlet list:
// contact/collision_detector.hpp) against the grid on every call (skin 0) and against every
// pair listed with no broadphase (brute force): the same contact points, bit for bit and in
// the same order, over random scenes of spheres, boxes and capsules (with a half-space) of
// sizes from 1 mm to 10 m whose geometries move between calls by less and more than the
// skin, turn, teleport, and once take a NaN pose; and the same list for 1, 2 and 3 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "contact/collision_detector.hpp"
#include "contact/split_count.hpp"
#include "support/every_pair_rule.hpp"
#include "support/same_bits.hpp"

namespace tribo::contact {
namespace {

using test::EveryPair;

using test::sameBits;

bool samePoint(const ContactPoint& a, const ContactPoint& b) {
  bool same = a.pair == b.pair && a.feature == b.feature && sameBits(a.depth, b.depth);
  for (int k = 0; k < 3; ++k)
    same = same && sameBits(a.position[k], b.position[k]) && sameBits(a.normal[k], b.normal[k]);
  return same;
}

// `got` equals `want` point by point; `want_pair` maps want's pair ids to got's.
template <typename Map>
void expectSame(const std::vector<ContactPoint>& got, const std::vector<ContactPoint>& want,
                Map want_pair, const std::string& where) {
  ASSERT_EQ(got.size(), want.size()) << where;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ContactPoint w = want[i];
    w.pair = want_pair(w.pair);
    EXPECT_TRUE(samePoint(got[i], w)) << where << ", point " << i << " of " << got.size();
  }
}

// A sphere, box or capsule of size `size` [m] (g % 3), or the half-space (g == 0).
Shape shapeOf(std::mt19937& rng, int g, double size) {
  std::uniform_real_distribution<double> f(0.3, 1.0);
  if (g == 0) return Shape::halfSpace();
  switch (g % 3) {
    case 0:
      return Shape::sphere(size * f(rng));
    case 1:
      return Shape::box(size * Eigen::Vector3d(f(rng), f(rng), f(rng)));
    default:
      return Shape::capsule(size * f(rng), size * f(rng));
  }
}

Eigen::Quaterniond randomTurn(std::mt19937& rng, double angle) {
  std::normal_distribution<double> n;
  const Eigen::Vector3d axis = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

struct Scene {
  std::vector<Shape> shapes;
  std::vector<Eigen::Isometry3d> poses;
  double size = 1.0;  // the typical geometry's size [m]
};

// n geometries (the first the floor z = 0), each of size `scale` times a log-uniform factor
// in [1, spread], centres in a box a few sizes wide standing on the floor, so many touch.
Scene randomScene(std::mt19937& rng, int n, double scale, double spread) {
  Scene s;
  s.size = scale;
  std::uniform_real_distribution<double> log_factor(0.0, std::log(spread));
  const double side = scale * std::cbrt(static_cast<double>(n)) * 1.2;
  std::uniform_real_distribution<double> at(0.0, side);
  for (int g = 0; g < n; ++g) {
    s.shapes.push_back(shapeOf(rng, g, scale * std::exp(log_factor(rng))));
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    if (g > 0) {
      t.linear() =
          randomTurn(rng, std::uniform_real_distribution<double>(0, 3.0)(rng)).toRotationMatrix();
      t.translation() = Eigen::Vector3d(at(rng), at(rng), 0.5 * at(rng));
    }
    s.poses.push_back(t);
  }
  return s;
}

// One move of every geometry but the floor: by `reach` times the scene's size along a random
// direction with a small turn; one geometry in twenty teleports anywhere in the scene.
void moveAll(std::mt19937& rng, Scene& s, double reach) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double side = s.size * std::cbrt(static_cast<double>(s.poses.size())) * 1.2;
  for (std::size_t g = 1; g < s.poses.size(); ++g) {
    Eigen::Isometry3d& t = s.poses[g];
    if (u(rng) < 0.05) {
      t.translation() = side * Eigen::Vector3d(u(rng), u(rng), 0.5 * u(rng));
      t.linear() = randomTurn(rng, 3.0 * u(rng)).toRotationMatrix();
      continue;
    }
    t.translation() += reach * s.size * u(rng) * Eigen::Vector3d(n(rng), n(rng), n(rng));
    t.linear() = (randomTurn(rng, 0.05 * reach) * Eigen::Quaterniond(t.linear()))
                     .normalized()
                     .toRotationMatrix();
  }
}

CollisionOptions withSkin(double skin) {
  CollisionOptions o;
  o.broadphase = true;
  o.broadphase_skin = skin;
  return o;
}

TEST(SkinList, TheSamePointsInTheSameOrderAsTheGridEveryCallAndAsEveryPairListed) {
  std::mt19937 rng(20261129);
  std::uniform_real_distribution<double> log_scale(std::log(1e-3), std::log(10.0));
  long calls_total = 0, builds_total = 0, points_total = 0;
  for (int scene = 0; scene < 8; ++scene) {
    // Scenes 0-5: one size each, 1 mm to 10 m; 6-7: sizes from 1 mm to 10 m mixed.
    const bool mixed = scene >= 6;
    const double scale = mixed ? 1e-3 : std::exp(log_scale(rng));
    const int n = mixed ? 150 : 60;
    Scene s = randomScene(rng, n, scale, mixed ? 1e4 : 3.0);
    std::vector<std::pair<int, int>> all;
    for (int g = 0; g < n; ++g)
      for (int h = g + 1; h < n; ++h) all.emplace_back(g, h);
    CollisionDetector every_call(s.shapes, std::make_unique<EveryPair>(n), withSkin(0.0));
    CollisionDetector brute(s.shapes, all);  // no broadphase: every pair to the narrowphase
    std::vector<CollisionDetector> skinned;
    for (const double skin : {0.02, 0.1, 0.5})
      skinned.emplace_back(s.shapes, std::make_unique<EveryPair>(n), withSkin(skin));
    CollisionDetector listed_skinned(s.shapes, all, withSkin(0.1));  // listed, with the list
    std::vector<ContactPoint> want, full, got;
    // Moves by 0 (standing still), far below, about and far above the skin, in turn.
    const double reaches[] = {0.0, 1e-4, 1e-3, 0.01, 0.05, 0.2, 1.0, 3.0};
    for (int call = 0; call < 32; ++call) {
      const std::string where = "scene " + std::to_string(scene) + " (scale " +
                                std::to_string(scale) + "), call " + std::to_string(call);
      every_call.detect(s.poses, want);
      brute.detect(s.poses, full);
      expectSame(
          want, full, [&](int p) { return all[p].first * n + all[p].second; },
          where + ", the grid against every pair");
      for (CollisionDetector& d : skinned) {
        d.detect(s.poses, got);
        expectSame(
            got, want, [](int p) { return p; }, where + ", the skin list");
      }
      listed_skinned.detect(s.poses, got);
      expectSame(
          got, full, [](int p) { return p; }, where + ", listed pairs with the list");
      for (const ContactPoint& p : want)
        ASSERT_TRUE(p.position.allFinite() && p.normal.allFinite() && std::isfinite(p.depth))
            << where;
      points_total += static_cast<long>(want.size());
      moveAll(rng, s, reaches[call % 8]);
    }
    calls_total += 32;
    for (const CollisionDetector& d : skinned) builds_total += d.skinListBuilds();
  }
  EXPECT_GT(points_total, 1000) << "the scenes have contacts to find";
  // The list was both kept over calls and rebuilt.
  EXPECT_LT(builds_total, 3 * calls_total);
  EXPECT_GT(builds_total, 3 * 8);
}

TEST(SkinList, ANanPoseRebuildsTheListAndGivesWhatTheGridGives) {
  std::mt19937 rng(7);
  Scene s = randomScene(rng, 40, 0.1, 3.0);
  CollisionDetector every_call(s.shapes, std::make_unique<EveryPair>(40), withSkin(0.0));
  CollisionDetector skinned(s.shapes, std::make_unique<EveryPair>(40), withSkin(0.1));
  std::vector<ContactPoint> want, got;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int call = 0; call < 6; ++call) {
    const Eigen::Isometry3d kept = s.poses[7];
    if (call == 2) s.poses[7].translation().x() = nan;
    if (call == 3) s.poses[9].linear()(0, 0) = nan;
    every_call.detect(s.poses, want);
    skinned.detect(s.poses, got);
    expectSame(
        got, want, [](int p) { return p; }, "call " + std::to_string(call));
    if (call == 2) s.poses[7] = kept;
    if (call == 3) s.poses[9].linear() = s.poses[10].linear();
    if (call == 1) {
      EXPECT_EQ(skinned.skinListBuilds(), 1) << "standing still: the first list is kept";
    }
  }
  EXPECT_GE(skinned.skinListBuilds(), 3) << "a NaN box is in no fat box";
}

TEST(SkinList, TheSameListForOneTwoAndThreeThreads) {
  std::mt19937 rng(11);
  const int n = 3000;  // enough boxes and pairs for a team in every stage
  Scene s = randomScene(rng, n, 0.05, 4.0);
  std::vector<CollisionDetector> detectors;
  for (int threads = 1; threads <= 3; ++threads) {
    detectors.emplace_back(s.shapes, std::make_unique<EveryPair>(n), withSkin(0.1));
    detectors.back().setThreads(threads);
  }
  CollisionDetector every_call(s.shapes, std::make_unique<EveryPair>(n), withSkin(0.0));
  const long split_before = splitLoopCount().load();
  std::vector<ContactPoint> want, got;
  for (int call = 0; call < 4; ++call) {
    every_call.detect(s.poses, want);
    ASSERT_GT(want.size(), 300U);
    for (std::size_t t = 0; t < detectors.size(); ++t) {
      detectors[t].detect(s.poses, got);
      expectSame(
          got, want, [](int p) { return p; },
          std::to_string(t + 1) + " threads, call " + std::to_string(call));
    }
    moveAll(rng, s, call % 2 == 0 ? 1e-3 : 0.3);
  }
  EXPECT_GT(splitLoopCount().load(), split_before) << "some stage was cut for a team";
}

// Pairs numbered with room between them, id = g * 65536 + h (g < h): ids past 2^26 have digits
// in the third 11-bit place of the detector's radix sort of long lists.
class SpreadPair : public PairRule {
 public:
  int pairId(int g, int h) const override { return std::min(g, h) * 65536 + std::max(g, h); }
  std::pair<int, int> geometries(int id) const override { return {id / 65536, id % 65536}; }
};

TEST(SkinList, ThousandsOfPairsComeInIdOrderAsEveryPairListed) {
  // 1200 spheres of 10 mm on a floor, a 20 x 20 x 3 lattice at a pitch 0.5 % under their
  // diameter, shaken by up to 0.2 % of it: some 4000 pairs in contact (the floor's 1200 with
  // them, always listed), long enough for the radix sort, whose ids reach 1199 * 65536 (27
  // bits, three digits); then shaken apart.
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> shake(-4e-5, 4e-5);
  const double r = 0.01, pitch = 0.995 * 2 * r;
  Scene s;
  s.size = 2 * r;
  s.shapes.push_back(Shape::halfSpace());
  s.poses.push_back(Eigen::Isometry3d::Identity());
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 3; ++k) {
        s.shapes.push_back(Shape::sphere(r));
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(i * pitch + shake(rng), j * pitch + shake(rng),
                                          0.999 * r + k * pitch + shake(rng));
        s.poses.push_back(t);
      }
  const int n = static_cast<int>(s.shapes.size());
  std::vector<std::pair<int, int>> all;
  for (int g = 0; g < n; ++g)
    for (int h = g + 1; h < n; ++h) all.emplace_back(g, h);
  CollisionDetector brute(s.shapes, all);  // no broadphase: every pair in id order
  CollisionDetector every_call(s.shapes, std::make_unique<SpreadPair>(), withSkin(0.0));
  CollisionDetector skinned(s.shapes, std::make_unique<SpreadPair>(), withSkin(0.1));
  auto spread = [&](int p) { return all[p].first * 65536 + all[p].second; };
  std::vector<ContactPoint> want, got;
  for (int call = 0; call < 3; ++call) {
    const std::string where = "call " + std::to_string(call);
    brute.detect(s.poses, want);
    ASSERT_GT(want.size(), call == 0 ? 3000U : 1000U) << where;  // the floor's pairs: 1200
    every_call.detect(s.poses, got);
    expectSame(got, want, spread, where + ", the grid every call");
    skinned.detect(s.poses, got);
    expectSame(got, want, spread, where + ", the skin list");
    moveAll(rng, s, call == 0 ? 1e-3 : 0.05);
  }
}

// Pairs numbered against the geometries' order: id = n^2 - (g n + h) (g < h), so the pairs a
// broadphase reports, sorted by geometry, come in decreasing id (the detector then sorts its
// candidates by id instead of merging them in geometry order).
class ReversedPair : public PairRule {
 public:
  explicit ReversedPair(int n) : n_(n) {}
  int pairId(int g, int h) const override {
    return n_ * n_ - (std::min(g, h) * n_ + std::max(g, h));
  }
  std::pair<int, int> geometries(int id) const override {
    const int v = n_ * n_ - id;
    return {v / n_, v % n_};
  }

 private:
  int n_;
};

TEST(SkinList, ARuleWhoseIdsRunAgainstTheGeometriesGivesItsOwnIdOrder) {
  std::mt19937 rng(20261202);
  for (const double scale : {2e-3, 0.05, 4.0}) {
    const int n = 400;
    Scene s = randomScene(rng, n, scale, 3.0);
    // Every pair listed in decreasing (g, h): the reversed rule's increasing id.
    std::vector<std::pair<int, int>> reversed;
    for (int g = n - 1; g >= 0; --g)
      for (int h = n - 1; h > g; --h) reversed.emplace_back(g, h);
    CollisionDetector brute(s.shapes, reversed);
    CollisionDetector skinned(s.shapes, std::make_unique<ReversedPair>(n), withSkin(0.1));
    auto id = [&](int p) { return n * n - (reversed[p].first * n + reversed[p].second); };
    std::vector<ContactPoint> want, got;
    std::size_t points = 0;
    for (int call = 0; call < 6; ++call) {
      const std::string where = "scale " + std::to_string(scale) + ", call " + std::to_string(call);
      brute.detect(s.poses, want);
      skinned.detect(s.poses, got);
      expectSame(got, want, id, where);
      points += want.size();
      moveAll(rng, s, call % 2 == 0 ? 1e-3 : 0.3);
    }
    EXPECT_GT(points, 300U) << "the scenes have contacts to find";
    EXPECT_GE(skinned.skinListBuilds(), 2) << "rebuilt, not only built";
  }
}

}  // namespace
}  // namespace tribo::contact
