// Scene format (see scenes/belt.yaml for a commented example). Keys in [] are optional;
// defaults are those of the structs they fill (core/model.hpp, core/body.hpp, ...).
//   [parameters]: {NAME: number or string}                 "$NAME" below is replaced
//   [simulation]: [duration] [time_step] [integrator: rk4|semi_implicit_euler|dopri5|bdf]
//                 [gravity] [baumgarte: {[alpha], [beta]}]
//                 [rtol] [atol] [max_step] [event_location]   (dopri5, bdf only)
//                 [threads: auto | N >= 1]   (threads of one force evaluation)
//                 [collision: {[broadphase], [closed_form_box_halfspace],
//                  [closed_form_primitives], [polyhedron_manifold], [max_points_per_pair],
//                  [joined_bodies_collide], [match_radius], [query_time_limit]}]
//   bodies: - name [kind: dynamic|kinematic] mass (dynamic) [inertia: 3 or 6 values]
//             [position] [orientation: w x y z | rpy: roll pitch yaw] [velocity]
//             [angular_velocity] [surface_velocity] [geometry: - name shape [size]
//             [radius] [length] [file] [scale] [surface] [collision_group] [collision_mask]
//             [position] [orientation | rpy]]
//           shape: box (size: 3 edges) | sphere (radius) | cylinder | capsule | cone (radius,
//           length along z) | halfspace | convex_mesh | mesh (file: STL/OBJ/DAE, relative
//           to the scene file; [scale: number or 3 numbers])
//   [robots]: - file [prefix] [position] [orientation | rpy] [base: auto|fixed|floating]
//               [joint_positions: {JOINT: value}] [joint_velocities: {JOINT: value}]
//               [package_paths: [DIR, ...]] [collision_group]
//             file: a URDF, relative to the scene file (package:// meshes through
//             package_paths, relative to the scene file, then --package-path, then
//             ROS_PACKAGE_PATH); position/orientation place its root link; bodies, joints and
//             geometries are named prefix + the URDF name (a body after the first link of a
//             group welded by fixed joints), each link's geometry has surface prefix + link
//             name. A link's Gazebo tags (mu1 -> Coulomb mu, kp, kd -> a linear normal law)
//             apply against the surfaces of the bodies: section where the scene gives no
//             material for that surface pair (derived from the default material).
//   [joints]: - name type parent child [anchor] [axis] [axis2]
//               [limit: {lower, upper, [stiffness], [damping]}] [spring: {stiffness, [reference]}]
//               [damping] [effort] [friction: {law, [load: reaction|constant], [normal_force],
//               [radius]}] [drive: {[mode: position|velocity], [constant], [slope], [amplitude],
//               [frequency], [phase]}] [mimic: {joint, [multiplier], [offset]}]
//             type: fixed|revolute|continuous|prismatic|planar_translation|spherical|universal|
//             cylindrical|planar|free (core/joint.hpp); anchor, axis and axis2 in world
//             coordinates at t = 0 (axis2: the zero-angle reference x; universal: the child's
//             axis). Limits, springs, damping, effort, friction, drive and mimic act on revolute
//             and prismatic coordinates (core/joint_elements.hpp); friction's law names an
//             entry of friction_laws.
//   [simulation.constraints]: {[projection], [tolerance], [iterations], [project_initial],
//             [redundant: error|remove], [solver: auto|dense|sparse], [sparse_threshold]}
//   [springs]: - name a point_a b point_b stiffness [damping] [rest_length]
//   [bushings]: - name a b [frame_a: {[position], [orientation | rpy]}] [frame_b: ...]
//                 [stiffness] [damping] [rotational_stiffness] [rotational_damping]
//               frames in their body's frame (the world's for a: world), identity when
//               absent; each gain 3 numbers >= 0 per axis of frame A (N/m, N s/m, N m/rad,
//               N m s/rad; 0 when absent); deflected at t = 0 if the frames differ there
//               (core/bushing.hpp)
//   [torsional_springs]: - name a b axis stiffness [damping] [rest_angle]
//               axis in world coordinates at t = 0, fixed in a from there; the angle is 0 at
//               t = 0 and the spring relaxed at rest_angle [rad] (core/torsional_spring.hpp)
//   [friction_laws]: {LAW: {key: value}}     LAW is a name known to makeFrictionLaw; a value
//                 is a number, an expression over parameters, or an option's word
//   [materials]: - name [normal: {[law: linear|hertz|hunt_crossley|recurdyn], [stiffness],
//                  [damping], [exponent], [max_depth], [restitution, impact_speed]}] friction
//                  [surfaces: [[s1, s2], ...]] [default: true|false]
//   [contacts]: - a b material                 (geometry names; forces reported on b)
//                 No contacts: automatic contacts between every two geometries that may touch
//                 (core/model_builder.hpp), material by surface pair, else the default one.
//   [output]: [interval] [channels: [GROUP...]] (io/output_channels.hpp)
//             [summary: {body, [coordinate: x|y|z] | channel: COLUMN, [stick_speed],
//             [last_cycles]}]
// rpy is R = Rz(yaw) Ry(pitch) Rx(roll) (fixed axes x, then y, then z, as in URDF). 6-value
// inertia is [ixx, iyy, izz, ixy, ixz, iyz], the entries of the symmetric matrix. Without
// inertia a dynamic body takes the solid-box inertia of its first box geometry (edges = size,
// rotated by that geometry's orientation; an offset is not shifted: the body origin is the
// centre of mass). Without a box, the first other solid geometry's uniform-density inertia
// about its centroid (contact/shape_inertia.hpp) is used the same way.
#include "io/scene_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "contact/shape_inertia.hpp"
#include "core/model_builder.hpp"
#include "core/number_text.hpp"
#include "friction/friction_law.hpp"
#include "friction/tabulated_law.hpp"
#include "io/file_read.hpp"
#include "io/friction_curve.hpp"
#include "io/mesh_loader.hpp"
#include "io/run_settings_check.hpp"
#include "io/scene_expression.hpp"
#include "io/scene_keys.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"
#include "io/utf8_check.hpp"

namespace tribo::io {
namespace {

using Keys = std::vector<std::string>;

std::string joined(const Keys& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out.empty() ? "(none)" : out;
}

// One YAML value and its key path. Scalars are read through the parameter table, so a
// "$name" scalar reads as the parameter's current value.
class Value {
 public:
  Value(const std::string& file, const ParameterTable& params, YAML::Node node, std::string path)
      : file_(&file), params_(&params), node_(std::move(node)), path_(std::move(path)) {}

  Value child(const YAML::Node& node, const std::string& key) const {
    return {*file_, *params_, node, path_.empty() ? key : path_ + "." + key};
  }
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  SourceLocation where() const {
    const YAML::Mark m = node_.Mark();
    return {*file_, m.line < 0 ? 0 : m.line + 1, m.column < 0 ? 0 : m.column + 1};
  }
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(where(), path_, what); }

  // What is there, for "expected X, found Y" messages.
  std::string found() const {
    if (node_.IsNull()) return "nothing";
    if (node_.IsSequence()) return "a sequence of " + std::to_string(node_.size()) + " items";
    if (node_.IsMap()) return "a mapping";
    const std::string& s = node_.Scalar();
    if (isReference(s)) return "'" + text() + "' (from " + s + ")";
    return "'" + s + "'";
  }

  std::string text() const {
    if (!node_.IsScalar()) fail("expected a string, found " + found());
    const std::string& s = node_.Scalar();
    return isReference(s) ? params_->resolve(s, where(), path_).text : s;
  }
  // A number, or an expression over parameters (io/scene_expression.hpp).
  double number() const {
    if (node_.IsScalar()) {
      const std::string t = text();
      if (const auto v = parseNumber(t)) return *v;
      try {
        return evaluateExpression(t, *params_, where(), path_);
      } catch (const SceneError&) {
        if (looksLikeExpression(t)) throw;  // else: a word, say so plainly below
      }
    }
    fail("expected a number, found " + found());
  }
  double positive() const {
    const double v = number();
    if (!(v > 0.0)) fail("expected a number > 0, found " + found());
    return v;
  }
  double nonNegative() const {
    const double v = number();
    if (!(v >= 0.0)) fail("expected a number >= 0, found " + found());
    return v;
  }
  int integer(int at_least) const {
    const double v = number();
    if (v != std::floor(v) || v < at_least || v > 1e9)
      fail("expected a whole number >= " + std::to_string(at_least) + ", found " + found());
    return static_cast<int>(v);
  }
  bool flag() const {
    const std::string t = node_.IsScalar() ? text() : "";
    if (t != "true" && t != "false") fail("expected true or false, found " + found());
    return t == "true";
  }
  // Index of the text in `names`.
  int choice(const Keys& names) const {
    const std::string t = node_.IsScalar() ? text() : "";
    const auto it = std::find(names.begin(), names.end(), t);
    if (!node_.IsScalar() || it == names.end())
      fail("expected one of " + joined(names) + ", found " + found());
    return static_cast<int>(it - names.begin());
  }

  // Items of a sequence (`null` reads as empty when allowed).
  std::vector<Value> items(const std::string& what, bool null_is_empty = false) const {
    std::vector<Value> out;
    if (null_is_empty && node_.IsNull()) return out;
    if (!node_.IsSequence()) fail("expected a sequence of " + what + ", found " + found());
    for (std::size_t i = 0; i < node_.size(); ++i)
      out.push_back({*file_, *params_, node_[i], path_ + "[" + std::to_string(i) + "]"});
    return out;
  }
  // A sequence of numbers whose length is one of `sizes`; `what` describes it.
  std::vector<double> numbers(std::initializer_list<std::size_t> sizes,
                              const std::string& what) const {
    if (!node_.IsSequence() || std::find(sizes.begin(), sizes.end(), node_.size()) == sizes.end())
      fail("expected " + what + ", found " + found());
    std::vector<double> out;
    for (const Value& item : items(what)) out.push_back(item.number());
    return out;
  }
  Vec3 vec3(const std::string& what = "3 numbers [x, y, z]") const {
    const auto v = numbers({3}, what);
    return {v[0], v[1], v[2]};
  }

 private:
  const std::string* file_;
  const ParameterTable* params_;
  YAML::Node node_;
  std::string path_;
};

// A mapping whose keys are checked at once: an unknown or repeated key is an error at that
// key, listing the accepted ones. An empty accepted list accepts any key.
class Map {
 public:
  Map(const Value& self, const Keys& accepted) : self_(self) {
    const YAML::Node& node = self.node();
    if (!node.IsMap())
      self.fail("expected a mapping" +
                (accepted.empty() ? std::string() : " with keys " + joined(accepted)) + ", found " +
                self.found());
    std::set<std::string> seen;  // not get(): a parameters: table may hold 10,000 keys
    for (auto it = node.begin(); it != node.end(); ++it) {
      const Value key = self.child(it->first, it->first.Scalar());
      if (!it->first.IsScalar()) key.fail("expected a key name, found " + key.found());
      const std::string name = it->first.Scalar();
      if (!accepted.empty() && std::find(accepted.begin(), accepted.end(), name) == accepted.end())
        key.fail("unknown key '" + name + "' (accepted keys: " + joined(accepted) + ")");
      if (!seen.insert(name).second) key.fail("key '" + name + "' given twice");
      entries_.emplace_back(name, self.child(it->second, name));
    }
  }

  const Value& self() const { return self_; }
  const std::vector<std::pair<std::string, Value>>& entries() const { return entries_; }
  std::optional<Value> get(const std::string& key) const {
    for (const auto& [name, value] : entries_)
      if (name == key) return value;
    return std::nullopt;
  }
  Value required(const std::string& key) const {
    if (auto v = get(key)) return *v;
    self_.fail("missing required key '" + key + "'");
  }
  Vec3 vec3(const std::string& key, const Vec3& fallback) const {
    const auto v = get(key);
    return v ? v->vec3() : fallback;
  }

 private:
  Value self_;
  std::vector<std::pair<std::string, Value>> entries_;
};

// Runs f; an error of the model builder, a law factory or a name lookup becomes a SceneError
// located at `at`.
template <typename F>
auto guarded(const Value& at, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ModelError& e) {
    at.fail(e.what());
  } catch (const std::invalid_argument& e) {  // incl. friction::FrictionParameterError
    at.fail(e.what());
  }
}

Quat orientation(const Map& m) {
  const auto q = m.get("orientation");
  const auto rpy = m.get("rpy");
  if (q && rpy) rpy->fail("give orientation or rpy, not both");
  if (q) {
    const auto v = q->numbers({4}, "a quaternion [w, x, y, z]");
    const Quat out(v[0], v[1], v[2], v[3]);
    if (out.norm() < 1e-12) q->fail("expected a non-zero quaternion [w, x, y, z]");
    return out.normalized();
  }
  if (rpy) {
    const Vec3 a = rpy->vec3("3 angles [roll, pitch, yaw] [rad]");
    return Quat(Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(a.y(), Vec3::UnitY()) *
                Eigen::AngleAxisd(a.x(), Vec3::UnitX()));
  }
  return Quat::Identity();
}

struct GeometrySpec {
  Value at;
  std::string name;
  contact::Shape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::string surface = {};
  std::uint32_t group = 1;
  std::uint32_t mask = 0xffffffffu;
};

// A collision filter bit set.
std::uint32_t bitSet(const Value& x) {
  const double b = x.number();
  if (b != std::floor(b) || b < 0 || b > 4294967295.0)
    x.fail("expected a whole number in [0, 4294967295] (a bit set), found " + x.found());
  return static_cast<std::uint32_t>(b);
}

// A robot link surface whose Gazebo tags still need their materials (after materials:).
struct GazeboSurface {
  Value at;
  UrdfModelResult::Surface surface;
};

struct LawEntry {
  Value at;
  friction::LawSpec spec;
  std::shared_ptr<const friction::FrictionLaw> law;  // built when a material selects it
};

class Loader {
 public:
  Loader(std::string file, const YAML::Node& root, std::vector<std::string> package_paths,
         const UserLaws& user_laws)
      : file_(std::move(file)),
        root_(root),
        package_paths_(std::move(package_paths)),
        user_laws_(user_laws) {}

  Scene load(const std::vector<std::string>& overrides, const RunSettings& settings) {
    const Value root(file_, params_, root_, "");
    const Map m(root, scene_keys::kTop);
    if (auto p = m.get("parameters")) readParameters(*p);
    params_.applyOverrides(overrides, file_);
    if (auto s = m.get("simulation")) readSimulation(*s);
    const auto robots = m.get("robots");
    if (auto b = robots ? m.get("bodies") : m.required("bodies"))
      for (const Value& v : b->items("bodies", robots.has_value())) readBody(v);
    if (robots)
      for (const Value& v : robots->items("robots")) readRobot(v);
    if (auto j = m.get("joints"))
      for (const Value& v : j->items("joints", true)) readJoint(v);
    if (auto s = m.get("springs"))
      for (const Value& v : s->items("springs", true)) readSpring(v);
    if (auto s = m.get("bushings"))
      for (const Value& v : s->items("bushings", true)) readBushing(v);
    if (auto s = m.get("torsional_springs"))
      for (const Value& v : s->items("torsional_springs", true)) readTorsionalSpring(v);
    if (auto f = m.get("friction_laws")) readFrictionLaws(*f);
    readJointReferences();
    if (auto mat = m.get("materials"))
      for (const Value& v : mat->items("materials", true)) readMaterial(v);
    applyGazeboTags();
    if (auto c = m.get("contacts"))
      for (const Value& v : c->items("contacts", true)) readContact(v);
    Scene scene;
    if (auto o = m.get("output")) scene.output = readOutput(*o);
    applyRunSettings(settings, scene.output);
    checkRunOptions(builder_.options(), file_);
    scene.path = file_;
    try {
      scene.model = builder_.build();
    } catch (const ModelError& e) {
      throw SceneError({file_}, "", e.what());
    }
    if (summary_channel_) {
      const std::vector<std::string> columns = channelColumns(*scene.model, scene.output.channels);
      if (std::find(columns.begin() + 1, columns.end(), scene.output.summary.channel) ==
          columns.end())
        summary_channel_->fail(
            "no recorded channel '" + scene.output.summary.channel +
            "' (output.channels: " + joined(scene.output.channels) +
            "; e.g. BODY.yaw needs rpy, JOINT.q needs joints, A/B.normal_force needs pairs, "
            "A/B.z.x needs friction_states)");
    }
    noteSurfaceVelocityOffTheSurface(*scene.model);
    scene.parameters = params_.values();
    scene.notes = notes_;
    return scene;
  }

 private:
  // A half-space's surface is its geometry's z = 0 plane: a body's surface_velocity (in each
  // geometry's frame) with a part along that z would push material through the surface,
  // which the contact ignores (it uses the tangential part only through the slip).
  void noteSurfaceVelocityOffTheSurface(const Model& model) {
    for (const Geometry& g : model.geometries) {
      if (g.body.isWorld() || g.shape.type != contact::ShapeType::kHalfSpace) continue;
      const Vec3& v = model.bodies[g.body.value].surface_velocity;
      if (std::abs(v.z()) <= 1e-9 * v.norm()) continue;
      notes_.push_back("bodies." + model.bodies[g.body.value].name + ".surface_velocity [" +
                       numberText(v.x()) + ", " + numberText(v.y()) + ", " + numberText(v.z()) +
                       "] is not tangent to the surface of half-space '" + g.name +
                       "' (its z must be 0: the velocity is read in the geometry's " +
                       "frame, whose z is the surface normal)");
    }
  }

  void applyRunSettings(const RunSettings& r, OutputSpec& output) {
    SimulationOptions& o = builder_.options();
    if (r.integrator) o.integrator = *r.integrator;
    if (r.time_step) o.time_step = *r.time_step;
    if (r.duration) o.duration = *r.duration;
    if (r.relative_tolerance) o.relative_tolerance = *r.relative_tolerance;
    if (r.absolute_tolerance) o.absolute_tolerance = *r.absolute_tolerance;
    if (r.event_location) o.event_location = *r.event_location;
    if (r.threads) o.threads = *r.threads;
    // A law the caller defined (in Python: it takes the GIL for each call) runs on the
    // calling thread alone.
    if (uses_user_law_) o.threads = 1;
    if (r.output_interval) {
      if (!(*r.output_interval > 0.0) || !std::isfinite(*r.output_interval))
        throw SceneError({file_}, "output.interval",
                         "expected a number > 0, found " + numberText(*r.output_interval));
      output.interval = *r.output_interval;
    }
  }

  void readParameters(const Value& v) {
    const Map table(v, {});
    for (const auto& [name, value] : table.entries()) {
      if (!value.node().IsScalar())
        value.fail("expected a number or a string, found " + value.found());
      params_.add(name, value.node().Scalar(), value.where());
    }
  }

  void readSimulation(const Value& v) {
    const Map m(v, scene_keys::kSimulation);
    SimulationOptions& o = builder_.options();
    if (auto x = m.get("duration")) o.duration = x->positive();
    if (auto x = m.get("time_step")) o.time_step = x->positive();
    if (auto x = m.get("integrator"))
      o.integrator = guarded(*x, [&] { return integratorFromName(x->text()); });
    if (auto x = m.get("rtol")) {
      o.relative_tolerance = x->positive();
      if (!(o.relative_tolerance < 1.0))
        x->fail("expected a number in (0, 1), found " + x->found());
    }
    if (auto x = m.get("atol")) o.absolute_tolerance = x->positive();
    if (auto x = m.get("max_step")) o.max_internal_step = x->nonNegative();
    if (auto x = m.get("event_location")) o.event_location = x->flag();
    if (auto x = m.get("threads")) {
      if (x->node().IsScalar() && x->text() == "auto") {
        o.threads = kAutoThreads;
      } else {
        try {
          o.threads = x->integer(1);
        } catch (const SceneError&) {
          x->fail("expected auto or a whole number >= 1, found " + x->found());
        }
      }
    }
    o.gravity = m.vec3("gravity", o.gravity);
    if (auto x = m.get("baumgarte")) {
      const Map b(*x, scene_keys::kBaumgarte);
      if (auto a = b.get("alpha")) o.baumgarte_alpha = a->nonNegative();
      if (auto a = b.get("beta")) o.baumgarte_beta = a->nonNegative();
    }
    if (auto x = m.get("constraints")) readConstraintOptions(*x, o.constraints);
    if (auto x = m.get("collision")) {
      const Map c(*x, scene_keys::kCollision);
      if (auto a = c.get("broadphase")) o.collision.broadphase = a->flag();
      if (auto a = c.get("closed_form_box_halfspace"))
        o.collision.closed_form_box_halfspace = a->flag();
      if (auto a = c.get("max_points_per_pair")) o.collision.max_points_per_pair = a->integer(1);
      if (auto a = c.get("closed_form_primitives")) o.collision.closed_form_primitives = a->flag();
      if (auto a = c.get("polyhedron_manifold")) o.collision.polyhedron_manifold = a->flag();
      if (auto a = c.get("joined_bodies_collide")) o.collision.joined_bodies_collide = a->flag();
      if (auto a = c.get("match_radius")) o.collision.match_radius = a->positive();
      if (auto a = c.get("query_time_limit")) o.collision.query_time_limit = a->nonNegative();
    }
  }

  void readBody(const Value& v) {
    const Map m(v, scene_keys::kBody);
    Body body;
    body.name = m.required("name").text();
    if (auto k = m.get("kind"))
      body.kind =
          k->choice(scene_keys::kBodyKinds) == 0 ? BodyKind::kDynamic : BodyKind::kKinematic;
    body.position = m.vec3("position", Vec3::Zero());
    body.orientation = orientation(m);
    body.velocity = m.vec3("velocity", Vec3::Zero());
    body.angular_velocity = m.vec3("angular_velocity", Vec3::Zero());
    body.surface_velocity = m.vec3("surface_velocity", Vec3::Zero());
    std::vector<GeometrySpec> geometries;
    if (auto g = m.get("geometry"))
      for (const Value& item : g->items("geometries", true))
        geometries.push_back(readGeometry(item));

    const bool dynamic = body.kind == BodyKind::kDynamic;
    if (auto mass = dynamic ? std::optional(m.required("mass")) : m.get("mass"))
      body.mass = mass->number();
    if (auto inertia = m.get("inertia")) {
      const auto i = inertia->numbers(
          {3, 6}, "3 principal moments [ixx, iyy, izz] or 6 values [ixx, iyy, izz, ixy, ixz, iyz]");
      body.inertia = Vec3(i[0], i[1], i[2]).asDiagonal();
      if (i.size() == 6) {
        body.inertia(0, 1) = body.inertia(1, 0) = i[3];
        body.inertia(0, 2) = body.inertia(2, 0) = i[4];
        body.inertia(1, 2) = body.inertia(2, 1) = i[5];
      }
    } else if (dynamic) {
      auto box = std::find_if(geometries.begin(), geometries.end(), [](const auto& g) {
        return g.shape.type == contact::ShapeType::kBox;
      });
      if (box == geometries.end())
        box = std::find_if(geometries.begin(), geometries.end(), [](const auto& g) {
          return g.shape.type != contact::ShapeType::kHalfSpace &&
                 g.shape.type != contact::ShapeType::kTriangleMesh;
        });
      if (box == geometries.end())
        v.fail("missing key 'inertia' (needed by a dynamic body without solid geometry)");
      const Mat3 local = guarded(box->at, [&] {
        return Mat3(contact::solidMassProperties(box->shape, body.mass).inertia);
      });
      const Mat3 r = box->pose.linear();
      body.inertia = r * local * r.transpose();
    }
    const BodyIndex index = guarded(v, [&] { return builder_.addBody(body); });
    for (const auto& g : geometries) {
      const int id =
          guarded(g.at, [&] { return builder_.addGeometry(g.name, index, g.shape, g.pose); });
      builder_.setGeometrySurface(id, g.surface);
      body_surfaces_.insert(g.surface);
      builder_.setCollisionFilter(id, g.group, g.mask);
      geometry_names_.push_back(g.name);
    }
  }

  GeometrySpec readGeometry(const Value& v) {
    const Map m(v, scene_keys::kGeometry);
    GeometrySpec g{v, m.required("name").text(), {}, Eigen::Isometry3d::Identity()};
    const Value shape = m.required("shape");
    const Keys& shapes = scene_keys::kShapes;
    const std::string kind = shapes[shape.choice(shapes)];
    // Keys each shape takes; any other dimension key is an error at that key.
    const std::map<std::string, Keys> takes{{"box", {"size"}},
                                            {"sphere", {"radius"}},
                                            {"cylinder", {"radius", "length"}},
                                            {"capsule", {"radius", "length"}},
                                            {"cone", {"radius", "length"}},
                                            {"halfspace", {}},
                                            {"convex_mesh", {"file", "scale"}},
                                            {"mesh", {"file", "scale"}}};
    for (const char* key : {"size", "radius", "length", "file", "scale"}) {
      const Keys& ok = takes.at(kind);
      if (auto x = m.get(key); x && std::find(ok.begin(), ok.end(), key) == ok.end())
        x->fail("a " + kind + " takes no " + key +
                (ok.empty() ? std::string() : " (it takes: " + joined(ok) + ")"));
    }
    if (kind == "box") {
      const Value size = m.required("size");
      const Vec3 edges = size.vec3("3 edge lengths [x, y, z] [m]");
      if (!(edges.minCoeff() > 0.0))
        size.fail("expected 3 edge lengths > 0, found " + size.found());
      g.shape = contact::Shape::box(edges / 2.0);
    } else if (kind == "sphere") {
      g.shape = contact::Shape::sphere(m.required("radius").positive());
    } else if (kind == "cylinder" || kind == "capsule" || kind == "cone") {
      const double r = m.required("radius").positive();
      const double h = 0.5 * m.required("length").positive();
      g.shape = kind == "cylinder"  ? contact::Shape::cylinder(r, h)
                : kind == "capsule" ? contact::Shape::capsule(r, h)
                                    : contact::Shape::cone(r, h);
    } else if (kind == "halfspace") {
      g.shape = contact::Shape::halfSpace();
    } else {
      const Value file = m.required("file");
      Vec3 scale = Vec3::Ones();
      if (auto x = m.get("scale")) {
        if (x->node().IsScalar()) {
          scale = Vec3::Constant(x->positive());
        } else {
          scale = x->vec3("a number or 3 numbers [sx, sy, sz]");
          if (!(scale.minCoeff() > 0.0)) x->fail("expected scales > 0, found " + x->found());
        }
      }
      std::filesystem::path path(file.text());
      if (path.is_relative()) path = std::filesystem::path(file_).parent_path() / path;
      try {
        const auto mesh = loadMesh(path.string(), scale);
        g.shape = kind == "mesh" ? contact::Shape::triangleMesh(mesh)
                                 : contact::Shape::convexMesh(contact::makeConvex(*mesh));
      } catch (const contact::MeshError& e) {
        file.fail(e.what());
      }
    }
    if (auto x = m.get("surface")) g.surface = x->text();
    if (auto x = m.get("collision_group")) g.group = bitSet(*x);
    if (auto x = m.get("collision_mask")) g.mask = bitSet(*x);
    g.pose.translation() = m.vec3("position", Vec3::Zero());
    g.pose.linear() = orientation(m).toRotationMatrix();
    guarded(v, [&] { ModelBuilder::checkGeometry(g.name, g.shape, g.pose); });  // before inertia
    return g;
  }

  void readRobot(const Value& v) {
    const Map m(v, scene_keys::kRobot);
    const Value file = m.required("file");
    const std::filesystem::path folder = std::filesystem::path(file_).parent_path();
    std::filesystem::path path(file.text());
    if (path.is_relative()) path = folder / path;
    std::vector<std::string> packages;
    if (auto p = m.get("package_paths"))
      for (const Value& item : p->items("package folders")) {
        const std::filesystem::path dir(item.text());
        packages.push_back((dir.is_relative() ? folder / dir : dir).string());
      }
    packages.insert(packages.end(), package_paths_.begin(), package_paths_.end());
    UrdfRobot robot;
    try {
      robot = readUrdf(path.string(), PackagePaths::withEnvironment(packages));
    } catch (const UrdfError& e) {
      file.fail(e.what());
    }
    UrdfPlacement placement;
    if (auto x = m.get("prefix")) placement.prefix = x->text();
    placement.base.translation() = m.vec3("position", Vec3::Zero());
    placement.base.linear() = orientation(m).toRotationMatrix();
    if (auto x = m.get("base"))
      placement.base_mode =
          std::array{UrdfPlacement::Base::kAuto, UrdfPlacement::Base::kFixed,
                     UrdfPlacement::Base::kFloating}[x->choice(scene_keys::kRobotBases)];
    auto joint_values = [&](const char* key, std::map<std::string, double>& out) {
      if (auto x = m.get(key)) {
        const Map values(*x, {});
        for (const auto& [name, value] : values.entries()) out[name] = value.number();
      }
    };
    joint_values("joint_positions", placement.joint_positions);
    joint_values("joint_velocities", placement.joint_velocities);
    if (auto x = m.get("collision_group")) placement.collision_group = bitSet(*x);
    const UrdfModelResult added =
        guarded(v, [&] { return addUrdfRobot(builder_, robot, placement); });
    for (const auto& note : added.notes)
      notes_.push_back(v.path() + " (" + file.text() +
                       (placement.prefix.empty() ? "" : ", prefix " + placement.prefix) +
                       "): " + note);
    for (const auto& s : added.surfaces)
      if (s.contact.mu1 || s.contact.kp || s.contact.kd) gazebo_surfaces_.push_back({v, s});
  }

  // Gives each robot link with Gazebo contact tags its own material against every surface of
  // the bodies: section, unless the scene names a material for that pair: the default
  // material changed by the tags as for `tribo run ROBOT.urdf` (io/urdf_model.hpp).
  void applyGazeboTags() {
    if (default_material_.empty()) return;  // nothing to derive from; pairs need materials
    const contact::Material& base = material_values_.at(default_material_);
    for (const auto& [at, s] : gazebo_surfaces_) {
      const contact::Material material = guarded(
          at, [&, &s = s] { return withGazeboTags(base, s.contact, std::max(s.body_mass, 1e-3)); });
      const int index = guarded(at, [&] { return builder_.addMaterial(material); });
      for (const std::string& other : body_surfaces_)
        if (!surface_pairs_.count({std::min(s.name, other), std::max(s.name, other)}))
          guarded(at, [&, &s = s] { builder_.addSurfacePairMaterial(s.name, other, index); });
    }
  }

  BodyIndex body(const Value& v) const {
    const std::string name = v.text();
    if (auto index = builder_.findBody(name)) return *index;
    Keys known{"world"};
    for (const auto& b : builder_.bodies()) known.push_back(b.name);
    v.fail("unknown body '" + name + "' (known bodies: " + joined(known) + ")");
  }

  void readConstraintOptions(const Value& v, ConstraintOptions& c) {
    const Map m(v, scene_keys::kConstraints);
    if (auto x = m.get("projection")) c.projection = x->flag();
    if (auto x = m.get("tolerance")) c.projection_tolerance = x->positive();
    if (auto x = m.get("iterations")) c.projection_iterations = x->integer(1);
    if (auto x = m.get("project_initial")) c.project_initial = x->flag();
    if (auto x = m.get("redundant"))
      c.redundant = x->choice(scene_keys::kRedundancyPolicies) == 0 ? RedundancyPolicy::kError
                                                                    : RedundancyPolicy::kRemove;
    if (auto x = m.get("solver"))
      c.solver = guarded(*x, [&] { return constraintSolverFromName(x->text()); });
    if (auto x = m.get("sparse_threshold")) c.sparse_threshold = x->integer(1);
  }

  void readJoint(const Value& v) {
    const Map m(v, scene_keys::kJoint);
    const std::string name = m.required("name").text();
    const Value type_value = m.required("type");
    const JointType type =
        guarded(type_value, [&] { return jointTypeFromName(type_value.text()); });
    const auto parent_value = m.get("parent");
    const BodyIndex parent = parent_value ? body(*parent_value) : BodyIndex::world();
    const BodyIndex child = body(m.required("child"));
    const Vec3 child_position =
        child.isWorld() ? Vec3::Zero() : builder_.bodies()[child.value].position;
    const Vec3 anchor = m.vec3("anchor", child_position);
    const Vec3 axis = m.vec3("axis", Vec3::UnitZ());
    const Vec3 axis2 = m.vec3("axis2", Vec3::Zero());
    const int joint = guarded(
        v, [&] { return builder_.addJoint(name, type, parent, child, anchor, axis, axis2); });
    if (auto x = m.get("limit")) {
      const Map l(*x, scene_keys::kJointLimit);
      JointLimit limit{l.required("lower").number(), l.required("upper").number(), 0.0, 0.0};
      if (auto k = l.get("stiffness")) limit.stiffness = k->nonNegative();
      if (auto c = l.get("damping")) limit.damping = c->nonNegative();
      guarded(*x, [&] { builder_.setJointLimit(joint, limit); });
    }
    if (auto x = m.get("spring")) {
      const Map sp(*x, scene_keys::kJointSpring);
      const auto reference = sp.get("reference");
      const JointSpring spring{sp.required("stiffness").number(),
                               reference ? reference->number() : 0.0};
      guarded(*x, [&] { builder_.setJointSpring(joint, spring); });
    }
    if (auto x = m.get("damping"))
      guarded(*x, [&] { builder_.setJointDamping(joint, x->number()); });
    if (auto x = m.get("effort")) guarded(*x, [&] { builder_.setJointEffort(joint, x->number()); });
    if (auto x = m.get("drive")) {
      const Map d(*x, scene_keys::kJointDrive);
      JointDrive drive;
      if (auto mode = d.get("mode"))
        drive.mode = mode->choice(scene_keys::kDriveModes) == 0 ? DriveMode::kPosition
                                                                : DriveMode::kVelocity;
      auto number = [&](const char* key) {
        const auto n = d.get(key);
        return n ? n->number() : 0.0;
      };
      drive.function = {number("constant"), number("slope"), number("amplitude"),
                        number("frequency"), number("phase")};
      guarded(*x, [&] { builder_.setJointDrive(joint, drive); });
    }
    // Friction names a law and mimic a joint, possibly defined later: resolved once all
    // joints and laws are read (readJointReferences).
    if (auto x = m.get("friction")) pending_friction_.emplace_back(joint, *x);
    if (auto x = m.get("mimic")) pending_mimic_.emplace_back(joint, *x);
  }

  void readJointReferences() {
    for (const auto& [joint, v] : pending_friction_) {
      const Map f(v, scene_keys::kJointFriction);
      JointFriction friction;
      friction.law = frictionLaw(f.required("law"));
      if (auto x = f.get("load"))
        friction.load = x->choice(scene_keys::kJointFrictionLoads) == 0
                            ? JointFrictionLoad::kReaction
                            : JointFrictionLoad::kConstant;
      if (auto x = f.get("normal_force")) {
        if (friction.load != JointFrictionLoad::kConstant)
          x->fail("normal_force applies to load: constant only");
        friction.normal_force = x->nonNegative();
      } else if (friction.load == JointFrictionLoad::kConstant) {
        v.fail("missing required key 'normal_force' (needed by load: constant)");
      }
      if (auto x = f.get("radius")) friction.radius = x->positive();
      guarded(v, [&, joint = joint] { builder_.setJointFriction(joint, friction); });
    }
    for (const auto& [joint, v] : pending_mimic_) {
      const Map mm(v, scene_keys::kJointMimic);
      const Value leader_value = mm.required("joint");
      const auto leader = builder_.findJoint(leader_value.text());
      if (!leader) {
        Keys known;
        for (const Joint& j : builder_.joints()) known.push_back(j.name);
        leader_value.fail("unknown joint '" + leader_value.text() +
                          "' (known joints: " + joined(known) + ")");
      }
      const auto multiplier = mm.get("multiplier");
      const auto offset = mm.get("offset");
      const std::string name = builder_.joints()[joint].name + " mimics " + leader_value.text();
      guarded(v, [&, joint = joint] {
        return builder_.addJointCoupling(name, *leader, joint,
                                         multiplier ? multiplier->number() : 1.0,
                                         offset ? offset->number() : 0.0);
      });
    }
  }

  // The friction law an entry of friction_laws names, built on first use.
  std::shared_ptr<const friction::FrictionLaw> frictionLaw(const Value& name) {
    const auto it = laws_.find(name.text());
    if (it == laws_.end()) {
      if (const auto user = user_laws_.find(name.text()); user != user_laws_.end()) {
        uses_user_law_ = true;
        return user->second;
      }
      Keys defined = law_names_;
      for (const auto& [user_name, law] : user_laws_) defined.push_back(user_name);
      name.fail("friction law '" + name.text() +
                "' is not defined in friction_laws (defined: " + joined(defined) + ")");
    }
    LawEntry& law = it->second;
    if (!law.law && law.spec.name == "tabulated") law.law = tabulatedLaw(law, name);
    if (!law.law) {
      try {
        law.law = friction::makeFrictionLaw(law.spec);
      } catch (const friction::FrictionParameterError& e) {
        law.at.fail(std::string(e.what()) + " (selected by " + name.path() + ")");
      }
    }
    return law.law;
  }

  // The `tabulated` law: its only key `file`, a CSV curve relative to the scene file
  // (io/friction_curve.hpp); rule violations are reported at the curve's line.
  std::shared_ptr<const friction::FrictionLaw> tabulatedLaw(const LawEntry& law,
                                                            const Value& selected_by) {
    for (const auto& [key, value] : law.spec.values)
      law.at.fail("tabulated: unknown key '" + key + "' (accepted keys: file)");
    for (const auto& [key, value] : law.spec.options)
      if (key != "file") law.at.fail("tabulated: unknown key '" + key + "' (accepted keys: file)");
    const auto file = law.spec.options.find("file");
    if (file == law.spec.options.end())
      law.at.fail("tabulated: missing required key 'file' (a CSV of speed, coefficient)");
    std::filesystem::path path = file->second;
    if (path.is_relative()) path = std::filesystem::path(file_).parent_path() / path;
    const FrictionCurve curve = readFrictionCurve(path.string());
    try {
      return std::make_shared<friction::TabulatedLaw>(curve.speeds, curve.coefficients);
    } catch (const friction::TabulatedPointError& e) {
      throw SceneError({path.string(), curve.lines[e.point], 0}, "",
                       std::string(e.what()) + " (selected by " + selected_by.path() + ")");
    } catch (const friction::FrictionParameterError& e) {
      law.at.fail(std::string(e.what()) + " (selected by " + selected_by.path() + ")");
    }
  }

  void readSpring(const Value& v) {
    const Map m(v, scene_keys::kSpring);
    const std::string name = m.required("name").text();
    const BodyIndex a = body(m.required("a"));
    const BodyIndex b = body(m.required("b"));
    const Vec3 pa = m.required("point_a").vec3();
    const Vec3 pb = m.required("point_b").vec3();
    const double k = m.required("stiffness").number();
    const auto damping = m.get("damping");
    const auto rest = m.get("rest_length");
    const double c = damping ? damping->number() : 0.0;
    const double l0 = rest ? rest->nonNegative() : -1.0;  // < 0: the initial distance
    guarded(v, [&] { builder_.addSpring(name, a, pa, b, pb, k, c, l0); });
  }

  // A bushing frame {[position], [orientation | rpy]} in its body's frame (identity when
  // absent).
  static void readFrame(const std::optional<Value>& v, Vec3& position, Quat& rotation) {
    if (!v) return;
    const Map m(*v, scene_keys::kFrame);
    position = m.vec3("position", Vec3::Zero());
    rotation = orientation(m);
  }

  // Three gains >= 0, each checked at its own item; zero when absent.
  static Vec3 gains(const Map& m, const std::string& key) {
    const auto v = m.get(key);
    if (!v) return Vec3::Zero();
    const std::string what = "3 numbers >= 0 [x, y, z] (per axis of frame A)";
    v->numbers({3}, what);  // the length first
    const std::vector<Value> items = v->items(what);
    return {items[0].nonNegative(), items[1].nonNegative(), items[2].nonNegative()};
  }

  void readBushing(const Value& v) {
    const Map m(v, scene_keys::kBushing);
    Bushing bushing;
    bushing.name = m.required("name").text();
    bushing.body_a = body(m.required("a"));
    bushing.body_b = body(m.required("b"));
    readFrame(m.get("frame_a"), bushing.position_a, bushing.orientation_a);
    readFrame(m.get("frame_b"), bushing.position_b, bushing.orientation_b);
    bushing.stiffness = gains(m, "stiffness");
    bushing.damping = gains(m, "damping");
    bushing.rotational_stiffness = gains(m, "rotational_stiffness");
    bushing.rotational_damping = gains(m, "rotational_damping");
    guarded(v, [&] { builder_.addBushing(bushing); });
  }

  void readTorsionalSpring(const Value& v) {
    const Map m(v, scene_keys::kTorsionalSpring);
    const std::string name = m.required("name").text();
    const BodyIndex a = body(m.required("a"));
    const BodyIndex b = body(m.required("b"));
    const Value axis_value = m.required("axis");
    const Vec3 axis = axis_value.vec3("3 numbers [x, y, z] (the axis, world)");
    if (!(axis.norm() > 0.0))
      axis_value.fail("expected a non-zero axis, found " + axis_value.found());
    const double k = m.required("stiffness").nonNegative();
    const auto damping = m.get("damping");
    const auto rest = m.get("rest_angle");
    const double c = damping ? damping->nonNegative() : 0.0;
    const double rest_angle = rest ? rest->number() : 0.0;
    guarded(v, [&] { builder_.addTorsionalSpring(name, a, b, axis, k, c, rest_angle); });
  }

  // The value of a law entry that is an expression over parameters, or nothing when the text
  // is not one (an option's word, a file name with '/' or '-').
  static std::optional<double> expressionValue(const Value& value, const std::string& text) {
    if (!looksLikeExpression(text)) return std::nullopt;
    try {
      return value.number();
    } catch (const SceneError&) {
      return std::nullopt;
    }
  }

  // Reads every law entry (known law name, scalar values, resolvable references) but builds
  // only the laws a material selects (readMaterial), so that values out of range for a law
  // that is not used are no error: e.g. `--set a=0.5` while the materials use recurdyn.
  // Key names are checked by makeFrictionLaw, and so also only for the laws in use.
  void readFrictionLaws(const Value& v) {
    Keys known = friction::knownFrictionLaws();
    for (const auto& name : friction::knownStatefulFrictionLaws()) known.push_back(name);
    for (const auto& name : friction::knownDynamicFrictionLaws()) known.push_back(name);
    known.push_back("tabulated");  // built here from its file (tabulatedLaw)
    const Map laws(v, {});
    for (const auto& [law, entry] : laws.entries()) {
      if (std::find(known.begin(), known.end(), law) == known.end())
        entry.fail("unknown friction law '" + law + "' (known laws: " + joined(known) + ")");
      LawEntry e{entry, {law, {}, {}}, nullptr};
      const Map keys(entry, {});
      for (const auto& [key, value] : keys.entries()) {
        if (!value.node().IsScalar())
          value.fail("expected a number or a string, found " + value.found());
        const std::string text = value.text();
        if (const auto number = parseNumber(text)) {
          e.spec.values[key] = *number;
        } else if (const auto result = expressionValue(value, text)) {
          e.spec.values[key] = *result;  // e.g. theta0: $theta with theta: '$d_c / $v'
        } else {
          e.spec.options[key] = text;  // a word: an option, or a file name
        }
      }
      law_names_.push_back(law);
      laws_.emplace(law, std::move(e));
    }
  }

  void readMaterial(const Value& v) {
    const Map m(v, scene_keys::kMaterial);
    const Value name_value = m.required("name");
    const std::string name = name_value.text();
    if (materials_.count(name)) name_value.fail("material '" + name + "' defined twice");
    contact::Material material;
    if (auto n = m.get("normal")) material.normal = readNormalLaw(*n);
    material.friction = frictionLaw(m.required("friction"));
    const int index = guarded(v, [&] { return builder_.addMaterial(material); });
    materials_[name] = index;
    material_values_[name] = material;
    if (auto d = m.get("default"); d && d->flag()) {
      if (!default_material_.empty())
        d->fail("material '" + default_material_ + "' is already the default");
      default_material_ = name;
      builder_.setDefaultMaterial(index);
    }
    if (auto list = m.get("surfaces")) {
      for (const Value& item : list->items("surface pairs [a, b]")) {
        if (!item.node().IsSequence() || item.node().size() != 2)
          item.fail("expected a surface pair [a, b], found " + item.found());
        const auto both = item.items("surface names");
        const std::string a = both[0].text(), b = both[1].text();
        guarded(item, [&] { builder_.addSurfacePairMaterial(a, b, index); });
        surface_pairs_.insert({std::min(a, b), std::max(a, b)});
      }
    }
  }

  contact::NormalLaw readNormalLaw(const Value& v) {
    const Map m(v, scene_keys::kNormal);
    contact::NormalLaw law;
    if (auto x = m.get("law"))
      law.type = guarded(*x, [&] { return contact::normalLawFromName(x->text()); });
    const std::string name = contact::normalLawName(law.type);
    auto only = [&](const char* key, std::initializer_list<contact::NormalLawType> types,
                    const std::string& which) {
      const auto x = m.get(key);
      if (x && std::find(types.begin(), types.end(), law.type) == types.end())
        x->fail(std::string(key) + " applies to law " + which + " only (this law is " + name + ")");
      return x;
    };
    using T = contact::NormalLawType;
    if (auto x = m.get("stiffness")) law.stiffness = x->number();
    if (auto x = only("damping", {T::kLinear, T::kHuntCrossley, T::kRecurDyn},
                      "linear, hunt_crossley or recurdyn"))
      law.damping = x->number();
    if (auto x = only("exponent", {T::kHuntCrossley, T::kRecurDyn}, "hunt_crossley or recurdyn"))
      law.exponent = x->number();
    if (auto x = only("max_depth", {T::kRecurDyn}, "recurdyn")) law.max_depth = x->number();
    const auto e = only("restitution", {T::kHuntCrossley}, "hunt_crossley");
    const auto speed = only("impact_speed", {T::kHuntCrossley}, "hunt_crossley");
    if (e || speed) {
      // alpha from the exact Hunt-Crossley restitution relation (contact/normal_law.hpp).
      if (!e || !speed) v.fail("restitution and impact_speed go together");
      if (m.get("damping")) v.fail("give damping or restitution, not both");
      law.damping =
          guarded(*e, [&] { return contact::huntCrossleyDamping(e->number(), speed->positive()); });
    }
    guarded(v, [&] { law.validate(); });
    return law;
  }

  void readContact(const Value& v) {
    const Map m(v, scene_keys::kContact);
    auto geometry = [&](const Value& g) {
      const auto index = builder_.findGeometry(g.text());
      if (!index)
        g.fail("unknown geometry '" + g.text() + "' (known geometries: " + joined(geometry_names_) +
               ")");
      return *index;
    };
    const int a = geometry(m.required("a"));
    const int b = geometry(m.required("b"));
    const Value mat = m.required("material");
    const auto it = materials_.find(mat.text());
    if (it == materials_.end()) {
      Keys known;
      for (const auto& [name, index] : materials_) known.push_back(name);
      mat.fail("unknown material '" + mat.text() + "' (known materials: " + joined(known) + ")");
    }
    guarded(v, [&] { builder_.addContactPair(a, b, it->second); });
  }

  OutputSpec readOutput(const Value& v) {
    const Map m(v, scene_keys::kOutput);
    OutputSpec out;
    if (auto x = m.get("interval")) out.interval = x->positive();
    if (auto x = m.get("channels")) {
      out.channels.clear();
      for (const Value& g : x->items("channels")) {
        const std::string name = g.text();
        if (!hasGroup(knownChannelGroups(), name))
          g.fail("unknown channel group '" + name + "' (known: " + joined(knownChannelGroups()) +
                 ")");
        if (hasGroup(out.channels, name)) g.fail("channel group '" + name + "' is listed twice");
        out.channels.push_back(name);
      }
    }
    if (auto x = m.get("summary")) {
      const Map s(*x, scene_keys::kSummary);
      const auto b = s.get("body");
      const auto channel = s.get("channel");
      if (!b && !channel) s.required("body");  // the message names what is missing
      if (b) {
        if (body(*b).isWorld()) b->fail("expected a body of the scene, found 'world'");
        out.summary.body = b->text();
      }
      if (channel) {
        if (s.get("coordinate")) channel->fail("give either channel or coordinate, not both");
        out.summary.channel = channel->text();
        summary_channel_.emplace(*channel);  // checked once the model is built
      }
      if (auto c = s.get("coordinate"))
        out.summary.coordinate = c->choice(scene_keys::kSummaryCoordinates);
      if (!out.summary.body.empty() && !hasGroup(out.channels, "contact"))
        out.channels.push_back("contact");  // the summary's stuck fraction reads it
      if (out.summary.channel.empty() && !hasGroup(out.channels, "position"))
        out.channels.push_back("position");
      if (auto c = s.get("stick_speed")) out.summary.stick_speed = c->nonNegative();
      if (auto c = s.get("last_cycles")) out.summary.last_cycles = c->integer(1);
    }
    return out;
  }

  std::string file_;
  std::optional<Value> summary_channel_;  // output.summary.channel, checked after the build
  YAML::Node root_;
  ParameterTable params_;
  ModelBuilder builder_;
  Keys geometry_names_;
  Keys law_names_;  // in file order, for messages
  std::map<std::string, LawEntry> laws_;
  std::map<std::string, int> materials_;
  std::vector<std::pair<int, Value>> pending_friction_;  // joint index, its friction block
  std::vector<std::pair<int, Value>> pending_mimic_;     // joint index, its mimic block
  std::string default_material_;  // name of the material marked default, if any
  std::map<std::string, contact::Material> material_values_;     // by name
  std::set<std::pair<std::string, std::string>> surface_pairs_;  // given a material, sorted
  std::set<std::string> body_surfaces_;  // surfaces of the bodies: section's geometry
  std::vector<GazeboSurface> gazebo_surfaces_;
  std::vector<std::string> package_paths_;  // --package-path folders
  const UserLaws& user_laws_;
  bool uses_user_law_ = false;  // a material's friction is one of user_laws_
  std::vector<std::string> notes_;
};

}  // namespace

namespace {

[[noreturn]] void yamlError(const YAML::Exception& e, const std::string& name) {
  const int line = e.mark.line < 0 ? 0 : e.mark.line + 1;
  const int column = e.mark.column < 0 ? 0 : e.mark.column + 1;
  throw SceneError({name, line, column}, "", "invalid YAML: " + e.msg);
}

}  // namespace

SceneDocument::SceneDocument(const std::string& yaml, const std::string& name_for_errors)
    : name_(name_for_errors) {
  requireUtf8Scene(yaml, name_);
  try {
    root_ = std::make_shared<const YAML::Node>(YAML::Load(yaml));
  } catch (const YAML::Exception& e) {
    yamlError(e, name_);
  }
}

Scene SceneDocument::load(const std::vector<std::string>& overrides,
                          const std::vector<std::string>& package_paths,
                          const RunSettings& settings, const UserLaws& user_laws) const {
  for (const auto& [name, law] : user_laws) {
    for (const auto* known :
         {&friction::knownFrictionLaws(), &friction::knownStatefulFrictionLaws(),
          &friction::knownDynamicFrictionLaws()})
      if (std::find(known->begin(), known->end(), name) != known->end() || name == "tabulated")
        throw SceneError(name_ + ": user friction law '" + name +
                         "' takes a built-in law's name; give it another");
    if (!law) throw SceneError(name_ + ": user friction law '" + name + "' is empty");
  }
  try {
    return Loader(name_, *root_, package_paths, user_laws).load(overrides, settings);
  } catch (const YAML::Exception& e) {  // any the reader did not foresee
    yamlError(e, name_);
  }
}

Scene loadSceneFromString(const std::string& yaml, const std::string& name_for_errors,
                          const std::vector<std::string>& overrides,
                          const std::vector<std::string>& package_paths,
                          const RunSettings& settings, const UserLaws& user_laws) {
  return SceneDocument(yaml, name_for_errors).load(overrides, package_paths, settings, user_laws);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides,
                const std::vector<std::string>& package_paths, const RunSettings& settings,
                const UserLaws& user_laws) {
  if (const std::size_t bad = firstBadUtf8(path); bad != std::string::npos)
    throw SceneError("scene file path '" + printableText(path) + "': expected UTF-8 text, found " +
                     badUtf8Reason(path, bad));
  if (looksLikeUrdf(path))
    throw SceneError(path + ": a URDF robot (its first element is <robot>), not a scene file: " +
                     "load it with sceneFromUrdf (`tribo run FILE`) or name it in a scene's " +
                     "robots:");
  std::string text;
  try {
    text = readFileBounded(path, "scene file", kMaxSceneBytes);
  } catch (const FileReadError& e) {
    throw SceneError(e.what());
  }
  return loadSceneFromString(text, path, overrides, package_paths, settings, user_laws);
}

}  // namespace tribo::io
