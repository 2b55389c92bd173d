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
    if (g.body.isWorld())
      world.push_back(geometryJson(g));
    else
      bodies[static_cast<std::size_t>(g.body.value)]["geometries"].push_back(geometryJson(g));
  }
  return nlohmann::json{{"bodies", bodies}, {"world", world}}.dump();
}

}  // namespace tribo::study
