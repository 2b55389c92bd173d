// Scene reader (io/scene_reader.hpp): bodies and their geometry, robots (URDF files placed in
// the scene), their links' Gazebo tags, and bodies by name.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <utility>

#include "contact/shape_inertia.hpp"
#include "core/prescribed_motion.hpp"
#include "io/mesh_loader.hpp"
#include "io/package_paths.hpp"
#include "io/scene_keys.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_signal.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::io::scene_detail {

void Loader::readBody(const Value& v) {
  const Map m(v, scene_keys::kBody);
  Body body;
  body.name = m.required("name").text();
  if (auto k = m.get("kind"))
    body.kind = k->choice(scene_keys::kBodyKinds) == 0 ? BodyKind::kDynamic : BodyKind::kKinematic;
  body.position = m.vec3("position", Vec3::Zero());
  body.orientation = orientation(m);
  readMotion(m, body);
  if (auto s = m.get("surface_velocity")) {
    // Numbers as before; a signal in any component makes the surface's speed vary in time.
    std::array<Signal, 3> signals = readSignals3(*s);
    for (int i = 0; i < 3; ++i) body.surface_velocity[i] = signals[i].value(0.0);
    if (std::any_of(signals.begin(), signals.end(),
                    [](const Signal& c) { return c.kind() != Signal::Kind::kConstant; }))
      body.surface_velocity_signal =
          std::make_shared<const std::array<Signal, 3>>(std::move(signals));
  }
  std::vector<GeometrySpec> geometries;
  if (auto g = m.get("geometry"))
    for (const Value& item : g->items("geometries", true)) geometries.push_back(readGeometry(item));

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
    auto box = std::find_if(geometries.begin(), geometries.end(),
                            [](const auto& g) { return g.shape.type == contact::ShapeType::kBox; });
    if (box == geometries.end())
      box = std::find_if(geometries.begin(), geometries.end(), [](const auto& g) {
        return g.shape.type != contact::ShapeType::kHalfSpace &&
               g.shape.type != contact::ShapeType::kTriangleMesh;
      });
    if (box == geometries.end())
      v.fail("missing key 'inertia' (needed by a dynamic body without solid geometry)");
    const Mat3 local = guarded(
        box->at, [&] { return Mat3(contact::solidMassProperties(box->shape, body.mass).inertia); });
    const Mat3 r = box->pose.linear();
    body.inertia = r * local * r.transpose();
  }
  auto add = [&](const Body& b, const std::string& suffix) {
    const BodyIndex index = guarded(v, [&] { return builder_.addBody(b); });
    for (const auto& g : geometries) {
      const int id = guarded(
          g.at, [&] { return builder_.addGeometry(g.name + suffix, index, g.shape, g.pose); });
      builder_.setGeometrySurface(id, g.surface);
      builder_.setCollisionFilter(id, g.group, g.mask);
      geometry_names_.push_back(g.name + suffix);
    }
  };
  for (const auto& g : geometries) body_surfaces_.insert(g.surface);  // once, not per copy
  const auto pattern = m.get("pattern");
  if (!pattern) {
    add(body, "");
    return;
  }
  const std::vector<PatternCopy> copies = readPattern(*pattern);
  builder_.reserve(copies.size(), copies.size() * geometries.size());
  for (const PatternCopy& copy : copies) {
    Body b = body;
    b.name += copy.suffix;
    b.position += copy.offset;
    add(b, copy.suffix);
  }
}

// `pattern: {grid: [nx, ny, nz], spacing: [dx, dy, dz], jitter: J, seed: S}`: the body
// nx ny nz times, copy (i, j, k) moved by (i dx, j dy, k dz) plus, with a jitter, a uniform
// offset in [-J, J] per axis drawn from a 64-bit Mersenne twister seeded with S (its raw
// output scaled, so the same seed gives the same scene with any standard library); each copy
// and its geometries named with the suffix _i_j_k.
std::vector<Loader::PatternCopy> Loader::readPattern(const Value& v) {
  const Map m(v, scene_keys::kBodyPattern);
  const Value grid = m.required("grid");
  const std::vector<double> n = grid.numbers({3}, "3 counts [nx, ny, nz], each >= 1");
  for (double c : n)
    if (!(c >= 1.0) || c != std::floor(c) || c > kMaxPatternBodies)
      grid.fail("expected 3 whole counts >= 1 [nx, ny, nz], found " + grid.found());
  const double total = n[0] * n[1] * n[2];
  if (total > kMaxPatternBodies)
    grid.fail("the pattern makes " + std::to_string(static_cast<long long>(total)) +
              " bodies, more than the " +
              std::to_string(static_cast<long long>(kMaxPatternBodies)) + " one entry may make");
  const Value spacing_value = m.required("spacing");
  const Vec3 spacing = spacing_value.vec3("3 distances [dx, dy, dz] [m]");
  if (!(spacing.cwiseAbs().maxCoeff() < 1e6))
    spacing_value.fail("expected 3 finite distances below 1e6 m, found " + spacing_value.found());
  double jitter = 0.0;
  if (auto j = m.get("jitter")) {
    jitter = j->number();
    if (!(jitter >= 0.0) || !(jitter < 1e6))
      j->fail("expected a distance >= 0 [m], found " + j->found());
  }
  const std::uint64_t seed =
      m.get("seed") ? static_cast<std::uint64_t>(m.get("seed")->integer(0)) : 1u;
  std::mt19937_64 random(seed);
  auto uniform = [&] {  // in [-1, 1): 53 bits of the engine's raw output
    return 2.0 * static_cast<double>(random() >> 11) * 0x1.0p-53 - 1.0;
  };
  std::vector<PatternCopy> copies;
  copies.reserve(static_cast<std::size_t>(total));
  const int nx = static_cast<int>(n[0]), ny = static_cast<int>(n[1]), nz = static_cast<int>(n[2]);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        PatternCopy c;
        // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "_" + std::string.
        c.suffix.append(1, '_').append(std::to_string(i)).append(1, '_');
        c.suffix.append(std::to_string(j)).append(1, '_').append(std::to_string(k));
        c.offset = Vec3(i * spacing.x(), j * spacing.y(), k * spacing.z());
        if (jitter > 0.0) {
          const double dx = uniform(), dy = uniform(), dz = uniform();
          c.offset += jitter * Vec3(dx, dy, dz);
        }
        copies.push_back(std::move(c));
      }
  return copies;
}

// `velocity` and `angular_velocity`: numbers, or for a kinematic body signals in any
// component (core/prescribed_motion.hpp); a varying turn is about one world axis.
void Loader::readMotion(const Map& m, Body& body) {
  const auto velocity = m.get("velocity");
  const auto spin = m.get("angular_velocity");
  auto varies = [](const std::array<Signal, 3>& s) {
    return std::any_of(s.begin(), s.end(),
                       [](const Signal& c) { return c.kind() != Signal::Kind::kConstant; });
  };
  std::array<Signal, 3> linear, angular;
  if (velocity) linear = readSignals3(*velocity);
  if (spin) angular = readSignals3(*spin);
  for (int i = 0; i < 3; ++i) {
    body.velocity[i] = linear[i].value(0.0);
    body.angular_velocity[i] = angular[i].value(0.0);
  }
  if (!varies(linear) && !varies(angular)) return;
  const Value& where = varies(linear) ? *velocity : *spin;
  if (body.kind != BodyKind::kKinematic)
    where.fail(
        "a velocity that varies in time is for a kinematic body (this body is dynamic: "
        "its velocity is an initial value; a load drives it)");
  auto motion = std::make_shared<PrescribedMotion>();
  motion->velocity = linear;
  if (varies(angular)) {
    int axis = -1;
    for (int i = 0; i < 3; ++i) {
      if (angular[i].isZero()) continue;
      if (axis >= 0)
        spin->fail(
            "a turning rate that varies in time is about one world axis: give one "
            "component a signal and the others 0, found " +
            spin->found() +
            " (a revolute joint driven along a signal turns a body about any axis)");
      axis = i;
    }
    motion->spin_axis = Vec3::Unit(axis);
    motion->spin_rate = angular[axis];
  } else if (body.angular_velocity.norm() > 0.0) {
    motion->spin_axis = body.angular_velocity.normalized();
    motion->spin_rate = Signal::constant(body.angular_velocity.norm());
  }
  body.motion = std::move(motion);
}

GeometrySpec Loader::readGeometry(const Value& v) {
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
    if (!(edges.minCoeff() > 0.0)) size.fail("expected 3 edge lengths > 0, found " + size.found());
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

void Loader::readRobot(const Value& v) {
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
void Loader::applyGazeboTags() {
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

BodyIndex Loader::body(const Value& v) const {
  const std::string name = v.text();
  if (auto index = builder_.findBody(name)) return *index;
  Keys known{"world"};
  for (const auto& b : builder_.bodies()) known.push_back(b.name);
  v.fail("unknown body '" + name + "' (known bodies: " + joined(known) + ")");
}

}  // namespace tribo::io::scene_detail
