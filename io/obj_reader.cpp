#include "io/obj_reader.hpp"

#include <Eigen/Geometry>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tribo::io {

using contact::MeshData;
using contact::MeshError;

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// A number as std::from_chars reads it, a leading '+' allowed too.
template <typename T>
bool parse(std::string_view s, T& value) {
  if (s.size() > 1 && s.front() == '+' && s[1] != '-') s.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && ptr == s.data() + s.size();
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const std::size_t begin = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > begin) out.push_back(line.substr(begin, i - begin));
  }
  return out;
}

// The face's corners (3 or more, as vertex indices) cut into triangles: ear clipping in the
// plane of the polygon's Newell normal; a corner that makes no ear (a polygon folded over
// itself) ends the clipping with a fan of what is left.
void triangulate(const std::vector<Eigen::Vector3d>& vertices, const std::vector<int>& corners,
                 std::vector<std::array<int, 3>>& out) {
  const std::size_t n = corners.size();
  if (n == 3) {
    out.push_back({corners[0], corners[1], corners[2]});
    return;
  }
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i)
    normal += vertices[corners[i]].cross(vertices[corners[(i + 1) % n]]);
  const bool flat = !(normal.squaredNorm() > 0.0) || !normal.allFinite();  // no plane: a fan
  // Two axes of the plane the polygon is seen in, counter-clockwise about the normal.
  const Eigen::Vector3d u = flat ? Eigen::Vector3d::UnitX() : normal.unitOrthogonal();
  const Eigen::Vector3d v = normal.cross(u);
  std::vector<Eigen::Vector2d> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& x = vertices[corners[i]];
    p[i] = {x.dot(u), x.dot(v)};
  }
  const auto cross = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (p[b] - p[a]).x() * (p[c] - p[a]).y() - (p[b] - p[a]).y() * (p[c] - p[a]).x();
  };
  std::vector<std::size_t> left(n);
  for (std::size_t i = 0; i < n; ++i) left[i] = i;
  std::size_t at = 0;
  std::size_t tried = 0;
  while (!flat && left.size() > 3 && tried < left.size()) {
    const std::size_t m = left.size();
    const std::size_t a = left[(at + m - 1) % m], b = left[at % m], c = left[(at + 1) % m];
    bool ear = cross(a, b, c) > 0.0;
    for (std::size_t k = 0; ear && k < m; ++k) {
      const std::size_t q = left[k];
      if (q == a || q == b || q == c || p[q] == p[a] || p[q] == p[b] || p[q] == p[c]) continue;
      ear = !(cross(a, b, q) >= 0.0 && cross(b, c, q) >= 0.0 && cross(c, a, q) >= 0.0);
    }
    if (ear) {
      out.push_back({corners[a], corners[b], corners[c]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(at % m));
      tried = 0;
    } else {
      ++at;
      ++tried;
    }
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k)
    out.push_back({corners[left[0]], corners[left[k]], corners[left[k + 1]]});
}

}  // namespace

MeshData readObj(std::string_view text, const std::string& name) {
  MeshData mesh;
  mesh.source = name;
  // Faces keep their written indices until every vertex is read (a face may name a later one).
  struct Face {
    int line;
    std::vector<std::int64_t> corners;
  };
  std::vector<Face> faces;
  int line_number = 0;
  std::size_t pos = 0;
  std::string joined;  // a line continued with '\'
  int first_line = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    while (!line.empty() && isBlank(line.back())) line.remove_suffix(1);
    if (!line.empty() && line.back() == '\\') {
      if (joined.empty()) first_line = line_number;
      joined.append(line.substr(0, line.size() - 1)).push_back(' ');
      continue;
    }
    if (!joined.empty()) {
      joined.append(line);
      line = joined;
    } else {
      first_line = line_number;
    }
    const auto fail = [&](const std::string& what) {
      throw MeshError("mesh file '" + name + "': line " + std::to_string(first_line) + ": " + what);
    };
    const std::vector<std::string_view> w = words(line);
    if (!w.empty() && w[0] == "v") {
      if (w.size() < 4) fail("a vertex needs 3 coordinates, found " + std::to_string(w.size() - 1));
      Eigen::Vector3d x;
      for (int k = 0; k < 3; ++k) {
        const std::string_view s = w[static_cast<std::size_t>(k) + 1];
        double value = 0.0;
        if (!parse(s, value) || !std::isfinite(value))
          fail("vertex coordinate '" + std::string(s) + "': expected a finite number");
        x[k] = value;
      }
      mesh.vertices.push_back(x);
    } else if (!w.empty() && w[0] == "f") {
      if (w.size() < 4) fail("a face needs 3 corners, found " + std::to_string(w.size() - 1));
      Face face{first_line, {}};
      const auto count = static_cast<std::int64_t>(mesh.vertices.size());
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string_view s = w[k].substr(0, w[k].find('/'));
        std::int64_t index = 0;
        if (!parse(s, index) || index == 0)
          fail("face corner '" + std::string(w[k]) + "': expected a vertex index (1 is the first)");
        if (index < 0) {
          if (-index > count)
            fail("face corner " + std::string(w[k]) + ": only " + std::to_string(count) +
                 " vertices before it");
          index += count + 1;
        }
        face.corners.push_back(index - 1);
      }
      faces.push_back(std::move(face));
    }
    joined.clear();
  }
  const auto count = static_cast<std::int64_t>(mesh.vertices.size());
  std::vector<int> corners;
  for (const Face& face : faces) {
    corners.clear();
    for (const std::int64_t i : face.corners) {
      if (i >= count)
        throw MeshError("mesh file '" + name + "': line " + std::to_string(face.line) +
                        ": face corner " + std::to_string(i + 1) + ": the file has " +
                        std::to_string(count) + " vertices");
      corners.push_back(static_cast<int>(i));
    }
    triangulate(mesh.vertices, corners, mesh.triangles);
  }
  return mesh;
}

}  // namespace tribo::io
