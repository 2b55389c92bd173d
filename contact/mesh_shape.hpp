// Triangle meshes as contact shapes: a convex mesh checked to be convex (every vertex on or
// below every face plane, within 1e-9 of its distance from the face) and solid (not flat),
// with its triangles turned to face outwards, and a box's own mesh (boxMeshData) for the shapes
// that treat a box as a polyhedron. Pure geometry on MeshData (contact/shape.hpp). Not here:
// reading mesh files (io/mesh_loader.hpp), computing convex hulls (a non-convex mesh given as
// convex is an error), repairing meshes.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <stdexcept>

#include "contact/shape.hpp"

namespace tribo::contact {

// A mesh that cannot be read or does not describe what was asked for. The message names
// the file (or "(inline)") and what was expected vs found.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A box of half extents h as a mesh: its 8 corners (corner k has bit 0, 1, 2 for +x, +y, +z)
// and 12 outward triangles.
MeshData boxMeshData(const Eigen::Vector3d& h);

// A vertex may lie above a face plane by this fraction of its distance from the face (or of
// the face's longest edge, when larger): rounding, not a dent.
inline constexpr double kConvexTolerance = 1e-9;
// A convex hull's smallest width across a face, relative to its size (the largest distance of
// a vertex from the vertices' centroid), at least: flatter or more needle-like hulls are not
// solids the narrowphase (libccd's MPR) can resolve.
inline constexpr double kMinConvexThickness = 1e-6;

// Checks convexity and orients the triangles outwards; throws MeshError naming the first
// vertex found above a face plane, a vertex not finite or past contact::kMaxLength, or a hull
// thinner than kMinConvexThickness times its size.
std::shared_ptr<const MeshData> makeConvex(const MeshData& mesh);

}  // namespace tribo::contact
