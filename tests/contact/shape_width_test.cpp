// Shape::thinnestHalfWidth, the simulator's shortcut past the deep-penetration check: never
// above the half width extent(n) in any direction (20 000 random unit directions per shape,
// plus the axes and the diagonals), and tight where the shape has a thinnest direction in
// closed form (a box along its shortest axis, a sphere and a capsule across, a cylinder along
// the shorter of its axis and its radius); the cone's bound is the smaller dimension over
// sqrt 2, and its thinnest half width sampled matches the closed form within the sampling.
// Shapes from 1 mm to 100 m, flat and slender.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "contact/shape.hpp"

namespace tribo::contact {
namespace {

using Eigen::Vector3d;

std::vector<Vector3d> directions(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vector3d> d;
  for (int k = 0; k < 20000; ++k) {
    Vector3d v(g(rng), g(rng), g(rng));
    if (v.norm() > 1e-9) d.push_back(v.normalized());
  }
  for (int k = 1; k < 27; ++k) {  // the axes, the face and body diagonals
    const Vector3d v(k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1);
    if (v.norm() > 0) d.push_back(v.normalized());
  }
  return d;
}

// The smallest extent over the directions; every one must be >= the bound.
double smallestExtent(const Shape& s, const std::vector<Vector3d>& dirs) {
  double least = std::numeric_limits<double>::infinity();
  const double bound = s.thinnestHalfWidth();
  for (const Vector3d& n : dirs) {
    const double e = s.extent(n);
    EXPECT_GE(e, bound * (1 - 1e-14)) << "direction " << n.transpose();
    least = std::min(least, e);
  }
  return least;
}

TEST(ShapeWidth, ThinnestHalfWidthBoundsEveryDirectionAndIsTight) {
  std::mt19937 rng(7);
  const std::vector<Vector3d> dirs = directions(rng);
  for (double scale : {1e-3, 0.2, 100.0}) {
    const Shape box = Shape::box(scale * Vector3d(0.5, 0.05, 2.0));
    EXPECT_DOUBLE_EQ(smallestExtent(box, dirs), 0.05 * scale);
    EXPECT_DOUBLE_EQ(box.thinnestHalfWidth(), 0.05 * scale);

    const Shape sphere = Shape::sphere(0.3 * scale);
    EXPECT_DOUBLE_EQ(smallestExtent(sphere, dirs), 0.3 * scale);

    const Shape capsule = Shape::capsule(0.1 * scale, 2.0 * scale);
    EXPECT_DOUBLE_EQ(smallestExtent(capsule, dirs), 0.1 * scale);

    for (const auto& [r, h] : {std::pair{0.1, 2.0}, std::pair{2.0, 0.1}, std::pair{1.0, 1.0}}) {
      const Shape cylinder = Shape::cylinder(r * scale, h * scale);
      EXPECT_DOUBLE_EQ(smallestExtent(cylinder, dirs), std::min(r, h) * scale) << r << " " << h;

      const Shape cone = Shape::cone(r * scale, h * scale);
      const double least = smallestExtent(cone, dirs);
      const double bound = std::min(r, h) * scale / std::numbers::sqrt2;
      EXPECT_DOUBLE_EQ(cone.thinnestHalfWidth(), bound);
      // Not tight for a cone: its thinnest half width is min(r, h) when slender or flat
      // (across, or along the axis), and at r = h it is 2 / sqrt 5 of r, at tan(theta) = 2
      // from the axis (the half width is r sin(theta) past that angle, h cos(theta) +
      // r sin(theta) / 2 before it); always within sqrt 2 of the bound.
      EXPECT_LE(least, std::numbers::sqrt2 * bound * (1 + 1e-12)) << r << " " << h;
      const double thinnest = r == h ? 2 / std::sqrt(5.0) * r : std::min(r, h);
      EXPECT_NEAR(least, thinnest * scale, 0.02 * thinnest * scale) << r << " " << h;
    }
  }
}

TEST(ShapeWidth, UnboundedAndUnmeasuredShapes) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(Shape::halfSpace().thinnestHalfWidth(), inf);
  EXPECT_EQ(Shape::sphere(0.0).thinnestHalfWidth(), inf);  // a point: extent is infinite too
  auto tetra = std::make_shared<MeshData>();
  tetra->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  EXPECT_EQ(Shape::triangleMesh(tetra).thinnestHalfWidth(), inf);
  EXPECT_EQ(Shape::convexMesh(tetra).thinnestHalfWidth(), 0.0);  // always measured
}

}  // namespace
}  // namespace tribo::contact
