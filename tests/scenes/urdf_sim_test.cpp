// Real URDF robots simulated headless: every file of the shared corpus dropped on the ground
// for 1 s at an automatic step within its own stability estimate, without NaN and without
// energy rising (nothing drives them, so kinetic plus gravitational energy can only fall); and a
// pendulum written as URDF moving exactly as the same pendulum written as a scene file
// (scenes/robots/pendulum.urdf).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "io/scene_loader.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "support/pendulum_scene.hpp"
#include "support/urdf_corpus.hpp"

namespace tribo {
namespace {

namespace fs = std::filesystem;

fs::path corpus() { return test::urdfCorpusFolder().value_or(""); }

// Kinetic plus gravitational energy [J].
double mechanicalEnergy(const Model& m, const State& s) {
  double e = 0.0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].kind != BodyKind::kDynamic) continue;
    const BodyState& x = s.bodies[b];
    const Eigen::Matrix3d r = x.orientation.toRotationMatrix();
    e +=
        0.5 * m.bodies[b].mass * x.velocity.squaredNorm() +
        0.5 * x.angular_velocity.dot(r * m.bodies[b].inertia * r.transpose() * x.angular_velocity) -
        m.bodies[b].mass * m.options.gravity.dot(x.position);
  }
  return e;
}

class UrdfOnGround : public ::testing::TestWithParam<std::string> {};

TEST_P(UrdfOnGround, OneSecondWithoutNanOrEnergyGain) {
  TRIBO_REQUIRE_URDF_CORPUS(folder);
  const std::string file = GetParam();
  std::ifstream in(corpus() / "expected.json");
  const nlohmann::json facts = nlohmann::json::parse(in)["urdfs"][file];
  if (!facts["is_valid_tree"].get<bool>()) GTEST_SKIP() << "invalid tree: tested by the reader";
  const io::Scene scene = io::sceneFromUrdf((corpus() / file).string(), {corpus().string()}, {});
  // The automatic step: within 0.9 of the stable step estimated at it, and 1 ms a whole
  // number of steps (or bdf, with no step limit, at the output interval).
  const double dt = scene.model->options.time_step;
  if (scene.model->options.integrator != IntegratorType::kBdf) {
    EXPECT_LE(dt, 0.9 * estimateStableStep(*scene.model).limit.max_step) << file;
    EXPECT_NEAR(1e-3 / dt, std::round(1e-3 / dt), 1e-9) << file << ": dt " << dt;
  }
  Simulator sim(scene.model);
  const Model& m = *scene.model;
  const double e0 = mechanicalEnergy(m, sim.state());
  double scale = 1e-3;  // J: m g times 1 m, for the tolerance
  for (const auto& b : m.bodies) scale += b.kind == BodyKind::kDynamic ? b.mass * 9.81 : 0.0;
  const long steps = std::lround(m.options.duration / m.options.time_step);
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    ASSERT_TRUE(status.ok) << file << ": " << status.message;
  }
  for (const auto& b : sim.state().bodies) {
    ASSERT_TRUE(b.position.allFinite() && b.velocity.allFinite() && b.angular_velocity.allFinite());
  }
  EXPECT_LE(mechanicalEnergy(m, sim.state()), e0 + 1e-6 * scale) << file;
  EXPECT_NEAR(sim.state().time, 1.0, m.options.time_step);
}

// Runs a URDF at tribo run's automatic settings (rk4 at the automatic step, the given
// duration) and checks that it completes and that kinetic plus gravitational energy never
// rises above its start: nothing drives the robot, joint dampers and the ground only take.
void runsWithoutEnergyGain(const std::string& path, const std::string& duration) {
  const io::Scene scene = io::sceneFromUrdf(path, {corpus().string()}, {"duration=" + duration});
  const Model& m = *scene.model;
  ASSERT_EQ(m.options.integrator, IntegratorType::kRk4);
  Simulator sim(scene.model);
  const double e0 = mechanicalEnergy(m, sim.state());
  double scale = 1e-3;  // J: m g times 1 m, for the tolerance
  for (const auto& b : m.bodies) scale += b.kind == BodyKind::kDynamic ? b.mass * 9.81 : 0.0;
  double highest = e0;
  const long steps = std::lround(m.options.duration / m.options.time_step);
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    ASSERT_TRUE(status.ok) << path << ": " << status.message;
    highest = std::max(highest, mechanicalEnergy(m, sim.state()));
  }
  EXPECT_LE(highest, e0 + 1e-6 * scale) << path;
  EXPECT_NEAR(sim.state().time, m.options.duration, m.options.time_step);
}

// The humanoid ragdoll: hips of three damped revolute joints through two massless links (a
// gimbal). Falling, both hips pass close to gimbal lock after 1.3 s, where the two links
// turn together against the hip dampers; the dampers' cap (core/joint_forces.hpp) must see
// the links' inertia there, or the automatic rk4 step is unstable and the run stops.
TEST(UrdfOnGroundLonger, HumanoidRunsThreeSecondsAtTheAutomaticStep) {
  TRIBO_REQUIRE_URDF_CORPUS(folder);
  runsWithoutEnergyGain((corpus() / "bullet3/humanoid.urdf").string(), "3");
}

// The class, generated: a heavy body on the world, a leg hung from it by revolute joints
// about x, z and y through two massless links, each with a damper as strong as the leg's
// own inertia allows at the step; the leg's centre of mass off every axis so that gravity
// swings it through many poses, and the middle joint starting 0.05 rad from gimbal lock.
TEST(UrdfOnGroundLonger, DampedGimbalThroughMasslessLinksNearLock) {
  const fs::path dir = fs::temp_directory_path() / "tribo_urdf_gimbal";
  fs::create_directories(dir);
  for (const double mass : {0.05, 1.0, 5.0, 40.0}) {
    const double length = 0.3, i_leg = mass * length * length / 12;
    const auto num = [](double v) { return std::to_string(v); };
    const auto inertial = [&](double m, double i, const std::string& xyz) {
      return "<inertial><origin xyz=\"" + xyz + "\"/><mass value=\"" + num(m) +
             "\"/><inertia ixx=\"" + num(i) + "\" ixy=\"0\" ixz=\"0\" iyy=\"" + num(i) +
             "\" iyz=\"0\" izz=\"" + num(i) + "\"/></inertial>";
    };
    const auto joint = [&](const std::string& name, const std::string& parent,
                           const std::string& child, const std::string& axis,
                           const std::string& rpy) {
      // Damping I_leg / (2 h) at the 1 ms step: the most the leg alone would be held to.
      return "<joint name=\"" + name + "\" type=\"continuous\"><parent link=\"" + parent +
             "\"/><child link=\"" + child + "\"/><origin rpy=\"" + rpy + "\"/><axis xyz=\"" + axis +
             "\"/><dynamics damping=\"" + num(i_leg / 2e-3) + "\"/></joint>";
    };
    const std::string robot =
        "<robot name=\"gimbal\"><link name=\"base\">" + inertial(4 * mass, mass, "0 0 0") +
        "</link><joint name=\"mount\" type=\"fixed\"><parent link=\"world\"/><child "
        "link=\"base\"/><origin xyz=\"0 0 2\"/></joint><link name=\"l1\"/><link "
        "name=\"l2\"/><link name=\"leg\">" +
        inertial(mass, i_leg, "0.05 0.08 -0.15") + "</link>" +
        joint("hip_x", "base", "l1", "1 0 0", "0 0 0") +
        joint("hip_z", "l1", "l2", "0 0 1", "0 0 1.5208") +
        joint("hip_y", "l2", "leg", "0 1 0", "0 0 0") + "</robot>";
    const fs::path path = dir / "gimbal.urdf";
    std::ofstream(path) << robot;
    SCOPED_TRACE(mass);
    runsWithoutEnergyGain(path.string(), "2");
  }
}

std::vector<std::string> corpusFiles() {
  std::ifstream in(corpus() / "expected.json");
  if (!in) return {"bullet3/cube.urdf"};
  const nlohmann::json all = nlohmann::json::parse(in);
  std::vector<std::string> files;
  for (const auto& [file, facts] : all["urdfs"].items()) files.push_back(file);
  return files;
}

INSTANTIATE_TEST_SUITE_P(Corpus, UrdfOnGround, ::testing::ValuesIn(corpusFiles()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(UrdfPendulum, MovesAsTheSamePendulumWrittenAsASceneFile) {
  // scenes/robots/pendulum.urdf: massless base (welded to the world), hinge about y at 2 m.
  // Both start the arm at q = 0.3 rad about +y: centre at 2 m + R_y(0.3) (0, 0, -0.5).
  const double q = 0.3;
  const io::Scene from_yaml =
      io::loadSceneFromString(test::pendulumSceneYaml(q, Vec3(0, 0, 2), 2.0), "pendulum.yaml");
  ModelBuilder builder;
  builder.options() = from_yaml.model->options;
  io::UrdfPlacement placement;
  placement.joint_positions["hinge"] = q;
  io::addUrdfRobot(builder,
                   io::readUrdf(std::string(TRIBO_SOURCE_DIR) + "/scenes/robots/pendulum.urdf"),
                   placement);
  const auto urdf_model = builder.build();
  ASSERT_EQ(urdf_model->dynamicBodyCount(), 1);

  Simulator a(from_yaml.model), b(urdf_model);
  const BodyIndex arm_a = *from_yaml.model->findBody("arm");
  const BodyIndex arm_b = *urdf_model->findBody("arm");
  EXPECT_TRUE(a.state().bodies[arm_a.value].position.isApprox(
      b.state().bodies[arm_b.value].position, 1e-12));
  double max_gap = 0.0, min_x = 0.0;
  for (int i = 0; i < 2000; ++i) {
    ASSERT_TRUE(a.step().ok);
    ASSERT_TRUE(b.step().ok);
    const Vec3 pa = a.state().bodies[arm_a.value].position;
    max_gap = std::max(max_gap, (pa - b.state().bodies[arm_b.value].position).norm());
    min_x = std::min(min_x, pa.x());
  }
  EXPECT_LT(max_gap, 1e-9);
  EXPECT_GT(min_x, -0.5 * std::sin(q) - 1e-3);  // it swings between -0.3 and +0.3 rad
  EXPECT_LT(min_x, -0.5 * std::sin(q) + 1e-3);
}

}  // namespace
}  // namespace tribo
