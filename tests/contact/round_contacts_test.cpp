// Closed-form sphere/capsule and capsule/capsule contacts (contact/round_contacts.hpp) against
// an independent minimisation of the distance between the segments (sampling and bisection on
// the derivative, no closed form), against FCL (fcl::collide and fcl::distance) on the same
// poses, and against analytic cases: parallel capsules lying one on another (two points at the
// ends of the overlap), crossed at 90 degrees, a sphere on a capsule's cap and side, far and
// exactly touching pairs; degenerate inputs (a centre on the segment, coincident and crossing
// segments, zero half lengths) and the order of the pair.
#include "contact/round_contacts.hpp"

#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <set>

#include "support/test_poses.hpp"

namespace tribo::contact {
namespace {

using Eigen::Isometry3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using test::pose;

// --- the independent reference ---

// Minimiser of a convex f over [lo, hi]: 64 equal steps of f bracket it, then bisection on
// the sign of its derivative g narrows the bracket to adjacent doubles. (Golden section on f
// itself stops where f is flat to rounding, sqrt(epsilon) of the range in the parameter,
// 1.5e-8 of the size: too coarse for positions at 1e-9; the derivative's sign is not flat.)
template <class F, class G>
double minimise(double lo, double hi, const F& f, const G& g) {
  if (!(hi > lo)) return lo;
  constexpr int kSteps = 64;
  auto at = [&](int i) { return i >= kSteps ? hi : lo + (hi - lo) * i / kSteps; };
  int best = 0;
  double f_best = f(lo);
  for (int i = 1; i <= kSteps; ++i) {
    const double v = f(at(i));
    if (v < f_best) f_best = v, best = i;
  }
  double a = at(std::max(best - 1, 0)), b = at(std::min(best + 1, kSteps));
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (a + b);
    if (!(m > a && m < b)) break;
    (g(m) > 0.0 ? b : a) = m;
  }
  return 0.5 * (a + b);
}

// The segment c + t u, |t| <= h.
struct Seg {
  Vector3d c, u;
  double h;
  Vector3d at(double t) const { return c + t * u; }
};
Seg axisOf(const Isometry3d& p, double h) { return {p.translation(), p.linear().col(2), h}; }

// The point of s nearest to p, by minimising |s(t) - p|^2 over t.
Vector3d nearestOn(const Seg& s, const Vector3d& p) {
  const double t = minimise(
      -s.h, s.h, [&](double t) { return (s.at(t) - p).squaredNorm(); },
      [&](double t) { return s.u.dot(s.at(t) - p); });
  return s.at(t);
}

// The closest points x on a and y on b: min over s of the distance of a(s) to b, whose
// derivative (the inner minimum is attained) is a.u . (a(s) - y(s)).
struct Closest {
  Vector3d x, y;
};
Closest nearestBetween(const Seg& a, const Seg& b) {
  const double s = minimise(
      -a.h, a.h, [&](double s) { return (a.at(s) - nearestOn(b, a.at(s))).squaredNorm(); },
      [&](double s) { return a.u.dot(a.at(s) - nearestOn(b, a.at(s))); });
  return {a.at(s), nearestOn(b, a.at(s))};
}

// The sphere/sphere contact of (x, ra) and (y, rb) written out plainly: depth ra + rb - d,
// normal from x to y, the point on A's surface moved back by half the depth.
struct Expected {
  double dist, depth;
  Vector3d normal, position;
};
Expected expectedFrom(const Closest& c, double ra, double rb) {
  Expected e;
  e.dist = (c.y - c.x).norm();
  e.depth = ra + rb - e.dist;
  e.normal = (c.y - c.x) / e.dist;
  e.position = c.x + ra * e.normal - 0.5 * e.depth * e.normal;
  return e;
}

// --- random poses ---

double logUniform(std::mt19937& rng) {  // 1 mm to 10 m
  return 1e-3 * std::pow(1e4, std::uniform_real_distribution<double>(0.0, 1.0)(rng));
}
double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
Quaterniond randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
}
Vector3d perpendicularTo(const Vector3d& u, std::mt19937& rng) {
  const Vector3d v = randomRotation(rng) * Vector3d::UnitX();
  return (v - v.dot(u) * u).normalized();
}

void expectSane(const std::vector<ContactPoint>& out) {
  for (const auto& p : out) {
    EXPECT_TRUE(p.position.allFinite());
    EXPECT_TRUE(p.normal.allFinite());
    EXPECT_TRUE(std::isfinite(p.depth));
    EXPECT_GT(p.depth, 0.0);
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
  }
}

// Capsule A and B placed so that the lines' common perpendicular joins A(s0) and B(t0), the
// parameters up to `past` half lengths (past 1, an end: the closest points move to it), at a
// distance `min_fraction` to `max_fraction` of ra + rb (below 1 with past <= 1: penetrating).
struct CapsulePair {
  double ra, ha, rb, hb;
  Isometry3d pa, pb;
  double size;
};
CapsulePair randomCapsules(std::mt19937& rng, double min_fraction, double max_fraction,
                           double past) {
  CapsulePair c;
  c.ra = logUniform(rng), c.ha = logUniform(rng), c.rb = logUniform(rng), c.hb = logUniform(rng);
  c.size = std::max({c.ra, c.ha, c.rb, c.hb});
  const Quaterniond qa = randomRotation(rng), qb = randomRotation(rng);
  const Vector3d ua = qa * Vector3d::UnitZ(), ub = qb * Vector3d::UnitZ();
  const Vector3d ca =
      c.size * Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  Vector3d n = ua.cross(ub);
  n = n.norm() > 1e-6 ? Vector3d(n.normalized()) : perpendicularTo(ua, rng);
  const double s0 = c.ha * uniform(rng, -past, past), t0 = c.hb * uniform(rng, -past, past);
  const double d = (c.ra + c.rb) * uniform(rng, min_fraction, max_fraction);
  c.pa = pose(ca, qa);
  c.pb = pose(ca + s0 * ua + d * n - t0 * ub, qb);
  return c;
}

// A sphere and a capsule: the centre beside the capsule's line up to 1.5 half lengths along
// it (past 1: over the end cap), at a distance up to 1.1 (rs + rc) from the line.
struct SphereCapsule {
  double rs, rc, hl, size;
  Vector3d centre;
  Isometry3d capsule;
};
SphereCapsule randomSphereCapsule(std::mt19937& rng) {
  SphereCapsule sc;
  sc.rs = logUniform(rng), sc.rc = logUniform(rng), sc.hl = logUniform(rng);
  sc.size = std::max({sc.rs, sc.rc, sc.hl});
  const Quaterniond q = randomRotation(rng);
  const Vector3d u = q * Vector3d::UnitZ();
  const Vector3d c =
      sc.size * Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  sc.centre = c + sc.hl * uniform(rng, -1.5, 1.5) * u +
              (sc.rs + sc.rc) * uniform(rng, 0.0, 1.1) * perpendicularTo(u, rng);
  sc.capsule = pose(c, q);
  return sc;
}

fcl::CollisionObjectd fclCapsule(double r, double h, const Isometry3d& p) {
  return fcl::CollisionObjectd(std::make_shared<fcl::Capsuled>(r, 2 * h), p);
}

// --- 1. against the independent minimisation ---

TEST(RoundContacts, CapsuleCapsuleMatchesTheMinimisedDistanceFromAMillimetreToTenMetres) {
  std::mt19937 rng(2024);
  int contacts = 0, separated = 0;
  double worst_depth = 0, worst_normal = 0, worst_position = 0, worst_swap = 0;
  for (int i = 0; i < 3000; ++i) {
    const CapsulePair c = randomCapsules(rng, 0.0, 1.1, 1.3);
    const Expected e =
        expectedFrom(nearestBetween(axisOf(c.pa, c.ha), axisOf(c.pb, c.hb)), c.ra, c.rb);
    const double size = std::max(c.size, c.pa.translation().cwiseAbs().maxCoeff());
    const double tol = 1e-9 * size;
    std::vector<ContactPoint> out, swapped;
    capsuleCapsuleContacts(c.pa, c.ra, c.ha, c.pb, c.rb, c.hb, 7, out);
    capsuleCapsuleContacts(c.pb, c.rb, c.hb, c.pa, c.ra, c.ha, 7, swapped);
    expectSane(out);
    expectSane(swapped);
    if (e.depth < -tol) {
      EXPECT_TRUE(out.empty()) << i;
      EXPECT_TRUE(swapped.empty()) << i;
      ++separated;
      continue;
    }
    if (e.depth < tol) continue;  // touching to rounding: either answer
    ++contacts;
    ASSERT_EQ(out.size(), 1u) << i;
    ASSERT_EQ(swapped.size(), 1u) << i;
    const ContactPoint& p = out[0];
    EXPECT_EQ(p.pair, 7);
    EXPECT_EQ(p.feature, 2);
    EXPECT_NEAR(p.depth, e.depth, tol) << i;
    worst_depth = std::max(worst_depth, std::abs(p.depth - e.depth) / size);
    // The normal's error times the distance is the lateral error of the closest points.
    if (e.dist > 1e-6 * size) {
      const double lateral = (p.normal - e.normal).norm() * e.dist;
      EXPECT_LE(lateral, tol) << i;
      worst_normal = std::max(worst_normal, lateral / size);
      EXPECT_LE((p.position - e.position).norm(), tol) << i;
      worst_position = std::max(worst_position, (p.position - e.position).norm() / size);
    }
    // 5. The other order: the normal flipped, the same point and depth.
    const ContactPoint& q = swapped[0];
    EXPECT_LE((q.normal + p.normal).norm() * std::max(e.dist, 1e-6 * size), tol) << i;
    EXPECT_LE((q.position - p.position).norm(), tol) << i;
    EXPECT_NEAR(q.depth, p.depth, tol) << i;
    worst_swap = std::max(worst_swap, (q.position - p.position).norm() / size);
  }
  std::printf(
      "capsule/capsule: %d contacts, %d separated; worst / size: depth %.2g, normal x distance "
      "%.2g, position %.2g, swapped position %.2g\n",
      contacts, separated, worst_depth, worst_normal, worst_position, worst_swap);
  EXPECT_GT(contacts, 2000);
  EXPECT_GT(separated, 100);
}

TEST(RoundContacts, SphereCapsuleMatchesTheMinimisedDistanceFromAMillimetreToTenMetres) {
  std::mt19937 rng(4048);
  int contacts = 0, separated = 0;
  double worst_depth = 0, worst_normal = 0, worst_position = 0;
  for (int i = 0; i < 3000; ++i) {
    const SphereCapsule sc = randomSphereCapsule(rng);
    const double rs = sc.rs, rc = sc.rc, hl = sc.hl, size0 = sc.size;
    const Vector3d centre = sc.centre, c = sc.capsule.translation();
    const Isometry3d capsule = sc.capsule;
    const Expected e = expectedFrom({centre, nearestOn(axisOf(capsule, hl), centre)}, rs, rc);
    const double size = std::max(size0, c.cwiseAbs().maxCoeff());
    const double tol = 1e-9 * size;
    std::vector<ContactPoint> out;
    sphereCapsuleContact(centre, rs, capsule, rc, hl, 3, out);
    expectSane(out);
    if (e.depth < -tol) {
      EXPECT_TRUE(out.empty()) << i;
      ++separated;
      continue;
    }
    if (e.depth < tol) continue;
    ++contacts;
    ASSERT_EQ(out.size(), 1u) << i;
    EXPECT_EQ(out[0].pair, 3);
    EXPECT_EQ(out[0].feature, 0);
    EXPECT_NEAR(out[0].depth, e.depth, tol) << i;
    worst_depth = std::max(worst_depth, std::abs(out[0].depth - e.depth) / size);
    if (e.dist > 1e-6 * size) {
      const double lateral = (out[0].normal - e.normal).norm() * e.dist;
      EXPECT_LE(lateral, tol) << i;
      worst_normal = std::max(worst_normal, lateral / size);
      EXPECT_LE((out[0].position - e.position).norm(), tol) << i;
      worst_position = std::max(worst_position, (out[0].position - e.position).norm() / size);
    }
  }
  std::printf(
      "sphere/capsule: %d contacts, %d separated; worst / size: depth %.2g, normal x distance "
      "%.2g, position %.2g\n",
      contacts, separated, worst_depth, worst_normal, worst_position);
  EXPECT_GT(contacts, 2000);
  EXPECT_GT(separated, 100);
}

// --- 2. against FCL ---

TEST(RoundContacts, AgreesWithFclsClosedFormsAtAnyDepth) {
  // Random pairs, mostly penetrating (the lines' distance up to 0.95 (ra + rb), the closest
  // points up to 1.3 half lengths along the lines, so ends too). FCL answers two capsules'
  // signed distance (fcl::distance) and a sphere/capsule collision (fcl::collide) in closed
  // form of its own (capsule_capsule-inl.h, sphere_capsule-inl.h): held to rounding. The
  // capsules' witness points W_a, W_b on the surfaces give depth n = W_a - W_b and the
  // position midway between them.
  std::mt19937 rng(77);
  fcl::CollisionRequestd request(1, true);
  fcl::DistanceRequestd distance_request(true);
  double worst_depth = 0, worst_normal = 0, worst_position = 0, worst_sphere = 0;
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const CapsulePair c = randomCapsules(rng, 0.0, 0.95, 1.3);
    std::vector<ContactPoint> out;
    capsuleCapsuleContacts(c.pa, c.ra, c.ha, c.pb, c.rb, c.hb, 0, out);
    const double size = std::max(c.size, c.pa.translation().cwiseAbs().maxCoeff());
    const double tol = 1e-9 * size;
    const fcl::CollisionObjectd a = fclCapsule(c.ra, c.ha, c.pa), b = fclCapsule(c.rb, c.hb, c.pb);
    fcl::DistanceResultd distance;
    fcl::distance(&a, &b, distance_request, distance);
    const Vector3d wa = distance.nearest_points[0], wb = distance.nearest_points[1];
    if (distance.min_distance > tol) {
      EXPECT_TRUE(out.empty()) << i;
      continue;
    }
    if (distance.min_distance > -tol) continue;  // touching to rounding
    ASSERT_EQ(out.size(), 1u) << i;
    const ContactPoint& p = out[0];
    ++compared;
    EXPECT_NEAR(-distance.min_distance, p.depth, tol) << i;
    EXPECT_LE((p.depth * p.normal - (wa - wb)).norm(), tol) << i;
    EXPECT_LE((p.position - 0.5 * (wa + wb)).norm(), tol) << i;
    worst_depth = std::max(worst_depth, std::abs(distance.min_distance + p.depth) / size);
    worst_normal = std::max(worst_normal, (p.depth * p.normal - (wa - wb)).norm() / size);
    worst_position = std::max(worst_position, (p.position - 0.5 * (wa + wb)).norm() / size);
  }
  int sphere_contacts = 0;
  for (int i = 0; i < 2000; ++i) {
    const SphereCapsule sc = randomSphereCapsule(rng);
    std::vector<ContactPoint> out;
    sphereCapsuleContact(sc.centre, sc.rs, sc.capsule, sc.rc, sc.hl, 0, out);
    const double size = std::max(sc.size, sc.capsule.translation().cwiseAbs().maxCoeff());
    const double tol = 1e-9 * size;
    const fcl::CollisionObjectd sphere(std::make_shared<fcl::Sphered>(sc.rs),
                                       pose(sc.centre, Quaterniond::Identity()));
    const fcl::CollisionObjectd b = fclCapsule(sc.rc, sc.hl, sc.capsule);
    fcl::CollisionResultd result;
    fcl::collide(&sphere, &b, request, result);
    if (result.numContacts() == 0) {
      EXPECT_TRUE(out.empty()) << i;  // FCL reports touching (depth 0) as a contact
      continue;
    }
    const auto& hit = result.getContact(0);
    if (hit.penetration_depth < tol) continue;
    ASSERT_EQ(out.size(), 1u) << i;
    ++sphere_contacts;
    EXPECT_NEAR(hit.penetration_depth, out[0].depth, tol) << i;
    EXPECT_LE((hit.normal - out[0].normal).norm() * (sc.rs + sc.rc - out[0].depth), tol) << i;
    worst_sphere = std::max(worst_sphere, std::abs(hit.penetration_depth - out[0].depth) / size);
  }
  std::printf(
      "%d capsule/capsule contacts against fcl::distance, worst / size: depth %.2g, depth x "
      "normal %.2g, position %.2g; %d sphere/capsule contacts against fcl::collide: depth %.2g\n",
      compared, worst_depth, worst_normal, worst_position, sphere_contacts, worst_sphere);
  EXPECT_GT(compared, 1500);
  EXPECT_GT(sphere_contacts, 1500);
}

TEST(RoundContacts, AgreesWithFclsMprOnShallowCapsuleContacts) {
  // fcl::collide on two capsules is libccd's MPR (GJKCollide -> ccdMPRPenetration): the
  // distance to a portal of the Minkowski difference found to libccd's absolute tolerance
  // (FCL's 1e-6 m), not the minimum penetration. Measured on these random pairs: at depths
  // up to 1 % of ra + rb, 0.1 % of the size off with normals 39 degrees apart; beyond, up to
  // 0.95 of the size and normals at right angles. So FCL's collide is a reference here only
  // for shallow contacts (0.01 % to 0.1 % of ra + rb): its depth within 2e-6 m (twice its
  // tolerance, an absolute length, not 1e-6 of the size), its normal within 0.999. It misses
  // contacts shallower than its tolerance: allowed only below 1e-5 m.
  std::mt19937 rng(78);
  fcl::CollisionRequestd request(1, true);
  double worst_depth = 0, worst_dot = 1, deepest_miss = 0;
  int compared = 0, missed = 0;
  for (int i = 0; i < 2000; ++i) {
    const CapsulePair c = randomCapsules(rng, 0.999, 0.9999, 1.0);
    std::vector<ContactPoint> out;
    ASSERT_EQ(capsuleCapsuleContacts(c.pa, c.ra, c.ha, c.pb, c.rb, c.hb, 0, out), 1) << i;
    const fcl::CollisionObjectd a = fclCapsule(c.ra, c.ha, c.pa), b = fclCapsule(c.rb, c.hb, c.pb);
    fcl::CollisionResultd result;
    fcl::collide(&a, &b, request, result);
    if (result.numContacts() == 0) {
      ++missed;
      deepest_miss = std::max(deepest_miss, out[0].depth);
      EXPECT_LT(out[0].depth, 1e-5) << i;
      continue;
    }
    ++compared;
    const auto& hit = result.getContact(0);
    EXPECT_NEAR(hit.penetration_depth, out[0].depth, 2e-6) << i;
    EXPECT_GT(hit.normal.dot(out[0].normal), 0.999) << i;
    worst_depth = std::max(worst_depth, std::abs(hit.penetration_depth - out[0].depth));
    worst_dot = std::min(worst_dot, hit.normal.dot(out[0].normal));
  }
  std::printf(
      "%d shallow capsule pairs against FCL's MPR: depth within %.2g m, normal dot >= %.7f; "
      "%d missed by FCL (deepest %.2g m)\n",
      compared, worst_depth, worst_dot, missed, deepest_miss);
  EXPECT_GT(compared, 1800);
}

// --- 3. analytic cases ---

// Exact rotations (no rounding of cos(pi/2)) taking the capsule's z to world x and to y.
const Eigen::Matrix3d kAlongX = (Eigen::Matrix3d() << 0, 0, 1, 0, 1, 0, -1, 0, 0).finished();
const Eigen::Matrix3d kAlongY = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished();
Isometry3d pose(const Vector3d& p, const Eigen::Matrix3d& r) {
  Isometry3d t = Isometry3d::Identity();
  t.linear() = r;
  t.translation() = p;
  return t;
}

TEST(RoundContacts, ParallelCapsulesLyingOneOnAnotherAreHeldAtBothEndsOfTheOverlap) {
  for (const double s : {1e-3, 1.0, 10.0}) {
    const double ra = 0.1 * s, ha = 0.5 * s, rb = 0.05 * s, hb = 0.3 * s, d = 1e-4 * s;
    // B along x over [0.1 s, 0.7 s], A over [-0.5 s, 0.5 s]: the overlap is [0.1 s, 0.5 s].
    const Isometry3d pa = pose({0, 0, 0}, kAlongX), pb = pose({0.4 * s, 0, ra + rb - d}, kAlongX);
    for (const bool b_first : {false, true}) {
      std::vector<ContactPoint> out;
      const int n = b_first ? capsuleCapsuleContacts(pb, rb, hb, pa, ra, ha, 0, out)
                            : capsuleCapsuleContacts(pa, ra, ha, pb, rb, hb, 0, out);
      ASSERT_EQ(n, 2);
      ASSERT_EQ(out.size(), 2u);
      std::set<int> features;
      std::vector<double> xs;
      for (const auto& p : out) {
        EXPECT_NEAR(p.depth, d, 1e-12 * s);
        EXPECT_NEAR(p.normal.z(), b_first ? -1.0 : 1.0, 1e-15);
        EXPECT_NEAR(p.position.y(), 0.0, 1e-15 * s);
        EXPECT_NEAR(p.position.z(), ra - d / 2, 1e-12 * s);
        features.insert(p.feature);
        xs.push_back(p.position.x());
      }
      std::sort(xs.begin(), xs.end());
      EXPECT_NEAR(xs[0], 0.1 * s, 1e-12 * s);
      EXPECT_NEAR(xs[1], 0.5 * s, 1e-12 * s);
      EXPECT_EQ(features, (std::set<int>{0, 1}));
    }
    // Turned 0.5 mrad about z (under the 1 mrad threshold): still both ends of the overlap,
    // [0.4 s - hb cos, 0.5 s], each at the exact depth of its own point, a horizontal offset
    // dx sin from B's axis at height h = ra + rb - d: ra + rb - sqrt(h^2 + (dx sin)^2). The
    // axes cross at B's centre, d deep, in between (the line contact's documented limit).
    std::vector<ContactPoint> out;
    const double yaw = 5e-4, h = ra + rb - d;
    capsuleCapsuleContacts(
        pa, ra, ha,
        pose({0.4 * s, 0, h},
             Eigen::AngleAxisd(yaw, Vector3d::UnitZ()).toRotationMatrix() * kAlongX),
        rb, hb, 0, out);
    ASSERT_EQ(out.size(), 2u);
    for (const auto& p : out) {
      const double dx = p.feature == 0 ? hb * std::cos(yaw) : 0.1 * s;
      EXPECT_NEAR(p.depth, ra + rb - std::hypot(h, dx * std::sin(yaw)), 1e-12 * s);
      EXPECT_LT(p.depth, d);
    }
    // Tilted 0.5 mrad in the vertical plane, B (over x in [-0.2 s, 0.4 s]) rising with x:
    // its high end 0.3 s sin(5e-4) = 1.5e-4 s > d above, out of contact; the low end of the
    // overlap alone, its depth d + hb sin(5e-4) (A's point right under B's lower end).
    out.clear();
    const Eigen::Matrix3d pitch = Eigen::AngleAxisd(-5e-4, Vector3d::UnitY()).toRotationMatrix();
    capsuleCapsuleContacts(pa, ra, ha, pose({0.1 * s, 0, ra + rb - d}, pitch * kAlongX), rb, hb, 0,
                           out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].feature, 0);
    EXPECT_NEAR(out[0].depth, d + hb * std::sin(5e-4), 1e-12 * s);
    // Turned 5 mrad: one point at the closest points (the crossing), depth d.
    out.clear();
    const Eigen::Matrix3d wide = Eigen::AngleAxisd(5e-3, Vector3d::UnitZ()).toRotationMatrix();
    capsuleCapsuleContacts(pa, ra, ha, pose({0.4 * s, 0, ra + rb - d}, wide * kAlongX), rb, hb, 0,
                           out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].feature, 2);
    EXPECT_NEAR(out[0].depth, d, 1e-12 * s);
    EXPECT_NEAR(out[0].normal.z(), 1.0, 1e-12);
  }
}

TEST(RoundContacts, CapsulesCrossedAtRightAnglesTouchAtTheCrossing) {
  for (const double s : {1e-3, 1.0, 10.0}) {
    const double ra = 0.1 * s, ha = 0.5 * s, rb = 0.05 * s, hb = 0.3 * s, d = 1e-4 * s;
    // B along y centred at (0.2 s, -0.1 s): it crosses A's axis at x = 0.2 s, y = 0.
    std::vector<ContactPoint> out;
    capsuleCapsuleContacts(pose({0, 0, 0}, kAlongX), ra, ha,
                           pose({0.2 * s, -0.1 * s, ra + rb - d}, kAlongY), rb, hb, 4, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].pair, 4);
    EXPECT_EQ(out[0].feature, 2);
    EXPECT_NEAR(out[0].depth, d, 1e-15 * s);
    EXPECT_NEAR(out[0].normal.z(), 1.0, 1e-15);
    EXPECT_LT((out[0].position - Vector3d(0.2 * s, 0, ra - d / 2)).norm(), 1e-15 * s);
  }
}

TEST(RoundContacts, ASphereRestsOnTheEndCapAndOnTheSide) {
  const double r = 0.1, hl = 0.3, rs = 0.05, d = 1e-4;
  const Isometry3d capsule = pose({0.5, -0.2, 1.0});
  const Vector3d c = capsule.translation();
  std::vector<ContactPoint> out;
  // On the top of the cap: normal from the sphere into the capsule, -z.
  sphereCapsuleContact(c + Vector3d(0, 0, hl + r + rs - d), rs, capsule, r, hl, 0, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].depth, d, 1e-15);
  EXPECT_NEAR(out[0].normal.z(), -1.0, 1e-15);
  EXPECT_LT((out[0].position - (c + Vector3d(0, 0, hl + r - d / 2))).norm(), 1e-15);
  // On the cap 40 degrees off the axis: along that direction from the end's centre.
  out.clear();
  const Vector3d dir(std::sin(0.7), 0, std::cos(0.7));
  sphereCapsuleContact(c + hl * Vector3d::UnitZ() + (r + rs - d) * dir, rs, capsule, r, hl, 0, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].depth, d, 1e-15);
  EXPECT_LT((out[0].normal + dir).norm(), 1e-14);
  EXPECT_LT((out[0].position - (c + hl * Vector3d::UnitZ() + (r - d / 2) * dir)).norm(), 1e-15);
  // On the side: normal -x, at the height of the centre.
  out.clear();
  sphereCapsuleContact(c + Vector3d(r + rs - d, 0, 0.1), rs, capsule, r, hl, 0, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].depth, d, 1e-15);
  EXPECT_NEAR(out[0].normal.x(), -1.0, 1e-15);
  EXPECT_LT((out[0].position - (c + Vector3d(r - d / 2, 0, 0.1))).norm(), 1e-15);
}

TEST(RoundContacts, FarApartOrExactlyTouchingGivesNothing) {
  // Radii and distances exact in binary: d == ra + rb to the last bit.
  const double ra = 0.25, rb = 0.5, ha = 1.0, hb = 0.75;
  std::vector<ContactPoint> out;
  EXPECT_EQ(capsuleCapsuleContacts(pose({0, 0, 0}, kAlongX), ra, ha, pose({0.5, 0, 0.75}, kAlongX),
                                   rb, hb, 0, out),
            0);
  EXPECT_EQ(capsuleCapsuleContacts(pose({0, 0, 0}, kAlongX), ra, ha, pose({0.5, 0, 0.75}, kAlongY),
                                   rb, hb, 0, out),
            0);
  EXPECT_EQ(capsuleCapsuleContacts(pose({0, 0, 0}, kAlongX), ra, ha, pose({1.75, 0, 0.75}), rb, hb,
                                   0, out),  // end to end, B upright: its end at (1.75, 0, 0)
            0);
  EXPECT_EQ(sphereCapsuleContact({0.75, 0, 0.5}, ra, pose({0, 0, 0}), rb, hb, 0, out), 0);
  EXPECT_EQ(sphereCapsuleContact({0, 0, 1.5}, ra, pose({0, 0, 0}), rb, hb, 0, out), 0);
  // Far apart.
  EXPECT_EQ(capsuleCapsuleContacts(pose({0, 0, 0}), ra, ha, pose({10, 3, -2}), rb, hb, 0, out), 0);
  EXPECT_EQ(sphereCapsuleContact({10, 3, -2}, ra, pose({0, 0, 0}), rb, hb, 0, out), 0);
  EXPECT_TRUE(out.empty());
  // A hair closer: contact.
  EXPECT_EQ(capsuleCapsuleContacts(pose({0, 0, 0}, kAlongX), ra, ha,
                                   pose({0.5, 0, 0.75 - 1e-12}, kAlongY), rb, hb, 0, out),
            1);
  EXPECT_EQ(sphereCapsuleContact({0.75 - 1e-12, 0, 0.5}, ra, pose({0, 0, 0}), rb, hb, 0, out), 1);
}

// --- 4. degenerate inputs ---

TEST(RoundContacts, DegenerateInputsGiveFiniteUnitNormals) {
  const Quaterniond q(Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()));
  const Isometry3d capsule = pose({0.3, 0.1, -0.2}, q);
  const Vector3d u = q * Vector3d::UnitZ(), x_axis = q * Vector3d::UnitX();
  std::vector<ContactPoint> out;
  // The sphere's centre on the segment: depth rs + r, normal the capsule's local x.
  for (const double t : {0.0, 0.2, 0.3}) {
    out.clear();
    ASSERT_EQ(sphereCapsuleContact(capsule.translation() + t * u, 0.05, capsule, 0.1, 0.3, 0, out),
              1);
    expectSane(out);
    EXPECT_NEAR(out[0].depth, 0.15, 1e-15);
    EXPECT_LT((out[0].normal - x_axis).norm(), 1e-15);
  }
  // A zero-length capsule (a sphere) with the centre on it.
  out.clear();
  ASSERT_EQ(sphereCapsuleContact(capsule.translation(), 0.05, capsule, 0.1, 0.0, 0, out), 1);
  expectSane(out);
  // Identical segments: two points at A's ends, depth ra + rb, normal A's local x.
  out.clear();
  ASSERT_EQ(capsuleCapsuleContacts(capsule, 0.1, 0.3, capsule, 0.05, 0.3, 0, out), 2);
  expectSane(out);
  for (const auto& p : out) {
    EXPECT_NEAR(p.depth, 0.15, 1e-15);
    EXPECT_LT((p.normal - x_axis).norm(), 1e-15);
  }
  // Segments crossing at one point (d = 0): normal along u_a x u_b, depth ra + rb; the other
  // order flips it.
  const Quaterniond qb = q * Quaterniond(Eigen::AngleAxisd(1.0, Vector3d::UnitX()));
  const Isometry3d crossing = pose(capsule.translation() + 0.1 * u, qb);
  const Vector3d ub = qb * Vector3d::UnitZ();
  out.clear();
  ASSERT_EQ(capsuleCapsuleContacts(capsule, 0.1, 0.3, crossing, 0.05, 0.2, 0, out), 1);
  ASSERT_EQ(capsuleCapsuleContacts(crossing, 0.05, 0.2, capsule, 0.1, 0.3, 0, out), 1);
  expectSane(out);
  EXPECT_NEAR(out[0].depth, 0.15, 1e-15);
  EXPECT_NEAR(std::abs(out[0].normal.dot(u.cross(ub).normalized())), 1.0, 1e-12);
  EXPECT_LT((out[0].normal + out[1].normal).norm(), 1e-15);
  EXPECT_LT((out[0].position - out[1].position).norm(), 1e-15);
  // The same crossing at the centres of both (the centre of B in A's plane too).
  out.clear();
  const Isometry3d centred = pose(capsule.translation(), qb);
  ASSERT_EQ(capsuleCapsuleContacts(capsule, 0.1, 0.3, centred, 0.05, 0.2, 0, out), 1);
  ASSERT_EQ(capsuleCapsuleContacts(centred, 0.05, 0.2, capsule, 0.1, 0.3, 0, out), 1);
  expectSane(out);
  EXPECT_LT((out[0].normal + out[1].normal).norm(), 1e-15);
  // Zero half lengths: spheres, at the same centre and apart.
  for (const double gap : {0.0, 0.1}) {
    out.clear();
    ASSERT_EQ(capsuleCapsuleContacts(capsule, 0.1, 0.0, pose(capsule.translation() + gap * u, qb),
                                     0.05, 0.0, 0, out),
              1);
    expectSane(out);
    EXPECT_NEAR(out[0].depth, 0.15 - gap, 1e-15);
    if (gap > 0) {
      EXPECT_LT((out[0].normal - u).norm(), 1e-15);
    }
  }
  // A zero-length capsule on a long one, and the colinear ends touching (coincident points).
  out.clear();
  ASSERT_EQ(capsuleCapsuleContacts(capsule, 0.1, 0.0, capsule, 0.05, 0.3, 0, out), 1);
  ASSERT_EQ(capsuleCapsuleContacts(capsule, 0.1, 0.3, pose(capsule.translation() + 0.6 * u, q),
                                   0.05, 0.3, 0, out),
            1);
  expectSane(out);
  // Zero radii: nothing even through each other.
  out.clear();
  EXPECT_EQ(capsuleCapsuleContacts(capsule, 0.0, 0.3, crossing, 0.0, 0.2, 0, out), 0);
  EXPECT_EQ(sphereCapsuleContact(capsule.translation(), 0.0, capsule, 0.0, 0.3, 0, out), 0);
}

// --- 5. the order of the pair ---

TEST(RoundContacts, SwappingTheCapsulesFlipsTheNormalAndKeepsThePoint) {
  // Single points at random (also checked in the random comparison above) and the line
  // contact of parallel capsules (the same two points in the other order).
  std::mt19937 rng(5);
  double worst = 0;
  for (int i = 0; i < 500; ++i) {
    const CapsulePair c = randomCapsules(rng, 0.0, 0.9, 1.0);
    std::vector<ContactPoint> ab, ba;
    ASSERT_EQ(capsuleCapsuleContacts(c.pa, c.ra, c.ha, c.pb, c.rb, c.hb, 0, ab), 1);
    ASSERT_EQ(capsuleCapsuleContacts(c.pb, c.rb, c.hb, c.pa, c.ra, c.ha, 0, ba), 1);
    const double size = std::max(c.size, c.pa.translation().cwiseAbs().maxCoeff());
    const double dist = c.ra + c.rb - ab[0].depth;
    EXPECT_LT((ab[0].normal + ba[0].normal).norm() * dist, 1e-12 * size) << i;
    EXPECT_LT((ab[0].position - ba[0].position).norm(), 1e-12 * size) << i;
    EXPECT_NEAR(ab[0].depth, ba[0].depth, 1e-12 * size) << i;
    worst = std::max(worst, (ab[0].position - ba[0].position).norm() / size);
  }
  std::printf("swapped single points within %.2g of the size\n", worst);
}

}  // namespace
}  // namespace tribo::contact
