// Joints as sets of algebraic constraints Phi(q) = 0 between a parent (body or world) and
// a child body, built from two primitives on the joint frames F_P (fixed in the parent) and
// F_C (fixed in the child), which coincide where the joint coordinate is zero:
//   distance:      Phi = u_i . (p_C - p_P)     (child anchor on a parent plane, u_i = F_P axis i)
//   perpendicular: Phi = u_i . w_j             (parent axis i stays normal to child axis j)
// (Haug 1989, "Computer Aided Kinematics and Dynamics of Mechanical Systems", ch. 3: the
// dot-1 and dot-2 constraints.) Joint z axis = the joint axis (rotation/slide axis, or plane
// normal for the planar joints); x is the zero-angle reference (universal: the child's axis).
//   fixed:               distance x,y,z + perpendicular (x,y),(y,z),(z,x)   6 equations
//   revolute:            distance x,y,z + perpendicular (z,x),(z,y)         5 (URDF revolute
//                        and continuous)
//   prismatic:           distance x,y   + perpendicular (x,y),(y,z),(z,x)   5
//   planar_translation:  distance z     + perpendicular (x,y),(y,z),(z,x)   4 (slides in the
//                        plane normal to z, does not rotate: the belt box)
//   spherical:           distance x,y,z                                      3
//   universal:           distance x,y,z + perpendicular (z,x)                4 (parent z, child x)
//   cylindrical:         distance x,y   + perpendicular (z,x),(z,y)         4 (turns and slides
//                        along z)
//   planar:              distance z     + perpendicular (z,x),(z,y)         3 (URDF planar: slides
//                        in the plane normal to z and turns about z)
//   free:                none                                                0 (URDF floating)
// Revolute and prismatic joints have a scalar coordinate (angle about z, slide along z) that
// limits, springs, dampers, efforts, friction and drives act on (core/joint_elements.hpp).
// Not here: the solve (core/constraint_solver.hpp), joint forces (core/joint_forces.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "core/joint_elements.hpp"

namespace tribo {

enum class JointType {
  kFixed,
  kRevolute,
  kPrismatic,
  kPlanarTranslation,
  kSpherical,
  kUniversal,
  kCylindrical,
  kPlanar,
  kFree
};

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
  // On the scalar coordinate of revolute and prismatic joints (empty for the others).
  JointElements elements;
  // Bit e set: equation e of jointEquations(type) was found redundant and is not solved
  // (ModelBuilder, with ConstraintOptions::redundant == kRemove).
  std::uint32_t dropped_equations = 0;
};

// One scalar constraint equation of a joint.
struct ConstraintEquation {
  enum class Kind { kDistance, kPerpendicular } kind;
  int parent_axis;  // i
  int child_axis;   // j (perpendicular only)
};

// The equations a joint type contributes, in a fixed order.
const std::vector<ConstraintEquation>& jointEquations(JointType type);

// Readable name of an equation for messages, e.g. "translation along y", "rotation z.x".
std::string equationName(const ConstraintEquation& e);

// True for the joints with one scalar coordinate (revolute: angle, prismatic: slide).
bool hasScalarCoordinate(JointType type);
// True when that coordinate is an angle [rad] (revolute), false for a length [m].
bool isAngular(JointType type);

// Scene names: "fixed", "revolute", "continuous" (= revolute), "prismatic",
// "planar_translation", "spherical", "universal", "cylindrical", "planar", "free".
// Throws std::invalid_argument listing the known names.
JointType jointTypeFromName(const std::string& name);
std::string jointTypeName(JointType type);

}  // namespace tribo
