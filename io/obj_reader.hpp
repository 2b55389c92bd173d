// Reads the geometry of a Wavefront OBJ file: its vertices (`v x y z`; a fourth number or
// colours after the three are ignored) and faces (`f` with corners written i, i/t, i//n or
// i/t/n: 1-based indices, or negative ones counting back from the last vertex read), a
// polygon cut into triangles by ear clipping in its own plane. Every other statement (normals,
// texture coordinates, groups, objects, smoothing, materials, lines, points, free-form
// geometry) is skipped, and no other file is opened (a `mtllib` is not read). Lines ending in
// '\' continue on the next.
// Tribo's own reader rather than assimp's: assimp 5.2.5's OBJ importer fills a 16 MB line
// buffer for every file (2 ms a mesh, 23 ms under AddressSanitizer, where it held the mesh
// fuzzer to 94 inputs a second), and this one names the line of each error.
// Not here: merging, scaling, welding (io/mesh_loader.cpp).
#pragma once

#include <string>
#include <string_view>

#include "contact/mesh_shape.hpp"

namespace tribo::io {

// The vertices and triangles as written (a vertex no face uses is kept). Throws
// contact::MeshError "mesh file 'NAME': line L: ..." on a number that is not one or is not
// finite, a face with fewer than 3 corners, an index 0 or one past the vertices.
contact::MeshData readObj(std::string_view text, const std::string& name);

}  // namespace tribo::io
