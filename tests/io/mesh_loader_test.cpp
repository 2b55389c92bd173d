// Mesh files: the same unit cube written as ASCII STL, OBJ and COLLADA must load as the same
// closed solid (8 vertices, 12 triangles, volume 1); scaling, convexity checks and unreadable
// files give what the header promises; bytes in memory read the same. Files whose declared
// sizes exceed what they hold (the class of the mesh fuzzer's out-of-memory finding), at
// several sizes, end in MeshError naming what was expected and found; OBJ polygons are cut
// into triangles that cover them.
#include "io/mesh_loader.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "contact/shape_inertia.hpp"

namespace tribo::contact {
namespace {

using io::loadMesh;

namespace fs = std::filesystem;

const double kV[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const int kT[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};

fs::path write(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("tribo_mesh_test_" + name);
  std::ofstream(path) << text;
  return path;
}

std::string stl() {
  std::ostringstream s;
  s << "solid cube\n";
  for (const auto& t : kT) {
    s << " facet normal 0 0 0\n  outer loop\n";
    for (int i : t) s << "   vertex " << kV[i][0] << " " << kV[i][1] << " " << kV[i][2] << "\n";
    s << "  endloop\n endfacet\n";
  }
  s << "endsolid cube\n";
  return s.str();
}

std::string obj() {
  std::ostringstream s;
  for (const auto& v : kV) s << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
  for (const auto& t : kT) s << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return s.str();
}

std::string dae() {
  std::ostringstream pos, idx;
  for (const auto& v : kV) pos << v[0] << " " << v[1] << " " << v[2] << " ";
  for (const auto& t : kT) idx << t[0] << " " << t[1] << " " << t[2] << " ";
  std::ostringstream s;
  s << R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="cube" name="cube"><mesh>
      <source id="cube-pos"><float_array id="cube-pos-array" count="24">)"
    << pos.str() << R"(</float_array>
        <technique_common><accessor source="#cube-pos-array" count="8" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="cube-vtx"><input semantic="POSITION" source="#cube-pos"/></vertices>
      <triangles count="12"><input semantic="VERTEX" source="#cube-vtx" offset="0"/><p>)"
    << idx.str() << R"(</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="n"><instance_geometry url="#cube"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
  return s.str();
}

TEST(MeshLoader, StlObjAndDaeGiveTheSameClosedCube) {
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"cube.stl", stl()}, {"cube.obj", obj()}, {"cube.dae", dae()}}) {
    const fs::path path = write(name, text);
    const auto mesh = loadMesh(path.string());
    EXPECT_EQ(mesh->vertices.size(), 8u) << name;
    EXPECT_EQ(mesh->triangles.size(), 12u) << name;
    const auto p = solidMassProperties(Shape::convexMesh(makeConvex(*mesh)), 1.0);
    EXPECT_NEAR(p.volume, 1.0, 1e-12) << name;
    EXPECT_TRUE(p.centroid.isApprox(Eigen::Vector3d(0.5, 0.5, 0.5), 1e-12)) << name;
    // Scaled by (2, 1, 0.5): volume 1, x extent 2.
    const auto scaled = loadMesh(path.string(), {2.0, 1.0, 0.5});
    double x_max = 0;
    for (const auto& v : scaled->vertices) x_max = std::max(x_max, v.x());
    EXPECT_DOUBLE_EQ(x_max, 2.0) << name;
    fs::remove(path);
  }
}

TEST(MeshLoader, BytesInMemoryReadAsTheFileDoes) {
  for (const auto& [hint, text] : std::vector<std::pair<std::string, std::string>>{
           {"stl", stl()}, {"obj", obj()}, {"dae", dae()}}) {
    const std::vector<unsigned char> bytes(text.begin(), text.end());
    const auto mesh = io::loadMeshFromMemory(bytes, hint, "mem." + hint, {2.0, 1.0, 1.0});
    EXPECT_EQ(mesh->source, "mem." + hint);
    EXPECT_EQ(mesh->vertices.size(), 8u) << hint;
    EXPECT_EQ(mesh->triangles.size(), 12u) << hint;
    double x_max = 0;
    for (const auto& v : mesh->vertices) x_max = std::max(x_max, v.x());
    EXPECT_DOUBLE_EQ(x_max, 2.0) << hint;
  }
  const std::string junk = "this is not a mesh\n";
  const std::vector<unsigned char> bytes(junk.begin(), junk.end());
  try {
    io::loadMeshFromMemory(bytes, "stl", "mem.stl");
    ADD_FAILURE() << "junk read as a mesh";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("mem.stl"), std::string::npos) << e.what();
  }
  EXPECT_THROW(io::loadMeshFromMemory({}, "obj", "empty.obj"), MeshError);
}

TEST(MeshLoader, ConvexityIsCheckedAndInwardFacesAreTurned) {
  auto mesh = loadMesh(write("c.obj", obj()).string());
  MeshData flipped = *mesh;
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  const auto fixed = makeConvex(flipped);
  EXPECT_NEAR(solidMassProperties(Shape::convexMesh(fixed), 1.0).volume, 1.0, 1e-12);
  // Push the (1, 1, 1) corner inwards past the faces it shares with its neighbours: not
  // convex any more.
  MeshData dented = *mesh;
  for (auto& v : dented.vertices)
    if (v.isApprox(Eigen::Vector3d(1, 1, 1))) v = Eigen::Vector3d(0.6, 0.6, 0.6);
  try {
    makeConvex(dented);
    ADD_FAILURE() << "a dented cube passed as convex";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("not convex"), std::string::npos) << e.what();
  }
}

TEST(MeshLoader, MissingOrUnreadableFilesNameTheFile) {
  try {
    loadMesh("/nonexistent/part.stl");
    ADD_FAILURE();
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/part.stl"), std::string::npos);
  }
  const fs::path junk = write("junk.stl", "this is not a mesh\n");
  EXPECT_THROW(loadMesh(junk.string()), MeshError);
  fs::remove(junk);
}

// The message of the MeshError that reading `text` as `hint` throws ("" when none is thrown).
std::string errorOf(const std::string& text, const std::string& hint) {
  const std::vector<unsigned char> bytes(text.begin(), text.end());
  try {
    io::loadMeshFromMemory(bytes, hint, "mem." + hint);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

bool has(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

TEST(MeshLoader, ColladaCountsBeyondWhatTheFileHoldsAreRefused) {
  // An array declaring more values than it holds: past its text, then past the file's bytes.
  for (const std::string count :
       {"25", "1000", "1000000", "4000000000", "99999999999999999999999"}) {
    const std::string e =
        errorOf(replaced(dae(), R"(count="24")", "count=\"" + count + "\""), "dae");
    EXPECT_TRUE(has(e, "mem.dae") && has(e, "line 6") && has(e, "<float_array>") &&
                has(e, "count="))
        << e;
    EXPECT_TRUE(has(e, "its text holds 24 values") || has(e, "bytes could hold")) << e;
  }
  // Triangles whose count needs more indices than the <p> holds (36).
  for (const std::string count : {"13", "100000", "400000000", "4294967295"}) {
    const std::string e = errorOf(
        replaced(dae(), R"(<triangles count="12">)", "<triangles count=\"" + count + "\">"), "dae");
    EXPECT_TRUE(has(e, "line 11") &&
                (has(e, "<triangles count=\"" + count + "\"> needs " +
                            std::to_string(3 * std::stoull(count)) + " indices in its <p>") ||
                 has(e, "<triangles> declares count=" + count + ": more values than the file's")))
        << e;
  }
  {  // an input offset of 1000: 1001 indices per corner
    const std::string e = errorOf(replaced(dae(), R"(offset="0")", R"(offset="1000")"), "dae");
    EXPECT_TRUE(has(e, "needs 36036 indices in its <p> (36 corners, 1001 per vertex), found 36"))
        << e;
  }
  // An accessor reading more values than the file could hold.
  for (const std::string count : {"100000", "3000000000"}) {
    const std::string e = errorOf(
        replaced(dae(), R"(count="8" stride="3")", "count=\"" + count + "\" stride=\"3\""), "dae");
    EXPECT_TRUE(
        has(e, "<accessor> declares count=" + count + " stride=3: more values than the file's"))
        << e;
  }
  // Counts that are not whole numbers.
  for (const std::string count : {"-5", "1e9", "0x10", "&#52;0"}) {
    const std::string e =
        errorOf(replaced(dae(), R"(count="24")", "count=\"" + count + "\""), "dae");
    EXPECT_TRUE(has(e, "<float_array> count='" + count + "': expected a whole number")) << e;
  }
}

TEST(MeshLoader, ColladaAccessorsReadOnlyWhatTheirArrayHolds) {
  // assimp 5.2.5 reads an accessor's values without checking its array's size: past the end,
  // or from address 0 when the array is empty or of names
  // (fuzz/regressions/mesh_fuzzer/crash-dae-accessor-past-array and -name-array-positions).
  const std::string array = R"(<float_array id="cube-pos-array" count="24">)";
  for (const auto& [declared, read] : std::vector<std::pair<std::string, std::string>>{
           {R"(<float_array id="cube-pos-array">)", "0"},
           {R"(<float_array id="cube-pos-array" count="0">)", "0"},
           {R"(<float_array id="cube-pos-array" count="3">)", "3"},
           {R"(<float_array id="cube-pos-array" count="23">)", "23"}}) {
    const std::string e = errorOf(replaced(dae(), array, declared), "dae");
    EXPECT_TRUE(has(e,
                    "line 7: <accessor source=\"#cube-pos-array\" count=\"8\" stride=\"3\" "
                    "offset=\"0\"> reads 24 values, its array declares " +
                        read))
        << e;
  }
  EXPECT_TRUE(has(errorOf(replaced(dae(), R"(stride="3">)", R"(stride="3" offset="1">)"), "dae"),
                  "reads 25 values, its array declares 24"));
  EXPECT_TRUE(
      has(errorOf(replaced(dae(), R"(count="8" stride="3")", R"(count="8" stride="2")"), "dae"),
          "a stride of at least its 3 values per element expected"));
  for (const std::string kind : {"Name_array", "IDREF_array"}) {
    const std::string names =
        replaced(replaced(dae(), array, "<" + kind + R"( id="cube-pos-array" count="24">)"),
                 "</float_array>", "</" + kind + ">");
    EXPECT_TRUE(has(errorOf(names, "dae"), "read by a mesh's <input>: a <float_array> expected"))
        << kind;
  }
}

TEST(MeshLoader, ColladaIndexListsHoldOnlyNumbers) {
  // assimp 5.2.5 reads a <p> until its end and a word that is not a number stops it for good
  // (fuzz/regressions/mesh_fuzzer/oom-dae-p-not-a-number): refused first, with the word.
  for (const std::string word : {"scn", "1x", "x", "0x1F", "1.5", "-"}) {
    const std::string e = errorOf(replaced(dae(), "<p>0 2 1 ", "<p>0 2 " + word + " "), "dae");
    EXPECT_TRUE(has(e, "mem.dae") && has(e, "line 11") && has(e, "<p> holds '" + word + "'")) << e;
  }
  EXPECT_TRUE(
      has(errorOf(replaced(dae(), "<p>0 2 1 ", "<p>0 2 <!-- c -->1 "), "dae"), "<p> holds markup"))
      << "markup";
  // Signs are numbers to assimp; the cube still reads with "+0".
  EXPECT_EQ(errorOf(replaced(dae(), "<p>0 2 1 ", "<p>+0 2 1 "), "dae"), "");
  // A polylist whose vertex counts add up past the file, or have a word in them.
  const std::string poly =
      replaced(replaced(dae(), R"(<triangles count="12">)", R"(<polylist count="12">)"),
               "</p></triangles>", "</p></polylist>");
  const std::string with_vcount =
      replaced(poly, "<p>", "<vcount>3 3 3 3 3 3 3 3 3 3 3 3</vcount><p>");
  EXPECT_EQ(errorOf(with_vcount, "dae"), "");
  for (const std::string first : {"4", "1000", "4000000000"}) {
    const std::string e =
        errorOf(replaced(with_vcount, "<vcount>3 ", "<vcount>" + first + " "), "dae");
    EXPECT_TRUE(has(e, "needs " + std::to_string(33 + std::stoull(first)) + " indices") ||
                has(e, "bytes could hold"))
        << e;
  }
  EXPECT_TRUE(
      has(errorOf(replaced(with_vcount, "<vcount>3 ", "<vcount>a "), "dae"), "<vcount> holds 'a'"));
}

TEST(MeshLoader, BinaryStlWhoseTriangleCountExceedsTheFileIsRefused) {
  // 80-byte header, a triangle count, 50 bytes per triangle: counts far past the bytes given.
  for (const std::uint32_t count : {2u, 1000u, 100000000u, 0xFFFFFFFFu}) {
    std::string bytes(80, 'x');
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>((count >> (8 * k)) & 0xFF));
    bytes.append(50, '\0');
    const std::string e = errorOf(bytes, "stl");
    EXPECT_TRUE(has(e, "mem.stl")) << count << ": " << e;
  }
}

TEST(MeshLoader, ObjIndicesPastTheVerticesAreRefusedWithTheirLine) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (const std::string index : {"4", "1000", "4000000000", "999999999999999999"}) {
    const std::string e = errorOf(v + "f 1 2 " + index + "\n", "obj");
    EXPECT_TRUE(has(e, "mem.obj': line 4: face corner " + index + ": the file has 3 vertices"))
        << e;
  }
  for (const std::string index : {"-4", "-4000000000"})
    EXPECT_TRUE(has(errorOf(v + "f 1 2 " + index + "\n", "obj"), "only 3 vertices before it"));
  for (const std::string corner : {"0", "a", "99999999999999999999999", "1.5"})
    EXPECT_TRUE(has(errorOf(v + "f 1 2 " + corner + "\n", "obj"),
                    "line 4: face corner '" + corner + "': expected a vertex index"));
  for (const std::string x : {"nan", "inf", "1e999", "x"})
    EXPECT_TRUE(has(errorOf("v 0 0 " + x + "\n", "obj"),
                    "line 1: vertex coordinate '" + x + "': expected a finite number"));
  EXPECT_TRUE(has(errorOf("v 0 0\n", "obj"), "a vertex needs 3 coordinates, found 2"));
  EXPECT_TRUE(has(errorOf(v + "f 1 2\n", "obj"), "a face needs 3 corners, found 2"));
  // A face may name a vertex written after it.
  EXPECT_EQ(errorOf("f 1 2 3\n" + v, "obj"), "");
}

TEST(MeshLoader, ObjPolygonsAreCutIntoTrianglesThatCoverThem) {
  // The cube as six quads, corners written in every index form: 12 triangles, volume 1.
  std::ostringstream s;
  s << "# quads\nmtllib none.mtl\no cube\n";
  for (const auto& v : kV) s << "v " << v[0] << " " << v[1] << " " << v[2] << " 1.0\n";
  s << "vt 0 0\nvn 0 0 1\n";
  s << "f 1/1 3/1 4/1 2/1\n"              // z = 0
    << "f 5//1 6//1 8//1 7//1\n"          // z = 1
    << "f -8/1/1 -7/1/1 -3/1/1 -4/1/1\n"  // y = 0: 1 2 6 5
    << "f 3 7 8 \\\n 4\n"                 // y = 1, continued
    << "f 1 5 7 3\nf 2 4 8 6\n";
  const std::string text = s.str();
  const auto mesh = io::loadMeshFromMemory(std::vector<unsigned char>(text.begin(), text.end()),
                                           "OBJ", "quads.obj");
  EXPECT_EQ(mesh->vertices.size(), 8u);
  EXPECT_EQ(mesh->triangles.size(), 12u);
  EXPECT_NEAR(solidMassProperties(Shape::convexMesh(makeConvex(*mesh)), 1.0).volume, 1.0, 1e-12);
  // A concave L-shaped hexagon (area 3) in a tilted plane: 4 triangles, all inside the L,
  // together its area.
  const Eigen::Vector2d l[6] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const Eigen::Vector3d ex = Eigen::Vector3d(1, 0, 1).normalized(), ey(0, 1, 0);
  for (int start = 0; start < 6; ++start) {  // every corner first
    std::ostringstream o;
    o.precision(17);
    for (const auto& p : l) {
      const Eigen::Vector3d x = p.x() * ex + p.y() * ey;
      o << "v " << x.x() << " " << x.y() << " " << x.z() << "\n";
    }
    o << "f";
    for (int k = 0; k < 6; ++k) o << " " << (start + k) % 6 + 1;
    o << "\n";
    const std::string t = o.str();
    const auto m =
        io::loadMeshFromMemory(std::vector<unsigned char>(t.begin(), t.end()), "obj", "l.obj");
    ASSERT_EQ(m->triangles.size(), 4u) << start;
    double area = 0;
    for (const auto& tri : m->triangles) {
      const Eigen::Vector3d a = m->vertices[tri[0]], b = m->vertices[tri[1]],
                            c = m->vertices[tri[2]];
      area += 0.5 * (b - a).cross(c - a).norm();
      const Eigen::Vector3d g = (a + b + c) / 3;
      const double gx = g.dot(ex), gy = g.dot(ey);
      EXPECT_FALSE(gx > 1 && gy > 1) << "triangle outside the L, corner " << start << " first";
    }
    EXPECT_NEAR(area, 3.0, 1e-12) << start;
  }
}

TEST(MeshLoader, OnlyStlObjDaeAndGltfAreRead) {
  const fs::path ply = write("cube.ply", "ply\nformat ascii 1.0\nend_header\n");
  try {
    loadMesh(ply.string());
    ADD_FAILURE() << "a .ply read";
  } catch (const MeshError& e) {
    EXPECT_TRUE(has(e.what(),
                    "expected an STL, OBJ, DAE, glTF or GLB file (by its extension), found '.ply'"))
        << e.what();
  }
  fs::remove(ply);
  const fs::path upper = write("CUBE.STL", stl());
  EXPECT_EQ(loadMesh(upper.string())->triangles.size(), 12u);
  fs::remove(upper);
  EXPECT_TRUE(has(errorOf(stl(), "ply"), "found 'ply'"));
}

}  // namespace
}  // namespace tribo::contact
