#include "io/mesh_loader.hpp"

#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string_view>

#include "io/collada_check.hpp"
#include "io/file_read.hpp"
#include "io/gltf_check.hpp"
#include "io/obj_reader.hpp"

namespace tribo::io {

using contact::MeshData;
using contact::MeshError;

namespace {

// Every node's meshes, in the file's frame (the transforms of the node and its ancestors
// applied), appended to `out`; a face naming a vertex the mesh does not have is refused.
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, MeshData& out,
             const std::string& name) {
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
      for (unsigned k = 0; k < 3; ++k)
        if (face.mIndices[k] >= mesh.mNumVertices)
          throw MeshError("mesh file '" + name + "': a triangle names vertex " +
                          std::to_string(face.mIndices[k]) + " of a mesh of " +
                          std::to_string(mesh.mNumVertices) + " vertices");
      out.triangles.push_back({base + static_cast<int>(face.mIndices[0]),
                               base + static_cast<int>(face.mIndices[1]),
                               base + static_cast<int>(face.mIndices[2])});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    collect(scene, *node.mChildren[c], transform, out, name);
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

// The importer settings both entry points share.
void configure(Assimp::Importer& importer) {
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_COLORS |
                                                          aiComponent_TEXCOORDS |
                                                          aiComponent_MATERIALS);
}

constexpr unsigned kSteps = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                            aiProcess_RemoveComponent | aiProcess_SortByPType;

void checkScale(const std::string& name, const Eigen::Vector3d& scale) {
  if (!scale.allFinite() || !(scale.minCoeff() > 0.0))
    throw MeshError("mesh file '" + name + "': scale must be 3 numbers > 0");
}

// The format of a file extension or hint, in lower case: "stl", "obj", "dae", "gltf" or
// "glb".
std::string format(const std::string& written, const std::string& name) {
  std::string f(written.starts_with('.') ? written.substr(1) : written);
  for (char& c : f) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (f != "stl" && f != "obj" && f != "dae" && f != "gltf" && f != "glb")
    throw MeshError("mesh file '" + name + "': expected an STL, OBJ, DAE, glTF or GLB file " +
                    "(by its extension), found '" + written + "'");
  return f;
}

// The folder assimp is told a glTF file is in: the buffers it asks for are named in it.
const std::string kGltfFolder = "/tribo-gltf/";

// The files assimp opens for a glTF: the file itself from memory, its buffers from the
// .gltf's folder (gltfBufferPath; checkGltf has checked them), read whole within
// kMaxMeshBytes. Nothing else is opened, nothing written.
class GltfFiles : public Assimp::IOSystem {
 public:
  GltfFiles(std::span<const unsigned char> bytes, std::string main,
            std::optional<std::filesystem::path> folder, std::string name)
      : bytes_(bytes), main_(std::move(main)), folder_(std::move(folder)), name_(std::move(name)) {}

  bool Exists(const char* file) const override {
    return file == main_ || resolve(file).has_value();
  }
  char getOsSeparator() const override { return '/'; }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::string_view(mode).find_first_of("wa+") != std::string_view::npos) return nullptr;
    if (file == main_) return new Assimp::MemoryIOStream(bytes_.data(), bytes_.size());
    const auto path = resolve(file);
    if (!path) return nullptr;
    try {
      const std::string data = readFileBounded(*path, "glTF buffer file", kMaxMeshBytes);
      auto* copy = new uint8_t[data.size()];
      std::copy(data.begin(), data.end(), copy);
      return new Assimp::MemoryIOStream(copy, data.size(), true);
    } catch (const FileReadError&) {
      return nullptr;
    }
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

 private:
  // The file a buffer name assimp asks for stands for, when it is one.
  std::optional<std::filesystem::path> resolve(const std::string& file) const {
    if (!file.starts_with(kGltfFolder)) return std::nullopt;
    try {
      return gltfBufferPath(file.substr(kGltfFolder.size()), folder_, name_);
    } catch (const MeshError&) {
      return std::nullopt;
    }
  }

  std::span<const unsigned char> bytes_;
  std::string main_;
  std::optional<std::filesystem::path> folder_;
  std::string name_;
};

// Scaled and welded, a mesh that holds at least one triangle.
std::shared_ptr<const MeshData> finish(MeshData&& read, const std::string& name,
                                       const Eigen::Vector3d& scale) {
  auto mesh = std::make_shared<MeshData>(std::move(read));
  mesh->source = name;
  if (mesh->triangles.empty())
    throw MeshError("mesh file '" + name + "': expected at least one triangle, found none");
  for (std::size_t i = 0; i < mesh->vertices.size(); ++i) {
    auto& v = mesh->vertices[i];
    v = v.cwiseProduct(scale);
    if (v.allFinite() && v.cwiseAbs().maxCoeff() <= contact::kMaxLength) continue;
    const std::string what = "mesh file '" + name + "': vertex " + std::to_string(i) +
                             " (after scale " + contact::lengthText(scale.x()) + ", " +
                             contact::lengthText(scale.y()) + ", " +
                             contact::lengthText(scale.z()) + ")";
    if (!v.allFinite()) throw MeshError(what + ": expected finite coordinates");
    throw MeshError(contact::outsideLengthLimit(what, v));
  }
  weld(*mesh);
  return mesh;
}

// A glTF through assimp after checkGltf, its buffers found through GltfFiles.
const aiScene* readGltf(Assimp::Importer& importer, std::span<const unsigned char> bytes,
                        const std::string& format,
                        const std::optional<std::filesystem::path>& folder,
                        const std::string& name) {
  checkGltf(bytes, format == "glb", folder, name);
  const std::string main = kGltfFolder + "mesh." + format;
  importer.SetIOHandler(new GltfFiles(bytes, main, folder, name));  // the importer owns it
  return importer.ReadFile(main, kSteps | aiProcess_ValidateDataStructure);
}

// STL, COLLADA and glTF through assimp, from memory: every node's meshes merged. `folder`
// holds a .gltf's buffer files (none: only embedded buffers).
MeshData readWithAssimp(std::span<const unsigned char> bytes, const std::string& format,
                        const std::optional<std::filesystem::path>& folder,
                        const std::string& name) {
  if (format == "dae")
    checkColladaSizes({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, name);
  Assimp::Importer importer;
  configure(importer);
  const aiScene* scene =
      format == "gltf" || format == "glb"
          ? readGltf(importer, bytes, format, folder, name)
          : importer.ReadFileFromMemory(bytes.data(), bytes.size(), kSteps, format.c_str());
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw MeshError("mesh file '" + name + "': cannot read it (" + importer.GetErrorString() + ")");
  MeshData mesh;
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), mesh, name);
  return mesh;
}

// loadMeshFromMemory with the folder of the file the bytes came from.
std::shared_ptr<const MeshData> load(std::span<const unsigned char> bytes, const std::string& hint,
                                     const std::string& name, const Eigen::Vector3d& scale,
                                     const std::optional<std::filesystem::path>& folder) {
  checkScale(name, scale);
  const std::string f = format(hint, name);
  if (bytes.empty()) throw MeshError("mesh file '" + name + "': cannot read it (no bytes)");
  if (f == "obj")
    return finish(readObj({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, name), name,
                  scale);
  return finish(readWithAssimp(bytes, f, folder, name), name, scale);
}

}  // namespace

std::shared_ptr<const MeshData> loadMesh(const std::string& path, const Eigen::Vector3d& scale) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw MeshError("mesh file '" + path + "': cannot open (no such file)");
  std::string bytes, hint;
  try {
    checkReadableFile(path, "mesh file", kMaxMeshBytes);  // what it is, before its name
    hint = format(std::filesystem::path(path).extension().string(), path);
    bytes = readFileBounded(path, "mesh file", kMaxMeshBytes);
  } catch (const FileReadError& e) {
    throw MeshError(e.what());
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  return load(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()), hint,
              path, scale, folder.empty() ? std::filesystem::path(".") : folder);
}

std::shared_ptr<const MeshData> loadMeshFromMemory(std::span<const unsigned char> bytes,
                                                   const std::string& hint,
                                                   const std::string& name_for_errors,
                                                   const Eigen::Vector3d& scale) {
  return load(bytes, hint, name_for_errors, scale, std::nullopt);
}

}  // namespace tribo::io
