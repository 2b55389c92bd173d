#include "core/joint.hpp"

#include <stdexcept>

#include "friction/name_table.hpp"

namespace tribo {

namespace {
using K = ConstraintEquation::Kind;
const ConstraintEquation kDx{K::kDistance, 0, 0}, kDy{K::kDistance, 1, 0}, kDz{K::kDistance, 2, 0};
const ConstraintEquation kPxy{K::kPerpendicular, 0, 1}, kPyz{K::kPerpendicular, 1, 2},
    kPzx{K::kPerpendicular, 2, 0}, kPzy{K::kPerpendicular, 2, 1};

// "continuous" is a revolute joint without limits (URDF's word); the first name is the name.
constexpr NameTable<JointType, 10> kNames{"joint type",
                                          {{{JointType::kFixed, "fixed"},
                                            {JointType::kRevolute, "revolute"},
                                            {JointType::kRevolute, "continuous"},
                                            {JointType::kPrismatic, "prismatic"},
                                            {JointType::kPlanarTranslation, "planar_translation"},
                                            {JointType::kSpherical, "spherical"},
                                            {JointType::kUniversal, "universal"},
                                            {JointType::kCylindrical, "cylindrical"},
                                            {JointType::kPlanar, "planar"},
                                            {JointType::kFree, "free"}}}};
}  // namespace

const std::vector<ConstraintEquation>& jointEquations(JointType type) {
  static const std::vector<ConstraintEquation> fixed{kDx, kDy, kDz, kPxy, kPyz, kPzx};
  static const std::vector<ConstraintEquation> revolute{kDx, kDy, kDz, kPzx, kPzy};
  static const std::vector<ConstraintEquation> prismatic{kDx, kDy, kPxy, kPyz, kPzx};
  static const std::vector<ConstraintEquation> planar_translation{kDz, kPxy, kPyz, kPzx};
  static const std::vector<ConstraintEquation> spherical{kDx, kDy, kDz};
  static const std::vector<ConstraintEquation> universal{kDx, kDy, kDz, kPzx};
  static const std::vector<ConstraintEquation> cylindrical{kDx, kDy, kPzx, kPzy};
  static const std::vector<ConstraintEquation> planar{kDz, kPzx, kPzy};
  static const std::vector<ConstraintEquation> none{};
  switch (type) {
    case JointType::kFixed:
      return fixed;
    case JointType::kRevolute:
      return revolute;
    case JointType::kPrismatic:
      return prismatic;
    case JointType::kPlanarTranslation:
      return planar_translation;
    case JointType::kSpherical:
      return spherical;
    case JointType::kUniversal:
      return universal;
    case JointType::kCylindrical:
      return cylindrical;
    case JointType::kPlanar:
      return planar;
    case JointType::kFree:
      return none;
  }
  return none;
}

std::string equationName(const ConstraintEquation& e) {
  static const char* kAxis[] = {"x", "y", "z"};
  if (e.kind == ConstraintEquation::Kind::kDistance)
    return std::string("translation along ") + kAxis[e.parent_axis];
  return std::string("rotation (parent ") + kAxis[e.parent_axis] + " normal to child " +
         kAxis[e.child_axis] + ")";
}

bool hasScalarCoordinate(JointType type) {
  return type == JointType::kRevolute || type == JointType::kPrismatic;
}

bool isAngular(JointType type) { return type == JointType::kRevolute; }

JointType jointTypeFromName(const std::string& name) { return kNames.fromName(name); }

std::string jointTypeName(JointType type) { return kNames.name(type); }

}  // namespace tribo
