#include "contact/mesh_loader.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <assimp/Importer.hpp>
#include <filesystem>
#include <map>
#include <sstream>

namespace tribo::contact {

namespace {

void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, MeshData& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    const int base = static_cast<int>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
      out.triangles.push_back({base + static_cast<int>(face.mIndices[0]),
                               base + static_cast<int>(face.mIndices[1]),
                               base + static_cast<int>(face.mIndices[2])});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    collect(scene, *node.mChildren[c], transform, out);
}

// Joins vertices with identical coordinates (several meshes of one file share corners).
void weld(MeshData& mesh) {
  std::map<std::array<double, 3>, int> index;
  std::vector<int> map(mesh.vertices.size());
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d& v = mesh.vertices[i];
    const auto [it, added] =
        index.try_emplace({v.x(), v.y(), v.z()}, static_cast<int>(kept.size()));
    if (added) kept.push_back(v);
    map[i] = it->second;
  }
  mesh.vertices = std::move(kept);
  std::vector<std::array<int, 3>> triangles;
  for (auto t : mesh.triangles) {
    for (int& i : t) i = map[i];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
  mesh.triangles = std::move(triangles);
}

}  // namespace

std::shared_ptr<const MeshData> loadMesh(const std::string& path, const Eigen::Vector3d& scale) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshError("mesh file '" + path + "': cannot open (expected an STL, OBJ or DAE file)");
  if (!scale.allFinite() || !(scale.minCoeff() > 0.0))
    throw MeshError("mesh file '" + path + "': scale must be 3 numbers > 0");
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_COLORS |
                                                          aiComponent_TEXCOORDS |
                                                          aiComponent_MATERIALS);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_RemoveComponent | aiProcess_SortByPType);
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw MeshError("mesh file '" + path + "': cannot read it (" + importer.GetErrorString() + ")");
  auto mesh = std::make_shared<MeshData>();
  mesh->source = path;
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), *mesh);
  if (mesh->triangles.empty())
    throw MeshError("mesh file '" + path + "': expected at least one triangle, found none");
  for (auto& v : mesh->vertices) v = v.cwiseProduct(scale);
  weld(*mesh);
  return mesh;
}

std::shared_ptr<const MeshData> makeConvex(const MeshData& mesh) {
  auto out = std::make_shared<MeshData>(mesh);
  const std::string who = "convex mesh '" + (mesh.source.empty() ? "(inline)" : mesh.source) + "'";
  if (out->vertices.size() < 4 || out->triangles.size() < 4)
    throw MeshError(who + ": expected a closed polyhedron (>= 4 vertices and faces), found " +
                    std::to_string(out->vertices.size()) + " vertices, " +
                    std::to_string(out->triangles.size()) + " triangles");
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double extent = 0.0;
  for (const auto& v : out->vertices) centre += v;
  centre /= static_cast<double>(out->vertices.size());
  for (const auto& v : out->vertices) extent = std::max(extent, (v - centre).norm());
  const double tolerance = 1e-9 * extent;
  for (std::size_t f = 0; f < out->triangles.size(); ++f) {
    auto& t = out->triangles[f];
    const Eigen::Vector3d& a = out->vertices[t[0]];
    Eigen::Vector3d n = (out->vertices[t[1]] - a).cross(out->vertices[t[2]] - a);
    if (n.norm() <= 1e-300) continue;  // degenerate triangle: no plane to check
    n.normalize();
    if (n.dot(centre - a) > 0.0) {  // faces inwards: turn it
      std::swap(t[1], t[2]);
      n = -n;
    }
    for (std::size_t v = 0; v < out->vertices.size(); ++v) {
      const double above = n.dot(out->vertices[v] - a);
      if (above > tolerance) {
        std::ostringstream s;
        s << who << ": not convex: vertex " << v << " lies " << above << " m above face " << f
          << " (expected every vertex on or below every face; use shape: mesh for a "
             "non-convex surface)";
        throw MeshError(s.str());
      }
    }
  }
  return out;
}

MeshData boxMeshData(const Eigen::Vector3d& h) {
  MeshData m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(),
                            (k & 4) ? h.z() : -h.z());
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

}  // namespace tribo::contact
