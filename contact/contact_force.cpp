#include "contact/contact_force.hpp"

namespace tribo::contact {

void frictionForce(const Material& material, ContactRecord& out) {
  out.friction_force =
      friction::tangentialForce(*material.friction, out.slip, out.normal_force, &out.mu);
}

void frictionForce(const Material& material, const friction::StickView& view, ContactRecord& out) {
  out.friction_force = material.friction->stickForce(out.slip, out.normal_force, view, &out.mu);
}

void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, ContactRecord& out) {
  contactKinematics(cp, a, b, out);
  normalForce(material, out);
  frictionForce(material, out);
}

void evaluateContact(const ContactPoint& cp, const GeometryMotion& a, const GeometryMotion& b,
                     const Material& material, const friction::StickView& view,
                     ContactRecord& out) {
  contactKinematics(cp, a, b, out);
  normalForce(material, out);
  frictionForce(material, view, out);
}

}  // namespace tribo::contact
