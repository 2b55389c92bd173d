// Closed-form box/box, capsule/box, cylinder/box, sphere/capsule and capsule/capsule contacts
// (contact/box_box_contacts.hpp, contact/box_round_contacts.hpp, contact/round_contacts.hpp)
// against FCL's narrowphase on the same poses in the same
// process: one detector per pair with closed_form_primitives on, and its baseline with it off
// (FCL's box/box manifold, libccd GJK/EPA for capsule and cylinder), so both carry the same
// detector overhead. Poses: a box resting flat on a bigger one (4 points), a box turned 45
// degrees on an edge pressed into a face, two boxes crossing edge to edge, separated boxes;
// a capsule lying on a box face and touching a box corner; a cylinder standing on a face; a
// sphere on a capsule's side, a capsule lying along another, two capsules crossed.
// Names: BM_Pair/<pose>/closed_form and BM_Pair/<pose>/fcl; counter points per call.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "contact/collision_detector.hpp"

namespace {

using tribo::contact::CollisionDetector;
using tribo::contact::CollisionOptions;
using tribo::contact::ContactPoint;
using tribo::contact::Shape;

Eigen::Isometry3d at(const Eigen::Vector3d& p,
                     const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  t.translation() = p;
  return t;
}

struct Case {
  Shape a, b;
  Eigen::Isometry3d pa, pb;
};

Case makeCase(int which) {
  const double a = 0.1, r2 = a * std::sqrt(2.0);
  const Eigen::Quaterniond qx(Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond qy(Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()));
  const Shape big = Shape::box({0.3, 0.3, 0.1}), cube = Shape::box({a, a, a});
  switch (which) {
    case 0:  // resting face
      return {big, cube, at({0, 0, 0}), at({0.02, -0.01, 0.2 - 3e-5})};
    case 1:  // an edge pressed into a face
      return {big, cube, at({0, 0, 0}), at({0.05, 0, 0.1 + r2 - 3e-5}, qx)};
    case 2:  // edges crossing
      return {cube, cube, at({0, 0, 0}, qy), at({0, 0, 2 * r2 - 3e-5}, qx)};
    case 3:  // separated (overlapping bounding spheres, a face axis separates)
      return {
          cube, cube, at({0, 0, 0}),
          at({a + r2 + 1e-3, 0.05, 0.02}, Eigen::Quaterniond(Eigen::AngleAxisd(
                                              std::numbers::pi / 4, Eigen::Vector3d::UnitZ())))};
    case 4:  // capsule lying on a face
      return {big, Shape::capsule(0.05, 0.1), at({0, 0, 0}), at({0, 0, 0.15 - 3e-5}, lying)};
    case 5:  // capsule end on a box corner
      return {cube, Shape::capsule(0.05, 0.1), at({0, 0, 0}),
              at(Eigen::Vector3d(a, a, a) + 0.15 * Eigen::Vector3d(1, 1, 1).normalized() -
                     Eigen::Vector3d::Constant(3e-5),
                 Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(),
                                                    Eigen::Vector3d(1, 1, 1)))};
    case 6:  // cylinder standing on a face
      return {big, Shape::cylinder(0.05, 0.1), at({0, 0, 0}), at({0.05, 0, 0.2 - 3e-5})};
    case 7:  // sphere on a capsule's side
      return {Shape::capsule(0.05, 0.1), Shape::sphere(0.05), at({0, 0, 0}, lying),
              at({0.03, 0, 0.1 - 3e-5})};
    case 8:  // capsule lying along another (a line contact: 2 points)
      return {Shape::capsule(0.05, 0.1), Shape::capsule(0.05, 0.1), at({0, 0, 0}, lying),
              at({0.05, 0, 0.1 - 3e-5}, lying)};
    default:  // capsules crossed at right angles
      return {Shape::capsule(0.05, 0.1), Shape::capsule(0.05, 0.1), at({0, 0, 0}, lying),
              at({0, 0, 0.1 - 3e-5}, Eigen::Quaterniond(Eigen::AngleAxisd(
                                         std::numbers::pi / 2, Eigen::Vector3d::UnitX())))};
  }
}

void BM_Pair(benchmark::State& st, int which, bool closed_form) {
  const Case c = makeCase(which);
  CollisionOptions options;
  options.closed_form_primitives = closed_form;
  CollisionDetector detector({c.a, c.b}, {{0, 1}}, options);
  const std::vector<Eigen::Isometry3d> poses{c.pa, c.pb};
  std::vector<ContactPoint> out;
  double points = 0;
  for (auto _ : st) {
    detector.detect(poses, out);
    points += static_cast<double>(out.size());
    benchmark::DoNotOptimize(out.data());
  }
  st.counters["points"] = points / static_cast<double>(st.iterations());
}

#define TRIBO_PAIR(which, name)                                                                  \
  BENCHMARK_CAPTURE(BM_Pair, name##_closed, which, true)->Name("BM_Pair/" #name "/closed_form"); \
  BENCHMARK_CAPTURE(BM_Pair, name##_fcl, which, false)->Name("BM_Pair/" #name "/fcl")

TRIBO_PAIR(0, box_box_resting_face);
TRIBO_PAIR(1, box_box_edge_on_face);
TRIBO_PAIR(2, box_box_edge_edge);
TRIBO_PAIR(3, box_box_separated);
TRIBO_PAIR(4, capsule_box_lying);
TRIBO_PAIR(5, capsule_box_corner);
TRIBO_PAIR(6, cylinder_box_standing);
TRIBO_PAIR(7, sphere_capsule_side);
TRIBO_PAIR(8, capsule_capsule_lying);
TRIBO_PAIR(9, capsule_capsule_crossed);

}  // namespace
