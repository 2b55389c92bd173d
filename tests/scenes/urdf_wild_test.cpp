// URDF as robots from public repositories write it (issue #11), each class of file written
// here in several sizes and masses, run for 1 s at `tribo run ROBOT.urdf`'s automatic
// settings on the ground: none stops falsely, and each is checked against an expectation
// computed here from its inputs (statics of the resting robot, closed-form inertias, energy
// that a dissipative element can only take away).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "study/scene_run.hpp"

namespace tribo {
namespace {

namespace fs = std::filesystem;
constexpr double kG = 9.81;

class UrdfWild : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tribo_wild_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string inertial(double m, double ixx, double iyy, double izz,
                     const std::string& xyz = "0 0 0") {
  return "<inertial><origin xyz=\"" + xyz + "\"/><mass value=\"" + num(m) + "\"/><inertia ixx=\"" +
         num(ixx) + "\" iyy=\"" + num(iyy) + "\" izz=\"" + num(izz) +
         "\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
}

std::string boxInertial(double m, double a, double b, double c) {
  return inertial(m, m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
}

std::string parameter(const io::Scene& s, const std::string& name) {
  for (const auto& [k, v] : s.parameters)
    if (k == name) return v;
  return "";
}

// The run must finish its second: no stop, whatever it warns about.
study::RunResult runOneSecond(const io::Scene& scene) {
  study::RunResult r = study::runScene(scene);
  EXPECT_TRUE(r.complete) << scene.path << ": " << r.message;
  EXPECT_NEAR(r.simulated_seconds, 1.0, 1.5 * scene.model->options.time_step) << scene.path;
  return r;
}

const Body& body(const io::Scene& s, const std::string& name) {
  return s.model->bodies[s.model->findBody(name)->value];
}

// Class 1: zero-radius spheres mark the feet. A block standing on four such points rests
// with each point carrying a quarter of its weight: depth m g / (4 k), and the automatic
// stiffness makes that the target 1 mm (k = m g / (4 d)).
TEST_F(UrdfWild, ZeroRadiusSpheresAreContactPointsThatCarryTheRobot) {
  struct Case {
    double mass, a, b, c;
  };
  for (const Case& k :
       {Case{0.4, 0.06, 0.04, 0.03}, Case{20.0, 0.4, 0.3, 0.2}, Case{300.0, 1.5, 0.9, 0.6}}) {
    std::string feet;
    for (int i = 0; i < 4; ++i)
      feet += "<collision><origin xyz=\"" + num((i % 2 ? 0.5 : -0.5) * k.a) + " " +
              num((i / 2 ? 0.5 : -0.5) * k.b) + " " + num(-0.5 * k.c) +
              "\"/><geometry><sphere radius=\"0\"/></geometry></collision>";
    const std::string path =
        write("feet.urdf", "<robot name=\"feet\"><link name=\"block\">" +
                               boxInertial(k.mass, k.a, k.b, k.c) + feet + "</link></robot>");
    const io::UrdfRobot robot = io::readUrdf(path);
    bool noted = false;
    for (const auto& i : robot.issues)
      noted |= i.message.find("a contact point") != std::string::npos;
    EXPECT_TRUE(noted);
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    EXPECT_EQ(parameter(scene, "support_points"), "4");
    const double stiffness = std::stod(parameter(scene, "stiffness"));
    EXPECT_NEAR(stiffness, k.mass * kG / (4 * 1e-3), 1e-9 * stiffness);
    const study::RunResult r = runOneSecond(scene);
    // At rest the points are at z = -depth, the block's centre c/2 above them.
    const double depth = k.mass * kG / (4 * stiffness);
    const int z = r.trajectory.columnIndex("block.z");
    EXPECT_NEAR(r.trajectory.column(z).back(), 0.5 * k.c - depth, 0.05 * depth) << k.mass;
  }
}

// Class 2: a URDF is known by its content, not its extension.
TEST_F(UrdfWild, UpperCaseAndOtherExtensionsAreUrdfByContent) {
  const std::string robot =
      "<?xml version=\"1.0\"?>\n<!-- exported -->\n<robot name=\"r\">"
      "<link name=\"l\">" +
      boxInertial(1.0, 0.1, 0.1, 0.1) +
      "<collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry>"
      "</collision></link></robot>";
  for (const std::string name : {"ARM.URDF", "arm.xml", "arm"}) {
    const std::string path = write(name, robot);
    EXPECT_TRUE(io::looksLikeUrdf(path)) << name;
    runOneSecond(io::sceneFromUrdf(path, {}, {}));
  }
  EXPECT_FALSE(io::looksLikeUrdf(write("scene.yaml", "simulation: {duration: 1}\n")));
  EXPECT_FALSE(io::looksLikeUrdf(write("other.xml", "<?xml version=\"1.0\"?><sdf/>")));
}

// Class 3: a link with a mass and no <inertia> gets its collision solid's inertia at that
// mass (closed forms), or a sphere of water's density without geometry; the automatic step
// stays on the scale of the contact, not 1e-8 s.
TEST_F(UrdfWild, MassWithoutInertiaTakesTheInertiaOfItsGeometry) {
  for (const double m : {0.05, 3.0, 250.0}) {
    const double a = 0.02 * std::cbrt(m), b = 1.5 * a, c = 2 * a, r = a, len = 3 * a;
    const std::string path = write(
        "bare.urdf",
        "<robot name=\"bare\"><link name=\"box\"><inertial><mass value=\"" + num(m) +
            "\"/></inertial><collision><geometry><box size=\"" + num(a) + " " + num(b) + " " +
            num(c) +
            "\"/></geometry></collision></link>"
            "<link name=\"can\"><inertial><mass value=\"" +
            num(m) + "\"/></inertial><collision><geometry><cylinder radius=\"" + num(r) +
            "\" length=\"" + num(len) +
            "\"/></geometry></collision></link>"
            "<link name=\"lump\"><inertial><mass value=\"" +
            num(m) +
            "\"/></inertial></link>"
            "<joint name=\"j1\" type=\"continuous\"><parent link=\"box\"/><child link=\"can\"/>"
            "<origin xyz=\"0 " +
            num(3 * a) +
            " 0\"/><axis xyz=\"0 1 0\"/></joint>"
            "<joint name=\"j2\" type=\"continuous\"><parent link=\"box\"/><child link=\"lump\"/>"
            "<origin xyz=\"0 " +
            num(-3 * a) + " 0\"/><axis xyz=\"0 1 0\"/></joint></robot>");
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    const Mat3 box = body(scene, "box").inertia, can = body(scene, "can").inertia,
               lump = body(scene, "lump").inertia;
    EXPECT_NEAR(box(0, 0), m * (b * b + c * c) / 12, 1e-12 * m);
    EXPECT_NEAR(box(1, 1), m * (a * a + c * c) / 12, 1e-12 * m);
    EXPECT_NEAR(box(2, 2), m * (a * a + b * b) / 12, 1e-12 * m);
    EXPECT_NEAR(can(2, 2), m * r * r / 2, 1e-12 * m);
    EXPECT_NEAR(can(0, 0), m * (3 * r * r + len * len) / 12, 1e-12 * m);
    const double radius = std::cbrt(3 * m / (4 * M_PI * 1000));
    EXPECT_NEAR(lump(0, 0), 0.4 * m * radius * radius, 1e-12 * m);
    int notes = 0;
    for (const auto& n : scene.notes) notes += n.find("no inertia: given") != std::string::npos;
    EXPECT_EQ(notes, 3);
    EXPECT_GE(scene.model->options.time_step, 1e-4);
    runOneSecond(scene);
  }
}

// Class 4a: a small sensor sphere fixed to a heavy torso is pushed deeper than its radius
// when the torso rests on it and its four corners. Statics with equal point springs k: the
// sensor protrudes p = 0.75 r below the face, so 5 k delta + k p = W, the corners at delta,
// the sensor at delta + p > r. A warning names the torso; the run goes on.
TEST_F(UrdfWild, SmallSensorSpherePushedDeeperThanItsRadiusIsAWarningNotAStop) {
  struct Case {
    double mass, a, b, c, r;
  };
  for (const Case& k : {Case{40.0, 0.3, 0.2, 0.5, 1e-3}, Case{2.0, 0.1, 0.08, 0.2, 5e-4},
                        Case{400.0, 0.8, 0.5, 1.6, 1.2e-3}}) {
    const std::string path = write(
        "torso.urdf",
        "<robot name=\"humanoid\"><link name=\"torso\">" + boxInertial(k.mass, k.a, k.b, k.c) +
            "<collision><geometry><box size=\"" + num(k.a) + " " + num(k.b) + " " + num(k.c) +
            "\"/></geometry></collision></link><link name=\"imu\"><inertial><mass "
            "value=\"0.001\"/><inertia ixx=\"1e-10\" iyy=\"1e-10\" izz=\"1e-10\" ixy=\"0\" "
            "ixz=\"0\" iyz=\"0\"/></inertial><collision><geometry><sphere radius=\"" +
            num(k.r) +
            "\"/></geometry></collision></link><joint name=\"imu_mount\" type=\"fixed\">"
            "<parent link=\"torso\"/><child link=\"imu\"/><origin xyz=\"0.01 0 " +
            num(-0.5 * k.c + 0.25 * k.r) + "\"/></joint></robot>");
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    EXPECT_EQ(parameter(scene, "support_points"), "5");
    const study::RunResult r = runOneSecond(scene);
    const double stiffness = std::stod(parameter(scene, "stiffness"));
    const double weight = (k.mass + 0.001) * kG, p = 0.75 * k.r;
    const double delta = (weight / stiffness - p) / 5;
    ASSERT_GT(delta + p, k.r);  // the case is what it claims
    EXPECT_GT(r.stats.max_penetration, k.r);
    const auto z = r.trajectory.column(r.trajectory.columnIndex("torso.z"));
    // The body's origin is the lumped centre of mass, 0.001 kg towards the sensor.
    const double com = (0.5 * k.c * k.mass + (0.25 * k.r) * 0.001) / (k.mass + 0.001);
    EXPECT_NEAR(z.back(), com - delta, 0.05 * delta) << k.mass;
    bool warned = false;
    for (const auto& w : r.warnings)
      warned |= w.find("body 'torso': geometry 'imu_collision'") != std::string::npos;
    EXPECT_TRUE(warned);
  }
}

// The cart of classes 4b and 6: a chassis on two thin wheels (cylinders rolling on their
// rims) and a caster point, the chassis' centre of mass at x = -a, the caster at x = -L.
std::string cart(double chassis, double wheel, double radius, double width, double a, double len) {
  std::string wheels;
  for (const int side : {-1, 1}) {
    const std::string n = side < 0 ? "left" : "right";
    wheels +=
        "<link name=\"" + n + "\">" +
        inertial(wheel, wheel * (3 * radius * radius + width * width) / 12,
                 wheel * (3 * radius * radius + width * width) / 12, wheel * radius * radius / 2) +
        "<collision><origin rpy=\"1.5707963267948966 0 0\"/><geometry><cylinder radius=\"" +
        num(radius) + "\" length=\"" + num(width) +
        "\"/></geometry></collision></link><joint name=\"" + n +
        "_axle\" type=\"continuous\"><parent link=\"chassis\"/><child link=\"" + n +
        "\"/><origin xyz=\"0 " + num(side * 2 * radius) + " 0\"/><axis xyz=\"0 1 0\"/></joint>";
  }
  return "<robot name=\"cart\"><link name=\"chassis\">" +
         inertial(chassis, chassis * 0.01, chassis * 0.01, chassis * 0.01, num(-a) + " 0 0") +
         "<collision><origin xyz=\"" + num(-len) + " 0 " + num(-radius) +
         "\"/><geometry><sphere radius=\"0\"/></geometry></collision></link>" + wheels + "</robot>";
}

// Class 4b and 6: an 80 kg cart on thin wheels rests at the target depth. The wheels' rims
// touch at 2 points each, the caster at 1 (5 support points): with k = W / (5 d), statics
// about the axle give the caster F_c = M g a / L and each wheel's 2 points the rest. Thin
// wheels are judged by their radius along the normal: no deep-penetration warning.
TEST_F(UrdfWild, CartOnThinWheelsRestsAtTheTargetDepthWithoutFalseAlarm) {
  struct Case {
    double chassis, wheel, radius, width;
  };
  for (const Case& k :
       {Case{80.0, 2.0, 0.15, 0.002}, Case{3.0, 0.1, 0.04, 0.001}, Case{800.0, 20.0, 0.4, 0.01}}) {
    const double len = 4 * k.radius, a = len / 5;
    const std::string path =
        write("cart.urdf", cart(k.chassis, k.wheel, k.radius, k.width, a, len));
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    EXPECT_EQ(parameter(scene, "support_points"), "5");
    const study::RunResult r = runOneSecond(scene);
    const double stiffness = std::stod(parameter(scene, "stiffness"));
    const double total = (k.chassis + 2 * k.wheel) * kG, caster = k.chassis * kG * a / len;
    EXPECT_NEAR(stiffness, total / (5 * 1e-3), 1e-9 * stiffness);
    const double wheel_depth = (total - caster) / 2 / (2 * stiffness);
    for (const char* side : {"left", "right"}) {
      const auto z = r.trajectory.column(r.trajectory.columnIndex(std::string(side) + ".z"));
      EXPECT_NEAR(z.back(), k.radius - wheel_depth, 0.05 * wheel_depth) << k.chassis;
    }
    for (const auto& w : r.warnings) EXPECT_EQ(w.find("penetrated"), std::string::npos) << w;
  }
}

// A chain of `links` light links (mass m, inertia i about each axis, box geometry) on
// revolute joints about y with <dynamics friction damping>, hanging from a massless base
// welded to the world: fingers.
std::string fingers(int links, double m, double i, double friction, double damping,
                    bool massless = false) {
  std::string out = "<robot name=\"hand\"><link name=\"palm\"/>";
  std::string parent = "palm";
  for (int k = 0; k < links; ++k) {
    const std::string n = "phalanx" + std::to_string(k);
    out += "<link name=\"" + n + "\">" +
           (massless ? std::string() : inertial(m, i, i, i, "0.01 0 0")) +
           "<collision><origin xyz=\"0.01 0 0\"/><geometry><box size=\"0.02 0.01 0.01\"/>"
           "</geometry></collision></link><joint name=\"" +
           n + "_joint\" type=\"revolute\"><parent link=\"" + parent + "\"/><child link=\"" + n +
           "\"/><origin xyz=\"" + (k ? "0.02" : "0") +
           " 0 0\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1.5\" upper=\"1.5\" effort=\"1\" "
           "velocity=\"1\"/><dynamics friction=\"" +
           num(friction) + "\" damping=\"" + num(damping) + "\"/></joint>";
    parent = n;
  }
  return out + "</robot>";
}

// Mechanical energy of the dynamic bodies [J] (kinetic + gravitational).
double mechanicalEnergy(const Model& m, const State& s) {
  double e = 0.0;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].kind != BodyKind::kDynamic) continue;
    const BodyState& x = s.bodies[b];
    const Mat3 r = x.orientation.toRotationMatrix();
    e +=
        0.5 * m.bodies[b].mass * x.velocity.squaredNorm() +
        0.5 * x.angular_velocity.dot(r * m.bodies[b].inertia * r.transpose() * x.angular_velocity) -
        m.bodies[b].mass * m.options.gravity.dot(x.position);
  }
  return e;
}

// Class 5: joint friction on light links. The step stays on the contact's scale, the run
// finishes, and friction and damping only take energy: kinetic plus gravitational energy
// never rises above its start (nothing drives the fingers; the ground only stores energy
// while pressed, bounded by the contact's elastic energy at the target depth).
TEST_F(UrdfWild, JointFrictionOnLightLinksIsStableAndOnlyDissipates) {
  struct Case {
    int links;
    double m, i, friction, damping;
  };
  for (const Case& k : {Case{3, 0.01, 1e-6, 5.0, 0.0}, Case{2, 1e-3, 1e-8, 0.5, 0.01},
                        Case{4, 0.2, 1e-4, 50.0, 1.0}}) {
    const std::string path = write("hand.urdf", fingers(k.links, k.m, k.i, k.friction, k.damping));
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    EXPECT_EQ(scene.model->options.integrator, IntegratorType::kRk4);
    EXPECT_GE(scene.model->options.time_step, 1e-4) << k.i;
    Simulator sim(scene.model);
    const double e0 = mechanicalEnergy(*scene.model, sim.state());
    double highest = e0;
    const long steps = std::lround(1.0 / scene.model->options.time_step);
    for (long n = 0; n < steps; ++n) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
      highest = std::max(highest, mechanicalEnergy(*scene.model, sim.state()));
    }
    EXPECT_LE(highest - e0, 1e-9 * std::abs(e0) + 1e-12) << k.i;
  }
}

// Class 6: an arm whose links are all massless gets stand-in masses; the automatic contact
// stiffness is sized for the weight of what moves, so where the arm lies on the ground each
// point sinks no deeper than the whole moving weight on one point would push it: W / k.
TEST_F(UrdfWild, MasslessArmGetsAStiffnessForWhatMoves) {
  for (const int links : {2, 3, 5}) {
    const std::string path = write("arm.urdf", fingers(links, 0.0, 0.0, 0.0, 0.0, true));
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    const study::RunResult r = runOneSecond(scene);
    double moving = 0.0;
    for (const auto& b : scene.model->bodies) moving += b.kind == BodyKind::kDynamic ? b.mass : 0;
    const double stiffness = std::stod(parameter(scene, "stiffness"));
    const int points = std::stoi(parameter(scene, "support_points"));
    EXPECT_NEAR(stiffness, moving * kG / (points * 1e-3), 1e-9 * stiffness);
    Simulator sim(scene.model);
    for (int n = 0; n < std::lround(1.0 / scene.model->options.time_step); ++n) sim.step();
    EXPECT_LE(sim.current().max_penetration, moving * kG / stiffness) << links;
  }
}

// Class 7: what Drake, Gazebo and PyBullet load: a revolute joint without <limit> turns
// freely, and an undeclared parent `world` is the world. An arm released horizontal on such a
// joint from a post swings through the bottom (no [0, 0] range holds it) with the closed
// form's speed there: w = sqrt(2 m g l / I_p), I_p = I_c + m l^2. --strict refuses the file.
TEST_F(UrdfWild, RevoluteWithoutLimitsOnAnUndeclaredWorldSwingsFreely) {
  struct Case {
    double m, len;
  };
  for (const Case& k : {Case{1.0, 0.5}, Case{0.02, 0.05}, Case{60.0, 2.0}}) {
    const double w = 0.05 * k.len, ic = k.m * (k.len * k.len + w * w) / 12;
    const double post = 3 * k.len;
    const std::string path =
        write("free.urdf",
              "<robot name=\"free\"><link name=\"post\"><collision><origin xyz=\"0 0 " +
                  num(-post / 2) + "\"/><geometry><box size=\"0.01 0.01 " + num(post) +
                  "\"/></geometry></collision></link><joint name=\"mount\" type=\"fixed\"><parent "
                  "link=\"world\"/><child link=\"post\"/></joint><link name=\"arm\">" +
                  inertial(k.m, ic, ic, k.m * w * w / 6, num(k.len / 2) + " 0 0") +
                  "</link><joint name=\"hinge\" type=\"revolute\"><parent link=\"post\"/><child "
                  "link=\"arm\"/><axis xyz=\"0 1 0\"/></joint></robot>");
    EXPECT_THROW(io::readUrdf(path, {}, {true}), io::UrdfError);
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    ASSERT_EQ(scene.model->dynamicBodyCount(), 1);
    ASSERT_EQ(scene.model->joints.size(), 1u);
    EXPECT_EQ(scene.model->joints[0].name, "hinge");
    EXPECT_FALSE(scene.model->joints[0].elements.limit);
    Simulator sim(scene.model);
    double fastest = 0.0;
    for (int n = 0; n < std::lround(1.0 / scene.model->options.time_step); ++n) {
      ASSERT_TRUE(sim.step().ok);
      fastest = std::max(fastest, sim.state().bodies[0].angular_velocity.norm());
    }
    const double expected = std::sqrt(2 * k.m * kG * k.len / 2 / (ic + k.m * k.len * k.len / 4));
    // The run samples the bottom at steps of h: the speed is flat there to second order.
    const double h = scene.model->options.time_step;
    EXPECT_NEAR(fastest, expected, 1e-3 * expected + expected * std::pow(expected * h, 2)) << k.m;
  }
}

// Class 9: a joint limit between a free base light about the joint's axis and a heavier arm
// (an arm dropped on the ground by its base, as the Panda is). The default limit is a
// critically damped stop at 0.5 / dt on the pair's reduced inertia I_p I_c / (I_p + I_c),
// I_p the base's own about the axis and I_c the arm's about the joint (parallel axes), so
// the automatic step is within 0.9 of the stable step estimated at its own gains, whatever
// the masses; it divides the 1 ms output interval; and the run says nothing about either.
TEST_F(UrdfWild, AutomaticStepIsWithinItsOwnEstimateOnALimitedJointOfAFreeBase) {
  struct Case {
    double base_mass, arm_mass, arm_length;
  };
  for (const Case& k : {Case{4.0, 3.0, 0.3}, Case{0.5, 2.0, 0.5}, Case{40.0, 0.05, 0.1},
                        Case{1.0, 1.0, 0.05}, Case{0.2, 20.0, 1.0}}) {
    for (const std::string integrator : {"rk4", "semi_implicit_euler"}) {
      const double l = k.arm_length, m = k.arm_mass;
      const double base_izz = k.base_mass * 0.02 / 12;  // a 0.1 m cube
      // The arm: a bar of length l along x from the joint, its centre of mass at l / 2.
      const double i_bar = m * (l * l + 0.0004) / 12;
      const std::string text =
          "<robot name=\"arm\"><link name=\"base\">" +
          inertial(k.base_mass, base_izz, base_izz, base_izz) +
          "<collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry></collision></link>"
          "<link name=\"arm\">" +
          inertial(m, m * 0.0008 / 12, i_bar, i_bar, num(l / 2) + " 0 0") +
          "<collision><origin xyz=\"" + num(l / 2) + " 0 0\"/><geometry><box size=\"" + num(l) +
          " 0.02 0.02\"/></geometry></collision></link><joint name=\"yaw\" type=\"revolute\">"
          "<parent link=\"base\"/><child link=\"arm\"/><origin xyz=\"0 0 0.07\"/>"
          "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
          "</joint></robot>";
      const io::Scene scene =
          io::sceneFromUrdf(write("arm.urdf", text), {}, {"integrator=" + integrator});
      const double dt = scene.model->options.time_step;
      const double per_ms = 1e-3 / dt;
      EXPECT_NEAR(per_ms, std::round(per_ms), 1e-9) << dt;
      const double i_arm = i_bar + m * (l / 2) * (l / 2);
      const double reduced = base_izz * i_arm / (base_izz + i_arm);
      const Joint& yaw = scene.model->joints.back();
      ASSERT_NE(yaw.name.find("yaw"), std::string::npos) << yaw.name;
      EXPECT_NEAR(yaw.elements.limit->stiffness, reduced * std::pow(0.5 / dt, 2),
                  1e-9 * yaw.elements.limit->stiffness)
          << integrator << " " << k.base_mass;
      const double limit = estimateStableStep(*scene.model).limit.max_step;
      EXPECT_LE(dt, 0.9 * limit) << integrator << " " << k.base_mass;
      // Semi-implicit Euler drifts on turning constrained bodies (docs/joints.md), and a
      // 20 kg arm landing on a 0.2 kg base tears the joint 0.1 m apart at rk4's automatic
      // step too (5 mm at 0.1 ms): such a run may stop, and then for constraint drift, the
      // guard made for it; rk4 with the arm at most ten times the base finishes.
      const study::RunResult r = study::runScene(scene);
      if ((integrator == "rk4" && m <= 10 * k.base_mass) || r.complete) {
        EXPECT_TRUE(r.complete) << r.message;
      } else {
        EXPECT_EQ(r.stop.quantity, "constraint_drift") << r.message;
      }
      for (const std::string& w : r.warnings) {
        EXPECT_EQ(w.find("exceeds the estimated stability limit"), std::string::npos) << w;
        EXPECT_EQ(w.find("not a whole multiple"), std::string::npos) << w;
      }
    }
  }
}

// The guards still stop what they exist to stop: a step far above the stability limit blows
// up (energy rising), whatever the robot. 60 times: the limit is the friction's yaw (3 times
// its translation's rate, core/stability.hpp), a chatter that dissipates, 20 times below the
// soft normal contact (URDF's default kp) whose divergence the guard stops.
TEST_F(UrdfWild, StepFarAboveTheLimitStillStops) {
  for (const double m : {0.5, 50.0}) {
    const double a = 0.1 * std::cbrt(m);
    const std::string path =
        write("block.urdf", "<robot name=\"b\"><link name=\"block\">" + boxInertial(m, a, a, a) +
                                "<collision><geometry><box size=\"" + num(a) + " " + num(a) + " " +
                                num(a) + "\"/></geometry></collision></link></robot>");
    const io::Scene probe = io::sceneFromUrdf(path, {}, {});
    const double limit = estimateStableStep(*probe.model).limit.max_step;
    const io::Scene scene =
        io::sceneFromUrdf(path, {}, {"dt=" + num(60 * limit), "integrator=rk4"});
    const study::RunResult r = study::runScene(scene);
    EXPECT_FALSE(r.complete) << m;
    EXPECT_EQ(r.stop.quantity, "energy") << r.message;
    EXPECT_NE(r.message.find("body 'block'"), std::string::npos) << r.message;
  }
}

// The step floor: a light link on a very stiff contact (Gazebo kp) needs a step far below
// min_dt. The automatic settings say so before the run, naming the element, and take bdf;
// with rk4 asked for, the run goes at min_dt with the same explanation.
TEST_F(UrdfWild, AStepBelowTheFloorIsExplainedAndTakesBdf) {
  for (const double kp : {1e9, 1e11}) {
    const double m = 0.001;
    const std::string path = write(
        "stiff.urdf", "<robot name=\"s\"><link name=\"pebble\">" + inertial(m, 1e-8, 1e-8, 1e-8) +
                          "<collision><geometry><sphere radius=\"0.005\"/></geometry></collision>"
                          "</link><gazebo reference=\"pebble\"><kp>" +
                          num(kp) + "</kp></gazebo></robot>");
    const io::Scene scene = io::sceneFromUrdf(path, {}, {});
    EXPECT_EQ(scene.model->options.integrator, IntegratorType::kBdf);
    bool explained = false;
    for (const auto& n : scene.notes)
      explained |= n.find("set by contact pair (ground, pebble_collision)") != std::string::npos &&
                   n.find("running with bdf instead") != std::string::npos;
    EXPECT_TRUE(explained);
    const io::Scene forced = io::sceneFromUrdf(path, {}, {"integrator=rk4"});
    EXPECT_EQ(forced.model->options.integrator, IntegratorType::kRk4);
    EXPECT_DOUBLE_EQ(forced.model->options.time_step, 1e-5);
    const double limit = estimateStableStep(*forced.model).limit.max_step;
    // Critically damped (kp without kd): a double real eigenvalue -w, w = sqrt(4 k / m) on the
    // estimate's four points, so the limit is RK4's real-axis bound z / w, z the real root of
    // R(-z) = 1: z^3 - 4 z^2 + 12 z - 24 = 0 (Newton from 3).
    double z = 3.0;
    for (int i = 0; i < 50; ++i) z -= (((z - 4) * z + 12) * z - 24) / ((3 * z - 8) * z + 12);
    EXPECT_NEAR(limit, z / std::sqrt(4 * kp / m), 1e-6 * limit);
  }
}

}  // namespace
}  // namespace tribo
