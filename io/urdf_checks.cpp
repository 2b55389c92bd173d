#include "io/urdf_checks.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "core/number_text.hpp"

namespace tribo::io {

void checkUrdfRobot(UrdfRobot& robot) {
  auto issue = [&](UrdfIssue::Severity sev, const std::string& link, const std::string& what) {
    robot.issues.push_back({sev, "link '" + link + "'", what});
  };
  using S = UrdfIssue::Severity;
  for (const UrdfLink& l : robot.links) {
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
