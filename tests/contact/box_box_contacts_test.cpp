// Closed-form box/box, capsule/box and cylinder/box contacts (contact/box_box_contacts.hpp,
// contact/box_round_contacts.hpp) against FCL's narrowphase on the same poses (the detector
// with closed_form_primitives off: FCL's box/box manifold, libccd GJK/EPA for the round
// shapes) and against a brute-force separating-axis test over the corners, and against
// analytic manifolds: a box resting flat, turned 45 degrees (the octagon), on an edge, edges
// crossing, a capsule lying on a face and over its border, a cylinder standing and lying.
#include "contact/box_box_contacts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>

#include "contact/box_round_contacts.hpp"
#include "contact/collision_detector.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"
#include "support/test_poses.hpp"

namespace tribo::contact {
namespace {

using tribo::Body;
using tribo::BodyIndex;
using tribo::BodyKind;
using tribo::IntegratorType;
using tribo::Mat3;
using tribo::ModelBuilder;
using tribo::Quat;
using tribo::Simulator;
using tribo::Vec3;

using Eigen::Isometry3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using test::pose;

CollisionOptions fclOnly() {
  CollisionOptions o;
  o.closed_form_primitives = false;
  return o;
}

const ContactPoint& deepest(const std::vector<ContactPoint>& c) {
  return *std::max_element(c.begin(), c.end(), [](const ContactPoint& x, const ContactPoint& y) {
    return x.depth < y.depth;
  });
}

// Brute-force separating-axis test, independent of the closed form: every corner of both
// boxes projected on each of the 15 axes. Returns the largest separation (< 0: overlap) and
// the axis of least penetration (from A towards B), and the runner-up separation of a
// different direction.
struct Sat {
  double best = -1e300, second = -1e300;
  Vector3d axis = Vector3d::Zero();
};
Sat bruteSat(const Isometry3d& pa, const Vector3d& ha, const Isometry3d& pb, const Vector3d& hb) {
  std::vector<Vector3d> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(pa.linear().col(i));
  for (int i = 0; i < 3; ++i) axes.push_back(pb.linear().col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vector3d l = pa.linear().col(i).cross(pb.linear().col(j));
      if (l.norm() > 1e-6) axes.push_back(l.normalized());
    }
  Sat sat;
  for (const Vector3d& l : axes) {
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (int k = 0; k < 8; ++k) {
      const Vector3d c((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
      const double x = l.dot(pa * c.cwiseProduct(ha)), y = l.dot(pb * c.cwiseProduct(hb));
      amin = std::min(amin, x), amax = std::max(amax, x);
      bmin = std::min(bmin, y), bmax = std::max(bmax, y);
    }
    const double up = bmin - amax, down = amin - bmax;  // separations along +l and -l
    const double s = std::max(up, down);
    const Vector3d dir = up >= down ? l : Vector3d(-l);
    if (s > sat.best) {
      if (sat.axis.cross(dir).norm() > 1e-9) sat.second = sat.best;
      sat.best = s, sat.axis = dir;
    } else if (s > sat.second && sat.axis.cross(dir).norm() > 1e-9) {
      sat.second = s;
    }
  }
  return sat;
}

Quaterniond randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized();
}

TEST(BoxBoxContacts, AgreesWithFclAndTheSeparatingAxesOverThousandsOfPoses) {
  // Sizes from 1 mm to 10 m, aspect ratios up to 20, B placed along a random direction at the
  // distance where the supports along it meet, then moved in or out by up to 2 % of the
  // smaller box: shallow overlaps, grazing and separated poses.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  CollisionDetector ours({Shape::box({1, 1, 1}), Shape::box({1, 1, 1})}, {{0, 1}});
  int poses = 0, contacts = 0, separated = 0, unambiguous = 0, face_points = 0, edge_pairs = 0;
  double worst_angle = 0.0, worst_depth = 0.0, worst_sat = 0.0;
  for (const double scale : {1e-3, 1e-2, 0.1, 1.0, 10.0}) {
    for (int i = 0; i < 1200; ++i) {
      Vector3d ha, hb;
      for (int k = 0; k < 3; ++k) {
        ha[k] = scale * std::pow(20.0, unit(rng));
        hb[k] = scale * std::pow(20.0, unit(rng));
      }
      const Isometry3d pa = pose(scale * Vector3d(unit(rng), unit(rng), unit(rng)),
                                 i % 5 == 0 ? Quaterniond::Identity() : randomRotation(rng));
      // Every fourth pose: B's face parallel to A's (resting-like), else random.
      const Quaterniond qb =
          i % 4 == 0
              ? Quaterniond(pa.linear()) *
                    Quaterniond(Eigen::AngleAxisd(unit(rng) * std::numbers::pi, Vector3d::UnitZ()))
              : randomRotation(rng);
      const Vector3d dir = i % 4 == 0 ? Vector3d(pa.linear().col(2))
                                      : Vector3d(randomRotation(rng) * Vector3d::UnitX());
      const Shape a = Shape::box(ha), b = Shape::box(hb);
      // The touching distance along dir, by bisection on the brute-force test (the
      // overlapping translations are convex and contain 0).
      double lo = 0.0, hi = 2.0 * (ha.norm() + hb.norm());
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (bruteSat(pa, ha, pose(pa.translation() + mid * dir, qb), hb).best < 0 ? lo : hi) = mid;
      }
      const double small = std::min(ha.minCoeff(), hb.minCoeff());
      const double shift = (unit(rng) * 0.024 - 0.004) * small;  // > 0: overlap
      const Isometry3d pb = pose(pa.translation() + (lo - shift) * dir, qb);
      CollisionDetector mine({a, b}, {{0, 1}});
      CollisionDetector fcl({a, b}, {{0, 1}}, fclOnly());
      std::vector<ContactPoint> x, y;
      const std::vector<Isometry3d> where{pa, pb};
      mine.detect(where, x);
      fcl.detect(where, y);
      const Sat sat = bruteSat(pa, ha, pb, hb);
      ++poses;
      // The decision: the separating axes, and FCL, except where the overlap is within
      // rounding of zero (FCL skips points of depth 0).
      if (std::abs(sat.best) > 1e-9 * scale) {
        ASSERT_EQ(!x.empty(), sat.best < 0) << scale << " " << i;
        ASSERT_EQ(!y.empty(), sat.best < 0) << scale << " " << i;
      }
      if (x.empty()) {
        ++separated;
        continue;
      }
      ++contacts;
      ASSERT_LE(x.size(), 8u);
      std::set<int> features;
      for (const auto& c : x) {
        EXPECT_GT(c.depth, 0.0);
        EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
        EXPECT_GT(c.normal.dot(x[0].normal), 1 - 1e-12);  // one normal per manifold
        features.insert(c.feature);
      }
      EXPECT_EQ(features.size(), x.size()) << "feature ids repeat";
      face_points += x.size() > 1;
      // Our deepest point never exceeds the least penetration over the 15 axes (the
      // chosen axis is at most 1/0.95 deeper than it), nor its normal's own separation.
      const double pen = -sat.best;
      const ContactPoint& d = deepest(x);
      EXPECT_LE(d.depth, pen / 0.95 * (1 + 1e-9)) << scale << " " << i;
      worst_sat = std::max(worst_sat, d.depth / pen - 1);
      // Where the least-penetration axis is clear (the runner-up separation at least 6 %
      // deeper, beyond both biases) the closed form and FCL must pick it: the same normal and
      // deepest depth.
      if (y.empty() || !(sat.second < 1.06 * sat.best)) continue;
      ++unambiguous;
      const ContactPoint& f = deepest(y);
      const double angle = std::acos(std::min(1.0, d.normal.dot(f.normal)));
      worst_angle = std::max(worst_angle, angle);
      worst_depth = std::max(worst_depth, std::abs(d.depth - f.depth) / pen);
      EXPECT_LT(angle, 1e-6) << scale << " " << i;
      EXPECT_GT(d.normal.dot(sat.axis), 1 - 1e-9) << scale << " " << i;
      // FCL's deepest to 1e-6 of the depth, or to 1e-12 of the boxes' size (its rounding on
      // edge pairs of 10 m boxes: 1.5e-11 m at 2.9e-6 m depth).
      const double size = std::max(ha.maxCoeff(), hb.maxCoeff());
      EXPECT_LE(std::abs(d.depth - f.depth), 1e-6 * d.depth + 1e-12 * size) << scale << " " << i;
      // An edge pair's depth is the penetration itself, to rounding: relative to the depth,
      // or to the coordinates' size (the closest points of two edges of a 10 m box carry
      // rounding of that size; clang at -O1 gives 1.3e-8 of a shallow depth there).
      if (d.feature >= 128) {
        ++edge_pairs;
        EXPECT_LE(std::abs(d.depth - pen), 1e-9 * pen + 1e-12 * size) << scale << " " << i;
      }
    }
  }
  std::printf(
      "%d poses: %d in contact (%d with several points), %d separated; %d with a clear axis: "
      "normal within %.2g rad of FCL's, deepest depth within %.2g (of the depth) of FCL's; "
      "deepest/penetration - 1 at most %.2g; %d edge-pair poses checked for depth\n",
      poses, contacts, face_points, separated, unambiguous, worst_angle, worst_depth, worst_sat,
      edge_pairs);
  EXPECT_GT(contacts, 2000);
  EXPECT_GT(separated, 300);
  EXPECT_GT(unambiguous, 1000);
  EXPECT_GT(face_points, 1000);
  EXPECT_GT(edge_pairs, 1000);  // 2009 of 6000: the edge-pair depth check cannot go quietly empty
}

TEST(BoxBoxContacts, ABoxRestingFlatGetsItsFourCornersInEitherOrder) {
  for (const double s : {1e-3, 0.1, 10.0}) {
    const Vector3d big(5 * s, 4 * s, s), small(s, 2 * s, 0.5 * s);
    const double d = 1e-4 * s;
    const Vector3d c(0.3 * s, -0.2 * s, big.z() + small.z() - d);
    for (const bool small_is_a : {false, true}) {
      std::vector<ContactPoint> out;
      const Isometry3d below = pose({0, 0, 0}), above = pose(c);
      if (small_is_a)
        boxBoxContacts(above, small, below, big, 7, 8, out);
      else
        boxBoxContacts(below, big, above, small, 7, 8, out);
      ASSERT_EQ(out.size(), 4u);
      std::set<int> features;
      for (const auto& p : out) {
        EXPECT_EQ(p.pair, 7);
        EXPECT_NEAR(p.depth, d, 1e-12 * s);
        EXPECT_NEAR(p.normal.z(), small_is_a ? -1.0 : 1.0, 1e-15);
        EXPECT_NEAR(std::abs(p.position.x() - c.x()), small.x(), 1e-12 * s);
        EXPECT_NEAR(std::abs(p.position.y() - c.y()), small.y(), 1e-12 * s);
        EXPECT_NEAR(p.position.z(), big.z() - d / 2, 1e-12 * s);
        features.insert(p.feature);
      }
      // The small box's bottom corners (0-3) as incident face, or the reference face's
      // four corners projected when the small box is A.
      if (!small_is_a) {
        EXPECT_EQ(features, (std::set<int>{0, 1, 2, 3}));
      }
      EXPECT_EQ(features.size(), 4u);
    }
  }
}

TEST(BoxBoxContacts, ACubeTurned45DegreesOnAnEqualCubeGivesTheOctagon) {
  const double a = 0.1, d = 1e-5;
  const Isometry3d pa = pose({0, 0, 0});
  const Isometry3d pb = pose(
      {0, 0, 2 * a - d}, Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitZ())));
  std::vector<ContactPoint> out;
  boxBoxContacts(pa, Vector3d::Constant(a), pb, Vector3d::Constant(a), 0, 8, out);
  ASSERT_EQ(out.size(), 8u);
  // The diamond |x| + |y| <= a sqrt 2 cut by the square |x|, |y| <= a: vertices
  // (+-a, +-(a sqrt 2 - a)) and (+-(a sqrt 2 - a), +-a).
  const double cut = a * std::sqrt(2.0) - a;
  for (const auto& p : out) {
    const double x = std::abs(p.position.x()), y = std::abs(p.position.y());
    const bool on_x = std::abs(x - a) < 1e-14 && std::abs(y - cut) < 1e-14;
    const bool on_y = std::abs(y - a) < 1e-14 && std::abs(x - cut) < 1e-14;
    EXPECT_TRUE(on_x || on_y) << p.position.transpose();
    EXPECT_NEAR(p.depth, d, 1e-15);
    EXPECT_NEAR(p.normal.z(), 1.0, 1e-15);
  }
  // max_points 4: the deepest, then the farthest spread (alternate octagon vertices).
  std::vector<ContactPoint> four;
  boxBoxContacts(pa, Vector3d::Constant(a), pb, Vector3d::Constant(a), 0, 4, four);
  ASSERT_EQ(four.size(), 4u);
  double nearest = 1e9;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      nearest = std::min(nearest, (four[i].position - four[j].position).norm());
  // Octagon vertices spread as far as possible: no two adjacent (side 2 cut).
  EXPECT_GT(nearest, 2 * cut * 1.5);
}

TEST(BoxBoxContacts, AnEdgeOnAFaceGivesItsTwoEndsAndCrossedEdgesOnePoint) {
  const double a = 0.1, d = 2e-5, reach = a * std::sqrt(2.0);
  const Vector3d h = Vector3d::Constant(a), hb(0.3, 0.2, 0.1);
  // B turned 45 degrees about x, its lowest edge (along x) pressed d into A's top face.
  const Quaterniond qx(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitX()));
  std::vector<ContactPoint> out;
  boxBoxContacts(pose({0, 0, 0}), hb, pose({0.05, 0, hb.z() + reach - d}, qx), h, 0, 8, out);
  ASSERT_EQ(out.size(), 2u);
  for (const auto& p : out) {
    EXPECT_NEAR(p.depth, d, 1e-15);
    EXPECT_NEAR(p.normal.z(), 1.0, 1e-15);
    EXPECT_NEAR(std::abs(p.position.x() - 0.05), a, 1e-15);
    EXPECT_NEAR(p.position.y(), 0.0, 1e-15);
  }
  // A turned about y (top edge along y), B about x (bottom edge along x): the edges cross at
  // the origin's vertical, one point with the overlap as depth and normal +z.
  const Quaterniond qy(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitY()));
  std::vector<ContactPoint> cross;
  boxBoxContacts(pose({0, 0, 0}, qy), h, pose({0, 0, 2 * reach - d}, qx), h, 0, 8, cross);
  ASSERT_EQ(cross.size(), 1u);
  EXPECT_NEAR(cross[0].depth, d, 1e-15);
  EXPECT_NEAR(cross[0].normal.z(), 1.0, 1e-12);
  EXPECT_LT((cross[0].position - Vector3d(0, 0, reach - d / 2)).norm(), 1e-15);
  EXPECT_GE(cross[0].feature, 128);
  // FCL's box/box answers the same point.
  CollisionDetector fcl({Shape::box(h), Shape::box(h)}, {{0, 1}}, fclOnly());
  std::vector<ContactPoint> f;
  fcl.detect(std::vector<Isometry3d>{pose({0, 0, 0}, qy), pose({0, 0, 2 * reach - d}, qx)}, f);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(f[0].depth, d, 1e-12);
  EXPECT_LT((f[0].position - cross[0].position).norm(), 1e-9);
}

TEST(BoxBoxContacts, FlushBoxesOfTheSameSizeKeepOnePointACorner) {
  // Equal boxes, the upper one 1.5 cm along x, leaning 1e-3 rad about y and turned about z by
  // integration noise (1e-12 rad): its y sides lie on the lower box's y side planes up to
  // 1e-13 m. Four points (two corners, two cut at the x edge), never a corner split in two.
  const Vector3d h(0.1, 0.1, 0.1);
  for (const double lean : {0.0, 1e-3, -1e-3}) {
    const Quaterniond q =
        Quaterniond(Eigen::AngleAxisd(lean > 0 ? 1e-12 : -1e-12, Vector3d::UnitZ())) *
        Quaterniond(Eigen::AngleAxisd(lean, Vector3d::UnitY()));
    const double lowest = Shape::box(h).support(-(q.conjugate() * Vector3d::UnitZ()));
    std::vector<ContactPoint> out;
    boxBoxContacts(pose({0.3, -0.7, 0.2}), h, pose({0.315, -0.7, 0.3 + lowest - 5e-4}, q), h, 0, 8,
                   out);
    ASSERT_EQ(out.size(), 4u) << lean;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        EXPECT_GT((out[i].position - out[j].position).norm(), 0.15) << lean;
  }
}

TEST(BoxBoxContacts, FeatureIdsStayWhileARestingBoxSlidesAndTurnsALittle) {
  const Vector3d big(0.5, 0.5, 0.1), small(0.1, 0.1, 0.1);
  std::vector<ContactPoint> first;
  boxBoxContacts(pose({0, 0, 0}), big, pose({0, 0, 0.2 - 1e-5}), small, 0, 8, first);
  ASSERT_EQ(first.size(), 4u);
  for (int step = 1; step < 50; ++step) {
    const Isometry3d pb = pose({1e-3 * step, 0, 0.2 - 1e-5},
                               Quaterniond(Eigen::AngleAxisd(1e-3 * step, Vector3d::UnitZ())) *
                                   Quaterniond(Eigen::AngleAxisd(1e-5 * step, Vector3d::UnitX())));
    std::vector<ContactPoint> out;
    boxBoxContacts(pose({0, 0, 0}), big, pb, small, 0, 8, out);
    ASSERT_GE(out.size(), 2u);
    for (const auto& p : out) {
      // The same corner keeps its id: the nearest point of the first step carries it.
      const ContactPoint* near = nullptr;
      double best = 1e9;
      for (const auto& q : first)
        if ((q.position - p.position).norm() < best)
          best = (q.position - p.position).norm(), near = &q;
      EXPECT_EQ(p.feature, near->feature) << step;
    }
  }
}

TEST(BoxBoxContacts, StackedBoxesCarryTheirWeightWithoutDriftFromAMilligramToATonne) {
  // A box of mass m (half size a, density kept near 1000 kg/m^3) on a fixed 6a x 6a x 2a box,
  // turned 0.3 rad about z, both orders of the pair, RK4 at 1 ms for 1 s, linear law with
  // k = 1e5 m N/m and c = 100 m N s/m per point (the same static depth m g / 4k at every
  // mass), Coulomb friction: the vertical contact force is m g, nothing slides or turns.
  constexpr double kG = 9.81;
  for (const double m : {1e-3, 1.0, 1e3}) {
    for (const bool top_first : {false, true}) {
      const double a = 0.05 * std::cbrt(m);
      ModelBuilder b;
      b.options().integrator = IntegratorType::kRk4;
      b.options().time_step = 1e-3;
      contact::Material material;
      material.normal = {contact::NormalLawType::kLinear, 1e5 * m, 100.0 * m};
      material.friction =
          friction::makeFrictionLaw({"coulomb", {{"mu", 0.5}, {"v_eps", 0.01}}, {}});
      const int mat = b.addMaterial(material);
      Body table;
      table.name = "table";
      table.kind = BodyKind::kKinematic;
      table.position = Vec3(0, 0, -a);
      const int below =
          b.addGeometry("table_shape", b.addBody(table), Shape::box(Vec3(3 * a, 3 * a, a)));
      Body body;
      body.name = "body";
      body.mass = m;
      body.inertia = Mat3::Identity() * m * (2 * a) * (2 * a) / 6;
      body.position = Vec3(0.4 * a, -0.3 * a, a - m * kG / (4 * 1e5 * m));
      body.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
      const BodyIndex ib = b.addBody(body);
      const int top = b.addGeometry("body_shape", ib, Shape::box(Vec3::Constant(a)));
      if (top_first)
        b.addContactPair(top, below, mat);
      else
        b.addContactPair(below, top, mat);
      Simulator sim(b.build());
      const Vec3 p0 = sim.state().bodies[ib.value].position;
      const Quat q0 = sim.state().bodies[ib.value].orientation;
      for (int i = 0; i < 1000; ++i) ASSERT_TRUE(sim.step().ok);
      double load = 0;
      for (const auto& r : sim.current().contacts) load += r.force().z() * (top_first ? -1 : 1);
      const auto& s = sim.state().bodies[ib.value];
      const double drift = (s.position - p0).norm();
      const double turn = Eigen::AngleAxisd(s.orientation * q0.conjugate()).angle();
      std::printf(
          "m %g kg, %s first: %zu points, load / m g - 1 = %.2g, drift %.2g m, turned "
          "%.2g rad\n",
          m, top_first ? "top" : "table", sim.current().contacts.size(), load / (m * kG) - 1, drift,
          turn);
      EXPECT_EQ(sim.current().contacts.size(), 4u);
      EXPECT_NEAR(load / (m * kG), 1.0, 1e-9);
      EXPECT_LT(drift, 1e-9 * a);
      EXPECT_LT(turn, 1e-9);
    }
  }
}

// --- capsule and cylinder on a box ---

TEST(BoxRoundContacts, ACapsuleLyingOnAFaceGetsBothEndsAndIsClippedAtTheBorder) {
  for (const double s : {1e-3, 1.0}) {
    const Vector3d h(s, 0.8 * s, 0.5 * s);
    const double r = 0.1 * s, hl = 0.4 * s, d = 1e-4 * s;
    const Quaterniond lying(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitY()));
    std::vector<ContactPoint> out;
    boxCapsuleContacts(pose({0, 0, 0}), h, pose({0.2 * s, 0.1 * s, h.z() + r - d}, lying), r, hl, 0,
                       out);
    ASSERT_EQ(out.size(), 2u);
    std::set<int> features;
    for (const auto& p : out) {
      EXPECT_NEAR(p.depth, d, 1e-12 * s);
      EXPECT_NEAR(p.normal.z(), 1.0, 1e-15);
      EXPECT_NEAR(std::abs(p.position.x() - 0.2 * s), hl, 1e-12 * s);
      EXPECT_NEAR(p.position.z(), h.z() - d / 2, 1e-12 * s);
      features.insert(p.feature);
    }
    EXPECT_EQ(features, (std::set<int>{0, 1}));
    // Moved to overhang +x by 0.1 s: the outer end clipped at x = s (feature 2 or 3).
    out.clear();
    boxCapsuleContacts(pose({0, 0, 0}), h, pose({0.7 * s, 0, h.z() + r - d}, lying), r, hl, 0, out);
    ASSERT_EQ(out.size(), 2u);
    double x_max = -1;
    for (const auto& p : out) x_max = std::max(x_max, p.position.x());
    EXPECT_NEAR(x_max, s, 1e-12 * s);
    // Tilted: only the lower end, at the exact depth of its sphere.
    out.clear();
    const double tilt = 0.05;
    const Quaterniond q(Eigen::AngleAxisd(std::numbers::pi / 2 - tilt, Vector3d::UnitY()));
    const double low = h.z() + r - d + hl * std::sin(tilt);  // centre height for d at the end
    boxCapsuleContacts(pose({0, 0, 0}), h, pose({0, 0, low}, q), r, hl, 0, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out[0].depth, d, 1e-12 * s);
  }
}

// Distance from a point to the box |x_k| <= h_k and the nearest box point.
double pointBoxDistance(const Vector3d& p, const Vector3d& h, Vector3d& on_box) {
  on_box = p.cwiseMax(-h).cwiseMin(h);
  return (p - on_box).norm();
}

// Independent reference for a capsule outside a box: its axis segment's distance to the box,
// minimised over the segment by golden-section search (the distance is convex along it).
struct Reference {
  double depth;
  Vector3d normal;
};
Reference capsuleReference(const Vector3d& c, const Vector3d& d, double hl, double r,
                           const Vector3d& h) {
  double lo = -hl, hi = hl;
  const double g = (std::sqrt(5.0) - 1) / 2;
  Vector3d q;
  auto f = [&](double t) { return pointBoxDistance(c + t * d, h, q); };
  for (int it = 0; it < 200; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    (f(m1) < f(m2) ? hi : lo) = f(m1) < f(m2) ? m2 : m1;
  }
  const Vector3d p = c + 0.5 * (lo + hi) * d;
  const double dist = pointBoxDistance(p, h, q);
  return {r - dist, (p - q) / dist};
}

TEST(BoxRoundContacts, CapsuleSinglePointsAreExactAndEitherOrderFlipsTheNormal) {
  // Random boxes and capsules (1 cm to 10 m), the capsule placed along a random direction at
  // the distance where the reference says it touches, then pushed in by 0.1-1.1 % of r.
  // The single-point contacts (corner or edge of the box, or a tilted end on a face) against
  // the reference to rounding. FCL's GJK/EPA (libccd) on the same poses is no reference for
  // the depth of a rounded shape (measured up to 14 % off); its normal on face contacts is
  // held to EPA's tolerance (1e-3 rad), its depth reported.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0, fcl_face = 0, pairs_of_points = 0;
  double worst_angle = 0, worst_depth = 0, fcl_angle = 0, fcl_depth = 0;
  for (const double scale : {1e-2, 1.0, 10.0}) {
    for (int i = 0; i < 300; ++i) {
      const Vector3d h = scale * Vector3d(0.5 + unit(rng), 0.5 + unit(rng), 0.5 + unit(rng));
      const double r = scale * (0.1 + 0.3 * unit(rng)), hl = scale * (0.2 + unit(rng));
      const Quaterniond q =
          i % 3 == 0 ? Quaterniond(Eigen::AngleAxisd(
                           std::numbers::pi / 2 + (i % 6 == 0 ? 0.0 : 0.3 * (unit(rng) - 0.5)),
                           Vector3d::UnitY()))
                     : randomRotation(rng);
      const Vector3d dir =
          i % 3 == 0 ? Vector3d::UnitZ() : Vector3d(randomRotation(rng) * Vector3d::UnitX());
      const Vector3d axis = q * Vector3d::UnitZ();
      double lo = 0.0, hi = 2.0 * (h.norm() + r + hl);
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (capsuleReference(mid * dir, axis, hl, r, h).depth > 0 ? lo : hi) = mid;
      }
      const double shift = (0.001 + 0.01 * unit(rng)) * r;
      const Vector3d c = (lo - shift) * dir;
      const std::vector<Isometry3d> poses{pose({0, 0, 0}), pose(c, q)};
      const Shape box = Shape::box(h), cap = Shape::capsule(r, hl);
      CollisionDetector mine({box, cap}, {{0, 1}});
      CollisionDetector flipped({cap, box}, {{0, 1}});
      CollisionDetector fcl({box, cap}, {{0, 1}}, fclOnly());
      std::vector<ContactPoint> x, xf, y;
      mine.detect(poses, x);
      flipped.detect(std::vector<Isometry3d>{poses[1], poses[0]}, xf);
      fcl.detect(poses, y);
      ASSERT_FALSE(x.empty()) << scale << " " << i;
      ASSERT_EQ(x.size(), xf.size());
      for (std::size_t k = 0; k < x.size(); ++k)
        EXPECT_LT((x[k].normal + xf[k].normal).norm(), 1e-15);
      const Reference ref = capsuleReference(c, axis, hl, r, h);
      const ContactPoint& d = deepest(x);
      EXPECT_NEAR(d.depth / ref.depth, 1.0, 1e-9) << scale << " " << i;
      const double angle = std::acos(std::min(1.0, d.normal.dot(ref.normal)));
      EXPECT_LT(angle, 1e-6) << scale << " " << i;
      worst_angle = std::max(worst_angle, angle);
      worst_depth = std::max(worst_depth, std::abs(d.depth / ref.depth - 1));
      pairs_of_points += x.size() == 2;
      ++compared;
      if (y.empty()) continue;
      const ContactPoint& f = deepest(y);
      const double fa = std::acos(std::min(1.0, d.normal.dot(f.normal)));
      const double fd = std::abs(f.depth / d.depth - 1);
      if (x.size() == 2 || std::abs(d.normal.cwiseAbs().maxCoeff() - 1) < 1e-12) {
        ++fcl_face;
        fcl_angle = std::max(fcl_angle, fa);
        EXPECT_LT(fa, 1e-3) << scale << " " << i;  // libccd's EPA tolerance
        fcl_depth = std::max(fcl_depth, fd);
      }
    }
  }
  std::printf(
      "%d capsule/box contacts (%d with both ends): deepest within %.2g of the reference depth, "
      "normal within %.2g rad; FCL on the %d face contacts: depth within %.2g, normal within "
      "%.2g rad\n",
      compared, pairs_of_points, worst_depth, worst_angle, fcl_face, fcl_depth, fcl_angle);
  EXPECT_EQ(compared, 900);
  EXPECT_GT(pairs_of_points, 50);
}

TEST(BoxRoundContacts, ACylinderStandsOnItsRimAndLiesOnTheTwoEndsOfItsLine) {
  const Vector3d h(1.0, 0.8, 0.2);
  const double r = 0.1, hl = 0.3, d = 1e-4;
  std::vector<ContactPoint> out;
  // Standing on its end: the 8 rim points at depth d.
  ASSERT_EQ(
      boxCylinderContacts(pose({0, 0, 0}), h, pose({0.2, -0.1, h.z() + hl - d}), r, hl, 0, out), 8);
  for (const auto& p : out) {
    EXPECT_NEAR(p.depth, d, 1e-13);
    EXPECT_NEAR(p.normal.z(), 1.0, 1e-15);
    EXPECT_NEAR((p.position - Vector3d(0.2, -0.1, h.z() - d / 2)).norm(), r, 1e-13);
  }
  // Lying along y: two points, at the ends of the line contact.
  out.clear();
  const Quaterniond lying(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitX()));
  ASSERT_EQ(
      boxCylinderContacts(pose({0, 0, 0}), h, pose({0, 0, h.z() + r - d}, lying), r, hl, 0, out),
      2);
  for (const auto& p : out) {
    EXPECT_NEAR(p.depth, d, 1e-13);
    EXPECT_NEAR(std::abs(p.position.y()), hl, 1e-13);
  }
  // Over the box's edge: no closed form, the detector gives FCL's answer.
  out.clear();
  const Isometry3d over = pose({0.95, 0, h.z() + hl - d});
  EXPECT_EQ(boxCylinderContacts(pose({0, 0, 0}), h, over, r, hl, 0, out), -1);
  EXPECT_TRUE(out.empty());
  CollisionDetector mine({Shape::box(h), Shape::cylinder(r, hl)}, {{0, 1}});
  CollisionDetector fcl({Shape::box(h), Shape::cylinder(r, hl)}, {{0, 1}}, fclOnly());
  std::vector<ContactPoint> x, y;
  mine.detect(std::vector<Isometry3d>{pose({0, 0, 0}), over}, x);
  fcl.detect(std::vector<Isometry3d>{pose({0, 0, 0}), over}, y);
  ASSERT_EQ(x.size(), y.size());
  ASSERT_FALSE(x.empty());
  EXPECT_EQ(x[0].position, y[0].position);
  // Cylinder first: the same points, normal flipped.
  CollisionDetector flipped({Shape::cylinder(r, hl), Shape::box(h)}, {{0, 1}});
  std::vector<ContactPoint> z;
  flipped.detect(std::vector<Isometry3d>{pose({0.2, -0.1, h.z() + hl - d}), pose({0, 0, 0})}, z);
  ASSERT_EQ(z.size(), 8u);
  for (const auto& p : z) EXPECT_NEAR(p.normal.z(), -1.0, 1e-15);
}

TEST(BoxRoundContacts, CylinderDeepestPointAgreesWithFclWhereTheClosedFormApplies) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 400; ++i) {
    const Vector3d h(1.0, 1.0, 0.3);
    const double r = 0.05 + 0.1 * unit(rng), hl = 0.05 + 0.2 * unit(rng);
    const Quaterniond q(
        Eigen::AngleAxisd(0.3 * unit(rng), Vector3d(unit(rng), unit(rng), 0).normalized()));
    const Shape cyl = Shape::cylinder(r, hl);
    const double lowest = cyl.support(-(q.conjugate() * Vector3d::UnitZ()));
    const Vector3d c(0.6 * (unit(rng) - 0.5), 0.6 * (unit(rng) - 0.5),
                     h.z() + lowest - 1e-3 * unit(rng));
    std::vector<ContactPoint> x;
    ASSERT_GE(boxCylinderContacts(pose({0, 0, 0}), h, pose(c, q), r, hl, 0, x), 0);
    CollisionDetector fcl({Shape::box(h), cyl}, {{0, 1}}, fclOnly());
    std::vector<ContactPoint> y;
    fcl.detect(std::vector<Isometry3d>{pose({0, 0, 0}), pose(c, q)}, y);
    if (x.empty() || y.empty()) {
      EXPECT_EQ(x.empty(), y.empty());
      continue;
    }
    ++compared;
    // The exact deepest depth is h.z + lowest - c.z; FCL's GJK/EPA within its tolerance.
    EXPECT_NEAR(deepest(x).depth, h.z() + lowest - c.z(), 1e-12);
    EXPECT_NEAR(deepest(y).depth, deepest(x).depth, 1e-6);
    EXPECT_GT(deepest(y).normal.z(), 1 - 1e-6);
  }
  EXPECT_GT(compared, 300);
}

}  // namespace
}  // namespace tribo::contact
