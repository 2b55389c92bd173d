// Mass properties of a solid shape of uniform density: the inertia tensor about its centroid
// (geometry axes) for a given mass, and where the centroid is in the geometry frame.
//
//   box:      m/12 (b^2 + c^2, a^2 + c^2, a^2 + b^2) for edges a, b, c
//   sphere:   2/5 m r^2
//   cylinder: Izz = m r^2 / 2, Ixx = Iyy = m (3 r^2 + L^2) / 12              (L = 2 h)
//   capsule:  cylinder of mass m_c plus two hemispheres of total mass m_s (split by volume):
//             Izz = m_c r^2/2 + 2/5 m_s r^2,
//             Ixx = m_c (L^2/12 + r^2/4) + m_s (2 r^2/5 + L^2/4 + 3 L r/8)
//   cone:     Izz = 3/10 m r^2, Ixx = m (3 r^2/20 + 3 H^2/80) about the centroid H/4 above
//             the base (H = 2 h)
//   meshes:   closed triangle meshes by signed tetrahedra (divergence theorem; Tonon 2004,
//             "Explicit exact formulas for the 3-D tetrahedron inertia tensor", J. Math.
//             Stat. 1(1):8-11)
// Not here: hollow shapes, open meshes (their volume is meaningless: an error), a
// half-space (no mass).
#pragma once

#include <Eigen/Core>

#include "contact/shape.hpp"

namespace tribo::contact {

struct MassProperties {
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // about the centroid [kg m^2]
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // geometry frame [m]
  double volume = 0.0;                                 // [m^3]
};

// Throws std::invalid_argument for a half-space or a mesh without a positive volume.
MassProperties solidMassProperties(const Shape& shape, double mass);

}  // namespace tribo::contact
