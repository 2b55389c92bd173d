// Direction-dependent friction through the whole engine (contact/anisotropy.hpp), against
// references computed here:
// - stopping distances of a block launched along, against and across its grain, at three
//   masses: the block's equation m u' = -r mu m g tanh(r u / v_eps) (the law sees the speed
//   r u along an axis with ratio r) gives x = int_0^v0 u du / (r mu g tanh(r u / v_eps)),
//   which tends to Coulomb's v0^2 / (2 r mu g);
// - the curved path of a block launched off its grain (scenes/experiments/
//   anisotropic_slider.yaml): the particle's equation u' = -mu g tanh(|R u| / v_eps)
//   R^2 u / |R u|, integrated by RK4 here;
// - the ratchet (scenes/experiments/ratchet_drive.yaml): a symmetric push moves a block whose
//   forward and backward coefficients differ; its equation integrated here;
// - the limit surface turns with the body exactly: a yawed block sliding at the same angle
//   to its grain gets the same force in its own frame (to 1e-12), and ratios of 1 give the
//   isotropic law's force;
// - a dynamic law's bristles turn with the grain: the same state, the block turned about the
//   normal, gives the same force in the block's frame (1e-12);
// - a ski whose tail is grooved (scenes/experiments/ski_on_slope.yaml) swings round to the
//   fall line like a weathervane, and a plain one does not: the tail's lateral friction acts
//   behind the centre of mass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81, kMu = 0.3;
const std::string kSlider =
    std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/anisotropic_slider.yaml";
const std::string kSki = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/ski_on_slope.yaml";
const std::string kRatchet =
    std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/ratchet_drive.yaml";

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

struct Planar {
  double x = 0, y = 0, u = 0, v = 0;
};

// RK4 at step h of the particle (x, y, u, v) with acceleration accel(t, u, v), to time T.
Planar integrate(Planar s, double duration, double h,
                 const std::function<Eigen::Vector2d(double, double, double)>& accel) {
  const long steps = std::lround(duration / h);
  for (long i = 0; i < steps; ++i) {
    const double t = i * h;
    const Eigen::Vector2d k1 = accel(t, s.u, s.v);
    const Eigen::Vector2d k2 = accel(t + h / 2, s.u + h / 2 * k1.x(), s.v + h / 2 * k1.y());
    const Eigen::Vector2d k3 = accel(t + h / 2, s.u + h / 2 * k2.x(), s.v + h / 2 * k2.y());
    const Eigen::Vector2d k4 = accel(t + h, s.u + h * k3.x(), s.v + h * k3.y());
    s.x += h * (s.u + h / 6 * (k1.x() + k2.x() + k3.x()));
    s.y += h * (s.v + h / 6 * (k1.y() + k2.y() + k3.y()));
    s.u += h / 6 * (k1.x() + 2 * k2.x() + 2 * k3.x() + k4.x());
    s.v += h / 6 * (k1.y() + 2 * k2.y() + 2 * k3.y() + k4.y());
  }
  return s;
}

// The scene's body `name` at the scene's duration, and at its start in `start`.
BodyState finalState(const io::Scene& scene, const std::string& name, BodyState* start) {
  Simulator sim(scene.model);
  const std::size_t body = static_cast<std::size_t>(scene.model->findBody(name)->value);
  if (start != nullptr) *start = sim.state().bodies[body];
  const long steps = std::lround(scene.model->options.duration / scene.model->options.time_step);
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      ADD_FAILURE() << status.message;
      break;
    }
  }
  return sim.state().bodies[body];
}

// The scene's block from its start, run to the scene's duration.
Planar run(const io::Scene& scene) {
  BodyState start;
  const BodyState b = finalState(scene, "block", &start);
  return {b.position.x() - start.position.x(), b.position.y() - start.position.y(), b.velocity.x(),
          b.velocity.y()};
}

// The particle's acceleration on the slider's plane: ratios (forward, backward) along x and
// `across` along y, the coulomb tanh law at v_eps.
Eigen::Vector2d sliderAccel(double u, double v, double forward, double backward, double across,
                            double v_eps) {
  const double r1 = u >= 0 ? forward : backward;
  const Eigen::Vector2d rs(r1 * u, across * v);
  const double speed = rs.norm();
  if (speed == 0.0) return Eigen::Vector2d::Zero();
  return -kMu * kG * std::tanh(speed / v_eps) * Eigen::Vector2d(r1 * rs.x(), across * rs.y()) /
         speed;
}

TEST(AnisotropicFriction, StoppingDistancesAlongAgainstAndAcrossTheGrainAtThreeMasses) {
  const double v0 = 1.0, v_eps = 1e-3;
  for (double mass : {0.2, 2.0, 20.0}) {
    for (const auto& [beta, ratio] : {std::pair{0.0, 0.5}, std::pair{kPi, 3.0},
                                      std::pair{kPi / 2, 1.5}, std::pair{-kPi / 2, 1.5}}) {
      const double r = ratio;  // a structured binding cannot be captured (C++17 rules)
      SCOPED_TRACE("m " + std::to_string(mass) + " beta " + std::to_string(beta));
      // Long enough to stop: v0 / (r mu g) and the tanh tail.
      const double duration = v0 / (r * kMu * kG) + 0.05;
      const Planar got = run(
          io::loadScene(kSlider, {set("m", mass), set("beta", beta), set("duration", duration)}));
      // x = int_0^v0 u du / (r mu g tanh(r u / v_eps)), by Simpson's rule on u.
      const int n = 200000;
      auto integrand = [&](double u) {
        return u == 0.0 ? v_eps / (r * r * kMu * kG)
                        : u / (r * kMu * kG * std::tanh(r * u / v_eps));
      };
      double sum = integrand(0.0) + integrand(v0);
      for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(v0 * i / n);
      const double distance = sum * v0 / (3.0 * n);
      const double coulomb = v0 * v0 / (2.0 * r * kMu * kG);
      EXPECT_NEAR(distance, coulomb, 1e-3 * coulomb);  // the reference is Coulomb's, nearly
      const double travelled = std::hypot(got.x, got.y);
      // What is left of the tanh tail after `duration`: u decays at rate r^2 mu g / v_eps.
      EXPECT_NEAR(travelled, distance, 1e-6 * distance);
      // Straight: no sideways drift off an axis.
      EXPECT_NEAR(std::atan2(got.y, got.x), beta == -kPi / 2 ? -kPi / 2 : beta, 1e-9);
      EXPECT_LT(std::hypot(got.u, got.v), 1e-6);
    }
  }
}

TEST(AnisotropicFriction, OffTheGrainThePathCurvesAsTheParticleEquationSays) {
  const double forward = 0.5, backward = 3.0, across = 1.5, v_eps = 1e-3;
  for (double beta : {0.6, 2.0, -1.0}) {
    SCOPED_TRACE(beta);
    const io::Scene scene = io::loadScene(kSlider, {set("beta", beta), "duration=0.8"});
    const Planar got = run(scene);
    const double dt = scene.model->options.time_step;
    auto accel = [&](double, double u, double v) {
      return sliderAccel(u, v, forward, backward, across, v_eps);
    };
    const Planar start{0, 0, std::cos(beta), std::sin(beta)};
    const Planar same = integrate(start, 0.8, dt, accel);
    const Planar fine = integrate(start, 0.8, dt / 10, accel);
    std::printf("beta %.2f: x %.9f y %.9f (particle %.9f %.9f; launch line's y %.9f)\n", beta,
                got.x, got.y, fine.x, fine.y, got.x * std::tan(beta));
    // The engine's block is the particle to the contact's rounding at the same step, and
    // within the step's own error of the converged path.
    EXPECT_NEAR(got.x, same.x, 1e-9);
    EXPECT_NEAR(got.y, same.y, 1e-9);
    EXPECT_NEAR(got.x, fine.x, 1e-6);
    EXPECT_NEAR(got.y, fine.y, 1e-6);
    // And it did curve: off the launch line by more than the tolerance a thousand times.
    EXPECT_GT(std::abs(got.y - got.x * std::tan(beta)), 1e-3);
  }
}

TEST(AnisotropicFriction, ASymmetricPushDrivesTheRatchetAsItsEquationSays) {
  const double v_eps = 1e-3, f = 2.0;
  for (double ratio : {0.8, 1.0, 1.4}) {
    SCOPED_TRACE(ratio);
    const io::Scene scene = io::loadScene(kRatchet, {set("ratio", ratio)});
    const Planar got = run(scene);
    const double dt = scene.model->options.time_step, duration = scene.model->options.duration;
    auto accel = [&](double t, double u, double) {
      const double r = u >= 0 ? 0.5 : 1.5;
      return Eigen::Vector2d(
          ratio * kMu * kG * std::sin(2 * kPi * f * t) - r * kMu * kG * std::tanh(r * u / v_eps),
          0.0);
    };
    const Planar same = integrate({}, duration, dt, accel);
    const Planar fine = integrate({}, duration, dt / 10, accel);
    std::printf("ratchet F0/(mu m g) %.1f: x %.9f m (equation %.9f) over %g periods\n", ratio,
                got.x, fine.x, duration * f);
    EXPECT_NEAR(got.x, same.x, 1e-9);
    EXPECT_NEAR(got.x, fine.x, 1e-6);
    EXPECT_GT(got.x, 0.01);  // forward, by centimetres
  }
  // A symmetric sole under the same push rocks about a fixed place once its first forward
  // half-period is over: over the second pair of periods it does not walk (to tanh's creep),
  // where the ratchet walks by centimetres.
  const Planar one = run(io::loadScene(kRatchet, {"backward=0.5", "duration=1"}));
  const Planar two = run(io::loadScene(kRatchet, {"backward=0.5", "duration=2"}));
  std::printf("symmetric sole: x %.6e m at 1 s, %.6e m at 2 s\n", one.x, two.x);
  EXPECT_LT(std::abs(two.x - one.x), 1e-4);
}

std::string turnedScene(double yaw, double beta, const std::string& anisotropy) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "simulation: {duration: 1, time_step: 0.001, gravity: [0, 0, -9.81]}\n"
                "bodies:\n"
                "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: "
                "halfspace}]}\n"
                "  - {name: block, mass: 1.5, position: [0, 0, %.17g], rpy: [0, 0, %.17g],\n"
                "     velocity: [%.17g, %.17g, 0],\n"
                "     geometry: [{name: box, shape: box, size: [0.3, 0.2, 0.1]}]}\n"
                "friction_laws:\n"
                "  stribeck: {mu_s: 0.35, mu_k: 0.3, v_st: 0.15, v_eps: 0.01}\n"
                "materials:\n"
                "  - {name: m, normal: {law: linear, stiffness: 1.0e5, damping: 0}, friction: "
                "stribeck%s}\n"
                "contacts:\n  - {a: floor, b: box, material: m}\n",
                0.05 - 1.5 * 9.81 / 4e5, yaw, 0.05 * std::cos(yaw + beta),
                0.05 * std::sin(yaw + beta), anisotropy.c_str());
  return buf;
}

Vec3 tangentialForceInBodyFrame(double yaw, double beta, const std::string& anisotropy) {
  const io::Scene s = io::loadSceneFromString(turnedScene(yaw, beta, anisotropy), "turned.yaml");
  Simulator sim(s.model);
  const std::size_t block = static_cast<std::size_t>(s.model->findBody("block")->value);
  const Vec3 f = sim.current().contact_wrench[block].force;
  return Eigen::AngleAxisd(-yaw, Vec3::UnitZ()) * Vec3(f.x(), f.y(), 0.0);
}

TEST(AnisotropicFriction, TheLimitSurfaceTurnsWithTheBodyExactly) {
  const std::string grain =
      ", anisotropy: {axis: [1, 0.5, 0], ratio: [0.4, 1.3], backward: [2.0, 0.7]}";
  for (double beta : {0.0, 0.4, 2.0, -2.5}) {
    const Vec3 reference = tangentialForceInBodyFrame(0.0, beta, grain);
    ASSERT_GT(reference.norm(), 0.0);
    for (double degrees : {15.0, 30.0, 45.0, 60.0}) {
      SCOPED_TRACE("beta " + std::to_string(beta) + " yaw " + std::to_string(degrees));
      const Vec3 turned = tangentialForceInBodyFrame(degrees * kPi / 180, beta, grain);
      EXPECT_LT((turned - reference).norm(), 1e-12 * reference.norm());
    }
    // Ratios of 1 are the isotropic law.
    const Vec3 iso = tangentialForceInBodyFrame(0.7, beta, "");
    const Vec3 ones = tangentialForceInBodyFrame(0.7, beta, ", anisotropy: {ratio: [1, 1]}");
    EXPECT_LT((ones - iso).norm(), 1e-12 * iso.norm());
    // And the grain does change the force: not parallel to the slip off its axes.
    const Vec3 slip(std::cos(beta), std::sin(beta), 0.0);
    EXPECT_GT(reference.normalized().cross(slip).norm(), 1e-2);
  }
}

// A dynamic law's bristles turn with the grain (contact/dynamic_friction.hpp): a block sliding
// under anisotropic LuGre for 8 ms has bristles deflected along its scaled slip; the same
// state with the block turned by 15 to 45 degrees about the normal, its velocity turned with
// it (so the slip is the same in the block's frame), gives the same friction force in the
// block's frame to 1e-12: the stored state turned with the axes. Kept in world vectors, as
// an isotropic law's state is, the bristle no longer lies along the scaled slip and its
// damping term gives ten times the force (measured: 19 N against 1.9 N at 15 degrees).
TEST(AnisotropicFriction, ADynamicLawsBristlesTurnWithTheGrain) {
  const std::string lugre =
      "lugre: {sigma0: 1.0e5, sigma1: 300, sigma2: 0.4, mu_c: 0.3, mu_s: 0.35, v_s: 0.01}\n";
  const std::string grain =
      ", anisotropy: {axis: [1, 0.5, 0], ratio: [0.4, 1.3], backward: [2.0, 0.7]}";
  for (double beta : {0.4, 2.0}) {
    std::string yaml = turnedScene(0.0, beta, grain);
    yaml.replace(yaml.find("stribeck: {"),
                 yaml.find("}\n", yaml.find("stribeck: {")) + 2 - yaml.find("stribeck: {"), lugre);
    yaml.replace(yaml.find("friction: stribeck"), 18, "friction: lugre");
    // LuGre's bristles at sigma0 1e5 per unit load want a step far below the scene's 1 ms.
    yaml.replace(yaml.find("time_step: 0.001"), 16, "time_step: 1.0e-5");
    // Each turned corner continues its own record: the nearest within 0.2 m (a turn of up to
    // 45 degrees moves a corner of the 0.3 x 0.2 m sole by 0.14 m, less than to its neighbour).
    yaml.replace(yaml.find("gravity: [0, 0, -9.81]}"), 23,
                 "gravity: [0, 0, -9.81], collision: {match_radius: 0.2}}");
    const io::Scene scene = io::loadSceneFromString(yaml, "turned_lugre.yaml");
    Simulator sim(scene.model);
    const std::size_t block = static_cast<std::size_t>(scene.model->findBody("block")->value);
    for (int i = 0; i < 800; ++i) {
      const StepStatus status = sim.step();
      ASSERT_TRUE(status.ok) << status.message;
    }
    const State settled = sim.state();
    ASSERT_GT(settled.friction_values.size(), 0u);
    auto forceInBlockFrame = [&](double yaw) {
      State turned = settled;
      const Eigen::AngleAxisd turn(yaw, Vec3::UnitZ());
      BodyState& b = turned.bodies[block];
      b.orientation = Eigen::Quaterniond(turn) * b.orientation;
      b.velocity = turn * b.velocity;
      b.angular_velocity = turn * b.angular_velocity;  // it rocks a little as it slides
      sim.setState(turned);
      const Vec3 f = sim.current().contact_wrench[block].force;
      return Vec3(b.orientation.conjugate() * Vec3(f.x(), f.y(), 0.0));
    };
    const Vec3 reference = forceInBlockFrame(0.0);
    ASSERT_GT(reference.norm(), 0.1);
    for (double degrees : {15.0, 30.0, 45.0}) {
      SCOPED_TRACE("beta " + std::to_string(beta) + " yaw " + std::to_string(degrees));
      const Vec3 turned = forceInBlockFrame(degrees * kPi / 180);
      std::printf(
          "beta %.1f turned %.0f deg: block-frame force [%.12f, %.12f] N (unturned "
          "[%.12f, %.12f])\n",
          beta, degrees, turned.x(), turned.y(), reference.x(), reference.y());
      EXPECT_LT((turned - reference).norm(), 1e-12 * reference.norm());
    }
  }
}

TEST(AnisotropicFriction, AGroovedSkiTurnsDownTheFallLineAndAPlainOneDoesNot) {
  auto finalYaw = [](const std::vector<std::string>& overrides, Vec3* velocity) {
    const BodyState b = finalState(io::loadScene(kSki, overrides), "ski", nullptr);
    *velocity = b.velocity;
    const Vec3 heading = b.orientation * Vec3::UnitX();
    return std::atan2(heading.y(), heading.x());
  };
  Vec3 v;
  const double grooved = finalYaw({}, &v);
  std::printf("grooved ski: yaw %.3f deg, velocity [%.3f, %.3f] m/s\n", grooved * 180 / kPi, v.x(),
              v.y());
  // Turning tip first toward the fall line (+x): from 60 degrees to 22.5 in 3 s (measured;
  // the restoring moment is the tail's lateral friction, which falls as 1 / speed while the
  // ski glides along its length, so the last degrees take longer), moving down it.
  EXPECT_GT(grooved, 0.0);
  EXPECT_LT(grooved, 25.0 * kPi / 180);
  EXPECT_GT(v.x(), 2.0 * std::abs(v.y()));
  const double plain = finalYaw({"across=1"}, &v);
  std::printf("plain ski: yaw %.3f deg, velocity [%.3f, %.3f] m/s\n", plain * 180 / kPi, v.x(),
              v.y());
  // Set down at 60 degrees it slides straight down the fall line sideways, not turning:
  // friction acts alike on both halves.
  EXPECT_NEAR(plain, 60.0 * kPi / 180, 1e-6);
  EXPECT_LT(std::abs(v.y()), 1e-6 * v.x());
}

}  // namespace
}  // namespace tribo
