// glTF 2.0 meshes: a tetrahedron and a cube written here as .gltf with a .bin beside it, .gltf
// with a base64 data URI and .glb load as the same vertices as the same solid written as OBJ
// (glTF's Y-up is not turned: coordinates as written), with the volume and centroid computed
// by hand; node translations, rotations and scales move the vertices as the glTF 2.0 spec
// says (T * R * S, parents first). Missing and truncated buffers, truncated .glb files, URL
// and absolute buffer URIs, out-of-range accessors and indices, node cycles, empty and
// far-flung meshes are refused with a MeshError naming the file. A URDF robot whose collision
// mesh is a .glb gets the inertia and lowest point of that solid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "contact/mesh_shape.hpp"
#include "contact/shape_inertia.hpp"
#include "core/model_builder.hpp"
#include "io/mesh_loader.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::contact {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

// A solid as positions and outward triangles.
struct Solid {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

Solid tetrahedron() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
          {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

Solid cube() {
  Solid s;
  for (int k = 0; k < 8; ++k) s.vertices.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  s.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return s;
}

template <class T>
void append(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

// The binary buffer: float positions, then 16-bit indices, padded to 4 bytes.
std::string buffer(const Solid& s) {
  std::string out;
  for (const auto& v : s.vertices)
    for (int i = 0; i < 3; ++i) append(out, static_cast<float>(v(i)));
  for (const auto& t : s.triangles)
    for (int i : t) append(out, static_cast<std::uint16_t>(i));
  while (out.size() % 4 != 0) out.push_back('\0');
  return out;
}

// The JSON of a glTF holding `s` in one buffer (`uri` empty: a .glb's chunk), its mesh in
// node `mesh_node` of `nodes`.
std::string json(const Solid& s, const std::string& uri,
                 const std::string& nodes = R"([{"mesh": 0}])") {
  const std::size_t positions = 12 * s.vertices.size(), indices = 6 * s.triangles.size();
  std::ostringstream o;
  o << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" << nodes
    << R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],)"
    << R"( "buffers": [{"byteLength": )" << buffer(s).size()
    << (uri.empty() ? "" : R"(, "uri": ")" + uri + "\"") << "}],"
    << R"( "bufferViews": [{"buffer": 0, "byteLength": )" << positions
    << R"(}, {"buffer": 0, "byteOffset": )" << positions << R"(, "byteLength": )" << indices
    << "}],"
    << R"( "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" << s.vertices.size()
    << R"(, "type": "VEC3"}, {"bufferView": 1, "componentType": 5123, )"
    << R"("count": )" << 3 * s.triangles.size() << R"(, "type": "SCALAR"}]})";
  return o.str();
}

std::string base64(const std::string& in) {
  static const char* const kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    std::uint32_t n = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) n |= static_cast<unsigned char>(in[i + 1]) << 8;
    if (i + 2 < in.size()) n |= static_cast<unsigned char>(in[i + 2]);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < in.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += i + 2 < in.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

std::string dataUri(const Solid& s) {
  return "data:application/octet-stream;base64," + base64(buffer(s));
}

// A .glb of `text` (JSON) and `bin`, each chunk padded to 4 bytes.
std::string glb(std::string text, std::string bin) {
  while (text.size() % 4 != 0) text.push_back(' ');
  while (bin.size() % 4 != 0) bin.push_back('\0');
  std::string out = "glTF";
  append(out, std::uint32_t{2});
  append(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  append(out, static_cast<std::uint32_t>(text.size()));
  out += "JSON" + text;
  append(out, static_cast<std::uint32_t>(bin.size()));
  out += std::string("BIN\0", 4) + bin;
  return out;
}

std::string obj(const Solid& s) {
  std::ostringstream o;
  for (const auto& v : s.vertices) o << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : s.triangles)
    o << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return o.str();
}

class GltfMesh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tribo_gltf_test_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }

  // The message of the MeshError loading `path` throws ("" when none).
  static std::string errorOf(const std::string& path) {
    try {
      io::loadMesh(path);
    } catch (const MeshError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

bool has(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

// The vertices, sorted, for comparing meshes whatever their order.
std::vector<std::array<double, 3>> sorted(const MeshData& m) {
  std::vector<std::array<double, 3>> out;
  for (const auto& v : m.vertices) out.push_back({v.x(), v.y(), v.z()});
  std::sort(out.begin(), out.end());
  return out;
}

TEST_F(GltfMesh, BinFileDataUriAndGlbReadAsTheSameSolidAsObj) {
  const Solid t = tetrahedron();
  write("tet.bin", buffer(t));
  const auto from_obj = io::loadMesh(write("tet.obj", obj(t)));
  for (const std::string& path :
       {write("tet.gltf", json(t, "tet.bin")), write("inline.gltf", json(t, dataUri(t))),
        write("tet.glb", glb(json(t, ""), buffer(t))),
        write("UPPER.GLB", glb(json(t, ""), buffer(t)))}) {
    const auto mesh = io::loadMesh(path);
    EXPECT_EQ(mesh->source, path);
    EXPECT_EQ(mesh->vertices.size(), 4u) << path;
    EXPECT_EQ(mesh->triangles.size(), 4u) << path;
    EXPECT_EQ(sorted(*mesh), sorted(*from_obj)) << path;  // Y-up not turned: as written
    // The corner tetrahedron: volume 1/6, centroid at a quarter of each edge.
    const auto p = solidMassProperties(Shape::convexMesh(makeConvex(*mesh)), 1.0);
    EXPECT_NEAR(p.volume, 1.0 / 6.0, 1e-12) << path;
    EXPECT_TRUE(p.centroid.isApprox(Eigen::Vector3d(0.25, 0.25, 0.25), 1e-12)) << path;
    // Scaled by (2, 3, 4): volume 4, bounding box to (2, 3, 4).
    const auto scaled = io::loadMesh(path, {2.0, 3.0, 4.0});
    EXPECT_NEAR(solidMassProperties(Shape::convexMesh(makeConvex(*scaled)), 1.0).volume, 4.0,
                1e-12);
  }
  // From memory: a data URI and a .glb read; a buffer file cannot be.
  for (const auto& [hint, text] : std::vector<std::pair<std::string, std::string>>{
           {"gltf", json(t, dataUri(t))}, {"glb", glb(json(t, ""), buffer(t))}}) {
    const auto mesh = io::loadMeshFromMemory(Bytes(text.begin(), text.end()), hint, "mem." + hint);
    EXPECT_EQ(sorted(*mesh), sorted(*from_obj)) << hint;
  }
  const std::string external = json(t, "tet.bin");
  try {
    io::loadMeshFromMemory(Bytes(external.begin(), external.end()), "gltf", "mem.gltf");
    ADD_FAILURE() << "an external buffer read from memory";
  } catch (const MeshError& e) {
    EXPECT_TRUE(has(e.what(), "mem.gltf") && has(e.what(), "'tet.bin'")) << e.what();
  }
}

TEST_F(GltfMesh, NodeTransformsMoveTheVerticesAsTheSpecSays) {
  const Solid t = tetrahedron();
  // A parent translating by (1, 2, 3); its child rotating 90 degrees about z (quaternion x, y,
  // z, w) after scaling by (2, 3, 4): v -> (1, 2, 3) + Rz(90) (2 x, 3 y, 4 z), i.e.
  // (1 - 3 y, 2 + 2 x, 3 + 4 z).
  const double h = std::sqrt(0.5);
  std::ostringstream nodes;
  nodes.precision(17);
  nodes << R"([{"translation": [1, 2, 3], "children": [1]}, {"mesh": 0, "rotation": [0, 0, )" << h
        << ", " << h << R"(], "scale": [2, 3, 4]}])";
  std::vector<Eigen::Vector3d> expected;
  for (const auto& v : t.vertices)
    expected.emplace_back(1 - 3 * v.y(), 2 + 2 * v.x(), 3 + 4 * v.z());
  for (const std::string& path : {write("moved.glb", glb(json(t, "", nodes.str()), buffer(t))),
                                  write("moved.gltf", json(t, dataUri(t), nodes.str()))}) {
    const auto mesh = io::loadMesh(path);
    ASSERT_EQ(mesh->vertices.size(), 4u);
    for (const auto& e : expected) {
      const bool found =
          std::any_of(mesh->vertices.begin(), mesh->vertices.end(),
                      [&](const Eigen::Vector3d& v) { return (v - e).norm() < 1e-6; });
      EXPECT_TRUE(found) << path << ": " << e.transpose();
    }
    // Volume scales by 2 * 3 * 4.
    EXPECT_NEAR(solidMassProperties(Shape::convexMesh(makeConvex(*mesh)), 1.0).volume, 4.0, 1e-5);
  }
  // A matrix (column-major) doing the same as the translation alone.
  const std::string matrix = R"([{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,2,3,1]}])";
  const auto moved = io::loadMesh(write("matrix.glb", glb(json(t, "", matrix), buffer(t))));
  double z_min = 1e9;
  for (const auto& v : moved->vertices) z_min = std::min(z_min, v.z());
  EXPECT_DOUBLE_EQ(z_min, 3.0);
}

TEST_F(GltfMesh, BuffersOutsideTheFolderAreReadRelativeToIt) {
  const Solid t = tetrahedron();
  write("shared/tet%20a.bin", "");  // a file literally named with '%20' is not the one meant
  write("shared/tet a.bin", buffer(t));
  EXPECT_EQ(io::loadMesh(write("robot/meshes/tet.gltf", json(t, "../../shared/tet%20a.bin")))
                ->vertices.size(),
            4u);
}

TEST_F(GltfMesh, MissingTruncatedAndFarAwayBuffersAreRefused) {
  const Solid t = tetrahedron();
  const std::string missing = write("missing.gltf", json(t, "nothere.bin"));
  const std::string e1 = errorOf(missing);
  EXPECT_TRUE(has(e1, missing) && has(e1, "nothere.bin") && has(e1, "No such file")) << e1;

  write("short.bin", buffer(t).substr(0, 40));
  const std::string short_gltf = write("short.gltf", json(t, "short.bin"));
  const std::string e2 = errorOf(short_gltf);
  EXPECT_TRUE(has(e2, short_gltf) && has(e2, "short.bin") && has(e2, "holds 40 bytes")) << e2;

  const std::string full = glb(json(t, ""), buffer(t));
  for (const std::size_t cut : {std::size_t{10}, std::size_t{30}, full.size() - 4}) {
    const std::string cut_glb = write("cut.glb", full.substr(0, cut));
    const std::string e = errorOf(cut_glb);
    EXPECT_TRUE(has(e, cut_glb)) << cut << ": " << e;
  }
  const std::string e3 = errorOf(write("cut.glb", full.substr(0, full.size() - 4)));
  EXPECT_TRUE(has(e3, "truncated")) << e3;

  const std::string short_uri = dataUri(t).substr(0, dataUri(t).size() - 8);
  EXPECT_TRUE(has(errorOf(write("d.gltf", json(t, short_uri))), "holds 66 bytes")) << short_uri;

  for (const std::string url : {"http://example.com/tet.bin", "HTTPS://example.com/tet.bin"})
    EXPECT_TRUE(has(errorOf(write("url.gltf", json(t, url))), "buffers are not downloaded")) << url;
  EXPECT_TRUE(has(errorOf(write("f.gltf", json(t, "file:///tmp/tet.bin"))), "a 'file:' URI"));
  write("tet.bin", buffer(t));
  EXPECT_TRUE(
      has(errorOf(write("abs.gltf", json(t, (dir_ / "tet.bin").string()))), "an absolute path"));
}

TEST_F(GltfMesh, AccessorsIndicesNodesAndEmptyFilesAreChecked) {
  const Solid t = tetrahedron();
  const std::string bin = buffer(t);
  const auto error = [&](const std::string& text) {
    return errorOf(write("bad.glb", glb(text, bin)));
  };
  const std::string good = json(t, "");
  const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  EXPECT_TRUE(has(error(replaced(good, R"("count": 4,)", R"("count": 5,)")),
                  "accessor 0: count 5 of 12 bytes reads 60 bytes of bufferView 0, which has 48"));
  EXPECT_TRUE(has(error(replaced(good, R"("count": 4,)", R"("count": 4000000000,)")),
                  "accessor 0: count 4000000000"));
  EXPECT_TRUE(has(error(replaced(good, R"("byteLength": 48)", R"("byteLength": 4800)")),
                  "bufferView 0: bytes 0 + 4800 reach past buffer 0's 72 bytes"));
  EXPECT_TRUE(has(error(replaced(good, R"("byteLength": 72)", R"("byteLength": 7200)")),
                  "buffer 0: byteLength 7200, the binary chunk holds 72 bytes"));
  // An index past the 4 vertices (the last triangle's last corner, 3, made 9): assimp drops
  // that triangle (no vertex read past the mesh), the 3 others stay.
  std::string far_index = bin;
  far_index[48 + 22] = 9;
  EXPECT_EQ(io::loadMesh(write("index.glb", glb(good, far_index)))->triangles.size(), 3u);
  EXPECT_TRUE(has(error(replaced(good, R"([{"mesh": 0}])",
                                 R"([{"children": [1]}, {"mesh": 0, "children": [0]}])")),
                  "cycle"));
  EXPECT_TRUE(has(error(replaced(good, R"("version": "2.0")", R"("version": "1.0")")),
                  "expected glTF 2.0"));
  EXPECT_TRUE(has(error(std::string(100, '[') + std::string(100, ']')), "nested more than 64"));
  // No mesh in any node: no triangle.
  const std::string empty =
      R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{}]})";
  EXPECT_TRUE(has(errorOf(write("empty.gltf", empty)), "expected at least one triangle"));
  // Vertices moved past the length limit by a node's scale: refused as for any file.
  const std::string far =
      errorOf(write("far.glb", glb(json(t, "", R"([{"mesh": 0, "scale": [1e7, 1, 1]}])"), bin)));
  EXPECT_TRUE(has(far, "far.glb") && has(far, "expected coordinates within +-1000000 m")) << far;
}

TEST_F(GltfMesh, UrdfRobotWithAGlbCollisionMeshGetsItsInertia) {
  // The unit cube centred on the link's origin by its node: mass 6 spreads to inertia
  // 6 (1 + 1) / 12 = 1 about each axis; its lowest point at z = -0.5.
  const Solid c = cube();
  const std::string nodes = R"([{"mesh": 0, "translation": [-0.5, -0.5, -0.5]}])";
  write("meshes/cube.glb", glb(json(c, "", nodes), buffer(c)));
  const std::string urdf = write("robot.urdf", R"(<robot name="r">
  <link name="block">
    <inertial><mass value="6"/></inertial>
    <collision><geometry><mesh filename="meshes/cube.glb"/></geometry></collision>
    <visual><geometry><mesh filename="meshes/cube.glb"/></geometry></visual>
  </link>
</robot>
)");
  const io::UrdfRobot robot = io::readUrdf(urdf);
  ModelBuilder builder;
  const io::UrdfModelResult result = io::addUrdfRobot(builder, robot, io::UrdfPlacement{});
  ASSERT_EQ(builder.bodies().size(), 1u);
  EXPECT_TRUE(builder.bodies()[0].inertia.isApprox(Eigen::Matrix3d::Identity(), 1e-9))
      << builder.bodies()[0].inertia;
  EXPECT_NEAR(result.lowest_point, -0.5, 1e-12);
}

}  // namespace
}  // namespace tribo::contact
