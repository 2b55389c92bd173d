// A model's geometry for the replay page (study/view/view_page.hpp), as JSON text: per body its
// name, kind, initial pose, surface velocity and geometries (shape, dimensions, local pose;
// meshes as vertex and triangle lists up to a size cap), the world's geometries, the springs
// (spring-dampers and bushings: their bodies and attachment points) and the joints (type,
// bodies, anchor and axis).
// Not here: the motion (study/view/view_trajectory.hpp), drawing (view/scene.js).
#pragma once

#include <string>

#include "core/model.hpp"

namespace tribo::study {

// Meshes with more triangles than this are drawn as their bounding box.
inline constexpr std::size_t kViewMeshTriangleCap = 20000;

// {"bodies": [{"name", "kind", "position": [x,y,z], "quaternion": [w,x,y,z],
//   "surface_velocity": [..], "geometries": [...]}], "world": [geometries],
//  "springs": [{"name", "kind": "spring" | "bushing", "a", "point_a", "b", "point_b"}],
//  "joints": [{"name", "type", "parent", "child", "anchor_in_parent", "axis_in_parent",
//   "anchor_in_child", "axis_in_child", "anchor", "axis"}]}.
// A geometry is {"name", "shape", "position", "quaternion", and per shape "half_extents" |
// "radius", "half_length" | "vertices", "triangles"}, with "surface_velocity" (the direction
// its surface moves, body frame [m/s]) on a body whose surface moves. Bodies are named by
// their index in "bodies", the world by -1; a point on a body is in its body frame (the
// world's in world coordinates); a spring also has "stiffness", "damping", "rest_length". A
// joint's axis is its z axis (rotation or slide axis, plane normal); "anchor" and "axis"
// are the child's in world coordinates at the initial pose.
std::string viewSceneJson(const Model& model);

}  // namespace tribo::study
