#include "study/view/view_scene.hpp"

#include <nlohmann/json.hpp>

namespace tribo::study {

namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
nlohmann::json quat(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

nlohmann::json geometryJson(const Geometry& g) {
  const contact::Shape& s = g.shape;
  nlohmann::json j = {{"name", g.name},
                      {"shape", contact::shapeName(s.type)},
                      {"position", vec(g.local_pose.translation())},
                      {"quaternion", quat(Eigen::Quaterniond(g.local_pose.rotation()))}};
  switch (s.type) {
    case contact::ShapeType::kBox:
      j["half_extents"] = vec(s.half_extents);
      break;
    case contact::ShapeType::kSphere:
    case contact::ShapeType::kCylinder:
    case contact::ShapeType::kCapsule:
    case contact::ShapeType::kCone:
      j["radius"] = s.radius;
      j["half_length"] = s.half_length;
      break;
    case contact::ShapeType::kHalfSpace:
      break;
    case contact::ShapeType::kConvexMesh:
    case contact::ShapeType::kTriangleMesh: {
      if (!s.mesh) break;
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.0), hi = lo;
      if (!s.mesh->vertices.empty()) lo = hi = s.mesh->vertices.front();
      for (const auto& v : s.mesh->vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      if (s.mesh->triangles.size() > kViewMeshTriangleCap) {
        j["shape"] = "box";  // too large to embed: its bounding box stands in
        j["position"] = vec(g.local_pose * (0.5 * (lo + hi)));
        j["half_extents"] = vec(0.5 * (hi - lo));
        j["note"] = "mesh of " + std::to_string(s.mesh->triangles.size()) +
                    " triangles drawn as its bounding box";
        break;
      }
      nlohmann::json vertices = nlohmann::json::array();
      for (const auto& v : s.mesh->vertices) {
        vertices.push_back(v.x());
        vertices.push_back(v.y());
        vertices.push_back(v.z());
      }
      nlohmann::json triangles = nlohmann::json::array();
      for (const auto& t : s.mesh->triangles)
        for (int i : t) triangles.push_back(i);
      j["vertices"] = std::move(vertices);
      j["triangles"] = std::move(triangles);
      break;
    }
  }
  return j;
}

}  // namespace

std::string viewSceneJson(const Model& model) {
  nlohmann::json bodies = nlohmann::json::array();
  for (const Body& b : model.bodies)
    bodies.push_back({{"name", b.name},
                      {"kind", b.kind == BodyKind::kKinematic ? "kinematic" : "dynamic"},
                      {"position", vec(b.position)},
                      {"quaternion", quat(b.orientation)},
                      {"velocity", vec(b.velocity)},
                      {"surface_velocity", vec(b.surface_velocity)},
                      {"geometries", nlohmann::json::array()}});
  nlohmann::json world = nlohmann::json::array();
  for (const Geometry& g : model.geometries) {
    if (g.body.isWorld()) {
      world.push_back(geometryJson(g));
      continue;
    }
    nlohmann::json j = geometryJson(g);
    // The direction the surface moves in: the body's surface_velocity read in the
    // geometry's frame (surfaceVelocityOf in core/model.hpp), here in the body frame.
    const Vec3& v = model.bodies[static_cast<std::size_t>(g.body.value)].surface_velocity;
    if (v.squaredNorm() > 0.0) j["surface_velocity"] = vec(g.local_pose.linear() * v);
    bodies[static_cast<std::size_t>(g.body.value)]["geometries"].push_back(std::move(j));
  }
  nlohmann::json springs = nlohmann::json::array();
  for (const SpringDamper& s : model.springs)
    springs.push_back({{"name", s.name},
                       {"kind", "spring"},
                       {"a", s.body_a.value},
                       {"point_a", vec(s.point_a)},
                       {"b", s.body_b.value},
                       {"point_b", vec(s.point_b)},
                       {"stiffness", s.stiffness},
                       {"damping", s.damping},
                       {"rest_length", s.rest_length}});
  for (const Bushing& s : model.bushings)
    springs.push_back({{"name", s.name},
                       {"kind", "bushing"},
                       {"a", s.body_a.value},
                       {"point_a", vec(s.position_a)},
                       {"b", s.body_b.value},
                       {"point_b", vec(s.position_b)}});
  nlohmann::json joints = nlohmann::json::array();
  for (const Joint& j : model.joints) {
    const Body& child = model.bodies[static_cast<std::size_t>(j.child.value)];
    const Vec3 axis_in_child = j.axes_in_child.col(2);
    joints.push_back({{"name", j.name},
                      {"type", jointTypeName(j.type)},
                      {"parent", j.parent.value},
                      {"child", j.child.value},
                      {"anchor_in_parent", vec(j.anchor_in_parent)},
                      {"axis_in_parent", vec(j.axes_in_parent.col(2))},
                      {"anchor_in_child", vec(j.anchor_in_child)},
                      {"axis_in_child", vec(axis_in_child)},
                      {"anchor", vec(child.position + child.orientation * j.anchor_in_child)},
                      {"axis", vec(child.orientation * axis_in_child)}});
  }
  return nlohmann::json{
      {"bodies", bodies}, {"world", world}, {"springs", springs}, {"joints", joints}}
      .dump();
}

}  // namespace tribo::study
