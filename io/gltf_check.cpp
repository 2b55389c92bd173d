#include "io/gltf_check.hpp"

#include <cctype>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "contact/mesh_shape.hpp"
#include "io/file_read.hpp"

namespace tribo::io {

using contact::MeshError;
using Json = nlohmann::json;
using Count = std::uint64_t;

namespace {

constexpr Count kHuge = std::numeric_limits<Count>::max();
Count times(Count a, Count b) { return (a != 0 && b > kHuge / a) ? kHuge : a * b; }
Count plus(Count a, Count b) { return b > kHuge - a ? kHuge : a + b; }

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw MeshError("mesh file '" + name + "': " + what);
}

std::uint32_t le32(std::span<const unsigned char> b, std::size_t at) {
  return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
         static_cast<std::uint32_t>(b[at + 2]) << 16 | static_cast<std::uint32_t>(b[at + 3]) << 24;
}

// The parts of a .glb: its JSON text and its binary chunk (empty when it has none).
struct Glb {
  std::string_view json;
  std::span<const unsigned char> bin;
  bool has_bin = false;
};

constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

Glb splitGlb(std::span<const unsigned char> b, const std::string& name) {
  if (b.size() < 20)
    fail(name, "a .glb starts with a 12-byte header and an 8-byte chunk header, found " +
                   std::to_string(b.size()) + " bytes");
  if (b[0] != 'g' || b[1] != 'l' || b[2] != 'T' || b[3] != 'F')
    fail(name, "expected a binary glTF file (starting 'glTF'), found other bytes");
  if (le32(b, 4) != 2) fail(name, "expected glTF version 2, found " + std::to_string(le32(b, 4)));
  if (le32(b, 8) != b.size())
    fail(name, "its header gives a length of " + std::to_string(le32(b, 8)) +
                   " bytes, the file holds " + std::to_string(b.size()) + " (truncated?)");
  const Count json_length = le32(b, 12);
  if (le32(b, 16) != kJsonChunk) fail(name, "expected the JSON chunk first");
  if (20 + json_length > b.size())
    fail(name, "its JSON chunk of " + std::to_string(json_length) + " bytes runs past the end");
  Glb glb;
  glb.json = {reinterpret_cast<const char*>(b.data() + 20), json_length};
  const std::size_t at = 20 + json_length;
  if (at == b.size()) return glb;
  if (at + 8 > b.size()) fail(name, "a chunk header is cut off after the JSON chunk");
  const Count bin_length = le32(b, at);
  if (le32(b, at + 4) != kBinChunk) return glb;  // chunks of other kinds are ignored
  if (at + 8 + bin_length > b.size())
    fail(name, "its binary chunk of " + std::to_string(bin_length) + " bytes runs past the end");
  glb.bin = b.subspan(at + 8, bin_length);
  glb.has_bin = true;
  return glb;
}

// Nesting of arrays and objects, strings skipped: refused past kMaxGltfNesting.
void checkNesting(std::string_view text, const std::string& name) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxGltfNesting)
        fail(name, "JSON nested more than " + std::to_string(kMaxGltfNesting) + " deep");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// The array `key` of `object`, or an empty array when it is absent.
const Json& arrayOf(const Json& object, const char* key, const std::string& name) {
  static const Json kEmpty = Json::array();
  const auto it = object.find(key);
  if (it == object.end()) return kEmpty;
  if (!it->is_array()) fail(name, std::string("'") + key + "': expected an array");
  return *it;
}

// The whole number `key` of `object` (`fallback` when absent; required when it is nullopt).
Count whole(const Json& object, const char* key, std::optional<Count> fallback,
            const std::string& where, const std::string& name) {
  const auto it = object.is_object() ? object.find(key) : object.end();
  if (it == object.end()) {
    if (!fallback) fail(name, where + ": '" + key + "' missing");
    return *fallback;
  }
  if (!it->is_number_unsigned())
    fail(name, where + ": '" + key + "': expected a whole number >= 0, found " + it->dump());
  return it->get<Count>();
}

std::string at(const char* kind, std::size_t i) {
  return std::string(kind) + " " + std::to_string(i);
}

bool isBase64(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
         c == '/';
}

// The bytes a base64 data URI's payload decodes to.
Count dataUriBytes(const std::string& uri, const std::string& where, const std::string& name) {
  const auto comma = uri.find(',');
  if (comma == std::string::npos || !uri.substr(0, comma).ends_with(";base64"))
    fail(name, where + ": expected a base64 data URI ('data:...;base64,...')");
  const std::string_view data = std::string_view(uri).substr(comma + 1);
  std::size_t padding = 0;
  while (padding < 2 && padding < data.size() && data[data.size() - 1 - padding] == '=') ++padding;
  for (std::size_t i = 0; i + padding < data.size(); ++i)
    if (!isBase64(data[i]))
      fail(name, where + ": its data URI holds '" + std::string(1, data[i]) +
                     "', not a base64 character");
  if (data.size() % 4 != 0)
    fail(name, where + ": its data URI's base64 text has " + std::to_string(data.size()) +
                   " characters, expected a multiple of 4");
  return data.size() / 4 * 3 - padding;
}

// The bytes each buffer holds (its byteLength, checked to be there).
std::vector<Count> checkBuffers(const Json& doc, const Glb* glb,
                                const std::optional<std::filesystem::path>& folder,
                                const std::string& name) {
  std::vector<Count> sizes;
  const Json& buffers = arrayOf(doc, "buffers", name);
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    const std::string where = at("buffer", i);
    const Count length = whole(buffers[i], "byteLength", std::nullopt, where, name);
    const auto uri = buffers[i].find("uri");
    Count held = 0;
    std::string source;
    if (uri == buffers[i].end()) {
      if (glb == nullptr || i != 0 || !glb->has_bin)
        fail(name, where + ": no 'uri', and it is not a .glb's binary chunk");
      held = glb->bin.size();
      source = "the binary chunk";
    } else if (!uri->is_string()) {
      fail(name, where + ": 'uri': expected a string");
    } else if (uri->get<std::string>().starts_with("data:")) {
      held = dataUriBytes(uri->get<std::string>(), where, name);
      source = "its data URI";
    } else {
      const auto path = gltfBufferPath(uri->get<std::string>(), folder, name);
      try {
        held = checkReadableFile(path, "glTF buffer file", kMaxMeshBytes);
      } catch (const FileReadError& e) {
        fail(name, where + ": " + e.what());
      }
      source = "file '" + path.string() + "'";
    }
    if (held < length)
      fail(name, where + ": byteLength " + std::to_string(length) + ", " + source + " holds " +
                     std::to_string(held) + " bytes (truncated?)");
    sizes.push_back(length);
  }
  return sizes;
}

struct View {
  Count length = 0;
  Count stride = 0;  // 0: tightly packed
};

std::vector<View> checkViews(const Json& doc, const std::vector<Count>& buffers,
                             const std::string& name) {
  std::vector<View> views;
  const Json& list = arrayOf(doc, "bufferViews", name);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = at("bufferView", i);
    const Count buffer = whole(list[i], "buffer", std::nullopt, where, name);
    const Count offset = whole(list[i], "byteOffset", 0, where, name);
    const Count length = whole(list[i], "byteLength", std::nullopt, where, name);
    const Count stride = whole(list[i], "byteStride", 0, where, name);
    if (buffer >= buffers.size())
      fail(name, where + ": buffer " + std::to_string(buffer) + ", the file has " +
                     std::to_string(buffers.size()));
    if (plus(offset, length) > buffers[buffer])
      fail(name, where + ": bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                     " reach past buffer " + std::to_string(buffer) + "'s " +
                     std::to_string(buffers[buffer]) + " bytes");
    if (stride != 0 && (stride < 4 || stride > 252))
      fail(name, where + ": byteStride " + std::to_string(stride) + ", expected 4 to 252");
    views.push_back({length, stride});
  }
  return views;
}

Count componentBytes(Count type, const std::string& where, const std::string& name) {
  switch (type) {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
    default:
      fail(name, where + ": componentType " + std::to_string(type) + " is not glTF's");
  }
}

Count components(const Json& accessor, const std::string& where, const std::string& name) {
  const auto it = accessor.find("type");
  const std::string type = (it != accessor.end() && it->is_string()) ? it->get<std::string>() : "";
  for (const auto& [word, n] : {std::pair<const char*, Count>{"SCALAR", 1},
                                {"VEC2", 2},
                                {"VEC3", 3},
                                {"VEC4", 4},
                                {"MAT2", 4},
                                {"MAT3", 9},
                                {"MAT4", 16}})
    if (type == word) return n;
  fail(name, where + ": 'type': expected SCALAR, VEC2 to VEC4 or MAT2 to MAT4");
}

void checkAccessors(const Json& doc, const std::vector<View>& views, Count file_bytes,
                    const std::string& name) {
  const Json& list = arrayOf(doc, "accessors", name);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = at("accessor", i);
    const Json& a = list[i];
    if (!a.is_object()) fail(name, where + ": expected an object");
    if (a.contains("sparse")) fail(name, where + ": sparse accessors are not read");
    const Count element =
        componentBytes(whole(a, "componentType", std::nullopt, where, name), where, name) *
        components(a, where, name);
    const Count count = whole(a, "count", std::nullopt, where, name);
    if (count == 0) fail(name, where + ": count 0, expected at least 1");
    if (!a.contains("bufferView")) {  // all zeros
      if (times(count, element) > file_bytes)
        fail(name, where + ": count " + std::to_string(count) +
                       " without a bufferView: more values than the file's " +
                       std::to_string(file_bytes) + " bytes could describe");
      continue;
    }
    const Count view = whole(a, "bufferView", std::nullopt, where, name);
    if (view >= views.size())
      fail(name, where + ": bufferView " + std::to_string(view) + ", the file has " +
                     std::to_string(views.size()));
    const Count stride = views[view].stride != 0 ? views[view].stride : element;
    const Count end =
        plus(plus(whole(a, "byteOffset", 0, where, name), times(count - 1, stride)), element);
    if (end > views[view].length)
      fail(name, where + ": count " + std::to_string(count) + " of " + std::to_string(element) +
                     " bytes reads " + std::to_string(end) + " bytes of bufferView " +
                     std::to_string(view) + ", which has " + std::to_string(views[view].length));
  }
}

// Every node has at most one parent, no node is its own ancestor, no path is too deep.
void checkNodes(const Json& doc, const std::string& name) {
  const Json& nodes = arrayOf(doc, "nodes", name);
  std::vector<int> parents(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (const Json& c : arrayOf(nodes[i], "children", name)) {
      if (!c.is_number_unsigned() || c.get<Count>() >= nodes.size())
        fail(name, at("node", i) + ": child " + c.dump() + " is not one of the file's " +
                       std::to_string(nodes.size()) + " nodes");
      if (++parents[c.get<std::size_t>()] > 1)
        fail(name, "node " + c.dump() + " is the child of more than one node");
    }
  std::vector<std::pair<std::size_t, int>> stack;  // node, depth
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (parents[i] == 0) stack.emplace_back(i, 1);
  std::size_t reached = 0;
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    ++reached;
    if (depth > kMaxGltfNodeDepth)
      fail(name, "nodes nested more than " + std::to_string(kMaxGltfNodeDepth) + " deep");
    for (const Json& c : arrayOf(nodes[node], "children", name))
      stack.emplace_back(c.get<std::size_t>(), depth + 1);
  }
  if (reached != nodes.size()) fail(name, "its nodes' children form a cycle");
}

void checkDocument(std::string_view text, const Glb* glb,
                   const std::optional<std::filesystem::path>& folder, Count file_bytes,
                   const std::string& name) {
  checkNesting(text, name);
  const Json doc = Json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) fail(name, "cannot read it: not a JSON object");
  const Json* version = nullptr;
  if (const auto asset = doc.find("asset"); asset != doc.end() && asset->contains("version"))
    version = &(*asset)["version"];
  if (version == nullptr || !version->is_string() || !version->get<std::string>().starts_with("2."))
    fail(name, "expected glTF 2.0 (asset.version \"2.0\")");
  if (doc.contains("scene")) whole(doc, "scene", 0, "the document", name);
  const auto buffers = checkBuffers(doc, glb, folder, name);
  checkAccessors(doc, checkViews(doc, buffers, name), file_bytes, name);
  checkNodes(doc, name);
}

// %XX escapes decoded.
std::string percentDecoded(const std::string& uri, const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out.push_back(uri[i]);
      continue;
    }
    const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
    if (i + 2 >= uri.size() || !hex(uri[i + 1]) || !hex(uri[i + 2]))
      fail(name, "buffer URI '" + uri + "': a '%' not followed by two hex digits");
    out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
    i += 2;
  }
  return out;
}

// The scheme of a URI ("http" of "http://..."), empty for a relative reference.
std::string schemeOf(const std::string& uri) {
  const auto colon = uri.find(':');
  if (colon == std::string::npos || colon == 0) return "";
  for (std::size_t i = 0; i < colon; ++i) {
    const char c = uri[i];
    if (!std::isalpha(static_cast<unsigned char>(c)) &&
        (i == 0 ||
         !(std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.')))
      return "";
  }
  return uri.substr(0, colon);
}

}  // namespace

std::filesystem::path gltfBufferPath(const std::string& uri,
                                     const std::optional<std::filesystem::path>& folder,
                                     const std::string& name) {
  const std::string quoted = "buffer URI '" + uri + "'";
  if (uri.empty()) fail(name, "a buffer URI is empty");
  std::string scheme = schemeOf(uri);
  for (char& c : scheme) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (scheme == "http" || scheme == "https")
    fail(name, quoted + ": buffers are not downloaded; expected a file named relative to the " +
                   ".gltf's folder, or a data URI");
  if (!scheme.empty())
    fail(name, quoted + ": expected a file named relative to the .gltf's folder, or a data " +
                   "URI, found a '" + scheme + ":' URI");
  const std::string decoded = percentDecoded(uri, name);
  if (decoded.starts_with('/') || decoded.starts_with('\\'))
    fail(name, quoted + ": an absolute path; expected one relative to the .gltf's folder");
  if (decoded.find('\0') != std::string::npos) fail(name, quoted + ": holds a NUL character");
  if (!folder)
    fail(name, quoted + ": a file beside the glTF, which is read from memory: only data URIs " +
                   "and a .glb's own chunk are read");
  return *folder / decoded;
}

void checkGltf(std::span<const unsigned char> bytes, bool binary,
               const std::optional<std::filesystem::path>& folder, const std::string& name) {
  if (!binary) {
    checkDocument({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, nullptr, folder,
                  bytes.size(), name);
    return;
  }
  const Glb glb = splitGlb(bytes, name);
  checkDocument(glb.json, &glb, folder, bytes.size(), name);
}

}  // namespace tribo::io
