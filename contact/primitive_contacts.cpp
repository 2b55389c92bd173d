#include "contact/primitive_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tribo::contact {

namespace {

constexpr int kRimPoints = 8;

struct Plane {
  Eigen::Vector3d n;
  double offset;  // n . x on the plane
};

Plane planeOf(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d n = pose.linear().col(2);
  return {n, n.dot(pose.translation())};
}

// Appends the point p (of the shape) if it lies below the plane, placed midway to the plane.
bool addIfBelow(const Plane& plane, const Eigen::Vector3d& p, int pair, int feature,
                std::vector<ContactPoint>& out) {
  const double depth = plane.offset - plane.n.dot(p);
  if (depth <= 0.0) return false;
  ContactPoint cp;
  cp.pair = pair;
  cp.feature = feature;
  cp.position = p + 0.5 * depth * plane.n;
  cp.normal = plane.n;
  cp.depth = depth;
  out.push_back(cp);
  return true;
}

// kRimPoints points of the circle (centre c, radius r, unit axis a), the first at the point
// deepest below the plane.
int rimContacts(const Plane& plane, const Eigen::Vector3d& c, const Eigen::Vector3d& a, double r,
                const Eigen::Vector3d& fallback, int pair, int first_feature,
                std::vector<ContactPoint>& out) {
  // The deepest rim point lies along -(n projected on the rim plane).
  Eigen::Vector3d e1 = -(plane.n - plane.n.dot(a) * a);
  if (e1.norm() < 1e-9) e1 = fallback - fallback.dot(a) * a;  // disc parallel to the plane
  e1.normalize();
  const Eigen::Vector3d e2 = a.cross(e1);
  // Skip the rim when even its deepest point is above the plane.
  if (plane.offset - plane.n.dot(c + r * e1) <= 0.0) return 0;
  int added = 0;
  for (int k = 0; k < kRimPoints; ++k) {
    const double phase = 2.0 * std::numbers::pi * k / kRimPoints;
    const Eigen::Vector3d p = c + r * (std::cos(phase) * e1 + std::sin(phase) * e2);
    added += addIfBelow(plane, p, pair, first_feature + k, out);
  }
  return added;
}

}  // namespace

void thinContacts(std::vector<ContactPoint>& out, std::size_t first, int max_points) {
  const std::size_t n = out.size() - first;
  if (max_points <= 0 || n <= static_cast<std::size_t>(max_points)) return;
  std::vector<ContactPoint> all(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  out.resize(first);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::size_t pick = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (all[i].depth > all[pick].depth) pick = i;
  for (int k = 0; k < max_points; ++k) {
    out.push_back(all[pick]);
    dist[pick] = -1.0;
    std::size_t next = pick;
    double best = -1.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (dist[i] < 0.0) continue;
      dist[i] = std::min(dist[i], (all[i].position - all[pick].position).squaredNorm());
      if (dist[i] > best) best = dist[i], next = i;
    }
    if (best < 0.0) break;
    pick = next;
  }
}

int boxHalfSpaceContacts(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& half_extents,
                         const Eigen::Isometry3d& plane_pose, int pair,
                         std::vector<ContactPoint>& out) {
  // The belt's and the box grids' hot path. A corner is t + R s with s = (+-hx, +-hy, +-hz),
  // summed as Eigen sums `box_pose * s` on this build, ((x + y) + z) + t per row, from the
  // three products e_i = R.col(i) h_i formed once (a sign flips a product exactly): the
  // corners are the same bits as the plain loop's (tests/contact/box_half_space_test.cpp).
  // The loop is unrolled so that each corner's signs are constants.
  const Eigen::Vector3d n = plane_pose.linear().col(2);
  const double offset = n.dot(plane_pose.translation());
  const Eigen::Vector3d t = box_pose.translation();
  const Eigen::Vector3d ex = box_pose.linear().col(0) * half_extents.x();
  const Eigen::Vector3d ey = box_pose.linear().col(1) * half_extents.y();
  const Eigen::Vector3d ez = box_pose.linear().col(2) * half_extents.z();
  int added = 0;
#pragma GCC unroll 8
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner =
        (((k & 1) ? ex : -ex) + ((k & 2) ? ey : -ey) + ((k & 4) ? ez : -ez)) + t;
    const double depth = offset - n.dot(corner);
    if (depth <= 0.0) continue;
    out.push_back({pair, k, corner + 0.5 * depth * n, n, depth});
    ++added;
  }
  return added;
}

int halfSpaceContacts(const Shape& shape, const Eigen::Isometry3d& pose,
                      const Eigen::Isometry3d& plane_pose, int pair, int max_points,
                      std::vector<ContactPoint>& out) {
  const Plane plane = planeOf(plane_pose);
  const Eigen::Vector3d c = pose.translation();
  const Eigen::Vector3d axis = pose.linear().col(2);
  const Eigen::Vector3d x_axis = pose.linear().col(0);
  const std::size_t first = out.size();
  switch (shape.type) {
    case ShapeType::kBox:
      return boxHalfSpaceContacts(pose, shape.half_extents, plane_pose, pair, out);
    case ShapeType::kSphere:
      return addIfBelow(plane, c - shape.radius * plane.n, pair, 0, out);
    case ShapeType::kCapsule: {
      int added = 0;
      for (int end = 0; end < 2; ++end) {
        const Eigen::Vector3d centre = c + (end ? 1.0 : -1.0) * shape.half_length * axis;
        added += addIfBelow(plane, centre - shape.radius * plane.n, pair, end, out);
      }
      return added;
    }
    case ShapeType::kCylinder: {
      int added = 0;
      for (int rim = 0; rim < 2; ++rim) {
        const Eigen::Vector3d centre = c + (rim ? 1.0 : -1.0) * shape.half_length * axis;
        added +=
            rimContacts(plane, centre, axis, shape.radius, x_axis, pair, rim * kRimPoints, out);
      }
      return added;
    }
    case ShapeType::kCone: {
      int added = addIfBelow(plane, c + shape.half_length * axis, pair, 0, out);
      added += rimContacts(plane, c - shape.half_length * axis, axis, shape.radius, x_axis, pair, 1,
                           out);
      return added;
    }
    case ShapeType::kConvexMesh:
    case ShapeType::kTriangleMesh: {
      // Cheap rejection: the mesh's lowest point along n is its support along -n.
      const Eigen::Vector3d n_local = pose.linear().transpose() * plane.n;
      if (plane.offset - plane.n.dot(c) + shape.support(-n_local) <= 0.0) return 0;
      const auto& vertices = shape.mesh->vertices;
      for (std::size_t v = 0; v < vertices.size(); ++v)
        addIfBelow(plane, pose * vertices[v], pair, static_cast<int>(v), out);
      thinContacts(out, first, max_points);
      return static_cast<int>(out.size() - first);
    }
    case ShapeType::kHalfSpace:
      return 0;
  }
  return 0;
}

int sphereSphereContact(const Eigen::Vector3d& ca, double ra, const Eigen::Vector3d& cb, double rb,
                        int pair, std::vector<ContactPoint>& out) {
  const Eigen::Vector3d d = cb - ca;
  const double dist2 = d.squaredNorm();
  const double reach = ra + rb;
  if (dist2 >= reach * reach) return 0;
  const double dist = std::sqrt(dist2);
  ContactPoint cp;
  cp.pair = pair;
  cp.feature = 0;
  cp.normal = dist > 1e-12 * reach ? Eigen::Vector3d(d / dist) : Eigen::Vector3d::UnitZ();
  cp.depth = reach - dist;
  // Midway between the two surface points along the line of centres.
  cp.position = ca + (ra - 0.5 * cp.depth) * cp.normal;
  out.push_back(cp);
  return 1;
}

int boxSphereContact(const Eigen::Isometry3d& box_pose, const Eigen::Vector3d& h,
                     const Eigen::Vector3d& centre, double radius, int pair,
                     std::vector<ContactPoint>& out) {
  const Eigen::Matrix3d& r = box_pose.linear();
  const Eigen::Vector3d local = r.transpose() * (centre - box_pose.translation());
  const Eigen::Vector3d closest = local.cwiseMax(-h).cwiseMin(h);
  ContactPoint cp;
  cp.pair = pair;
  cp.feature = 0;
  const Eigen::Vector3d d = local - closest;
  const double dist2 = d.squaredNorm();
  if (dist2 > 0.0) {  // centre outside the box
    if (dist2 >= radius * radius) return 0;
    const double dist = std::sqrt(dist2);
    const Eigen::Vector3d n_local = d / dist;
    cp.depth = radius - dist;
    cp.normal = r * n_local;
    // Midway between the box surface point and the sphere's deepest point.
    cp.position = box_pose * closest - 0.5 * cp.depth * cp.normal;
  } else {  // centre inside: leave through the nearest face
    const Eigen::Vector3d gap = h - local.cwiseAbs();
    int axis = 0;
    gap.minCoeff(&axis);
    Eigen::Vector3d n_local = Eigen::Vector3d::Zero();
    n_local[axis] = local[axis] >= 0.0 ? 1.0 : -1.0;
    cp.depth = gap[axis] + radius;
    cp.normal = r * n_local;
    Eigen::Vector3d face = local;
    face[axis] = n_local[axis] * h[axis];
    cp.position = box_pose * face - 0.5 * cp.depth * cp.normal;
  }
  out.push_back(cp);
  return 1;
}

}  // namespace tribo::contact
