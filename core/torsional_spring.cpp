#include "core/torsional_spring.hpp"

#include <cmath>

namespace tribo {

TorsionalDeflection torsionalDeflection(const TorsionalSpring& spring, const BodyKinematics& a,
                                        const BodyKinematics& b) {
  TorsionalDeflection out;
  const Vec3 axis = a.rotation * spring.axis_a;
  const Vec3 ua = a.rotation * spring.reference_a;
  const Vec3 va = axis.cross(ua);
  const Vec3 ub = b.rotation * spring.reference_b;
  const double x = ua.dot(ub), y = va.dot(ub);
  const double r2 = x * x + y * y;
  // u_B within 1e-8 rad of the axis: theta is undefined, no torque.
  if (r2 < 1e-16) return out;
  const double theta = std::atan2(y, x);
  out.angle = std::remainder(theta - spring.rest_angle, 2.0 * M_PI);
  out.gradient = ub.cross(x * va - y * ua) / r2;
  out.rate = (b.angular_velocity - a.angular_velocity).dot(out.gradient);
  return out;
}

Vec3 torsionalTorque(const TorsionalSpring& spring, const TorsionalDeflection& d) {
  return -(spring.stiffness * d.angle + spring.damping * d.rate) * d.gradient;
}

double torsionalEnergy(const TorsionalSpring& spring, const TorsionalDeflection& d) {
  return 0.5 * spring.stiffness * d.angle * d.angle;
}

}  // namespace tribo
