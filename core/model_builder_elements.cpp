// ModelBuilder: bushings, torsional springs and applied loads (core/bushing.hpp,
// core/torsional_spring.hpp, core/applied_load.hpp).
#include <cmath>
#include <sstream>

#include "core/model_builder.hpp"
#include "core/number_text.hpp"

namespace tribo {

namespace {

std::string vectorText(const Vec3& v) {
  std::ostringstream s;
  s << '[' << numberText(v.x()) << ", " << numberText(v.y()) << ", " << numberText(v.z()) << ']';
  return s.str();
}

// Per-axis gains: finite and >= 0.
void checkGains(const std::string& who, const char* what, const Vec3& gains) {
  if (!gains.allFinite() || gains.minCoeff() < 0.0)
    throw ModelError(who + ": " + what + " must be 3 finite values >= 0 (got " + vectorText(gains) +
                     ")");
}

void checkGain(const std::string& who, const char* what, double gain) {
  if (!std::isfinite(gain) || gain < 0.0)
    throw ModelError(who + ": " + what + " must be >= 0 (got " + numberText(gain) + ")");
}

Quat checkedOrientation(const std::string& who, const char* what, const Quat& q) {
  if (!q.coeffs().allFinite() || q.norm() < 1e-12)
    throw ModelError(who + ": " + what + " must be a finite, non-zero quaternion");
  return q.normalized();
}

}  // namespace

void ModelBuilder::addBushing(const Bushing& bushing) {
  const std::string who = "bushing '" + bushing.name + "'";
  checkedBody(bushing.body_a, who + " body A");
  checkedBody(bushing.body_b, who + " body B");
  if (bushing.body_a == bushing.body_b) throw ModelError(who + ": both frames on the same body");
  if (!bushing.position_a.allFinite() || !bushing.position_b.allFinite())
    throw ModelError(who + ": frame positions must be finite");
  checkGains(who, "stiffness", bushing.stiffness);
  checkGains(who, "damping", bushing.damping);
  checkGains(who, "rotational_stiffness", bushing.rotational_stiffness);
  checkGains(who, "rotational_damping", bushing.rotational_damping);
  Bushing b = bushing;
  b.orientation_a = checkedOrientation(who, "frame A orientation", bushing.orientation_a);
  b.orientation_b = checkedOrientation(who, "frame B orientation", bushing.orientation_b);
  model_.bushings.push_back(b);
}

void ModelBuilder::addTorsionalSpring(const std::string& name, BodyIndex a, BodyIndex b,
                                      const Vec3& axis_world, double stiffness, double damping,
                                      double rest_angle) {
  const std::string who = "torsional spring '" + name + "'";
  const Body ba = checkedBody(a, who + " body A");
  const Body bb = checkedBody(b, who + " body B");
  if (a == b) throw ModelError(who + ": both ends on the same body");
  if (!axis_world.allFinite() || axis_world.norm() < 1e-12)
    throw ModelError(who + ": axis must be a finite, non-zero vector (got " +
                     vectorText(axis_world) + ")");
  checkGain(who, "stiffness", stiffness);
  checkGain(who, "damping", damping);
  if (!std::isfinite(rest_angle))
    throw ModelError(who + ": rest angle must be finite (got " + numberText(rest_angle) + ")");
  const Vec3 axis = axis_world.normalized();
  const Vec3 reference = axis.unitOrthogonal();
  // The world's frame is the identity: ba.orientation is then the identity too.
  const Quat to_a = ba.orientation.conjugate(), to_b = bb.orientation.conjugate();
  TorsionalSpring s;
  s.name = name;
  s.body_a = a;
  s.body_b = b;
  s.axis_a = (to_a * axis).normalized();
  s.reference_a = (to_a * reference).normalized();
  s.reference_b = (to_b * reference).normalized();
  s.stiffness = stiffness;
  s.damping = damping;
  s.rest_angle = rest_angle;
  model_.torsional_springs.push_back(s);
}

void ModelBuilder::addLoad(const AppliedLoad& load) {
  const std::string who = "load '" + load.name + "'";
  const Body body = checkedBody(load.body, who);
  if (load.body.isWorld()) throw ModelError(who + ": cannot act on the world");
  if (body.kind != BodyKind::kDynamic)
    throw ModelError(who + ": body '" + body.name +
                     "' is kinematic (its motion is prescribed; a load needs a dynamic body)");
  if (!load.point.allFinite())
    throw ModelError(who + ": point must be finite (got " + vectorText(load.point) + ")");
  for (const AppliedLoad& other : model_.loads)
    if (other.name == load.name) throw ModelError(who + ": a load of that name already exists");
  model_.loads.push_back(load);
}

}  // namespace tribo
