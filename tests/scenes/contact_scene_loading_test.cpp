// Scene files with every shape, automatic contacts, filters and materials per surface pair:
// what the loader builds, what it rejects (with file, key and what was expected), and that
// each shape dropped on the ground comes to rest on it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"
#include "support/scene_text.hpp"

namespace tribo {
namespace {

namespace fs = std::filesystem;

// A folder of the running test's own: CTest runs this binary's tests in parallel processes.
fs::path testFolder() {
  const fs::path dir =
      fs::temp_directory_path() /
      ("tribo_shapes_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::create_directories(dir);
  return dir;
}

// A unit-cube OBJ next to the scene (meshes resolve relative to the scene file).
fs::path writeCube(const std::string& name, double a) {
  const fs::path path = testFolder() / name;
  std::ofstream out(path);
  for (int k = 0; k < 8; ++k)
    out << "v " << ((k & 1) ? a : -a) << " " << ((k & 2) ? a : -a) << " " << ((k & 4) ? a : -a)
        << "\n";
  for (const char* f : {"1 3 2", "2 3 4", "5 6 7", "6 8 7", "1 2 5", "2 6 5", "3 7 4", "4 7 8",
                        "1 5 3", "3 5 7", "2 4 6", "4 8 6"})
    out << "f " << f << "\n";
  return path;
}

const char* kShapes = R"(
simulation: {duration: 1.0, time_step: 0.001, integrator: rk4}
bodies:
  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace, surface: steel}]}
  - {name: box, mass: 1, position: [0, 0, 0.0499],
     geometry: [{name: g_box, shape: box, size: [0.2, 0.2, 0.1], surface: rubber}]}
  - {name: ball, mass: 1, position: [1, 0, 0.0999],
     geometry: [{name: g_ball, shape: sphere, radius: 0.1}]}
  - {name: can, mass: 1, position: [2, 0, 0.0999],
     geometry: [{name: g_can, shape: cylinder, radius: 0.1, length: 0.2}]}
  - {name: pill, mass: 1, position: [3, 0, 0.0499], rpy: [0, 1.5707963267948966, 0],
     geometry: [{name: g_pill, shape: capsule, radius: 0.05, length: 0.2}]}
  - {name: cone, mass: 1, position: [4, 0, 0.0999],
     geometry: [{name: g_cone, shape: cone, radius: 0.1, length: 0.2}]}
  - {name: hull, mass: 1, position: [5, 0, 0.0999],
     geometry: [{name: g_hull, shape: convex_mesh, file: cube_for_scene_test.obj, scale: 1}]}
  - {name: shell, mass: 1, inertia: [0.0067, 0.0067, 0.0067], position: [6, 0, 0.0999],
     geometry: [{name: g_shell, shape: mesh, file: cube_for_scene_test.obj}]}
friction_laws:
  coulomb: {mu: 0.5, v_eps: 0.01}
  elastic_stick: {mu_s: 0.6, mu_k: 0.5, stiffness: 1e5, damping: 50}
materials:
  - {name: soft, normal: {law: hunt_crossley, stiffness: 3e7, restitution: 0.2, impact_speed: 0.1},
     friction: coulomb, default: true}
  - {name: grippy, normal: {law: linear, stiffness: 1e5, damping: 100},
     friction: elastic_stick, surfaces: [[steel, rubber]]}
)";

io::Scene loadShapes(const std::string& text = kShapes) {
  const fs::path mesh = writeCube("cube_for_scene_test.obj", 0.1);
  return io::loadSceneFromString(text, (testFolder() / "shapes.yaml").string());
}

TEST(ContactScenes, EveryShapeLoadsPairsAutomaticallyAndComesToRestOnTheGround) {
  const io::Scene scene = loadShapes();
  const Model& m = *scene.model;
  ASSERT_TRUE(m.automatic_contacts);
  ASSERT_EQ(m.geometries.size(), 8u);
  // 7 bodies on the ground plus 21 pairs among them, all with a material.
  const std::vector<ContactPair> pairs = allAutomaticPairs(m);
  EXPECT_EQ(pairs.size(), 7u + 21u);
  for (const auto& p : pairs) {
    // Forces reported on the dynamic body: the ground is always A.
    EXPECT_NE(m.geometries[p.geometry_b].name, "floor");
    const bool steel_rubber =
        m.geometries[p.geometry_a].name == "floor" && m.geometries[p.geometry_b].name == "g_box";
    EXPECT_EQ(p.material, steel_rubber ? 1 : 0);
  }
  Simulator sim(scene.model);
  while (sim.state().time < 1.0 - 1e-9) ASSERT_TRUE(sim.step().ok) << sim.state().time;
  for (std::size_t b = 1; b < m.bodies.size(); ++b) {
    const BodyState& s = sim.state().bodies[b];
    EXPECT_LT(s.velocity.norm(), 1e-3) << m.bodies[b].name;
    EXPECT_LT(s.angular_velocity.norm(), 1e-2) << m.bodies[b].name;  // no rocking
    EXPECT_LT(Eigen::AngleAxisd(s.orientation * m.bodies[b].orientation.conjugate()).angle(), 1e-3)
        << m.bodies[b].name;
  }
}

TEST(ContactScenes, JointsAndMasksFilterAutomaticPairs) {
  const std::string base = R"(
bodies:
  - {name: a, mass: 1, position: [0, 0, 1], geometry: [{name: ga, shape: sphere, radius: 0.1}]}
  - {name: b, mass: 1, position: [0.15, 0, 1],
     geometry: [{name: gb, shape: sphere, radius: 0.1, collision_group: 2, collision_mask: 1}]}
  - {name: c, mass: 1, position: [0.3, 0, 1],
     geometry: [{name: gc, shape: sphere, radius: 0.1, collision_group: 2, collision_mask: 1}]}
joints:
  - {name: hinge, type: revolute, parent: a, child: b, anchor: [0.075, 0, 1], axis: [0, 1, 0]}
friction_laws: {coulomb: {mu: 0.3}}
materials: [{name: any, friction: coulomb, default: true}]
)";
  const io::Scene scene = io::loadSceneFromString(base, "filters.yaml");
  // a-b joined: out; b-c: group 2 vs mask 1: out; a-c: group 1 & mask 1, group 2 & mask all.
  const std::vector<ContactPair> pairs = allAutomaticPairs(*scene.model);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(scene.model->geometries[pairs[0].geometry_a].name, "ga");
  EXPECT_EQ(scene.model->geometries[pairs[0].geometry_b].name, "gc");
  // Asked for, joined bodies collide.
  std::string joined = base;
  joined.insert(0, "simulation: {collision: {joined_bodies_collide: true}}\n");
  EXPECT_EQ(allAutomaticPairs(*io::loadSceneFromString(joined, "filters.yaml").model).size(), 2u);
}

TEST(ContactScenes, EveryCollisionOptionKeyReachesTheModel) {
  const std::string text = R"(
simulation:
  collision: {broadphase: true, closed_form_box_halfspace: false, closed_form_primitives: false,
              polyhedron_manifold: false, max_points_per_pair: 3, joined_bodies_collide: true,
              match_radius: 0.002, query_time_limit: 2.5}
bodies:
  - {name: a, mass: 1, geometry: [{name: ga, shape: sphere, radius: 0.1}]}
)";
  const io::Scene scene = io::loadSceneFromString(text, "options.yaml");
  const contact::CollisionOptions& c = scene.model->options.collision;
  const contact::CollisionOptions defaults;
  EXPECT_NE(c.broadphase, defaults.broadphase);
  EXPECT_TRUE(c.broadphase);
  EXPECT_FALSE(c.closed_form_box_halfspace);
  EXPECT_FALSE(c.closed_form_primitives);
  EXPECT_FALSE(c.polyhedron_manifold);
  EXPECT_TRUE(defaults.polyhedron_manifold);
  EXPECT_EQ(c.max_points_per_pair, 3);
  EXPECT_TRUE(c.joined_bodies_collide);
  EXPECT_EQ(c.match_radius, 0.002);
  EXPECT_EQ(c.query_time_limit, 2.5);
  EXPECT_EQ(defaults.query_time_limit, 60.0);
  for (const char* bad : {"-1", "nan", "x"})
    EXPECT_NE(test::sceneErrorOf(test::replaced(text, "query_time_limit: 2.5",
                                                std::string("query_time_limit: ") + bad))
                  .find("simulation.collision.query_time_limit"),
              std::string::npos)
        << bad;
  EXPECT_NE(test::sceneErrorOf(
                test::replaced(text, "polyhedron_manifold: false", "polyhedron_manifold: 2"))
                .find("simulation.collision.polyhedron_manifold: expected true or false"),
            std::string::npos);
}

std::string errorOf(const std::string& text) {
  try {
    loadShapes(text);
  } catch (const io::SceneError& e) {
    return e.what();
  }
  return "";
}

using test::replaced;

TEST(ContactScenes, BadShapesAndMaterialsAreNamedWithTheirKeys) {
  EXPECT_NE(
      errorOf(replaced(kShapes, "shape: sphere, radius: 0.1", "shape: sphere, size: [1, 1, 1]"))
          .find("bodies[2].geometry[0].size: a sphere takes no size (it takes: radius)"),
      std::string::npos);
  EXPECT_NE(errorOf(replaced(kShapes, "radius: 0.1, length: 0.2}]}\n  - {name: pill",
                             "radius: -0.1, length: 0.2}]}\n  - {name: pill"))
                .find("radius: expected a number > 0"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kShapes, "file: cube_for_scene_test.obj, scale: 1",
                             "file: missing_part.stl"))
                .find("missing_part.stl': cannot open"),
            std::string::npos);
  EXPECT_NE(
      errorOf(replaced(kShapes,
                       "{law: hunt_crossley, stiffness: 3e7, restitution: 0.2, impact_speed: 0.1}",
                       "{law: hertz, stiffness: 3e7, damping: 4}"))
          .find("materials[0].normal.damping: damping applies to law linear, hunt_crossley "
                "or recurdyn only (this law is hertz)"),
      std::string::npos);
  EXPECT_NE(errorOf(replaced(kShapes, "restitution: 0.2, impact_speed: 0.1}", "restitution: 0.5}"))
                .find("restitution and impact_speed go together"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kShapes, "friction: coulomb, default: true", "friction: coulomb"))
                .find("no material for surfaces"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kShapes, "surfaces: [[steel, rubber]]",
                             "surfaces: [[steel, rubber]], default: true"))
                .find("material 'soft' is already the default"),
            std::string::npos);
}

}  // namespace
}  // namespace tribo
