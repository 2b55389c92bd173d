#include "io/urdf_checks.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "contact/shape.hpp"
#include "core/number_text.hpp"

namespace tribo::io {

namespace {

// A collision's dimension or origin past contact::kMaxLength, said as the URDF names it.
std::string overLimit(const UrdfCollision& c) {
  using K = UrdfCollision::Kind;
  std::string e;
  if (c.kind == K::kBox)
    e = contact::overLengthLimit("collision <box size> (an edge length)", c.size.maxCoeff());
  if (c.kind != K::kBox && c.kind != K::kMesh && e.empty())
    e = contact::overLengthLimit("collision radius", c.radius);
  if ((c.kind == K::kCylinder || c.kind == K::kCapsule) && e.empty())
    e = contact::overLengthLimit("collision length", c.length);
  if (e.empty()) e = contact::outsideLengthLimit("collision <origin xyz>", c.origin.translation());
  return e;
}

}  // namespace

void checkUrdfRobot(UrdfRobot& robot) {
  auto issue = [&](UrdfIssue::Severity sev, const std::string& link, const std::string& what) {
    robot.issues.push_back({sev, "link '" + link + "'", what});
  };
  using S = UrdfIssue::Severity;
  for (const UrdfJoint& j : robot.joints)
    if (const std::string e = contact::outsideLengthLimit("<origin xyz>", j.origin.translation());
        !e.empty())
      robot.issues.push_back({S::kError, "joint '" + j.name + "'", e});
  for (const UrdfLink& l : robot.links) {
    if (const std::string e =
            contact::outsideLengthLimit("<inertial><origin xyz>", l.inertial_origin.translation());
        !e.empty())
      issue(S::kError, l.name, e);
    for (const UrdfCollision& c : l.collisions) {
      auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
      using K = UrdfCollision::Kind;
      if (c.kind == K::kSphere && c.radius == 0.0) {
        issue(S::kNote, l.name,
              "collision sphere of radius 0 at (" + numberText(c.origin.translation().x()) + ", " +
                  numberText(c.origin.translation().y()) + ", " +
                  numberText(c.origin.translation().z()) + "): a contact point");
      } else if (c.kind == K::kBox && !(c.size.allFinite() && c.size.minCoeff() > 0.0)) {
        issue(S::kError, l.name, "collision box size must be > 0");
      } else if (c.kind != K::kBox && c.kind != K::kMesh && !positive(c.radius)) {
        issue(S::kError, l.name,
              "collision radius must be > 0 (got " + numberText(c.radius) +
                  (c.kind == K::kSphere ? "; 0 makes a contact point)" : ")"));
      } else if ((c.kind == K::kCylinder || c.kind == K::kCapsule) && !positive(c.length)) {
        issue(S::kError, l.name, "collision length must be > 0 (got " + numberText(c.length) + ")");
      } else if (const std::string e = overLimit(c); !e.empty()) {
        issue(S::kError, l.name, e);
      }
    }
    if (!l.has_inertial) {
      if (!l.collisions.empty())
        issue(S::kWarning, l.name, "has collision geometry but no <inertial>: it is massless");
      continue;
    }
    if (!std::isfinite(l.mass) || l.mass < 0.0) {
      issue(S::kError, l.name, "mass must be >= 0 (got " + numberText(l.mass) + ")");
      continue;
    }
    if (l.mass == 0.0) {
      issue(S::kWarning, l.name, "has zero mass");
      continue;
    }
    const Eigen::Matrix3d& i = l.inertia;
    if (!i.allFinite()) {
      issue(S::kError, l.name, "inertia is not finite");
      continue;
    }
    if (i.isZero(0.0)) continue;  // given its geometry's inertia, noted by io/urdf_model.hpp
    const Eigen::Vector3d p = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(i).eigenvalues();
    if (p.minCoeff() <= 0.0) {
      issue(S::kWarning, l.name,
            "inertia is not positive definite (principal moments " + numberText(p(0)) + ", " +
                numberText(p(1)) + ", " + numberText(p(2)) + ")");
    } else if (p(0) + p(1) < p(2) * (1.0 - 1e-9)) {
      issue(S::kWarning, l.name,
            "principal moments " + numberText(p(0)) + ", " + numberText(p(1)) + ", " +
                numberText(p(2)) + " violate the triangle inequality");
    }
  }
}

}  // namespace tribo::io
