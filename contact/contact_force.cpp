#include "contact/contact_force.hpp"

namespace tribo::contact {

namespace {

// Inlined into both entries: the memoryless one is the hot path of every scene.
[[gnu::always_inline]] inline void kinematicsAndNormal(const ContactPoint& cp,
                                                       const GeometryMotion& a,
                                                       const GeometryMotion& b,
                                                       const Material& material,
                                                       ContactRecord& out) {
  const Eigen::Vector3d& n = cp.normal;
  const Eigen::Vector3d v_rel = b.pointVelocity(cp.position) - a.pointVelocity(cp.position);
  const double vn = n.dot(v_rel);
  out.point = cp;
  out.depth_rate = -vn;
  const Eigen::Vector3d v_slide = v_rel + b.surface_velocity - a.surface_velocity;
  out.slip = v_slide - n.dot(v_slide) * n;
  out.normal_force = material.normal.force(cp.depth, out.depth_rate);
}

}  // namespace

void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, ContactRecord& out) {
  kinematicsAndNormal(cp, a, b, material, out);
  out.friction_force =
      friction::tangentialForce(*material.friction, out.slip, out.normal_force, &out.mu);
}

void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, const friction::StickView& view,
                     ContactRecord& out) {
  kinematicsAndNormal(cp, a, b, material, out);
  out.friction_force = material.friction->stickForce(out.slip, out.normal_force, view, &out.mu);
}

}  // namespace tribo::contact
