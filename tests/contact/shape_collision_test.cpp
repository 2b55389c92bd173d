// Every collision shape collides: each on a half-space (the closed-form manifold against
// FCL's deepest point and against geometry), the FCL pairs among them (depth and normal
// against configurations whose answer is known), and the sphere closed forms against FCL.
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

// A cube of edge 2 a centred on the origin, as a mesh (12 outward triangles).
std::shared_ptr<const MeshData> cubeMesh(double a) {
  auto m = std::make_shared<MeshData>();
  for (int k = 0; k < 8; ++k)
    m->vertices.emplace_back((k & 1) ? a : -a, (k & 2) ? a : -a, (k & 4) ? a : -a);
  m->triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                  {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

struct NamedShape {
  const char* name;
  Shape shape;
};

std::vector<NamedShape> solids() {
  return {{"box", Shape::box({0.1, 0.15, 0.05})},
          {"sphere", Shape::sphere(0.1)},
          {"cylinder", Shape::cylinder(0.1, 0.15)},
          {"capsule", Shape::capsule(0.05, 0.1)},
          {"cone", Shape::cone(0.1, 0.12)},
          {"convex_mesh", Shape::convexMesh(makeConvex(*cubeMesh(0.07)))},
          {"mesh", Shape::triangleMesh(cubeMesh(0.07))}};
}

TEST(ShapeOnHalfSpace, EveryShapeTouchesATiltedPlaneAtItsSupportPoint) {
  // The deepest closed-form point must equal the exact penetration: the plane's offset less
  // the shape's lowest point, given by its support function, and match FCL's answer.
  const Eigen::Quaterniond plane_q(Eigen::AngleAxisd(0.3, Vector3d(1, 2, 0).normalized()));
  const Isometry3d plane = pose({0.1, 0.2, -0.3}, plane_q);
  const Vector3d n = plane_q * Vector3d::UnitZ();
  CollisionOptions fcl_only;
  fcl_only.closed_form_box_halfspace = fcl_only.closed_form_primitives = false;
  for (const auto& [name, shape] : solids()) {
    CollisionDetector closed({Shape::halfSpace(), shape}, {{0, 1}});
    CollisionDetector fcl({Shape::halfSpace(), shape}, {{0, 1}}, fcl_only);
    int compared = 0;
    for (int i = 0; i < 12; ++i) {
      const Eigen::Quaterniond q(Eigen::AngleAxisd(0.23 * i, Vector3d(1, -1, 2).normalized()));
      const Vector3d n_local = q.conjugate() * n;
      const double lowest = shape.support(-n_local);  // below the centre, along -n
      const double depth = 1e-3 * (1 + i % 3);
      const Isometry3d body = pose(plane * Vector3d(0.01 * i, 0, 0) + (lowest - depth) * n, q);
      const std::vector<Isometry3d> poses{plane, body};
      std::vector<ContactPoint> a, b;
      closed.detect(poses, a);
      fcl.detect(poses, b);
      ASSERT_FALSE(a.empty()) << name << " " << i;
      double deepest = 0.0;
      for (const auto& c : a) {
        deepest = std::max(deepest, c.depth);
        EXPECT_TRUE(c.normal.isApprox(n, 1e-12)) << name;
        EXPECT_GE(c.feature, 0) << name;
      }
      // Rim sampling puts a point exactly at the deepest rim point: exact for every shape.
      EXPECT_NEAR(deepest, depth, 1e-12) << name << " " << i;
      if (!b.empty()) {  // FCL's single deepest point (it has no manifold)
        double fcl_deepest = 0.0;
        for (const auto& c : b) fcl_deepest = std::max(fcl_deepest, c.depth);
        EXPECT_NEAR(fcl_deepest, depth, 1e-6) << name << " " << i;
        ++compared;
      }
      // Lifted clear of the plane: nothing.
      const std::vector<Isometry3d> apart{plane, pose(body.translation() + 2 * depth * n, q)};
      closed.detect(apart, a);
      EXPECT_TRUE(a.empty()) << name;
    }
    EXPECT_GT(compared, 0) << name << ": FCL never answered";
  }
}

TEST(ShapeOnHalfSpace, FlatFacesRestOnSeveralPointsOfEqualDepth) {
  // A face resting flat must not rock on one point: box 4 corners, cylinder and cone 8 rim
  // points, the mesh cube its 4 bottom vertices, all at the same depth.
  const double depth = 2e-4;
  struct Case {
    Shape shape;
    double half_height;
    std::size_t points;
  };
  const std::vector<Case> cases{{Shape::box({0.1, 0.1, 0.05}), 0.05, 4},
                                {Shape::cylinder(0.1, 0.05), 0.05, 8},
                                {Shape::cone(0.1, 0.05), 0.05, 8},
                                {Shape::convexMesh(makeConvex(*cubeMesh(0.1))), 0.1, 4},
                                {Shape::triangleMesh(cubeMesh(0.1)), 0.1, 4}};
  for (const auto& c : cases) {
    CollisionDetector d({Shape::halfSpace(), c.shape}, {{0, 1}});
    std::vector<ContactPoint> out;
    d.detect(std::vector<Isometry3d>{Isometry3d::Identity(), pose({0, 0, c.half_height - depth})},
             out);
    ASSERT_EQ(out.size(), c.points) << shapeName(c.shape.type);
    Vector3d centre = Vector3d::Zero();
    for (const auto& p : out) {
      EXPECT_NEAR(p.depth, depth, 1e-15);
      centre += p.position / static_cast<double>(out.size());
    }
    // Symmetric support: the points' centroid is under the centre (no net torque).
    EXPECT_NEAR(centre.head<2>().norm(), 0.0, 1e-12) << shapeName(c.shape.type);
  }
}

TEST(ShapeOnHalfSpace, CapsuleLyingDownTouchesWithBothEnds) {
  CollisionDetector d({Shape::halfSpace(), Shape::capsule(0.05, 0.2)}, {{0, 1}});
  std::vector<ContactPoint> out;
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitY()));
  d.detect(std::vector<Isometry3d>{Isometry3d::Identity(), pose({0, 0, 0.049}, lying)}, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(std::abs(out[0].position.x() - out[1].position.x()), 0.4, 1e-12);
  for (const auto& c : out) EXPECT_NEAR(c.depth, 1e-3, 1e-12);
}

TEST(FclPairs, EveryShapeCollidesWithEveryOtherAlongAKnownAxis) {
  // Shape B placed above shape A on the z axis, overlapping by 1 mm between A's top and B's
  // bottom (support functions): FCL must report a contact with depth 1 mm and a normal from
  // A into B; lifted 1 mm clear, none.
  const auto all = solids();
  int pairs = 0;
  for (const auto& [name_a, a] : all) {
    for (const auto& [name_b, b] : all) {
      const double gap = a.support(Vector3d::UnitZ()) + b.support(-Vector3d::UnitZ());
      CollisionOptions options;
      options.closed_form_primitives = false;  // FCL for sphere pairs too
      CollisionDetector d({a, b}, {{0, 1}}, options);
      std::vector<ContactPoint> out;
      // Off the mesh faces' diagonals (a contact exactly on a triangle edge is degenerate);
      // the cube mesh's faces are flat, so the depth stays 1 mm.
      const bool mesh = a.type == ShapeType::kConvexMesh || a.type == ShapeType::kTriangleMesh ||
                        b.type == ShapeType::kConvexMesh || b.type == ShapeType::kTriangleMesh;
      const Vector3d side = mesh ? Vector3d(0.003, 0.002, 0.0) : Vector3d::Zero();
      d.detect(std::vector<Isometry3d>{pose({0, 0, 0}), pose(side + Vector3d(0, 0, gap - 1e-3))},
               out);
      ASSERT_FALSE(out.empty()) << name_a << " / " << name_b;
      // Against a triangle mesh FCL tests triangle by triangle, and side triangles dipping
      // into a round shape get oblique normals: there only the deepest point is held to it.
      const bool meshes = a.type == ShapeType::kTriangleMesh || b.type == ShapeType::kTriangleMesh;
      const ContactPoint* deepest_point = &out[0];
      for (const auto& c : out) {
        if (c.depth > deepest_point->depth) deepest_point = &c;
        if (!meshes) {
          EXPECT_GT(c.normal.z(), 0.99) << name_a << " / " << name_b;
        }
      }
      const double deepest = deepest_point->depth;
      EXPECT_GT(deepest_point->normal.z(), 0.99) << name_a << " / " << name_b;
      if (!meshes) {
        EXPECT_NEAR(deepest, 1e-3, 2e-5) << name_a << " / " << name_b;
      }
      d.detect(std::vector<Isometry3d>{pose({0, 0, 0}), pose(side + Vector3d(0, 0, gap + 1e-3))},
               out);
      EXPECT_TRUE(out.empty()) << name_a << " / " << name_b;
      ++pairs;
    }
  }
  EXPECT_EQ(pairs, 49);
}

TEST(ClosedForms, SphereSphereAndBoxSphereMatchFcl) {
  CollisionOptions fcl_only;
  fcl_only.closed_form_primitives = false;
  const std::vector<Shape> shapes{Shape::sphere(0.1), Shape::sphere(0.07),
                                  Shape::box({0.2, 0.1, 0.05})};
  const std::vector<std::pair<int, int>> pairs{{0, 1}, {2, 0}, {1, 2}};
  CollisionDetector closed(shapes, pairs), fcl(shapes, pairs, fcl_only);
  int compared = 0;
  for (int i = 0; i < 30; ++i) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.4 * i, Vector3d(0.3, 1, -0.5).normalized()));
    const std::vector<Isometry3d> poses{pose({0.05 * std::sin(i), 0.12, 0.03 * i - 0.4}),
                                        pose({0.02 * i - 0.3, 0.05, -0.1}), pose({0, 0, 0}, q)};
    std::vector<ContactPoint> a, b;
    closed.detect(poses, a);
    fcl.detect(poses, b);
    ASSERT_EQ(a.size(), b.size()) << i;
    for (std::size_t k = 0; k < a.size(); ++k) {
      ASSERT_EQ(a[k].pair, b[k].pair);
      EXPECT_NEAR(a[k].depth, b[k].depth, 1e-6) << i;
      EXPECT_GT(a[k].normal.dot(b[k].normal), 1 - 1e-6) << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 5);
}

TEST(ClosedForms, SphereCentreInsideABoxLeavesThroughTheNearestFace) {
  std::vector<ContactPoint> out;
  boxSphereContact(pose({0, 0, 0}), {0.5, 0.5, 0.2}, {0.1, 0.0, 0.15}, 0.1, 0, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].normal.isApprox(Vector3d::UnitZ()));
  EXPECT_NEAR(out[0].depth, 0.05 + 0.1, 1e-15);
}

TEST(Broadphase, AutomaticCullingKeepsEveryTouchingPairOfManyShapes) {
  // A row of mixed shapes, every other one overlapping its neighbour; all pairs listed.
  std::vector<Shape> shapes;
  std::vector<Isometry3d> poses;
  const auto all = solids();
  for (int i = 0; i < 14; ++i) {
    shapes.push_back(all[i % all.size()].shape);
    poses.push_back(pose({0.19 * i + ((i % 4 == 1) ? -0.063 : 0.0), 0, 0.5}));
  }
  shapes.push_back(Shape::halfSpace());
  poses.push_back(pose({0, 0, 0.46}));
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < static_cast<int>(shapes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(shapes.size()); ++j) pairs.emplace_back(i, j);
  CollisionOptions with_bp;
  with_bp.broadphase = true;
  CollisionDetector direct(shapes, pairs), culled(shapes, pairs, with_bp);
  std::vector<ContactPoint> a, b;
  direct.detect(poses, a);
  culled.detect(poses, b);
  ASSERT_GT(a.size(), 10u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].pair, b[i].pair);
    EXPECT_TRUE(a[i].position.isApprox(b[i].position, 1e-9));
  }
}

}  // namespace
}  // namespace tribo::contact
