#include "contact/contact_force.hpp"

namespace tribo::contact {

void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, ContactRecord& out) {
  const Eigen::Vector3d& n = cp.normal;
  const Eigen::Vector3d v_rel = b.pointVelocity(cp.position) - a.pointVelocity(cp.position);
  const double vn = n.dot(v_rel);
  out.point = cp;
  out.depth_rate = -vn;
  const Eigen::Vector3d v_slide = v_rel + b.surface_velocity - a.surface_velocity;
  out.slip = v_slide - n.dot(v_slide) * n;
  out.normal_force = material.normal.force(cp.depth, out.depth_rate);
  out.friction_force =
      friction::tangentialForce(*material.friction, out.slip, out.normal_force, &out.mu);
}

}  // namespace tribo::contact
