#include "contact/shape.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "friction/name_table.hpp"

namespace tribo::contact {

namespace {

Eigen::Vector3d meshHalfExtents(const MeshData& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return 0.5 * (hi - lo);
}

}  // namespace

std::string lengthText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

std::string overLengthLimit(const std::string& what, double found) {
  if (std::isnan(found) || std::abs(found) <= kMaxLength) return {};
  return what + ": expected at most " + lengthText(kMaxLength) + " m, found " + lengthText(found) +
         " m";
}

std::string outsideLengthLimit(const std::string& what, const Eigen::Vector3d& p) {
  if (!(p.cwiseAbs().maxCoeff() > kMaxLength)) return {};
  return what + ": expected coordinates within +-" + lengthText(kMaxLength) + " m, found (" +
         lengthText(p.x()) + ", " + lengthText(p.y()) + ", " + lengthText(p.z()) + ") m";
}

double Shape::size() const {
  switch (type) {
    case ShapeType::kBox:
      return half_extents.minCoeff();
    case ShapeType::kSphere:
      return radius > 0.0 ? radius : std::numeric_limits<double>::infinity();
    case ShapeType::kCapsule:
      return radius;
    case ShapeType::kCylinder:
    case ShapeType::kCone:
      return std::min(radius, half_length);
    case ShapeType::kConvexMesh:
      return mesh ? meshHalfExtents(*mesh).minCoeff() : 0.0;
    case ShapeType::kHalfSpace:
    case ShapeType::kTriangleMesh:
      return std::numeric_limits<double>::infinity();
  }
  return 0.0;
}

double Shape::extent(const Eigen::Vector3d& n) const {
  if (type == ShapeType::kHalfSpace || type == ShapeType::kTriangleMesh || isPoint())
    return std::numeric_limits<double>::infinity();
  return 0.5 * (support(n) + support(-n));
}

double Shape::thinnestHalfWidth() const {
  switch (type) {
    case ShapeType::kCone:
      return size() / std::numbers::sqrt2;
    case ShapeType::kConvexMesh:
      return 0.0;
    default:  // the smallest half dimension bounds the width in every direction
      return size();
  }
}

double Shape::support(const Eigen::Vector3d& d) const {
  switch (type) {
    case ShapeType::kBox:
      return d.cwiseAbs().dot(half_extents);
    case ShapeType::kSphere:
      return radius * d.norm();
    case ShapeType::kCapsule:
      return radius * d.norm() + half_length * std::abs(d.z());
    case ShapeType::kCylinder:
      return radius * std::hypot(d.x(), d.y()) + half_length * std::abs(d.z());
    case ShapeType::kCone:
      return std::max(half_length * d.z(),
                      -half_length * d.z() + radius * std::hypot(d.x(), d.y()));
    case ShapeType::kConvexMesh:
    case ShapeType::kTriangleMesh: {
      double best = -std::numeric_limits<double>::infinity();
      for (const auto& v : mesh->vertices) best = std::max(best, d.dot(v));
      return best;
    }
    case ShapeType::kHalfSpace:
      return d.z() > 0 && d.head<2>().norm() == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  return 0.0;
}

void Shape::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const std::string name = shapeName(type);
  switch (type) {
    case ShapeType::kBox:
      if (!half_extents.allFinite() || !(half_extents.minCoeff() > 0.0))
        throw std::invalid_argument("box half extents must be > 0");
      if (auto e = overLengthLimit("box size (an edge length)", 2.0 * half_extents.maxCoeff());
          !e.empty())
        throw std::invalid_argument(e);
      return;
    case ShapeType::kSphere:
      if (!(std::isfinite(radius) && radius >= 0.0))
        throw std::invalid_argument("sphere radius must be >= 0 (0: a contact point)");
      if (auto e = overLengthLimit("sphere radius", radius); !e.empty())
        throw std::invalid_argument(e);
      return;
    case ShapeType::kCylinder:
    case ShapeType::kCapsule:
    case ShapeType::kCone:
      if (!positive(radius)) throw std::invalid_argument(name + " radius must be > 0");
      if (!positive(half_length)) throw std::invalid_argument(name + " length must be > 0");
      if (auto e = overLengthLimit(name + " radius", radius); !e.empty())
        throw std::invalid_argument(e);
      if (auto e = overLengthLimit(name + " length", 2.0 * half_length); !e.empty())
        throw std::invalid_argument(e);
      return;
    case ShapeType::kConvexMesh:
    case ShapeType::kTriangleMesh: {
      if (!mesh || mesh->vertices.size() < 3 || mesh->triangles.empty())
        throw std::invalid_argument(name + " needs at least one triangle");
      const int n = static_cast<int>(mesh->vertices.size());
      for (std::size_t i = 0; i < mesh->vertices.size(); ++i) {
        const Eigen::Vector3d& v = mesh->vertices[i];
        if (!v.allFinite()) throw std::invalid_argument(name + ": a vertex is not finite");
        const std::string from = mesh->source.empty() ? "" : " of '" + mesh->source + "'";
        if (auto e = outsideLengthLimit(name + from + " vertex " + std::to_string(i), v);
            !e.empty())
          throw std::invalid_argument(e);
      }
      for (const auto& t : mesh->triangles)
        for (int i : t)
          if (i < 0 || i >= n) throw std::invalid_argument(name + ": triangle index out of range");
      return;
    }
    case ShapeType::kHalfSpace:
      return;
  }
}

namespace {

constexpr NameTable<ShapeType, 8> kShapeNames{"shape",
                                              {{{ShapeType::kBox, "box"},
                                                {ShapeType::kSphere, "sphere"},
                                                {ShapeType::kCylinder, "cylinder"},
                                                {ShapeType::kCapsule, "capsule"},
                                                {ShapeType::kCone, "cone"},
                                                {ShapeType::kHalfSpace, "halfspace"},
                                                {ShapeType::kConvexMesh, "convex_mesh"},
                                                {ShapeType::kTriangleMesh, "mesh"}}}};

}  // namespace

std::string shapeName(ShapeType type) { return kShapeNames.name(type); }

}  // namespace tribo::contact
