#include "contact/box_round_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/box_box_contacts.hpp"
#include "contact/primitive_contacts.hpp"
#include "contact/shape.hpp"

namespace tribo::contact {

namespace {

using Eigen::Vector3d;

constexpr double kEdgeBias = 0.95;  // as box_box_contacts: an edge axis must beat the face by 5 %

// The segment c + t d, |t| <= hl, in the box's frame.
struct Segment {
  Vector3d c, d;
  double hl;
  Vector3d at(double t) const { return c + t * d; }
};

// Parameter range of the segment inside the slabs |x_j| <= h_j of the axes j != skip (skip = -1:
// all three). False when empty.
bool clipToSlabs(const Segment& s, const Vector3d& h, int skip, double& t0, double& t1) {
  t0 = -s.hl;
  t1 = s.hl;
  for (int j = 0; j < 3; ++j) {
    if (j == skip) continue;
    if (std::abs(s.d[j]) < 1e-15) {
      if (std::abs(s.c[j]) > h[j]) return false;
      continue;
    }
    double lo = (-h[j] - s.c[j]) / s.d[j], hi = (h[j] - s.c[j]) / s.d[j];
    if (lo > hi) std::swap(lo, hi);
    t0 = std::max(t0, lo);
    t1 = std::min(t1, hi);
  }
  return t0 <= t1;
}

// Ends of the segment clipped to face k's rectangle (outward normal sg e_k), each a contact
// when depth = h_k + r - sg x_k > 0. Returns the number appended.
int faceEnds(const Segment& s, const Vector3d& h, double r, int k, double sg,
             const Eigen::Isometry3d& box_pose, int pair, std::vector<ContactPoint>& out) {
  double t0 = 0.0, t1 = 0.0;
  if (!clipToSlabs(s, h, k, t0, t1)) return 0;
  Vector3d u = Vector3d::Zero();
  u[k] = sg;
  const Vector3d u_world = box_pose.linear() * u;
  int added = 0;
  for (int end = 0; end < 2; ++end) {
    if (end == 1 && !(t1 > t0)) break;  // a single point (a sphere, or a clipped sliver)
    const double t = end == 0 ? t0 : t1;
    const Vector3d x = s.at(t);
    const double depth = h[k] + r - sg * x[k];
    if (!(depth > 0.0)) continue;
    ContactPoint& cp = out.emplace_back();
    cp.pair = pair;
    const bool clipped = end == 0 ? t > -s.hl : t < s.hl;
    cp.feature = end + (clipped ? 2 : 0);
    cp.position = box_pose * (x - (r - 0.5 * depth) * u);
    cp.normal = u_world;
    cp.depth = depth;
    ++added;
  }
  return added;
}

// One contact point: box surface point `on_box`, segment point `on_seg`, unit n (box frame)
// from the box into the capsule, depth.
int singlePoint(const Vector3d& on_box, const Vector3d& on_seg, const Vector3d& n, double r,
                double depth, int feature, const Eigen::Isometry3d& box_pose, int pair,
                std::vector<ContactPoint>& out) {
  ContactPoint& cp = out.emplace_back();
  cp.pair = pair;
  cp.feature = feature;
  cp.position = box_pose * (0.5 * (on_box + on_seg - r * n));
  cp.normal = box_pose.linear() * n;
  cp.depth = depth;
  return 1;
}

}  // namespace

int boxCapsuleContacts(const Eigen::Isometry3d& box_pose, const Vector3d& h,
                       const Eigen::Isometry3d& capsule_pose, double radius, double half_length,
                       int pair, std::vector<ContactPoint>& out) {
  const Eigen::Matrix3d& rb = box_pose.linear();
  const Segment s{rb.transpose() * (capsule_pose.translation() - box_pose.translation()),
                  rb.transpose() * capsule_pose.linear().col(2), half_length};
  double t0 = 0.0, t1 = 0.0;
  if (!clipToSlabs(s, h, -1, t0, t1)) {
    // Separate: the nearest of the two clamped ends and of S against the box edges. Side
    // (j, sign) is `beyond` when some point of S lies past that face's plane; the box point
    // nearest to a point of S is on edge (k, s1, s2) only if S reaches beyond both faces
    // meeting there, so the other edges are skipped. A face plane farther than r from all
    // of S: no contact.
    bool beyond[3][2];
    for (int j = 0; j < 3; ++j) {
      const double reach = half_length * std::abs(s.d[j]);
      if (std::abs(s.c[j]) - reach - h[j] >= radius) return 0;
      beyond[j][0] = -s.c[j] + reach > h[j];
      beyond[j][1] = s.c[j] + reach > h[j];
    }
    double best = std::numeric_limits<double>::infinity();
    Vector3d on_seg, on_box;
    for (int end = 0; end < 2; ++end) {
      const Vector3d p = s.at(end ? half_length : -half_length);
      const Vector3d q = p.cwiseMax(-h).cwiseMin(h);
      const double d2 = (p - q).squaredNorm();
      if (d2 < best) best = d2, on_seg = p, on_box = q;
    }
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      for (int corner = 0; corner < 4; ++corner) {
        if (!beyond[k1][corner & 1] || !beyond[k2][(corner >> 1) & 1]) continue;
        Vector3d centre = Vector3d::Zero();
        centre[k1] = (corner & 1) ? h[k1] : -h[k1];
        centre[k2] = (corner & 2) ? h[k2] : -h[k2];
        Vector3d p, q;
        closestOnSegments(s.c, s.d, half_length, centre, Vector3d::Unit(k), h[k], p, q);
        const double d2 = (p - q).squaredNorm();
        if (d2 < best) best = d2, on_seg = p, on_box = q;
      }
    }
    if (best >= radius * radius) return 0;
    const double d = std::sqrt(best);
    const Vector3d n = (on_seg - on_box) / d;
    int k = 0;
    n.cwiseAbs().maxCoeff(&k);
    if (std::abs(n[k]) > 1.0 - 1e-9) {  // on a face: the clipped ends
      const int added = faceEnds(s, h, radius, k, n[k] > 0 ? 1.0 : -1.0, box_pose, pair, out);
      if (added > 0) return added;
    }
    return singlePoint(on_box, on_seg, n, radius, radius - d, 4, box_pose, pair, out);
  }
  // S crosses the box: the least-penetration axis of the Minkowski sum.
  int face = 0;
  double o_face = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const double o = h[k] + half_length * std::abs(s.d[k]) + radius - std::abs(s.c[k]);
    if (o < o_face) o_face = o, face = k;
  }
  int edge = -1;
  double o_edge = std::numeric_limits<double>::infinity();
  Vector3d n_edge = Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    Vector3d l = s.d.cross(Vector3d::Unit(k));
    const double len = l.norm();
    if (len < 1e-6) continue;
    l /= len;
    const double o = h.dot(l.cwiseAbs()) + radius - std::abs(s.c.dot(l));
    if (o < o_edge) o_edge = o, edge = k, n_edge = s.c.dot(l) >= 0.0 ? l : Vector3d(-l);
  }
  if (edge < 0 || !(o_edge < kEdgeBias * o_face)) {
    const int added =
        faceEnds(s, h, radius, face, s.c[face] >= 0.0 ? 1.0 : -1.0, box_pose, pair, out);
    if (added > 0 || edge < 0) return added;
  }
  // The box edge parallel to e_edge farthest along n against the segment.
  Vector3d centre = Vector3d::Zero();
  for (int j = 0; j < 3; ++j)
    if (j != edge) centre[j] = n_edge[j] >= 0.0 ? h[j] : -h[j];
  Vector3d p, q;
  closestOnSegments(s.c, s.d, half_length, centre, Vector3d::Unit(edge), h[edge], p, q);
  return singlePoint(q, p, n_edge, radius, o_edge, 5, box_pose, pair, out);
}

int boxCylinderContacts(const Eigen::Isometry3d& box_pose, const Vector3d& h,
                        const Eigen::Isometry3d& cylinder_pose, double radius, double half_length,
                        int pair, std::vector<ContactPoint>& out) {
  const Eigen::Matrix3d& rb = box_pose.linear();
  const Vector3d c = rb.transpose() * (cylinder_pose.translation() - box_pose.translation());
  const Vector3d a = rb.transpose() * cylinder_pose.linear().col(2);
  Vector3d extent;
  int k = 0;
  double s_k = -std::numeric_limits<double>::infinity();
  for (int j = 0; j < 3; ++j) {
    extent[j] = half_length * std::abs(a[j]) + radius * std::sqrt(std::max(0.0, 1.0 - a[j] * a[j]));
    const double s = std::abs(c[j]) - h[j] - extent[j];
    if (s >= 0.0) return 0;  // separated along a box axis
    if (s > s_k) s_k = s, k = j;
  }
  // Exact only when the box is a half-space for this cylinder: over face k's rectangle,
  // centre outside the face, not reaching the opposite face.
  for (int j = 0; j < 3; ++j)
    if (j != k && std::abs(c[j]) + extent[j] > h[j]) return -1;
  if (std::abs(c[k]) <= h[k] || std::abs(c[k]) - extent[k] < -h[k]) return -1;
  const double sg = c[k] >= 0.0 ? 1.0 : -1.0;
  const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  Eigen::Isometry3d plane = Eigen::Isometry3d::Identity();
  plane.linear().col(0) = rb.col(sg > 0 ? k1 : k2);
  plane.linear().col(1) = rb.col(sg > 0 ? k2 : k1);
  plane.linear().col(2) = sg * rb.col(k);
  Vector3d face = Vector3d::Zero();
  face[k] = sg * h[k];
  plane.translation() = box_pose * face;
  return halfSpaceContacts(Shape::cylinder(radius, half_length), cylinder_pose, plane, pair, 0,
                           out);
}

}  // namespace tribo::contact
