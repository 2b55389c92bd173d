// A model's geometry for the replay page (study/view/view_page.hpp), as JSON text: per body its
// name, kind, initial pose, surface velocity and geometries (shape, dimensions, local pose;
// meshes as vertex and triangle lists up to a size cap), and the world's geometries.
// Not here: the motion (study/view/view_trajectory.hpp), drawing (view/scene.js).
#pragma once

#include <string>

#include "core/model.hpp"

namespace tribo::study {

// Meshes with more triangles than this are drawn as their bounding box.
inline constexpr std::size_t kViewMeshTriangleCap = 20000;

// {"bodies": [{"name", "kind", "position": [x,y,z], "quaternion": [w,x,y,z],
//   "surface_velocity": [..], "geometries": [...]}], "world": [geometries]}; a geometry is
// {"name", "shape", "position", "quaternion", and per shape "half_extents" | "radius",
// "half_length" | "vertices", "triangles"}.
std::string viewSceneJson(const Model& model);

}  // namespace tribo::study
