#include "contact/mesh_shape.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <sstream>
#include <string>

namespace tribo::contact {

std::shared_ptr<const MeshData> makeConvex(const MeshData& mesh) {
  auto out = std::make_shared<MeshData>(mesh);
  const std::string who = "convex mesh '" + (mesh.source.empty() ? "(inline)" : mesh.source) + "'";
  if (out->vertices.size() < 4 || out->triangles.size() < 4)
    throw MeshError(who + ": expected a closed polyhedron (>= 4 vertices and faces), found " +
                    std::to_string(out->vertices.size()) + " vertices, " +
                    std::to_string(out->triangles.size()) + " triangles");
  for (std::size_t v = 0; v < out->vertices.size(); ++v) {
    const Eigen::Vector3d& p = out->vertices[v];
    if (!p.allFinite())
      throw MeshError(who + ": vertex " + std::to_string(v) + ": expected finite coordinates");
    if (auto e = outsideLengthLimit("vertex " + std::to_string(v), p); !e.empty())
      throw MeshError(who + ": " + e);
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double extent = 0.0;
  for (const auto& v : out->vertices) centre += v;
  centre /= static_cast<double>(out->vertices.size());
  for (const auto& v : out->vertices) extent = std::max(extent, (v - centre).norm());
  // The hull's width across its thinnest face (for a convex hull, the smallest of these
  // bounds its smallest width from above).
  double thickness = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < out->triangles.size(); ++f) {
    auto& t = out->triangles[f];
    const Eigen::Vector3d& a = out->vertices[t[0]];
    const Eigen::Vector3d& b = out->vertices[t[1]];
    const Eigen::Vector3d& c = out->vertices[t[2]];
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() <= 1e-300) continue;  // degenerate triangle: no plane to check
    n.normalize();
    if (n.dot(centre - a) > 0.0) {  // faces inwards: turn it
      std::swap(t[1], t[2]);
      n = -n;
    }
    // Rounding of n . (v - a) grows with |v - a| and with the face's size, not with the
    // mesh's: a tolerance relative to those keeps one far vertex (which makes the mesh's
    // extent huge) from hiding a dent elsewhere.
    const double face = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    double depth = 0.0;
    for (std::size_t v = 0; v < out->vertices.size(); ++v) {
      const Eigen::Vector3d d = out->vertices[v] - a;
      const double above = n.dot(d);
      depth = std::max(depth, -above);
      if (above > kConvexTolerance * std::max(d.norm(), face)) {
        std::ostringstream s;
        s << who << ": not convex: vertex " << v << " lies " << above << " m above face " << f
          << " (expected every vertex on or below every face; use shape: mesh for a "
             "non-convex surface)";
        throw MeshError(s.str());
      }
    }
    thickness = std::min(thickness, depth);
  }
  if (!(thickness >= kMinConvexThickness * extent)) {
    std::ostringstream s;
    s << who << ": expected a solid at least " << kMinConvexThickness
      << " times as thick as its size, found " << thickness << " m thick across " << extent
      << " m (a flat or needle-like hull; use shape: mesh for a surface)";
    throw MeshError(s.str());
  }
  return out;
}

MeshData boxMeshData(const Eigen::Vector3d& h) {
  MeshData m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(),
                            (k & 4) ? h.z() : -h.z());
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

}  // namespace tribo::contact
