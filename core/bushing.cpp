#include "core/bushing.hpp"

#include "core/rotation_log.hpp"

namespace tribo {

BushingDeflection bushingDeflection(const Bushing& bushing, const BodyKinematics& a,
                                    const BodyKinematics& b) {
  BushingDeflection out;
  const Quat qa = a.orientation * bushing.orientation_a;
  const Quat qb = b.orientation * bushing.orientation_b;
  out.frame_a = a.rotation * bushing.orientation_a.toRotationMatrix();
  const Vec3 origin_a = a.position + a.rotation * bushing.position_a;
  out.origin_b = b.position + b.rotation * bushing.position_b;
  const Mat3 to_a = out.frame_a.transpose();
  out.translation = to_a * (out.origin_b - origin_a);
  out.rotation = rotationLog(qa.conjugate() * qb);
  out.translation_rate = to_a * (b.pointVelocity(out.origin_b) - a.pointVelocity(out.origin_b));
  out.angular_rate = to_a * (b.angular_velocity - a.angular_velocity);
  return out;
}

PairWrench bushingWrench(const Bushing& bushing, const BushingDeflection& d) {
  const Vec3 force_a = bushing.stiffness.cwiseProduct(d.translation) +
                       bushing.damping.cwiseProduct(d.translation_rate);
  const Vec3 torque_a =
      inverseRightJacobian(d.rotation) * bushing.rotational_stiffness.cwiseProduct(d.rotation) +
      bushing.rotational_damping.cwiseProduct(d.angular_rate);
  return {-(d.frame_a * force_a), d.origin_b, -(d.frame_a * torque_a)};
}

double bushingEnergy(const Bushing& bushing, const BushingDeflection& d) {
  return 0.5 * (d.translation.dot(bushing.stiffness.cwiseProduct(d.translation)) +
                d.rotation.dot(bushing.rotational_stiffness.cwiseProduct(d.rotation)));
}

}  // namespace tribo
