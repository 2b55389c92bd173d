// Collision shapes attached to bodies, described in the geometry's own frame.
//
// A box is centred on its frame origin with the given half extents [m]. A half-space is
// the solid below the plane z = 0 of its frame (outward normal +z). The set is what the
// validating scenes need; it is not a mesh or convex-hull library.
#pragma once

#include <Eigen/Core>
#include <string>

namespace tribo::contact {

enum class ShapeType { kBox, kHalfSpace };

struct Shape {
  ShapeType type = ShapeType::kBox;
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);  // box only [m]

  static Shape box(const Eigen::Vector3d& half_extents) { return {ShapeType::kBox, half_extents}; }
  static Shape halfSpace() { return {ShapeType::kHalfSpace, Eigen::Vector3d::Zero()}; }

  // Characteristic size [m]: smallest box half extent, infinite for a half-space. A
  // penetration deeper than this means the contact has failed (the run is unstable).
  double size() const;
};

std::string shapeName(ShapeType type);

}  // namespace tribo::contact
