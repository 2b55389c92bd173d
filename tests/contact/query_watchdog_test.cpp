// The time limit on one FCL query (contact/query_watchdog.hpp): a query held past the limit
// is reported with its pair and the time it ran, one that ends in time never is; the
// collision detector watches exactly the pairs that reach FCL; and a run whose query
// overruns ends with status 7 naming both geometries and their bodies (core/dynamics.cpp).
// A query that truly never returns cannot be made here (the load-time limits refuse every
// known one, tests/io/convex_mesh_limits_test.cpp), so a limit far below a real query's
// time stands in for it.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <thread>
#include <vector>

#include "contact/collision_detector.hpp"
#include "contact/mesh_shape.hpp"
#include "core/dynamics.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

using contact::QueryWatchdog;
using Clock = std::chrono::steady_clock;

struct Overrun {
  int a = -2, b = -2;
  double seconds = 0.0;
};

// Records every report; the first one's values are kept.
struct Recorder {
  std::mutex mutex;
  std::vector<Overrun> reports;
  QueryWatchdog::OverrunHandler handler() {
    return [this](int a, int b, double s) {
      const std::lock_guard lock(mutex);
      reports.push_back({a, b, s});
    };
  }
  std::size_t count() {
    const std::lock_guard lock(mutex);
    return reports.size();
  }
};

TEST(QueryWatchdog, AQueryHeldPastTheLimitIsReportedWithItsPairAndTime) {
  for (const double limit : {0.01, 0.05}) {
    Recorder r;
    {
      QueryWatchdog watchdog(limit, r.handler(), 3);
      const auto start = Clock::now();
      watchdog.begin(2, 4, 9);
      while (r.count() == 0 && Clock::now() - start < std::chrono::seconds(10))
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      watchdog.end(2);
    }
    ASSERT_GE(r.reports.size(), 1u) << limit;
    EXPECT_EQ(r.reports[0].a, 4);
    EXPECT_EQ(r.reports[0].b, 9);
    EXPECT_GT(r.reports[0].seconds, limit);
  }
}

TEST(QueryWatchdog, QueriesThatEndInTimeAreNeverReported) {
  Recorder r;
  {
    QueryWatchdog watchdog(0.2, r.handler(), 1);
    watchdog.reserveLanes(4);
    const auto start = Clock::now();
    // Many short queries on every lane over several looks of the watchdog.
    while (Clock::now() - start < std::chrono::milliseconds(300))
      for (int lane = 0; lane < 4; ++lane) {
        watchdog.begin(lane, lane, lane + 1);
        watchdog.end(lane);
      }
  }
  EXPECT_EQ(r.count(), 0u);
}

TEST(QueryWatchdog, ALimitThatIsNotPositiveOrAMissingHandlerIsRefused) {
  Recorder r;
  for (const double limit : {0.0, -1.0, std::nan(""), HUGE_VAL})
    EXPECT_THROW(QueryWatchdog(limit, r.handler(), 1), std::invalid_argument) << limit;
  EXPECT_THROW(QueryWatchdog(1.0, nullptr, 1), std::invalid_argument);
}

// A convex UV sphere of radius r with `rings` x 2 `rings` faces around: its support
// function (FCL's, a pass over the vertices) makes every query take a measurable time.
std::shared_ptr<const contact::MeshData> sphereHull(double r, int rings) {
  contact::MeshData m;
  const int around = 2 * rings;
  m.vertices.emplace_back(0, 0, r);
  for (int i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;
    for (int j = 0; j < around; ++j) {
      const double phi = 2 * std::numbers::pi * j / around;
      m.vertices.emplace_back(r * std::sin(theta) * std::cos(phi),
                              r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  }
  m.vertices.emplace_back(0, 0, -r);
  const int south = static_cast<int>(m.vertices.size()) - 1;
  auto at = [&](int ring, int j) { return 1 + (ring - 1) * around + (j % around); };
  for (int j = 0; j < around; ++j) {
    m.triangles.push_back({0, at(1, j), at(1, j + 1)});
    m.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
    for (int i = 1; i + 1 < rings; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return contact::makeConvex(m);
}

// Two overlapping hulls (geometries 1 and 2) beside a box (0): only the hull pair reaches FCL.
TEST(QueryWatchdog, TheDetectorReportsTheHullPairThatOverruns) {
  using contact::Shape;
  for (const int rings : {8, 24}) {
    const auto hull = sphereHull(0.5, rings);
    contact::CollisionDetector detector(
        {Shape::box(Eigen::Vector3d(1, 1, 1)), Shape::convexMesh(hull), Shape::convexMesh(hull)},
        {{1, 2}});
    Recorder r;
    ASSERT_TRUE(detector.watchQueries(1e-7, r.handler()));
    Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
    moved.translation() = Eigen::Vector3d(0.3, 0.2, 0.1);
    const std::vector<Eigen::Isometry3d> poses{Eigen::Isometry3d::Identity(),
                                               Eigen::Isometry3d::Identity(), moved};
    std::vector<contact::ContactPoint> points;
    for (int i = 0; i < 10000 && r.count() == 0; ++i) detector.detect(poses, points);
    EXPECT_FALSE(points.empty()) << rings;
    ASSERT_GE(r.count(), 1u) << rings;
    EXPECT_EQ(r.reports[0].a, 1);
    EXPECT_EQ(r.reports[0].b, 2);
  }
}

// Any two geometries on demand (automatic contacts).
class AllPairs : public contact::PairRule {
 public:
  explicit AllPairs(int n) : n_(n) {}
  int pairId(int g, int h) const override { return g < h ? g * n_ + h : h * n_ + g; }
  std::pair<int, int> geometries(int id) const override { return {id / n_, id % n_}; }

 private:
  int n_;
};

TEST(QueryWatchdog, OnlyPairsThatReachFclAreWatched) {
  using contact::Shape;
  const auto hull = sphereHull(0.5, 4);
  const Shape box = Shape::box(Eigen::Vector3d(1, 1, 1));
  auto noop = [](int, int, double) {};
  struct Case {
    std::vector<Shape> shapes;
    bool watched;  // some pair has no closed form
  };
  const std::vector<Case> cases{
      {{Shape::halfSpace(), box, box, Shape::sphere(0.5)}, false},  // closed forms only
      {{Shape::halfSpace(), box, Shape::capsule(0.1, 0.5)}, false},
      {{Shape::halfSpace(), Shape::cylinder(0.2, 0.3)}, false},  // on a half-space
      {{box, Shape::cylinder(0.2, 0.3)}, true},                  // box edge: FCL
      {{Shape::sphere(0.5), Shape::capsule(0.1, 0.5), Shape::capsule(0.2, 0.1)}, false},
      {{Shape::sphere(0.5), Shape::cylinder(0.1, 0.5)}, true},  // no round closed form
      {{Shape::halfSpace(), Shape::convexMesh(hull)}, false},
      {{Shape::convexMesh(hull), Shape::convexMesh(hull)}, true},  // a type with itself
      {{Shape::halfSpace(), Shape::convexMesh(hull), box}, true}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const int n = static_cast<int>(cases[i].shapes.size());
    contact::CollisionDetector automatic(cases[i].shapes, std::make_unique<AllPairs>(n));
    EXPECT_EQ(automatic.watchQueries(1.0, noop), cases[i].watched) << "case " << i;
  }
  // Listed: the half-space/box pair has its closed form, the hull/box pair does not.
  contact::CollisionDetector closed({Shape::halfSpace(), box, Shape::convexMesh(hull)}, {{0, 1}});
  EXPECT_FALSE(closed.watchQueries(1.0, noop));
  contact::CollisionDetector open({Shape::halfSpace(), box, Shape::convexMesh(hull)}, {{1, 2}});
  EXPECT_TRUE(open.watchQueries(1.0, noop));
}

// A hull resting on a box: a run whose hull query overruns its limit ends with status 7, naming
// both geometries and their bodies; with the watch off (limit 0) the same run completes.
std::unique_ptr<Simulator> hullsTouching(double limit) {
  ModelBuilder b;
  b.options().integrator = IntegratorType::kRk4;
  b.options().time_step = 1e-3;
  b.options().collision.query_time_limit = limit;
  contact::Material material;
  material.normal = {contact::NormalLawType::kLinear, 1e5, 10.0};
  material.friction = friction::makeFrictionLaw({"coulomb", {{"mu", 0.3}, {"v_eps", 0.01}}, {}});
  const int mat = b.addMaterial(material);
  const auto hull = sphereHull(0.1, 16);
  Body base;
  base.name = "base";
  base.kind = BodyKind::kKinematic;
  base.position = Vec3(0.0, 0.0, -0.05);
  const int below =
      b.addGeometry("pad", b.addBody(base), contact::Shape::box(Vec3(0.5, 0.5, 0.05)));
  Body puck;
  puck.name = "puck";
  puck.mass = 1.0;
  puck.inertia = Mat3::Identity() * 0.004;
  puck.position = Vec3(0.0, 0.0, 0.1 - 9.81 / 1e5);  // its pole at its static depth
  const int above = b.addGeometry("cap", b.addBody(puck), contact::Shape::convexMesh(hull));
  b.addContactPair(below, above, mat);
  return std::make_unique<Simulator>(b.build());
}

TEST(QueryWatchdogDeathTest, ARunWhoseQueryOverrunsEndsWithStatus7NamingThePair) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        auto sim = hullsTouching(1e-7);
        for (int i = 0; i < 100000; ++i) sim->step();
      },
      testing::ExitedWithCode(kQueryOverrunStatus),
      "geometry 'pad' \\(body 'base'\\) and geometry 'cap' \\(body 'puck'\\).*limit");
  auto sim = hullsTouching(0.0);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(sim->step().ok);
  EXPECT_FALSE(sim->current().contacts.empty());
}

}  // namespace
}  // namespace tribo
