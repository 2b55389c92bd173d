#include "contact/polyhedron_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/mesh_shape.hpp"
#include "contact/primitive_contacts.hpp"

namespace tribo::contact {

namespace {

constexpr double kFaceTolerance = 1e-9;  // coplanar triangles: normals and offsets (x size)
constexpr double kFaceBias = 1.05;       // a face overlap within 5% of EPA's depth is a face

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The corners of the convex hull of `ids` on the plane with unit normal n, counter-clockwise
// about n (Andrew's monotone chain; collinear points dropped).
std::vector<int> hullLoop(const std::vector<Eigen::Vector3d>& vertices, std::vector<int> ids,
                          const Eigen::Vector3d& n) {
  const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  auto at = [&](int i) { return Eigen::Vector2d(vertices[i].dot(e1), vertices[i].dot(e2)); };
  std::sort(ids.begin(), ids.end(), [&](int a, int b) {
    const Eigen::Vector2d pa = at(a), pb = at(b);
    return pa.x() < pb.x() || (pa.x() == pb.x() && pa.y() < pb.y());
  });
  if (ids.size() < 3) return ids;
  std::vector<int> hull(2 * ids.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {  // lower chain
    while (k >= 2 && cross2(at(hull[k - 2]), at(hull[k - 1]), at(ids[i])) <= 0.0) --k;
    hull[k++] = ids[i];
  }
  for (std::size_t i = ids.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross2(at(hull[k - 2]), at(hull[k - 1]), at(ids[i])) <= 0.0) --k;
    hull[k++] = ids[i];
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

// Sutherland-Hodgman: keeps the part of `in` with s . (x - p) <= 0.
void clip(const std::vector<Eigen::Vector3d>& in, const Eigen::Vector3d& p,
          const Eigen::Vector3d& s, std::vector<Eigen::Vector3d>& out) {
  out.clear();
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& x = in[i];
    const Eigen::Vector3d& y = in[(i + 1) % n];
    const double dx = s.dot(x - p), dy = s.dot(y - p);
    if (dx <= 0.0) out.push_back(x);
    if ((dx <= 0.0) != (dy <= 0.0)) out.push_back(x + (y - x) * (dx / (dx - dy)));
  }
}

int mostAligned(const Polyhedron& p, const Eigen::Vector3d& d) {
  int best = 0;
  double best_dot = -std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const double dot = p.faces[f].normal.dot(d);
    if (dot > best_dot) best_dot = dot, best = static_cast<int>(f);
  }
  return best;
}

}  // namespace

double Polyhedron::support(const Eigen::Vector3d& d) const {
  double best = -std::numeric_limits<double>::infinity();
  for (const auto& v : vertices) best = std::max(best, d.dot(v));
  return best;
}

bool isPolyhedron(const Shape& shape) {
  return shape.type == ShapeType::kBox || (shape.type == ShapeType::kConvexMesh && shape.mesh);
}

Polyhedron makePolyhedron(const Shape& shape) {
  if (!isPolyhedron(shape))
    throw std::invalid_argument("polyhedron: a box or convex_mesh was expected, got " +
                                shapeName(shape.type));
  const MeshData mesh =
      shape.type == ShapeType::kBox ? boxMeshData(shape.half_extents) : *shape.mesh;
  Polyhedron p;
  p.vertices = mesh.vertices;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& v : p.vertices) centroid += v / static_cast<double>(p.vertices.size());
  for (const auto& v : p.vertices) p.size = std::max(p.size, (v - centroid).norm());
  // Coplanar triangles into faces: area-weighted normal sums and their vertices.
  std::vector<Eigen::Vector3d> sums;
  std::vector<std::vector<int>> members;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = p.vertices[t[0]];
    Eigen::Vector3d n = (p.vertices[t[1]] - a).cross(p.vertices[t[2]] - a);
    if (n.norm() <= kFaceTolerance * p.size * p.size) continue;  // degenerate
    if (n.dot(a - centroid) < 0.0) n = -n;                       // outward
    const Eigen::Vector3d u = n.normalized();
    std::size_t f = 0;
    for (; f < p.faces.size(); ++f)
      if (p.faces[f].normal.dot(u) > 1.0 - kFaceTolerance &&
          std::abs(p.faces[f].offset - u.dot(a)) <= kFaceTolerance * p.size)
        break;
    if (f == p.faces.size()) {
      p.faces.push_back({u, u.dot(a), {}});
      sums.push_back(Eigen::Vector3d::Zero());
      members.emplace_back();
    }
    sums[f] += n;
    members[f].insert(members[f].end(), t.begin(), t.end());
  }
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    Polyhedron::Face& face = p.faces[f];
    std::sort(members[f].begin(), members[f].end());
    members[f].erase(std::unique(members[f].begin(), members[f].end()), members[f].end());
    face.normal = sums[f].normalized();
    face.offset = -std::numeric_limits<double>::infinity();
    for (int v : members[f]) face.offset = std::max(face.offset, face.normal.dot(p.vertices[v]));
    face.loop = hullLoop(p.vertices, members[f], face.normal);
  }
  return p;
}

int polyhedronContacts(const Polyhedron& a, const Eigen::Isometry3d& pose_a, const Polyhedron& b,
                       const Eigen::Isometry3d& pose_b, const Eigen::Vector3d& normal, double depth,
                       int pair, int max_points, ClipScratch& scratch,
                       std::vector<ContactPoint>& out) {
  if (a.faces.empty() || b.faces.empty() || !(depth > 0.0)) return 0;
  const Eigen::Matrix3d& ra = pose_a.linear();
  const Eigen::Matrix3d& rb = pose_b.linear();
  // Candidate faces: A's facing along n, B's facing against it; their overlaps.
  const Polyhedron::Face& fa = a.faces[mostAligned(a, ra.transpose() * normal)];
  const Polyhedron::Face& fb = b.faces[mostAligned(b, -(rb.transpose() * normal))];
  const Eigen::Vector3d ua = ra * fa.normal, ub = rb * fb.normal;
  const double overlap_a = ua.dot(pose_a.translation()) + fa.offset -
                           (ua.dot(pose_b.translation()) - b.support(-(rb.transpose() * ua)));
  const double overlap_b = ub.dot(pose_b.translation()) + fb.offset -
                           (ub.dot(pose_a.translation()) - a.support(-(ra.transpose() * ub)));
  const double slack = kFaceTolerance * (a.size + b.size);
  const bool reference_a = overlap_a <= overlap_b + slack;  // A's face on a tie
  const double overlap = reference_a ? overlap_a : overlap_b;
  if (!(overlap > 0.0) || overlap > kFaceBias * depth + slack) return 0;  // edge/edge

  const Polyhedron& ref = reference_a ? a : b;
  const Polyhedron& inc = reference_a ? b : a;
  const Eigen::Isometry3d& ref_pose = reference_a ? pose_a : pose_b;
  const Eigen::Isometry3d& inc_pose = reference_a ? pose_b : pose_a;
  const Polyhedron::Face& face = reference_a ? fa : fb;
  const Eigen::Vector3d u = reference_a ? ua : ub;  // out of the reference body
  const Polyhedron::Face& incident =
      inc.faces[mostAligned(inc, -(inc_pose.linear().transpose() * u))];
  scratch.polygon.clear();
  for (int v : incident.loop) scratch.polygon.push_back(inc_pose * inc.vertices[v]);
  const std::size_t m = face.loop.size();
  for (std::size_t k = 0; k < m && !scratch.polygon.empty(); ++k) {
    const Eigen::Vector3d p = ref_pose * ref.vertices[face.loop[k]];
    const Eigen::Vector3d q = ref_pose * ref.vertices[face.loop[(k + 1) % m]];
    clip(scratch.polygon, p, (q - p).cross(u), scratch.clipped);
    std::swap(scratch.polygon, scratch.clipped);
  }
  const double plane = u.dot(ref_pose.translation()) + face.offset;
  const std::size_t first = out.size();
  for (const Eigen::Vector3d& x : scratch.polygon) {
    const double d = plane - u.dot(x);
    if (!(d > 0.0)) continue;
    ContactPoint& cp = out.emplace_back();
    cp.pair = pair;
    cp.feature = -1;
    cp.position = x + 0.5 * d * u;
    cp.normal = reference_a ? u : Eigen::Vector3d(-u);
    cp.depth = d;
  }
  thinContacts(out, first, max_points);
  return static_cast<int>(out.size() - first);
}

}  // namespace tribo::contact
