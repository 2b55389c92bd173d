#include "core/model_builder.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <set>
#include <sstream>

namespace tribo {

namespace {

std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool finite(const Vec3& v) { return v.allFinite(); }

// Orthonormal frame whose third column is `axis` (normalized).
Mat3 frameWithZ(const Vec3& axis) {
  const Vec3 z = axis.normalized();
  Vec3 helper = Vec3::UnitX();
  if (std::abs(z.x()) > 0.9) helper = Vec3::UnitY();
  const Vec3 x = (helper - helper.dot(z) * z).normalized();
  Mat3 r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return r;
}

}  // namespace

IntegratorType integratorFromName(const std::string& name) {
  if (name == "semi_implicit_euler") return IntegratorType::kSemiImplicitEuler;
  if (name == "rk4") return IntegratorType::kRk4;
  throw std::invalid_argument("unknown integrator '" + name +
                              "' (expected one of: semi_implicit_euler, rk4)");
}

std::string integratorName(IntegratorType type) {
  return type == IntegratorType::kRk4 ? "rk4" : "semi_implicit_euler";
}

std::optional<BodyIndex> Model::findBody(const std::string& name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return BodyIndex{static_cast<int>(i)};
  if (name == "world") return BodyIndex::world();
  return std::nullopt;
}

int Model::dynamicBodyCount() const {
  int n = 0;
  for (const auto& b : bodies) n += b.kind == BodyKind::kDynamic;
  return n;
}

BodyIndex ModelBuilder::addBody(const Body& body) {
  const std::string who = "body '" + body.name + "'";
  if (body.name.empty() || body.name == "world")
    throw ModelError("body name must be non-empty and not 'world' (got '" + body.name + "')");
  if (findBody(body.name)) throw ModelError(who + ": a body of that name already exists");
  if (body.kind == BodyKind::kDynamic) {
    if (!std::isfinite(body.mass) || body.mass <= 0.0)
      throw ModelError(who + ": mass must be > 0 (got " + str(body.mass) + ")");
    if (!body.inertia.allFinite() || (body.inertia - body.inertia.transpose()).norm() >
                                         1e-9 * body.inertia.norm())
      throw ModelError(who + ": inertia must be a finite symmetric matrix");
    Eigen::SelfAdjointEigenSolver<Mat3> eig(body.inertia);
    const Vec3 p = eig.eigenvalues();
    if (p.minCoeff() <= 0.0)
      throw ModelError(who + ": inertia must be positive definite (smallest principal moment " +
                       str(p.minCoeff()) + ")");
    if (p(0) + p(1) < p(2) * (1 - 1e-12))
      throw ModelError(who + ": principal moments violate the triangle inequality");
  }
  if (!finite(body.position) || !finite(body.velocity) || !finite(body.angular_velocity) ||
      !finite(body.surface_velocity) || !body.orientation.coeffs().allFinite() ||
      body.orientation.norm() < 1e-12)
    throw ModelError(who + ": initial pose and velocities must be finite");
  Body b = body;
  b.orientation.normalize();
  model_.bodies.push_back(b);
  return BodyIndex{static_cast<int>(model_.bodies.size()) - 1};
}

Body ModelBuilder::checkedBody(BodyIndex index, const std::string& what) const {
  if (index.isWorld()) return Body{"world", BodyKind::kKinematic};
  if (index.value < 0 || index.value >= static_cast<int>(model_.bodies.size()))
    throw ModelError(what + ": body index " + std::to_string(index.value) + " out of range");
  return model_.bodies[index.value];
}

int ModelBuilder::addGeometry(const std::string& name, BodyIndex body,
                              const contact::Shape& shape, const Eigen::Isometry3d& local_pose) {
  const std::string who = "geometry '" + name + "'";
  checkedBody(body, who);
  if (findGeometry(name)) throw ModelError(who + ": a geometry of that name already exists");
  if (shape.type == contact::ShapeType::kBox &&
      (!shape.half_extents.allFinite() || shape.half_extents.minCoeff() <= 0.0))
    throw ModelError(who + ": box half extents must be > 0");
  model_.geometries.push_back({name, body, shape, local_pose});
  return static_cast<int>(model_.geometries.size()) - 1;
}

int ModelBuilder::addMaterial(const contact::Material& material) {
  if (!material.friction) throw ModelError("contact material without a friction law");
  try {
    material.normal.validate();
  } catch (const std::invalid_argument& e) {
    throw ModelError(std::string("contact material: ") + e.what());
  }
  model_.materials.push_back(material);
  return static_cast<int>(model_.materials.size()) - 1;
}

void ModelBuilder::addContactPair(int a, int b, int material) {
  const int ng = static_cast<int>(model_.geometries.size());
  if (a < 0 || b < 0 || a >= ng || b >= ng)
    throw ModelError("contact pair: geometry index out of range");
  const auto& ga = model_.geometries[a];
  const auto& gb = model_.geometries[b];
  const std::string who = "contact pair (" + ga.name + ", " + gb.name + ")";
  if (material < 0 || material >= static_cast<int>(model_.materials.size()))
    throw ModelError(who + ": material index out of range");
  if (ga.body == gb.body) throw ModelError(who + ": both geometries are on the same body");
  auto dynamic = [&](BodyIndex i) {
    return !i.isWorld() && model_.bodies[i.value].kind == BodyKind::kDynamic;
  };
  if (!dynamic(ga.body) && !dynamic(gb.body))
    throw ModelError(who + ": at least one geometry must be on a dynamic body");
  if (ga.shape.type == contact::ShapeType::kHalfSpace &&
      gb.shape.type == contact::ShapeType::kHalfSpace)
    throw ModelError(who + ": two half-spaces cannot touch");
  model_.contact_pairs.push_back({a, b, material});
}

void ModelBuilder::addJoint(const std::string& name, JointType type, BodyIndex parent,
                            BodyIndex child, const Vec3& anchor_world, const Vec3& axis_world) {
  const std::string who = "joint '" + name + "'";
  const Body p = checkedBody(parent, who + " parent");
  const Body c = checkedBody(child, who + " child");
  if (child.isWorld() || c.kind != BodyKind::kDynamic)
    throw ModelError(who + ": the child must be a dynamic body");
  if (parent == child) throw ModelError(who + ": parent and child are the same body");
  if (!finite(anchor_world) || !finite(axis_world) || axis_world.norm() < 1e-12)
    throw ModelError(who + ": anchor must be finite and axis non-zero");
  const Mat3 axes_world = frameWithZ(axis_world);
  Joint j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  const Mat3 rp = p.orientation.toRotationMatrix();
  const Mat3 rc = c.orientation.toRotationMatrix();
  j.anchor_in_parent = rp.transpose() * (anchor_world - p.position);
  j.axes_in_parent = rp.transpose() * axes_world;
  j.anchor_in_child = rc.transpose() * (anchor_world - c.position);
  j.axes_in_child = rc.transpose() * axes_world;
  model_.joints.push_back(j);
}

void ModelBuilder::addSpring(const std::string& name, BodyIndex a, const Vec3& pa, BodyIndex b,
                             const Vec3& pb, double k, double c, double rest_length) {
  const std::string who = "spring '" + name + "'";
  const Body ba = checkedBody(a, who + " body A");
  const Body bb = checkedBody(b, who + " body B");
  if (a == b) throw ModelError(who + ": both ends on the same body");
  if (!std::isfinite(k) || k < 0.0)
    throw ModelError(who + ": stiffness must be >= 0 (got " + str(k) + ")");
  if (!std::isfinite(c) || c < 0.0)
    throw ModelError(who + ": damping must be >= 0 (got " + str(c) + ")");
  if (!finite(pa) || !finite(pb)) throw ModelError(who + ": attachment points must be finite");
  SpringDamper s;
  s.name = name;
  s.body_a = a;
  s.body_b = b;
  s.point_a = ba.orientation.conjugate() * (pa - ba.position);
  s.point_b = bb.orientation.conjugate() * (pb - bb.position);
  s.stiffness = k;
  s.damping = c;
  s.rest_length = rest_length < 0.0 ? (pb - pa).norm() : rest_length;
  model_.springs.push_back(s);
}

std::optional<BodyIndex> ModelBuilder::findBody(const std::string& name) const {
  return model_.findBody(name);
}

std::optional<int> ModelBuilder::findGeometry(const std::string& name) const {
  for (std::size_t i = 0; i < model_.geometries.size(); ++i)
    if (model_.geometries[i].name == name) return static_cast<int>(i);
  return std::nullopt;
}

std::shared_ptr<const Model> ModelBuilder::build() const {
  const auto& o = options_;
  if (!std::isfinite(o.time_step) || o.time_step <= 0.0)
    throw ModelError("options: time step must be > 0 (got " + str(o.time_step) + ")");
  if (!std::isfinite(o.duration) || o.duration <= 0.0)
    throw ModelError("options: duration must be > 0 (got " + str(o.duration) + ")");
  if (!finite(o.gravity)) throw ModelError("options: gravity must be finite");
  if (!(o.baumgarte_alpha >= 0.0) || !(o.baumgarte_beta >= 0.0))
    throw ModelError("options: Baumgarte alpha and beta must be >= 0");
  if (model_.dynamicBodyCount() == 0) throw ModelError("the model has no dynamic body");
  auto model = std::make_shared<Model>(model_);
  model->options = options_;
  return model;
}

}  // namespace tribo
