// Joints as sets of algebraic constraints Phi(q) = 0 between a parent (body or world) and
// a child body, built from two primitives on the joint frames F_P (fixed in the parent) and
// F_C (fixed in the child), which coincide in the initial configuration:
//   distance:      Phi = u_i . (p_C - p_P)     (child anchor on a parent plane, u_i = F_P axis i)
//   perpendicular: Phi = u_i . w_j             (parent axis i stays normal to child axis j)
// Joint z axis = the joint axis (rotation/slide axis, or plane normal for planar_translation).
//   fixed:               distance x,y,z + perpendicular (x,y),(y,z),(z,x)   6 equations
//   revolute:            distance x,y,z + perpendicular (z,x),(z,y)         5
//   prismatic:           distance x,y   + perpendicular (x,y),(y,z),(z,x)   5
//   planar_translation:  distance z     + perpendicular (x,y),(y,z),(z,x)   4 (slides in the
//                        plane normal to z, does not rotate: the belt box)
//   spherical:           distance x,y,z                                      3
// Not here: limits, joint friction and drives (later); the solve (core/constraint_solver).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/body.hpp"

namespace tribo {

enum class JointType { kFixed, kRevolute, kPrismatic, kPlanarTranslation, kSpherical };

struct Joint {
  std::string name;
  JointType type = JointType::kFixed;
  BodyIndex parent = BodyIndex::world();
  BodyIndex child;
  // Joint frame in each body's coordinates (origin = anchor, columns = joint axes).
  Vec3 anchor_in_parent = Vec3::Zero();
  Mat3 axes_in_parent = Mat3::Identity();
  Vec3 anchor_in_child = Vec3::Zero();
  Mat3 axes_in_child = Mat3::Identity();
};

// One scalar constraint equation of a joint.
struct ConstraintEquation {
  enum class Kind { kDistance, kPerpendicular } kind;
  int parent_axis;  // i
  int child_axis;   // j (perpendicular only)
};

// The equations a joint type contributes, in a fixed order.
const std::vector<ConstraintEquation>& jointEquations(JointType type);

// Scene names: "fixed", "revolute", "prismatic", "planar_translation", "spherical".
// Throws std::invalid_argument listing the known names.
JointType jointTypeFromName(const std::string& name);
std::string jointTypeName(JointType type);

}  // namespace tribo
