// Binary STL bytes of a mesh (80-byte header, triangle count, per triangle a zero normal and
// three float32 corners, a zero attribute) and the hulls the hostile-input tests use: a unit
// cube with one corner moved far away, a tetrahedron with one far vertex, a thin plate. Not
// here: expectations; each test states its own.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace tribo::test {

struct HullSpec {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // outward, counter-clockwise
};

inline std::string binaryStl(const HullSpec& h) {
  std::string out(80, ' ');
  auto put32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
  };
  auto putFloat = [&](double v) {
    const float f = static_cast<float>(v);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    put32(bits);
  };
  put32(static_cast<std::uint32_t>(h.triangles.size()));
  for (const auto& t : h.triangles) {
    for (int k = 0; k < 3; ++k) putFloat(0.0);
    for (int i : t)
      for (int k = 0; k < 3; ++k) putFloat(h.vertices[static_cast<std::size_t>(i)](k));
    out.push_back('\0');
    out.push_back('\0');
  }
  return out;
}

// Cube of edge 1 centred on the origin; corner 7 (+x +y +z) moved to (far, 0.5, 0.5).
inline HullSpec cubeWithFarCorner(double far) {
  HullSpec h;
  for (int k = 0; k < 8; ++k)
    h.vertices.emplace_back((k & 1) ? 0.5 : -0.5, (k & 2) ? 0.5 : -0.5, (k & 4) ? 0.5 : -0.5);
  h.vertices[7] = Eigen::Vector3d(far, 0.5, 0.5);
  h.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return h;
}

// Tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,far): convex for any far > 0.
inline HullSpec tetrahedronWithFarVertex(double far) {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, far}},
          {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
}

// A square plate of edge 1 and the given thickness (a box's 8 corners).
inline HullSpec plate(double thickness) {
  HullSpec h = cubeWithFarCorner(0.5);
  for (auto& v : h.vertices) v.z() *= thickness;
  return h;
}

}  // namespace tribo::test
