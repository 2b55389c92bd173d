// Geometry poses in the world (Workspace::geometry_poses) against their definition, worked
// out here from each body's position and quaternion: X_g = [R(q) | p] X_local, with R(q) the
// unit quaternion's rotation (Shoemake, "Animating rotation with quaternion curves", 1985)
// written out on components. Over random models of every arrangement updatePoses handles
// apart: bodies with no geometry, one geometry in the body's own frame, several (the first or
// a later one in the body's frame), geometries offset and rotated, geometries on the world,
// geometries added in any order of bodies; kinematic and dynamic bodies; a second evaluation
// at another state (no pose left from the first); 1 and 2 threads equal bit for bit.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "core/dynamics.hpp"
#include "core/model_builder.hpp"

namespace tribo {
namespace {

// "b12", "g7": a name of a prefix and a number.
std::string named(const char* prefix, int i) {
  char text[32];
  std::snprintf(text, sizeof text, "%s%d", prefix, i);
  return text;
}

Quat randomOrientation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

Vec3 randomVector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

// R(q) from the quaternion's components (w, x, y, z), |q| = 1.
Mat3 rotationOf(const Quat& q) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  Mat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

struct Arrangement {
  std::shared_ptr<const Model> model;
  int origin_geometries = 0, offset_geometries = 0, world_geometries = 0;
};

// `bodies` bodies at random poses; each geometry on a random body (or the world), in the
// body's own frame or at a random offset and rotation, in random order.
Arrangement randomArrangement(std::mt19937& rng, int bodies, int geometries, double scale,
                              int threads) {
  ModelBuilder b;
  std::vector<BodyIndex> index;
  for (int i = 0; i < bodies; ++i) {
    Body body;
    body.name = named("b", i);
    body.kind = i % 5 == 4 ? BodyKind::kKinematic : BodyKind::kDynamic;
    body.mass = 1.0;
    body.inertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
    body.position = randomVector(rng, scale);
    body.orientation = randomOrientation(rng);
    index.push_back(b.addBody(body));
  }
  Arrangement a;
  std::uniform_int_distribution<int> on(-1, bodies - 1);
  std::uniform_int_distribution<int> kind(0, 2);
  for (int g = 0; g < geometries; ++g) {
    const int body = on(rng);
    Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
    const bool offset = body < 0 || kind(rng) == 0;
    if (offset) {
      local.linear() = randomOrientation(rng).toRotationMatrix();
      local.translation() = randomVector(rng, 0.3 * scale);
    }
    b.addGeometry(named("g", g),
                  body < 0 ? BodyIndex::world() : index[static_cast<std::size_t>(body)],
                  contact::Shape::sphere(0.01 * scale), local);
    (body < 0 ? a.world_geometries : offset ? a.offset_geometries : a.origin_geometries) += 1;
  }
  b.options().gravity = Vec3::Zero();
  b.options().threads = threads;
  a.model = b.build();
  return a;
}

// The state with every body moved to a new random pose.
State moved(const State& s, std::mt19937& rng, double scale) {
  State out = s;
  for (BodyState& body : out.bodies) {
    body.position = randomVector(rng, scale);
    body.orientation = randomOrientation(rng);
  }
  return out;
}

void expectPosesDefined(const Model& m, const State& state, const Workspace& ws, double scale) {
  for (std::size_t g = 0; g < m.geometries.size(); ++g) {
    const Geometry& geo = m.geometries[g];
    Eigen::Isometry3d body_pose = Eigen::Isometry3d::Identity();
    if (!geo.body.isWorld()) {
      const BodyState& s = state.bodies[geo.body.value];
      body_pose.linear() = rotationOf(s.orientation);
      body_pose.translation() = s.position;
    }
    const Eigen::Matrix4d expected = (body_pose * geo.local_pose).matrix();
    const Eigen::Matrix4d found = ws.geometry_poses[g].matrix();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) {
        const double unit = j == 3 ? scale : 1.0;  // translations scale with the scene
        ASSERT_NEAR(found(i, j), expected(i, j), 1e-14 * unit) << geo.name << " " << i << j;
      }
    ASSERT_EQ(found.row(3), Eigen::RowVector4d(0, 0, 0, 1)) << geo.name;
  }
}

TEST(GeometryPose, EveryArrangementMatchesItsDefinition) {
  std::mt19937 rng(11);
  int origin = 0, offset = 0, world = 0;
  for (const double scale : {1e-3, 1.0, 1e3})
    for (int k = 0; k < 20; ++k) {
      const int bodies = 1 + k % 7;
      const Arrangement a = randomArrangement(rng, bodies, 3 * bodies, scale, 1);
      Dynamics dynamics(a.model);
      const State first = dynamics.initialState();
      expectPosesDefined(*a.model, first, dynamics.evaluate(first), scale);
      const State second = moved(first, rng, scale);
      expectPosesDefined(*a.model, second, dynamics.evaluate(second), scale);
      origin += a.origin_geometries;
      offset += a.offset_geometries;
      world += a.world_geometries;
    }
  // Every arrangement was met, and often.
  EXPECT_GT(origin, 100);
  EXPECT_GT(offset, 100);
  EXPECT_GT(world, 50);
}

TEST(GeometryPose, SeveralGeometriesInOneBodysFrameAllFollowIt) {
  ModelBuilder b;
  Body body;
  body.name = "carrier";
  body.mass = 1.0;
  body.inertia = Mat3::Identity();
  const BodyIndex i = b.addBody(body);
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  local.translation() = Vec3(0.5, 0.0, 0.0);
  b.addGeometry("offset_first", i, contact::Shape::sphere(0.1), local);
  b.addGeometry("own_frame", i, contact::Shape::sphere(0.1));
  b.addGeometry("own_frame_again", i, contact::Shape::sphere(0.2));
  b.options().gravity = Vec3::Zero();
  const auto model = b.build();
  Dynamics dynamics(model);
  std::mt19937 rng(3);
  for (int k = 0; k < 10; ++k) {
    const State s = moved(dynamics.initialState(), rng, 2.0);
    const Workspace& ws = dynamics.evaluate(s);
    expectPosesDefined(*model, s, ws, 2.0);
    EXPECT_EQ(ws.geometry_poses[1].matrix(), ws.geometry_poses[2].matrix());
  }
}

TEST(GeometryPose, TwoThreadsGiveTheSameBits) {
  std::mt19937 rng(5);
  const Arrangement one = randomArrangement(rng, 4000, 6000, 1.0, 1);
  std::mt19937 same(5);
  const Arrangement two = randomArrangement(same, 4000, 6000, 1.0, 2);
  Dynamics d1(one.model), d2(two.model);
  ASSERT_EQ(d2.mostThreads(), 2);  // the scene splits
  const State s = moved(d1.initialState(), rng, 1.0);
  const Workspace& w1 = d1.evaluate(s);
  const Workspace& w2 = d2.evaluate(s);
  for (std::size_t g = 0; g < one.model->geometries.size(); ++g)
    ASSERT_EQ(w1.geometry_poses[g].matrix(), w2.geometry_poses[g].matrix()) << g;
  expectPosesDefined(*two.model, s, w2, 1.0);
}

}  // namespace
}  // namespace tribo
