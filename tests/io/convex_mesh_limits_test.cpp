// Convex meshes that once hung libccd's MPR (FCL's narrowphase) forever: a cube with one
// corner moved far away (non-convex, once passed as convex because the check's tolerance grew
// with the far corner), a tetrahedron with one far vertex (convex, a needle), a plate of
// nearly no thickness. Each is refused with a MeshError naming the file and what was
// expected, or accepted and then answers collision queries against a box at many poses. A
// hang would show as the test's CTest timeout (60 s), not as an assertion.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>

#include "contact/collision_detector.hpp"
#include "contact/mesh_shape.hpp"
#include "io/mesh_loader.hpp"
#include "support/stl_bytes.hpp"

namespace tribo {
namespace {

using contact::MeshError;

// The error of loading `hull` as a binary STL and making it convex; "" when accepted (then
// `out` holds the hull).
std::string convexErrorOf(const test::HullSpec& hull,
                          std::shared_ptr<const contact::MeshData>* out = nullptr) {
  const std::string bytes = test::binaryStl(hull);
  try {
    const auto mesh = io::loadMeshFromMemory(
        std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()), "stl",
        "hull.stl");
    const auto convex = contact::makeConvex(*mesh);
    if (out) *out = convex;
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// Collision queries of `hull` against a 10 x 10 x 1 box under it, at random poses around
// the box's top face: every answer finite.
void queryAgainstBox(const std::shared_ptr<const contact::MeshData>& hull, double scale) {
  using contact::Shape;
  contact::CollisionDetector detector(
      {Shape::convexMesh(hull), Shape::box(Eigen::Vector3d(5, 5, 0.5))}, {{0, 1}});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<contact::ContactPoint> points;
  for (int i = 0; i < 300; ++i) {
    Eigen::Isometry3d hull_pose = Eigen::Isometry3d::Identity();
    hull_pose.linear() = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().matrix();
    hull_pose.translation() = Eigen::Vector3d(u(rng), u(rng), 0.5 * scale * u(rng));
    Eigen::Isometry3d box_pose = Eigen::Isometry3d::Identity();
    box_pose.translation().z() = -0.5;
    const std::array poses{hull_pose, box_pose};
    detector.detect(poses, points);
    for (const auto& p : points) {
      ASSERT_TRUE(p.position.allFinite());
      ASSERT_TRUE(std::isfinite(p.depth));
    }
  }
}

TEST(ConvexMeshLimits, CubeWithOneFarCornerIsRefusedAtEveryDistance) {
  // Within the 1e6 m limit: the far corner bends a face, and a vertex lies about 1 m above
  // another (computed by hand: the corner's neighbours on the +x face); past it: the limit.
  for (const double far : {2.0, 1e3, 1e5, 1e6}) {
    const std::string e = convexErrorOf(test::cubeWithFarCorner(far));
    EXPECT_TRUE(has(e, "hull.stl") && has(e, "not convex")) << far << ": " << e;
  }
  for (const double far : {1e7, 1e10, 1e15, 1e20, 9e22, 1e30}) {
    const std::string e = convexErrorOf(test::cubeWithFarCorner(far));
    EXPECT_TRUE(has(e, "hull.stl") && has(e, "vertex") && has(e, "1000000 m") &&
                has(e, contact::lengthText(static_cast<float>(far))))
        << far << ": " << e;
  }
}

TEST(ConvexMeshLimits, NeedleTetrahedraAreRefusedAndTheOthersCollideInBoundedWork) {
  // Thickness 1/sqrt(2) (the slanted face's distance from the origin), size 3/4 of the far
  // vertex's distance: refused once their ratio falls under kMinConvexThickness (1e-6).
  for (const double far : {0.1, 1.0, 10.0, 1e3, 1e5}) {
    std::shared_ptr<const contact::MeshData> hull;
    const std::string e = convexErrorOf(test::tetrahedronWithFarVertex(far), &hull);
    ASSERT_EQ(e, "") << far;
    queryAgainstBox(hull, std::min(far, 1.0));
  }
  for (const double far : {1e6, 1e7, 1e10, 9e22}) {
    const std::string e = convexErrorOf(test::tetrahedronWithFarVertex(far));
    EXPECT_TRUE(has(e, "hull.stl") && (has(e, "thick") || has(e, "1000000 m"))) << far << ": " << e;
  }
}

TEST(ConvexMeshLimits, NearlyFlatHullsAreRefusedAndThickOnesCollide) {
  // A unit plate: size sqrt(2)/2 (its corners from its centre), so refused under 7.07e-7 m.
  // Checked on the vertices as given: assimp's STL reader joins vertices closer than 1e-4 of
  // the mesh's diagonal, which collapses the thinner plates before the check sees them.
  auto checked = [](const test::HullSpec& h) -> std::string {
    contact::MeshData mesh;
    mesh.vertices = h.vertices;
    mesh.triangles = h.triangles;
    mesh.source = "plate";
    try {
      (void)contact::makeConvex(mesh);
    } catch (const MeshError& e) {
      return e.what();
    }
    return "";
  };
  for (const double t : {1e-12, 1e-9, 1e-7, 5e-7}) {
    const std::string e = checked(test::plate(t));
    EXPECT_TRUE(has(e, "'plate'") && has(e, "thick") && has(e, "expected a solid"))
        << t << ": " << e;
    EXPECT_FALSE(convexErrorOf(test::plate(t)).empty()) << t;  // through the STL reader too
  }
  for (const double t : {1e-6, 1e-5}) EXPECT_EQ(checked(test::plate(t)), "") << t;
  for (const double t : {1e-3, 0.1, 1.0}) {
    std::shared_ptr<const contact::MeshData> hull;
    ASSERT_EQ(convexErrorOf(test::plate(t), &hull), "") << t;
    queryAgainstBox(hull, 1.0);
  }
}

TEST(ConvexMeshLimits, CollisionDetectorRefusesShapesPastTheLimit) {
  using contact::Shape;
  for (const double far : {1e7, 1e10, 9e22}) {
    auto mesh = std::make_shared<contact::MeshData>();
    const test::HullSpec h = test::tetrahedronWithFarVertex(far);
    mesh->vertices = h.vertices;
    mesh->triangles = h.triangles;
    EXPECT_THROW(contact::CollisionDetector(
                     {Shape::convexMesh(mesh), Shape::box(Eigen::Vector3d(5, 5, 0.5))}, {{0, 1}}),
                 std::invalid_argument)
        << far;
  }
  EXPECT_THROW(contact::CollisionDetector(
                   {Shape::box(Eigen::Vector3d(1e154, 1, 1)), Shape::box(Eigen::Vector3d(1, 1, 1))},
                   {{0, 1}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace tribo
