// Reads triangle meshes from STL, OBJ and COLLADA (DAE) files with the Open Asset Import
// Library (assimp), the one place it is used. All meshes of the file are merged, each node's
// transform applied (COLLADA's unit scale included, its up-axis not: coordinates are taken
// as written), duplicate vertices joined, polygons triangulated; `scale` multiplies each axis
// afterwards. A convex mesh is checked to be convex (every vertex on or below every face
// plane, within 1e-9 of the mesh size) and its triangles turned to face outwards. A box's own
// mesh (boxMeshData) is built here too, for the shapes that treat a box as a polyhedron.
// Not here: computing convex hulls (a non-convex file given as convex_mesh is an error),
// repairing meshes, textures or materials.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <stdexcept>
#include <string>

#include "contact/shape.hpp"

namespace tribo::contact {

// A mesh file that cannot be read or does not describe what was asked for. The message
// names the file and what was expected vs found.
class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::shared_ptr<const MeshData> loadMesh(const std::string& path,
                                         const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

// A box of half extents h as a mesh: its 8 corners (corner k has bit 0, 1, 2 for +x, +y, +z)
// and 12 outward triangles.
MeshData boxMeshData(const Eigen::Vector3d& h);

// Checks convexity and orients the triangles outwards; throws MeshError naming the first
// vertex found above a face plane.
std::shared_ptr<const MeshData> makeConvex(const MeshData& mesh);

}  // namespace tribo::contact
