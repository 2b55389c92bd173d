// Mass properties: closed forms against the mesh integration of the same solid (a cube, a
// finely tessellated cylinder and cone) and a numerical check of the capsule.
#include "contact/shape_inertia.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tribo::contact {
namespace {

// A closed polygonal frustum mesh (bottom radius r0 at z0, top radius r1 at z1; r1 = 0 is a
// cone), n sides, outward triangles.
std::shared_ptr<MeshData> frustum(double r0, double z0, double r1, double z1, int n) {
  auto m = std::make_shared<MeshData>();
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    m->vertices.emplace_back(r0 * std::cos(t), r0 * std::sin(t), z0);
    m->vertices.emplace_back(r1 * std::cos(t), r1 * std::sin(t), z1);
  }
  const int bottom = static_cast<int>(m->vertices.size());
  m->vertices.emplace_back(0, 0, z0);
  m->vertices.emplace_back(0, 0, z1);
  for (int k = 0; k < n; ++k) {
    const int a0 = 2 * k, a1 = 2 * k + 1, b0 = 2 * ((k + 1) % n), b1 = b0 + 1;
    m->triangles.push_back({a0, b0, b1});
    m->triangles.push_back({a0, b1, a1});
    m->triangles.push_back({bottom, b0, a0});
    m->triangles.push_back({bottom + 1, a1, b1});
  }
  return m;
}

TEST(ShapeInertia, CubeMeshMatchesTheBoxFormula) {
  auto cube = std::make_shared<MeshData>();
  for (int k = 0; k < 8; ++k)
    cube->vertices.emplace_back((k & 1) ? 0.3 : -0.1, (k & 2) ? 0.2 : -0.2, (k & 4) ? 0.05 : -0.05);
  cube->triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                     {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  const auto mesh = solidMassProperties(Shape::triangleMesh(cube), 2.0);
  const auto box = solidMassProperties(Shape::box({0.2, 0.2, 0.05}), 2.0);
  EXPECT_NEAR(mesh.volume, 0.4 * 0.4 * 0.1, 1e-15);
  EXPECT_TRUE(mesh.centroid.isApprox(Eigen::Vector3d(0.1, 0, 0)));
  EXPECT_TRUE(mesh.inertia.isApprox(box.inertia, 1e-12));
}

TEST(ShapeInertia, CylinderAndConeMatchTheirTessellations) {
  const int n = 2000;  // the polygon's inertia converges as 1 - O(1/n^2)
  const auto cyl = solidMassProperties(Shape::cylinder(0.1, 0.2), 3.0);
  const auto cyl_mesh =
      solidMassProperties(Shape::triangleMesh(frustum(0.1, -0.2, 0.1, 0.2, n)), 3.0);
  EXPECT_TRUE(cyl.inertia.isApprox(cyl_mesh.inertia, 1e-5));
  EXPECT_NEAR(cyl.volume / cyl_mesh.volume, 1.0, 1e-5);
  const auto cone = solidMassProperties(Shape::cone(0.1, 0.15), 3.0);
  const auto cone_mesh =
      solidMassProperties(Shape::triangleMesh(frustum(0.1, -0.15, 0.0, 0.15, n)), 3.0);
  EXPECT_TRUE(cone.inertia.isApprox(cone_mesh.inertia, 1e-5));
  EXPECT_TRUE(cone.centroid.isApprox(cone_mesh.centroid, 1e-5));
}

TEST(ShapeInertia, CapsuleMatchesAVoxelIntegration) {
  const double r = 0.05, h = 0.1, m = 1.0;
  const auto p = solidMassProperties(Shape::capsule(r, h), m);
  // Midpoint rule over a grid: inside when the distance to the axis segment is below r.
  const int n = 160;
  const double lx = r, lz = h + r;
  double count = 0, ixx = 0, izz = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < 2 * n; ++k) {
        const double x = -lx + (i + 0.5) * 2 * lx / n, y = -lx + (j + 0.5) * 2 * lx / n;
        const double z = -lz + (k + 0.5) * 2 * lz / (2 * n);
        const double dz = std::max(0.0, std::abs(z) - h);
        if (x * x + y * y + dz * dz > r * r) continue;
        count += 1;
        ixx += y * y + z * z;
        izz += x * x + y * y;
      }
  EXPECT_NEAR(p.inertia(0, 0) / (m * ixx / count), 1.0, 2e-3);
  EXPECT_NEAR(p.inertia(2, 2) / (m * izz / count), 1.0, 2e-3);
  EXPECT_THROW(solidMassProperties(Shape::halfSpace(), 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::contact
