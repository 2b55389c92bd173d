// Face manifolds of convex meshes with boxes and each other (contact/polyhedron_contacts.hpp):
// faces merged from triangles, the manifold of a cube mesh against FCL's own box/box
// manifold (an independent implementation, ODE's dBoxBox) over many poses, a patch clipped
// at an edge, and edge/edge contacts left to EPA's single point.
#include "contact/polyhedron_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/collision_detector.hpp"
#include "contact/mesh_shape.hpp"
#include "support/test_poses.hpp"

namespace tribo::contact {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;

using test::pose;

// A box of half extents h as a convex mesh (12 triangles; makeConvex orients them).
Shape boxAsMesh(const Vector3d& h) { return Shape::convexMesh(makeConvex(boxMeshData(h))); }

TEST(Polyhedron, MergesCoplanarTrianglesIntoConvexFaces) {
  const Polyhedron cube = makePolyhedron(boxAsMesh({0.1, 0.2, 0.3}));
  ASSERT_EQ(cube.faces.size(), 6u);
  for (const auto& f : cube.faces) {
    ASSERT_EQ(f.loop.size(), 4u);
    for (int v : f.loop) EXPECT_NEAR(f.normal.dot(cube.vertices[v]), f.offset, 1e-15);
    // Counter-clockwise seen from outside: the loop's area vector along the normal.
    Vector3d area = Vector3d::Zero();
    for (std::size_t k = 0; k < 4; ++k)
      area += cube.vertices[f.loop[k]].cross(cube.vertices[f.loop[(k + 1) % 4]]);
    EXPECT_GT(area.dot(f.normal), 0.0);
  }
  // A pyramid whose square base is split into four triangles around a centre vertex: one
  // base face of four corners (the centre is not a corner).
  MeshData pyramid;
  pyramid.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 0}, {0, 0, 1}};
  pyramid.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4},
                       {0, 1, 5}, {1, 2, 5}, {2, 3, 5}, {3, 0, 5}};
  const Polyhedron p = makePolyhedron(Shape::convexMesh(makeConvex(pyramid)));
  ASSERT_EQ(p.faces.size(), 5u);
  int bases = 0;
  for (const auto& f : p.faces) {
    if (f.normal.z() > -0.99) continue;
    ++bases;
    EXPECT_EQ(f.loop.size(), 4u);
    for (int v : f.loop) EXPECT_NE(v, 4);
  }
  EXPECT_EQ(bases, 1);
  EXPECT_THROW(makePolyhedron(Shape::sphere(1.0)), std::invalid_argument);
}

TEST(PolyhedronManifold, CubeMeshOnABoxMatchesFclsBoxBoxManifold) {
  // Box A below, B above overlapping A's top by 1 mm at its lowest point, B turned and tilted
  // a little differently each time. B as a convex mesh (our manifold) against B as a box
  // (FCL's own box/box manifold): the same points, depths and normals.
  const Vector3d ha(0.3, 0.2, 0.1), hb(0.1, 0.12, 0.05);
  CollisionDetector ours({Shape::box(ha), boxAsMesh(hb)}, {{0, 1}});
  CollisionOptions fcl_box_box;  // FCL's own box/box, not the closed form (box_box_contacts)
  fcl_box_box.closed_form_primitives = false;
  CollisionDetector fcl({Shape::box(ha), Shape::box(hb)}, {{0, 1}}, fcl_box_box);
  int compared = 0, tilted = 0;
  for (int i = 0; i < 40; ++i) {
    const double tilt = (i % 4) * 0.01;  // 0 (resting flat) to 0.03 rad
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.37 * i, Vector3d::UnitZ())) *
        Eigen::Quaterniond(Eigen::AngleAxisd(tilt, Vector3d(1, 0.5 * i, 0).normalized()));
    const Vector3d n_local = q.conjugate() * Vector3d::UnitZ();
    const double lowest = Shape::box(hb).support(-n_local);
    const Vector3d where(0.013 * (i % 7) - 0.04, 0.011 * (i % 5) - 0.02, 0.0);
    const std::vector<Isometry3d> poses{pose({0, 0, 0}),
                                        pose(where + Vector3d(0, 0, ha.z() + lowest - 1e-3), q)};
    std::vector<ContactPoint> a, b;
    ours.detect(poses, a);
    fcl.detect(poses, b);
    ASSERT_EQ(a.size(), b.size()) << i;
    ASSERT_GE(a.size(), tilt == 0 ? 4u : 1u) << i;
    for (const auto& c : a) {
      double nearest = 1e9;
      const ContactPoint* match = nullptr;
      for (const auto& d : b)
        if ((d.position - c.position).norm() < nearest)
          nearest = (d.position - c.position).norm(), match = &d;
      EXPECT_LT(nearest, 1e-9) << i;
      EXPECT_NEAR(c.depth, match->depth, 1e-9) << i;
      EXPECT_GT(c.normal.dot(match->normal), 1 - 1e-12) << i;
      EXPECT_EQ(c.feature, -1);
    }
    tilted += tilt > 0 && a.size() >= 2;
    ++compared;
  }
  EXPECT_EQ(compared, 40);
  EXPECT_GT(tilted, 10);  // tilted faces touch along an edge: 2 points, not EPA's one
}

TEST(PolyhedronManifold, EveryOrderOfMeshesAndBoxesGivesTheFourCornersOfARestingCube) {
  const Vector3d h(0.1, 0.1, 0.1);
  const std::vector<std::pair<Shape, Shape>> pairs{{Shape::box({0.3, 0.3, 0.1}), boxAsMesh(h)},
                                                   {boxAsMesh({0.3, 0.3, 0.1}), Shape::box(h)},
                                                   {boxAsMesh({0.3, 0.3, 0.1}), boxAsMesh(h)}};
  for (const auto& [a, b] : pairs) {
    for (const bool manifold : {true, false}) {
      CollisionOptions options;
      options.polyhedron_manifold = manifold;
      CollisionDetector d({a, b}, {{0, 1}}, options);
      std::vector<ContactPoint> out;
      d.detect(std::vector<Isometry3d>{pose({0, 0, 0}), pose({0.02, -0.01, 0.2 - 2e-5})}, out);
      if (!manifold) {
        EXPECT_EQ(out.size(), 1u);  // GJK/EPA alone: one point, on which the cube would rock
        continue;
      }
      ASSERT_EQ(out.size(), 4u) << shapeName(a.type) << " / " << shapeName(b.type);
      Vector3d centre = Vector3d::Zero();
      for (const auto& c : out) {
        EXPECT_NEAR(c.depth, 2e-5, 1e-12);
        EXPECT_NEAR(c.normal.z(), 1.0, 1e-12);
        EXPECT_NEAR(std::abs(c.position.x() - 0.02), 0.1, 1e-12);
        EXPECT_NEAR(std::abs(c.position.y() + 0.01), 0.1, 1e-12);
        centre += c.position / 4;
      }
      EXPECT_NEAR((centre.head<2>() - Eigen::Vector2d(0.02, -0.01)).norm(), 0.0, 1e-12);
    }
  }
}

TEST(PolyhedronManifold, APatchOverAnEdgeIsClippedToTheFaceBelow) {
  // A 0.2 m cube mesh overhanging the +x edge of a box's top face by 5 cm: the patch is the
  // 0.15 x 0.2 m overlap, its two outer corners cut at the edge (x = 0.3).
  CollisionDetector d({Shape::box({0.3, 0.3, 0.1}), boxAsMesh({0.1, 0.1, 0.1})}, {{0, 1}});
  std::vector<ContactPoint> out;
  d.detect(std::vector<Isometry3d>{pose({0, 0, 0}), pose({0.25, 0, 0.2 - 1e-4})}, out);
  ASSERT_EQ(out.size(), 4u);
  double x_min = 1, x_max = -1;
  for (const auto& c : out) {
    x_min = std::min(x_min, c.position.x());
    x_max = std::max(x_max, c.position.x());
    EXPECT_NEAR(std::abs(c.position.y()), 0.1, 1e-12);
    EXPECT_NEAR(c.depth, 1e-4, 1e-12);
  }
  EXPECT_NEAR(x_min, 0.15, 1e-12);
  EXPECT_NEAR(x_max, 0.3, 1e-12);
}

TEST(PolyhedronManifold, CrossedEdgesKeepEpasSinglePoint) {
  // Two cubes rotated 45 degrees about perpendicular horizontal axes, touching edge to edge:
  // no face is the separating axis, so the single EPA point stays (with FCL's depth).
  const double a = 0.1, overlap = 1e-3;
  const Eigen::Quaterniond qa(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitX()));
  const Eigen::Quaterniond qb(Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitY()));
  const double reach = a * std::sqrt(2.0);  // centre to the edge
  const std::vector<Isometry3d> poses{pose({0, 0, 0}, qa), pose({0, 0, 2 * reach - overlap}, qb)};
  CollisionDetector ours({boxAsMesh({a, a, a}), boxAsMesh({a, a, a})}, {{0, 1}});
  CollisionOptions off;
  off.polyhedron_manifold = false;
  CollisionDetector epa({boxAsMesh({a, a, a}), boxAsMesh({a, a, a})}, {{0, 1}}, off);
  std::vector<ContactPoint> x, y;
  ours.detect(poses, x);
  epa.detect(poses, y);
  ASSERT_EQ(x.size(), 1u);
  ASSERT_EQ(y.size(), 1u);
  EXPECT_NEAR(x[0].depth, overlap, 1e-6);
  EXPECT_TRUE(x[0].position.isApprox(y[0].position));
  EXPECT_NEAR(x[0].normal.z(), 1.0, 1e-6);
}

}  // namespace
}  // namespace tribo::contact
