// Checks a glTF 2.0 mesh file (.gltf JSON, .glb binary container) before assimp reads it,
// and says where its buffers are. Refused with contact::MeshError naming the file and what
// was expected and found:
//   - a .glb whose header is not 'glTF' version 2, whose declared length differs from the
//     bytes held (a truncated file), or whose JSON or binary chunk runs past its end;
//   - JSON nested deeper than kMaxGltfNesting (assimp's parser recurses per level), text that
//     is not JSON, an asset.version that is not 2.x;
//   - a buffer whose data is not all there: a data URI (base64) holding fewer bytes than its
//     byteLength, an external file that is missing, unreadable, over kMaxMeshBytes or shorter
//     than byteLength, a .glb buffer longer than its binary chunk;
//   - a buffer URI with a scheme (http:, https:, file:, ...) or an absolute path: buffers are
//     read only from data URIs, the .glb's own chunk, or files named relative to the .gltf's
//     folder (`../` allowed, as glTF's relative references are);
//   - a buffer view reaching past its buffer, an accessor reaching past its buffer view (or,
//     without one, more zeros than the file's bytes could describe), a sparse accessor;
//   - a node hierarchy that is not a forest (a node with two parents, a cycle) or deeper
//     than kMaxGltfNodeDepth.
// Not here: reading the geometry (io/mesh_loader.cpp, through assimp), indices past the
// vertices (assimp drops such a triangle; the loader refuses any left in its result),
// materials, images, animations.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace tribo::io {

// JSON nesting (a glTF file nests about 6 deep) and node hierarchy depth, at most.
inline constexpr int kMaxGltfNesting = 64;
inline constexpr int kMaxGltfNodeDepth = 1000;

// The file a buffer's `uri` (not a data URI) names: `folder` / uri, percent escapes decoded.
// Throws contact::MeshError for a URI with a scheme, an absolute path, an empty URI, a bad
// escape, or when there is no folder (bytes read from memory).
std::filesystem::path gltfBufferPath(const std::string& uri,
                                     const std::optional<std::filesystem::path>& folder,
                                     const std::string& name);

// The checks above on a file's bytes; `binary` for .glb; `folder` holds the .gltf (none for
// bytes read from memory: external buffers are refused). Throws contact::MeshError.
void checkGltf(std::span<const unsigned char> bytes, bool binary,
               const std::optional<std::filesystem::path>& folder, const std::string& name);

}  // namespace tribo::io
