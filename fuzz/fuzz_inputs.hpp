// What each libFuzzer harness does with one input, as inline functions, so that the harnesses
// (fuzz/*_fuzzer.cpp) and the GoogleTest replay of the committed seeds and regressions
// (tests/study/fuzz_regressions_test.cpp, in every build) run the same code. Each function
// swallows the typed error its loader promises for bad input; anything else (another
// exception, a crash, a sanitizer report, an abort on a broken contract) is a finding.
// Input formats are described in docs/fuzzing.md.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "contact/collision_detector.hpp"
#include "contact/mesh_shape.hpp"
#include "fuzz/urdf_tree_input.hpp"
#include "io/mesh_loader.hpp"
#include "io/scene_expression.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_parameters.hpp"
#include "io/urdf_reader.hpp"
#include "study/sweep/sweep_grid.hpp"

namespace tribo::fuzz {

// The pieces of `text` between '\n's (an empty text gives one empty piece).
inline std::vector<std::string> lines(std::string_view text) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find('\n', begin);
    out.emplace_back(text.substr(begin, end == std::string_view::npos ? end : end - begin));
    if (end == std::string_view::npos) return out;
    begin = end + 1;
  }
}

// Scene YAML text; lines "#set NAME=VALUE" (YAML comments, so seeds stay valid scenes) are
// also --set overrides. Bad input: io::SceneError.
inline void sceneYaml(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  constexpr std::string_view kSet = "#set ";
  for (const auto& line : lines(text))
    if (line.starts_with(kSet)) overrides.push_back(line.substr(kSet.size()));
  try {
    (void)io::loadSceneFromString(text, "fuzz.yaml", overrides);
  } catch (const io::SceneError&) {
  }
}

// URDF text. Bad input: io::UrdfError, or issues in the robot read; a robot read without
// errors has only finite numbers, none negative where a negative is wrong (checkReadRobot).
inline void urdf(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    const io::UrdfRobot robot = io::readUrdfFromString(xml, "fuzz.urdf");
    if (!robot.hasErrors()) checkReadRobot(robot);
  } catch (const io::UrdfError&) {
  }
}

// A mesh that loaded and passed the convexity check (contact::makeConvex) meets a box: one
// collision query through contact/ (FCL's narrowphase, libccd, the face manifold), which must
// return. Small meshes only (the query is the point, not the hull's size).
inline void collideWithBox(const std::shared_ptr<const contact::MeshData>& mesh) {
  if (mesh->vertices.size() > 256) return;
  std::shared_ptr<const contact::MeshData> hull;
  try {
    hull = contact::makeConvex(*mesh);
  } catch (const contact::MeshError&) {
    return;
  }
  using contact::Shape;
  contact::CollisionDetector detector({Shape::convexMesh(hull), Shape::box({1.0, 1.0, 0.5})},
                                      {{0, 1}});
  // The box's top face through the hull's centre of vertices, so the two overlap.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& v : hull->vertices) centre += v;
  centre /= static_cast<double>(hull->vertices.size());
  Eigen::Isometry3d box = Eigen::Isometry3d::Identity();
  box.translation() = centre - Eigen::Vector3d(0, 0, 0.5);
  const std::array poses{Eigen::Isometry3d(Eigen::Isometry3d::Identity()), box};
  std::vector<contact::ContactPoint> points;
  detector.detect(poses, points);
}

// First byte: the format hint (0 stl, 1 obj, 2 dae; modulo 3), then the file's bytes.
// Bad input: contact::MeshError. A mesh read is then tried as a convex hull against a box.
inline void mesh(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  static const char* const kHints[] = {"stl", "obj", "dae"};
  const std::string hint = kHints[data[0] % 3];
  std::shared_ptr<const contact::MeshData> read;
  try {
    read = io::loadMeshFromMemory(std::span(data + 1, size - 1), hint, "fuzz." + hint);
  } catch (const contact::MeshError&) {
    return;
  }
  collideWithBox(read);
}

// Near-degenerate and far-flung convex hulls (docs/fuzzing.md): first byte: the shape (modulo
// 2: 0 a cube, 1 a tetrahedron); then 4 bytes per vertex: a magnitude 10^(b0 % 43 - 12) (1e-12
// to 1e30 m) and a displacement (b1, b2, b3) / 127 times it, added to the unit shape's vertex
// (missing bytes: no displacement). Written as a binary STL, read with io::loadMeshFromMemory,
// then as mesh() does. Bad input: contact::MeshError.
inline void hull(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  static const std::vector<std::array<int, 3>> kCube = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                                        {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                                        {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  static const std::vector<std::array<int, 3>> kTetra = {
      {0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::vector<Eigen::Vector3d> v;
  const bool cube = data[0] % 2 == 0;
  if (cube)
    for (int k = 0; k < 8; ++k)
      v.emplace_back((k & 1) ? 0.5 : -0.5, (k & 2) ? 0.5 : -0.5, (k & 4) ? 0.5 : -0.5);
  else
    v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (std::size_t i = 0; i < v.size() && 1 + 4 * i + 3 < size; ++i) {
    const std::uint8_t* b = data + 1 + 4 * i;
    const double magnitude = std::pow(10.0, static_cast<double>(b[0] % 43) - 12.0);
    v[i] += magnitude / 127.0 *
            Eigen::Vector3d(static_cast<std::int8_t>(b[1]), static_cast<std::int8_t>(b[2]),
                            static_cast<std::int8_t>(b[3]));
  }
  const auto& triangles = cube ? kCube : kTetra;
  std::string stl(80, ' ');
  auto put = [&](const void* p) { stl.append(static_cast<const char*>(p), 4); };
  const auto count = static_cast<std::uint32_t>(triangles.size());
  const std::uint8_t le[4] = {static_cast<std::uint8_t>(count), 0, 0, 0};
  put(le);
  for (const auto& t : triangles) {
    const float zero = 0.0f;
    for (int k = 0; k < 3; ++k) put(&zero);
    for (int i : t)
      for (int k = 0; k < 3; ++k) {
        const float f = static_cast<float>(v[static_cast<std::size_t>(i)](k));
        put(&f);
      }
    stl.append(2, '\0');
  }
  std::shared_ptr<const contact::MeshData> read;
  try {
    read = io::loadMeshFromMemory(
        std::span(reinterpret_cast<const unsigned char*>(stl.data()), stl.size()), "stl",
        "fuzz.stl");
  } catch (const contact::MeshError&) {
    return;
  }
  collideWithBox(read);
}

inline void spanGrid(study::SweepAxis axis) {
  std::vector<study::SweepAxis> axes;
  axes.push_back(std::move(axis));
  const study::SweepGrid grid(std::move(axes));
  if (grid.size() == 0) std::abort();  // an axis without values must have thrown
  (void)grid.overrides(0);
  (void)grid.values(grid.size() - 1);
}

// First byte: the parser (modulo 4), then the argument text:
//   0 io::parseNumber (must give a finite number or nothing)
//   1 --set: the '\n'-separated overrides through ParameterTable::applyOverrides, on a table
//     with a numeric parameter k and a word parameter friction (k must keep a finite value:
//     a number, or an expression that evaluates)
//   2 --grid: study::parseGridAxis, the SweepGrid it spans, its first and last point (text
//     whose COUNT field is a plain number from 100001 to 1000000 is skipped)
//   3 --list: study::parseListAxis, the same
// Bad input: io::SceneError, study::SweepSpecError.
inline void cliValues(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 4) {
      case 0: {
        const auto v = io::parseNumber(text);
        if (v && !std::isfinite(*v)) std::abort();
        break;
      }
      case 1: {
        io::ParameterTable table;
        table.add("k", "2.5e5", {"fuzz.yaml", 1, 1});
        table.add("friction", "coulomb", {"fuzz.yaml", 2, 1});
        table.applyOverrides(lines(text), "fuzz.yaml");
        // k was checked when overridden: it must evaluate to a finite number.
        double k = 0;
        try {
          k = io::evaluateExpression("$k", table, {"fuzz.yaml", 1, 1}, "k");
        } catch (const io::SceneError&) {
          std::abort();
        }
        if (!std::isfinite(k)) std::abort();
        break;
      }
      case 2: {
        // COUNT from 1e5 to kMaxPoints: skipped. Such grids are made value by value (a
        // million take 0.5 s in Release, longer under ASan) and only slow the fuzzer down; above
        // kMaxPoints they are refused before any value is made, and are fuzzed.
        // The count is read as the parser reads it (leading zeros included: "01000000" once
        // slipped past a test of the text's length), its blanks around it trimmed.
        std::string_view count = text.substr(text.rfind(':') + 1);
        while (!count.empty() && std::isspace(static_cast<unsigned char>(count.front())))
          count.remove_prefix(1);
        while (!count.empty() && std::isspace(static_cast<unsigned char>(count.back())))
          count.remove_suffix(1);
        long points = 0;
        const auto read = std::from_chars(count.data(), count.data() + count.size(), points);
        if (read.ec == std::errc() && points > 100000 && points <= 1000000) break;
        spanGrid(study::parseGridAxis(text));
        break;
      }
      default:
        spanGrid(study::parseListAxis(text));
        break;
    }
  } catch (const io::SceneError&) {
  } catch (const study::SweepSpecError&) {
  }
}

}  // namespace tribo::fuzz
