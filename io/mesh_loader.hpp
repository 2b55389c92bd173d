// Reads triangle meshes from STL, OBJ and COLLADA (DAE) files with the Open Asset Import
// Library (assimp), the one place it is used. All meshes of the file are merged, each node's
// transform applied (COLLADA's unit scale included, its up-axis not: coordinates are taken
// as written), duplicate vertices joined, polygons triangulated; `scale` multiplies each axis
// afterwards. Not here: convexity checks and a box's mesh (contact/mesh_shape.hpp),
// textures or materials.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "contact/mesh_shape.hpp"

namespace tribo::io {

// Throws contact::MeshError naming the file when it cannot be read or holds no triangle.
std::shared_ptr<const contact::MeshData> loadMesh(
    const std::string& path, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace tribo::io
