#include "contact/anisotropy.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tribo::contact {

namespace {

// The ratio along axis i for a component c (of the frame geometry's motion) of that sense.
double ratio(const Anisotropy& an, int i, double c) {
  return c >= 0.0 ? an.forward[static_cast<std::size_t>(i)]
                  : an.backward[static_cast<std::size_t>(i)];
}

std::string numberText(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

}  // namespace

void Anisotropy::validate() {
  const char* names[2] = {"along the axis", "across the axis"};
  for (int i = 0; i < 2; ++i) {
    for (const auto& [which, value] :
         {std::pair{"forward", forward[static_cast<std::size_t>(i)]},
          std::pair{"backward", backward[static_cast<std::size_t>(i)]}}) {
      if (!(std::isfinite(value) && value > 0.0))
        throw std::invalid_argument(std::string("anisotropy: the ") + which + " ratio " + names[i] +
                                    " must be finite and > 0 (got " + numberText(value) + ")");
    }
  }
  const double length = axis.norm();
  if (!std::isfinite(length) || length == 0.0)
    throw std::invalid_argument("anisotropy: axis must be a finite, non-zero direction (got [" +
                                numberText(axis.x()) + ", " + numberText(axis.y()) + ", " +
                                numberText(axis.z()) + "])");
  axis /= length;
}

SlipAxes slipAxes(const Anisotropy& an, const Eigen::Matrix3d& frame_rotation,
                  const Eigen::Vector3d& n) {
  SlipAxes axes;
  axes.sense = an.frame_is_b ? 1.0 : -1.0;
  const Eigen::Vector3d a = frame_rotation * an.axis;
  Eigen::Vector3d t = a - n.dot(a) * n;
  if (t.norm() < 1e-9) {  // the axis along the normal: the frame's next axis instead
    Eigen::Index k = 0;
    an.axis.cwiseAbs().minCoeff(&k);
    const Eigen::Vector3d b = frame_rotation.col(k);
    t = b - n.dot(b) * n;
  }
  axes.t1 = t.normalized();
  axes.t2 = n.cross(axes.t1);
  return axes;
}

Eigen::Vector3d toLawPlane(const Anisotropy& an, const SlipAxes& axes, const Eigen::Vector3d& v) {
  const double c1 = axes.t1.dot(v), c2 = axes.t2.dot(v);
  return ratio(an, 0, axes.sense * c1) * c1 * axes.t1 +
         ratio(an, 1, axes.sense * c2) * c2 * axes.t2;
}

Eigen::Vector3d fromLawPlane(const Anisotropy& an, const SlipAxes& axes, const Eigen::Vector3d& v) {
  const double c1 = axes.t1.dot(v), c2 = axes.t2.dot(v);
  return c1 / ratio(an, 0, axes.sense * c1) * axes.t1 +
         c2 / ratio(an, 1, axes.sense * c2) * axes.t2;
}

Eigen::Vector3d forceFromLawPlane(const Anisotropy& an, const SlipAxes& axes,
                                  const Eigen::Vector3d& f) {
  const double c1 = axes.t1.dot(f), c2 = axes.t2.dot(f);
  return ratio(an, 0, -axes.sense * c1) * c1 * axes.t1 +
         ratio(an, 1, -axes.sense * c2) * c2 * axes.t2;
}

Eigen::Vector3d enterLawPlane(const Anisotropy& an, const SlipAxes& axes, ContactRecord& out) {
  const Eigen::Vector3d slip = out.slip;
  out.slip = toLawPlane(an, axes, slip);
  return slip;
}

void leaveLawPlane(const Anisotropy& an, const SlipAxes& axes, const Eigen::Vector3d& slip,
                   ContactRecord& out) {
  out.friction_force = forceFromLawPlane(an, axes, out.friction_force);
  out.slip = slip;
  if (out.normal_force > 0.0) out.mu = out.friction_force.norm() / out.normal_force;
}

}  // namespace tribo::contact
