#include "core/model_builder.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "core/constraint_rows.hpp"
#include "core/number_text.hpp"
#include "core/prescribed_motion.hpp"

namespace tribo {

namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace

std::optional<int> Model::findActuator(const std::string& name) const {
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].elements.actuator && joints[j].elements.actuator->name == name)
      return static_cast<int>(j);
  return std::nullopt;
}

std::optional<std::size_t> Model::findLoad(const std::string& name) const {
  for (std::size_t i = 0; i < loads.size(); ++i)
    if (loads[i].name == name) return i;
  return std::nullopt;
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
      throw ModelError(who + ": mass must be > 0 (got " + numberText(body.mass) + ")");
    if (!body.inertia.allFinite() ||
        (body.inertia - body.inertia.transpose()).norm() > 1e-9 * body.inertia.norm())
      throw ModelError(who + ": inertia must be a finite symmetric matrix");
    Eigen::SelfAdjointEigenSolver<Mat3> eig(body.inertia);
    const Vec3 p = eig.eigenvalues();
    if (p.minCoeff() <= 0.0)
      throw ModelError(who + ": inertia must be positive definite (smallest principal moment " +
                       numberText(p.minCoeff()) + ")");
    if (p(0) + p(1) < p(2) * (1 - 1e-12))
      throw ModelError(who + ": principal moments violate the triangle inequality");
  }
  if (!finite(body.position) || !finite(body.velocity) || !finite(body.angular_velocity) ||
      !finite(body.surface_velocity) || !body.orientation.coeffs().allFinite() ||
      body.orientation.norm() < 1e-12)
    throw ModelError(who + ": initial pose and velocities must be finite");
  if (auto e = contact::outsideLengthLimit("position", body.position); !e.empty())
    throw ModelError(who + ": " + e);
  Body b = body;
  b.orientation.normalize();
  if (b.motion) {  // core/prescribed_motion.hpp
    if (b.kind != BodyKind::kKinematic)
      throw ModelError(who +
                       ": a velocity along signals is for kinematic bodies (a dynamic "
                       "body's velocity is an initial value; apply a load to drive it)");
    const Vec3& e = b.motion->spin_axis;
    if (!finite(e) || std::abs(e.norm() - 1.0) > 1e-12)
      throw ModelError(who + ": the turning axis must be a unit vector (got " +
                       numberText(e.norm()) + " long)");
    const BodyState at0 = b.motion->at(b, 0.0);  // the values at t = 0 the body reports
    b.velocity = at0.velocity;
    b.angular_velocity = at0.angular_velocity;
  }
  body_index_.emplace(b.name, static_cast<int>(model_.bodies.size()));
  model_.bodies.push_back(std::move(b));
  return BodyIndex{static_cast<int>(model_.bodies.size()) - 1};
}

Body ModelBuilder::checkedBody(BodyIndex index, const std::string& what) const {
  if (index.isWorld()) return Body{"world", BodyKind::kKinematic};
  if (index.value < 0 || index.value >= static_cast<int>(model_.bodies.size()))
    throw ModelError(what + ": body index " + std::to_string(index.value) + " out of range");
  return model_.bodies[index.value];
}

int ModelBuilder::addGeometry(const std::string& name, BodyIndex body, const contact::Shape& shape,
                              const Eigen::Isometry3d& local_pose) {
  const std::string who = "geometry '" + name + "'";
  // The index alone (checkedBody would copy the body: a pattern adds thousands of geometries).
  if (!body.isWorld() && (body.value < 0 || body.value >= static_cast<int>(model_.bodies.size())))
    throw ModelError(who + ": body index " + std::to_string(body.value) + " out of range");
  if (findGeometry(name)) throw ModelError(who + ": a geometry of that name already exists");
  checkGeometry(name, shape, local_pose);
  Geometry geometry;
  geometry.name = name;
  geometry.body = body;
  geometry.shape = shape;
  geometry.local_pose = local_pose;
  model_.geometries.push_back(std::move(geometry));
  geometry_index_.emplace(name, static_cast<int>(model_.geometries.size()) - 1);
  return static_cast<int>(model_.geometries.size()) - 1;
}

void ModelBuilder::checkGeometry(const std::string& name, const contact::Shape& shape,
                                 const Eigen::Isometry3d& local_pose) {
  const std::string who = "geometry '" + name + "'";
  if (shape.type == contact::ShapeType::kBox &&
      (!shape.half_extents.allFinite() || shape.half_extents.minCoeff() <= 0.0))
    throw ModelError(who + ": box half extents must be > 0");
  try {
    shape.validate();
  } catch (const std::invalid_argument& e) {
    throw ModelError(who + ": " + e.what());
  }
  if (!local_pose.matrix().allFinite())
    throw ModelError(who + ": position and orientation must be finite");
  if (auto e = contact::outsideLengthLimit("position", local_pose.translation()); !e.empty())
    throw ModelError(who + ": " + e);
}

int ModelBuilder::addMaterial(const contact::Material& material) {
  if (!material.friction) throw ModelError("contact material without a friction law");
  contact::Material checked = material;
  try {
    checked.normal.validate();
    if (checked.anisotropy.active) checked.anisotropy.validate();  // normalises the axis
  } catch (const std::invalid_argument& e) {
    throw ModelError(std::string("contact material: ") + e.what());
  }
  model_.materials.push_back(std::move(checked));
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
  if (const contact::Anisotropy& an = model_.materials[material].anisotropy; an.active) {
    const auto& frame = an.frame_is_b ? gb : ga;
    if (frame.shape.type == contact::ShapeType::kSphere)
      throw ModelError(who + ": the material's anisotropy is fixed in the frame of sphere '" +
                       frame.name +
                       "', whose surface has no direction of its own; fix it in the other "
                       "geometry (anisotropy.frame: " +
                       (an.frame_is_b ? "a" : "b") + ")");
  }
  model_.contact_pairs.push_back({a, b, material});
}

void ModelBuilder::setGeometrySurface(int geometry, const std::string& surface) {
  if (geometry < 0 || geometry >= static_cast<int>(model_.geometries.size()))
    throw ModelError("geometry surface: geometry index out of range");
  model_.geometries[geometry].surface = surface;
}

void ModelBuilder::setCollisionFilter(int geometry, std::uint32_t group, std::uint32_t mask) {
  if (geometry < 0 || geometry >= static_cast<int>(model_.geometries.size()))
    throw ModelError("collision filter: geometry index out of range");
  model_.geometries[geometry].collision_group = group;
  model_.geometries[geometry].collision_mask = mask;
}

void ModelBuilder::addSurfacePairMaterial(const std::string& surface_a,
                                          const std::string& surface_b, int material) {
  const std::string who = "surface pair (" + surface_a + ", " + surface_b + ")";
  if (material < 0 || material >= static_cast<int>(model_.materials.size()))
    throw ModelError(who + ": material index out of range");
  // Keyed by the two names in order, each prefixed by its length (names may hold any byte).
  const auto& [first, second] = std::minmax(surface_a, surface_b);
  if (!surface_pairs_.insert(std::to_string(first.size()) + ":" + first + second).second)
    throw ModelError(who + ": a material for this surface pair is already given");
  surface_materials_.push_back({surface_a, surface_b, material});
}

void ModelBuilder::setDefaultMaterial(int material) {
  if (material < 0 || material >= static_cast<int>(model_.materials.size()))
    throw ModelError("default material: material index out of range");
  default_material_ = material;
}

void ModelBuilder::addAutomaticContacts(Model& model) const {
  const int n = static_cast<int>(model.geometries.size());
  if (n > kMaxAutomaticGeometries)
    throw ModelError("automatic contacts: " + std::to_string(n) + " geometries, more than the " +
                     std::to_string(kMaxAutomaticGeometries) +
                     " they take: list the contacts instead");
  AutomaticContacts& rule = model.automatic;
  rule.geometry_count = n;
  rule.joined_bodies_collide = model.options.collision.joined_bodies_collide;
  std::unordered_map<std::string, int> surfaces;  // name -> index, in order of first use
  for (const Geometry& g : model.geometries) {
    const auto it = surfaces.try_emplace(g.surface, static_cast<int>(surfaces.size())).first;
    rule.surface.push_back(it->second);
    rule.dynamic.push_back(!g.body.isWorld() &&
                           model.bodies[g.body.value].kind == BodyKind::kDynamic);
    rule.plane.push_back(g.shape.type == contact::ShapeType::kHalfSpace);
    rule.body.push_back(g.body);
    rule.group.push_back(g.collision_group);
    rule.mask.push_back(g.collision_mask);
  }
  rule.surface_count = static_cast<int>(surfaces.size());
  rule.default_material = default_material_;
  for (const auto& e : surface_materials_) {
    const auto a = surfaces.find(e.surface_a);
    const auto b = surfaces.find(e.surface_b);
    if (a == surfaces.end() || b == surfaces.end()) continue;
    rule.pair_material.emplace_back(surfacePairKey(a->second, b->second), e.material);
  }
  std::sort(rule.pair_material.begin(), rule.pair_material.end());
  if (!rule.joined_bodies_collide)
    for (const Joint& j : model.joints) rule.joined.push_back(bodyPairKey(j.parent, j.child));
  std::sort(rule.joined.begin(), rule.joined.end());
  rule.joined.erase(std::unique(rule.joined.begin(), rule.joined.end()), rule.joined.end());
  if (default_material_ >= 0) return;
  // A missing surface-pair material is an error before the run, found over classes of
  // geometries (surface, filter, kind) with up to two bodies each: linear in geometries.
  struct Class {
    int first = -1, other = -1;  // geometries on two different bodies, when there are
  };
  std::map<std::tuple<int, std::uint32_t, std::uint32_t, bool, bool>, Class> classes;
  for (int g = 0; g < n; ++g) {
    const Geometry& geo = model.geometries[static_cast<std::size_t>(g)];
    Class& c = classes[{rule.surface[g], geo.collision_group, geo.collision_mask,
                        rule.dynamic[g] != 0, rule.plane[g] != 0}];
    if (c.first < 0)
      c.first = g;
    else if (c.other < 0 && model.geometries[static_cast<std::size_t>(c.first)].body != geo.body)
      c.other = g;
  }
  for (auto x = classes.begin(); x != classes.end(); ++x)
    for (auto y = x; y != classes.end(); ++y) {
      const int g = x->second.first;
      const int h = x == y ? x->second.other : y->second.first;
      if (h < 0) continue;
      int pair = automaticPairId(model, g, h);
      if (pair < 0 && x != y && y->second.other >= 0)  // the first two share a body
        pair = automaticPairId(model, g, y->second.other);
      if (pair < 0) continue;
      if (automaticPair(model, pair).material >= 0) continue;
      const Geometry& a = model.geometries[static_cast<std::size_t>(pair / n)];
      const Geometry& b = model.geometries[static_cast<std::size_t>(pair % n)];
      throw ModelError("automatic contact (" + a.name + ", " + b.name +
                       "): no material for surfaces ('" + a.surface + "', '" + b.surface +
                       "'): give a default material or one for this surface pair");
    }
}

void ModelBuilder::addSpring(const std::string& name, BodyIndex a, const Vec3& pa, BodyIndex b,
                             const Vec3& pb, double k, double c, double rest_length) {
  const std::string who = "spring '" + name + "'";
  const Body ba = checkedBody(a, who + " body A");
  const Body bb = checkedBody(b, who + " body B");
  if (a == b) throw ModelError(who + ": both ends on the same body");
  if (!std::isfinite(k) || k < 0.0)
    throw ModelError(who + ": stiffness must be >= 0 (got " + numberText(k) + ")");
  if (!std::isfinite(c) || c < 0.0)
    throw ModelError(who + ": damping must be >= 0 (got " + numberText(c) + ")");
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
  if (const auto it = body_index_.find(name); it != body_index_.end()) return BodyIndex{it->second};
  if (name == "world") return BodyIndex::world();
  return std::nullopt;
}

std::optional<int> ModelBuilder::findGeometry(const std::string& name) const {
  if (const auto it = geometry_index_.find(name); it != geometry_index_.end()) return it->second;
  return std::nullopt;
}

void ModelBuilder::reserve(std::size_t bodies, std::size_t geometries) {
  model_.bodies.reserve(model_.bodies.size() + bodies);
  model_.geometries.reserve(model_.geometries.size() + geometries);
  body_index_.reserve(body_index_.size() + bodies);
  geometry_index_.reserve(geometry_index_.size() + geometries);
}

std::shared_ptr<const Model> ModelBuilder::build() const& {
  checkOptions();
  return finish(std::make_shared<Model>(model_));
}

std::shared_ptr<const Model> ModelBuilder::build() && {
  checkOptions();
  return finish(std::make_shared<Model>(std::move(model_)));
}

void ModelBuilder::checkOptions() const {
  const auto& o = options_;
  if (!std::isfinite(o.time_step) || o.time_step <= 0.0)
    throw ModelError("options: time step must be > 0 (got " + numberText(o.time_step) + ")");
  if (!std::isfinite(o.duration) || o.duration <= 0.0)
    throw ModelError("options: duration must be > 0 (got " + numberText(o.duration) + ")");
  // One step longer than the whole run would simulate nothing (or overshoot the duration).
  if (o.time_step > o.duration)
    throw ModelError("options: time_step (" + numberText(o.time_step) +
                     " s) is larger than the duration (" + numberText(o.duration) + " s)");
  if (o.duration / o.time_step > kMaxSteps)
    throw ModelError("options: duration / time_step = " + numberText(o.duration / o.time_step) +
                     " steps, more than the " + numberText(kMaxSteps) +
                     " a run may take (duration " + numberText(o.duration) + " s, time_step " +
                     numberText(o.time_step) + " s)");
  if (!finite(o.gravity)) throw ModelError("options: gravity must be finite");
  if (!(o.baumgarte_alpha >= 0.0) || !(o.baumgarte_beta >= 0.0))
    throw ModelError("options: Baumgarte alpha and beta must be >= 0");
  if (!(o.constraints.drift_warning > 0.0) || !(o.constraints.drift_stop > 0.0))
    throw ModelError("options: constraint drift_warning and drift_stop must be > 0 (got " +
                     numberText(o.constraints.drift_warning) + ", " +
                     numberText(o.constraints.drift_stop) + ")");
  if (!std::isfinite(o.relative_tolerance) || o.relative_tolerance <= 0.0 ||
      o.relative_tolerance >= 1.0)
    throw ModelError("options: relative tolerance must be in (0, 1) (got " +
                     numberText(o.relative_tolerance) + ")");
  if (!std::isfinite(o.absolute_tolerance) || o.absolute_tolerance <= 0.0)
    throw ModelError("options: absolute tolerance must be > 0 (got " +
                     numberText(o.absolute_tolerance) + ")");
  if (!std::isfinite(o.max_internal_step) || o.max_internal_step < 0.0)
    throw ModelError("options: max internal step must be >= 0, 0 for no limit (got " +
                     numberText(o.max_internal_step) + ")");
}

std::shared_ptr<const Model> ModelBuilder::finish(std::shared_ptr<Model> model) const {
  const auto& o = options_;
  model->options = options_;
  finishJoints(*model);
  // A velocity drive along a function signal sums its integral panel by panel as the run
  // goes: room for the whole run now, so that warm steps do not allocate.
  for (const Joint& j : model->joints)
    if (j.elements.drive && j.elements.drive->signal)
      j.elements.drive->signal->reserveIntegral(o.duration);
  // Kinematic bodies along signals: their integrals likewise; a joint to one is refused, as
  // the constraint rows carry only dynamic bodies' accelerations (core/prescribed_motion.hpp).
  for (const Body& b : model->bodies)
    if (b.motion) b.motion->reserveIntegrals(o.duration);
  for (const Joint& j : model->joints)
    for (BodyIndex end : {j.parent, j.child})
      if (!end.isWorld() && model->bodies[end.value].motion)
        throw ModelError("joint '" + j.name + "': body '" + model->bodies[end.value].name +
                         "' moves along signals, and a joint cannot follow its acceleration; "
                         "attach with a spring or bushing, or make it a dynamic body on a "
                         "driven joint");
  model->constraint_equations = static_cast<int>(constraintRows(*model).size());
  if (model->contact_pairs.empty() && (default_material_ >= 0 || !surface_materials_.empty())) {
    addAutomaticContacts(*model);
    model->automatic_contacts = true;
    model->options.collision.broadphase = true;
  }
  return model;
}

}  // namespace tribo
