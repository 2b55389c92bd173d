#include "contact/shape_inertia.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tribo::contact {

namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Matrix3d diagonal(double xx, double yy, double zz) {
  return Eigen::Vector3d(xx, yy, zz).asDiagonal();
}

MassProperties meshProperties(const MeshData& mesh, double mass) {
  // Second moments C = integral of x x^T dV over signed tetrahedra (origin, a, b, c).
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& d = mesh.vertices[t[2]];
    const double v = a.dot(b.cross(d)) / 6.0;
    const Eigen::Vector3d s = a + b + d;
    volume += v;
    first += v * s / 4.0;
    c += v / 20.0 * (s * s.transpose() + a * a.transpose() + b * b.transpose() + d * d.transpose());
  }
  if (!(volume > 0.0))
    throw std::invalid_argument(
        "mesh '" + mesh.source +
        "': no positive enclosed volume (expected a closed mesh with outward triangles)");
  MassProperties p;
  p.volume = volume;
  p.centroid = first / volume;
  const Eigen::Matrix3d c_centroid = c - volume * p.centroid * p.centroid.transpose();
  p.inertia = (mass / volume) * (c_centroid.trace() * Eigen::Matrix3d::Identity() - c_centroid);
  return p;
}

}  // namespace

MassProperties solidMassProperties(const Shape& s, double m) {
  MassProperties p;
  const double r = s.radius, r2 = r * r;
  const double length = 2.0 * s.half_length;
  switch (s.type) {
    case ShapeType::kBox: {
      const Eigen::Vector3d e2 = (2.0 * s.half_extents).cwiseAbs2();
      p.inertia = diagonal(m / 12 * (e2.y() + e2.z()), m / 12 * (e2.x() + e2.z()),
                           m / 12 * (e2.x() + e2.y()));
      p.volume = 8.0 * s.half_extents.prod();
      return p;
    }
    case ShapeType::kSphere:
      p.inertia = diagonal(0.4 * m * r2, 0.4 * m * r2, 0.4 * m * r2);
      p.volume = 4.0 / 3.0 * kPi * r2 * r;
      return p;
    case ShapeType::kCylinder: {
      const double xx = m * (3 * r2 + length * length) / 12;
      p.inertia = diagonal(xx, xx, 0.5 * m * r2);
      p.volume = kPi * r2 * length;
      return p;
    }
    case ShapeType::kCapsule: {
      const double v_c = kPi * r2 * length, v_s = 4.0 / 3.0 * kPi * r2 * r;
      const double m_c = m * v_c / (v_c + v_s), m_s = m - m_c;
      const double xx = m_c * (length * length / 12 + r2 / 4) +
                        m_s * (0.4 * r2 + length * length / 4 + 3 * length * r / 8);
      p.inertia = diagonal(xx, xx, m_c * r2 / 2 + 0.4 * m_s * r2);
      p.volume = v_c + v_s;
      return p;
    }
    case ShapeType::kCone: {
      const double xx = m * (3 * r2 / 20 + 3 * length * length / 80);
      p.inertia = diagonal(xx, xx, 0.3 * m * r2);
      p.centroid = Eigen::Vector3d(0, 0, -s.half_length + length / 4);
      p.volume = kPi * r2 * length / 3;
      return p;
    }
    case ShapeType::kConvexMesh:
    case ShapeType::kTriangleMesh:
      return meshProperties(*s.mesh, m);
    case ShapeType::kHalfSpace:
      break;
  }
  throw std::invalid_argument("a half-space has no mass properties");
}

}  // namespace tribo::contact
