#include "contact/round_contacts.hpp"

#include <algorithm>
#include <cmath>

namespace tribo::contact {

namespace {

using Eigen::Vector3d;

constexpr double kParallel = 1e-3;  // |u_a x u_b| below this: near-parallel axes
constexpr double kTiny = 1e-12;     // of the pair's size: coincident points, an empty overlap

// x clamped to [-h, h] (h >= 0), without std::clamp's precondition on the bounds.
double clampTo(double x, double h) { return std::max(-h, std::min(h, x)); }

// The sphere/sphere point between the sphere (x, ra) of A and (y, rb) of B when it penetrates;
// `fallback` (unit) is the normal when the centres are closer than `tiny`.
int roundPoint(const Vector3d& x, double ra, const Vector3d& y, double rb, const Vector3d& fallback,
               double tiny, int pair, int feature, std::vector<ContactPoint>& out) {
  const Vector3d v = y - x;
  const double d = v.norm();
  const double depth = ra + rb - d;
  if (!(depth > 0.0)) return 0;
  ContactPoint& cp = out.emplace_back();
  cp.pair = pair;
  cp.feature = feature;
  cp.normal = d > tiny ? Vector3d(v / d) : fallback;
  cp.depth = depth;
  // x + (ra - depth / 2) n, written symmetrically in A and B.
  cp.position = 0.5 * (x + y) + 0.5 * (ra - rb) * cp.normal;
  return 1;
}

}  // namespace

int sphereCapsuleContact(const Vector3d& centre, double sphere_radius,
                         const Eigen::Isometry3d& capsule_pose, double radius, double half_length,
                         int pair, std::vector<ContactPoint>& out) {
  const Vector3d c = capsule_pose.translation();
  const Vector3d u = capsule_pose.linear().col(2);
  const Vector3d y = c + clampTo(u.dot(centre - c), half_length) * u;
  const double tiny = kTiny * (sphere_radius + radius + half_length);
  return roundPoint(centre, sphere_radius, y, radius, capsule_pose.linear().col(0), tiny, pair, 0,
                    out);
}

int capsuleCapsuleContacts(const Eigen::Isometry3d& pose_a, double radius_a, double half_length_a,
                           const Eigen::Isometry3d& pose_b, double radius_b, double half_length_b,
                           int pair, std::vector<ContactPoint>& out) {
  const Vector3d ca = pose_a.translation(), ua = pose_a.linear().col(2);
  const Vector3d cb = pose_b.translation(), ub = pose_b.linear().col(2);
  const double ha = half_length_a, hb = half_length_b;
  const double reach = radius_a + radius_b;
  const double tiny = kTiny * (reach + ha + hb);

  // Closest points x = ca + s ua, y = cb + t ub (Ericson 5.1.9, about the centres): the
  // stationary point of |w + s ua - t ub|^2 is s = b t - c, t = b s + f.
  const Vector3d w = ca - cb;
  const double b = ua.dot(ub), c = ua.dot(w), f = ub.dot(w);
  const Vector3d axb = ua.cross(ub);
  const double sin2 = axb.squaredNorm();  // 1 - b^2 without its cancellation
  double s = sin2 > kTiny * kTiny ? clampTo((b * f - c) / sin2, ha) : 0.0;
  const double t = clampTo(b * s + f, hb);
  s = clampTo(b * t - c, ha);
  const Vector3d x = ca + s * ua, y = cb + t * ub;
  if ((y - x).squaredNorm() >= reach * reach) return 0;

  const double sin_ab = std::sqrt(sin2);
  const Vector3d to_b = cb - ca;
  Vector3d fallback = pose_a.linear().col(0);  // (near-)parallel: perpendicular to A's axis
  if (sin_ab > 1e-9) {
    fallback = axb / sin_ab;
    if (fallback.dot(to_b) < -tiny) fallback = -fallback;
  }

  if (sin_ab < kParallel) {
    // B's segment projected on A's axis is -c +- hb |b|; its overlap with [-ha, ha].
    const double lo = std::max(-ha, -c - hb * std::abs(b));
    const double hi = std::min(ha, -c + hb * std::abs(b));
    if (hi - lo > tiny) {
      int added = 0;
      for (int end = 0; end < 2; ++end) {
        const Vector3d xe = ca + (end == 0 ? lo : hi) * ua;
        const Vector3d ye = cb + clampTo(ub.dot(xe - cb), hb) * ub;
        added += roundPoint(xe, radius_a, ye, radius_b, fallback, tiny, pair, end, out);
      }
      if (added > 0) return added;
    }
  }
  return roundPoint(x, radius_a, y, radius_b, fallback, tiny, pair, 2, out);
}

}  // namespace tribo::contact
