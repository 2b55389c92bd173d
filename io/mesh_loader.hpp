// Reads triangle meshes from STL, OBJ, COLLADA (DAE) and glTF 2.0 (.gltf, .glb) files, told
// apart by the file's extension (any case): STL, COLLADA and glTF with the Open Asset Import
// Library (assimp), the one place it is used, a COLLADA file's declared sizes checked first
// (io/collada_check.hpp), a glTF's buffers, views, accessors and nodes too
// (io/gltf_check.hpp); OBJ with Tribo's own reader (io/obj_reader.hpp). All meshes of the
// file are merged, each node's transform applied (COLLADA's unit scale included, its up-axis
// not: coordinates are taken as written; glTF is metres, its Y-up not turned either),
// duplicate vertices joined, polygons triangulated; `scale` multiplies each axis afterwards.
// A .gltf's external buffers are read from files named relative to its folder (never from a
// URL). Not here: other formats, convexity checks and a box's mesh (contact/mesh_shape.hpp),
// textures or materials.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>
#include <string>

#include "contact/mesh_shape.hpp"

namespace tribo::io {

// Throws contact::MeshError naming the file when it cannot be read, is not named .stl, .obj,
// .dae, .gltf or .glb, or holds no triangle. The file is read whole, then as
// loadMeshFromMemory does, a .gltf's buffer files found beside it.
std::shared_ptr<const contact::MeshData> loadMesh(
    const std::string& path, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

// The same from the bytes of a file held in memory; `hint` is the format's file extension
// ("stl", "obj", "dae", "gltf", "glb", any case; no other). `name_for_errors` stands for the
// file name in messages and in MeshData::source. Meshes a DAE or OBJ file references by name
// (external files) are not found; a .gltf naming a buffer file is refused (data URIs are
// read). Throws contact::MeshError.
std::shared_ptr<const contact::MeshData> loadMeshFromMemory(
    std::span<const unsigned char> bytes, const std::string& hint,
    const std::string& name_for_errors, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace tribo::io
