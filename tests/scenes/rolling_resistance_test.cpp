// Rolling resistance and spinning friction with stiction (contact/rolling_resistance.hpp),
// through the whole engine, against statics and closed forms:
// - a ball pushed at its centre to 0.999 of its rolling threshold mu_r m g / r_e stays (no
//   creep over 10 s) and at 1.001 rolls, at three masses and radii; set down on a slope at
//   0.9 of its threshold tan(alpha) = mu_r / r_e it stays
//   (scenes/experiments/ball_on_slope.yaml); above the threshold it accelerates at
//   g (sin(alpha) - mu_r cos(alpha) / r_e) / (1 + I / (m r_e^2)), the rolling ball's
//   equations with the moment held at mu_r F_n;
// - a ball rolling on a flat floor at v0 decelerates at g mu_r / r_e / (1 + I / (m r_e^2))
//   and stops after v0^2 / (2 a), then stays;
// r_e = r - d / 2 is the lever of friction about the centre in the penalty contact (sunk by
// d = F_n / k, the point midway into the depth: contact/primitive_contacts.cpp); as k grows
// it tends to r and these to the rigid ball's (5/7) forms.
// - a solid cylinder lying on the slope (scenes/experiments/cylinder_on_slope.yaml: its two
//   rims' lowest points carry the load) holds at
//   0.9 of its threshold and at 1.5 accelerates as the same equations say with I = m r^2 / 2;
// - a ball spinning about the vertical (scenes/experiments/spinning_ball.yaml) spins down
//   linearly, I w' = -mu_spin r_c m g, stops at I w0 / (mu_spin r_c m g) having turned
//   w0^2 / (2 |w'|) (the work of the moment equals the kinetic energy it took), and stays;
// - a spinning top on a round tip (scenes/experiments/spinning_top.yaml) does the same with
//   I = m R^2 / 2 at three masses, disc radii and patch radii, and twisted slowly to 0.999 of
//   mu_spin r_c m g it holds (the angular spring's give M / k, then no creep) while at 1.001
//   it turns, accelerating at the excess over I.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;
const std::string kSlope = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/ball_on_slope.yaml";
const std::string kSpin = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/spinning_ball.yaml";
const std::string kCylinder =
    std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/cylinder_on_slope.yaml";
const std::string kTop = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/spinning_top.yaml";

std::string set(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

// Runs a scene, calling `each` after every step with body `body`'s state; stops at a failure.
void run(const io::Scene& scene, const std::function<void(const State&, const BodyState&)>& each,
         const std::string& body = "ball") {
  Simulator sim(scene.model);
  const std::size_t ball = static_cast<std::size_t>(scene.model->findBody(body)->value);
  const long steps = std::lround(scene.model->options.duration / scene.model->options.time_step);
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      ADD_FAILURE() << status.message;
      return;
    }
    each(sim.state(), sim.state().bodies[ball]);
  }
}

struct Size {
  double m, r;
};

// The lever r - d / 2 at load m g cos(alpha) on the scene's contact stiffness 1e5 m N/m.
double lever(double r, double alpha) { return r - 0.5 * kG * std::cos(alpha) / 1e5; }

constexpr Size kSizes[3] = {{0.2, 0.02}, {2.0, 0.05}, {20.0, 0.2}};

// As exact break-away is tested (tests/scenes/exact_break_away_test.cpp): the load rises
// smoothly over 10 s, since a load applied at once to unloaded springs is always exceeded by
// the resisting moment while the ball comes to rest (it must decelerate), by more than 0.1%.
TEST(RollingResistance, ABallPushedTo0999OfItsThresholdHoldsAndAt1001Rolls) {
  for (const Size& size : kSizes) {
    const double mu_r = 0.04 * size.r, r_e = lever(size.r, 0.0);
    const double threshold = mu_r * size.m * kG / r_e;  // the push the moment can hold [N]
    for (double ratio : {0.999, 1.001}) {
      SCOPED_TRACE("m " + std::to_string(size.m) + " r " + std::to_string(size.r) + " ratio " +
                   std::to_string(ratio));
      const io::Scene scene =
          io::loadScene(kSlope, {set("m", size.m), set("r", size.r), set("rolling_length", mu_r),
                                 "ratio=0", set("push", ratio * threshold), "duration=30"});
      double x_settled = 0.0, x_end = 0.0, v_end = 0.0, t_rolling = -1.0;
      run(scene, [&](const State& s, const BodyState& b) {
        if (std::abs(s.time - 20.0) < 0.5e-4) x_settled = b.position.x();
        if (t_rolling < 0.0 && b.velocity.x() > 1e-4) t_rolling = s.time;
        x_end = b.position.x();
        v_end = b.velocity.x();
      });
      std::printf(
          "m %5.1f r %.2f push %.3f of mu_r m g / r_e: x at 20 s %.3e m, at 30 s %.3e m, v "
          "%.2e m/s, rolling from %.3f s\n",
          size.m, size.r, ratio, x_settled, x_end, v_end, t_rolling);
      if (ratio < 1.0) {
        // The springs' give, F / k_t and (M / k_r) r_e: micrometres at every size (the
        // stiffnesses scale with m and m r^2); then no creep at all.
        const double give = ratio * threshold / (1e5 * size.m) +
                            ratio * mu_r * size.m * kG / (2e4 * size.m * size.r * size.r) * r_e;
        EXPECT_NEAR(x_settled, give, 0.05 * give);
        EXPECT_LT(std::abs(x_end - x_settled), 1e-12);
        EXPECT_LT(std::abs(v_end), 1e-12);
        EXPECT_LT(t_rolling, 0.0);
      } else {
        // It lets go near the ramp's end, where the push passes the threshold (9.74 s), and
        // rolls: 0.1 mm/s within half a second at the excess's 2.8e-4 m/s^2.
        EXPECT_GT(t_rolling, 9.5);
        EXPECT_LT(t_rolling, 11.0);
        EXPECT_GT(x_end - x_settled, 0.01);
      }
    }
  }
}

// Set down on a slope at 0.9 of the threshold (scenes/experiments/ball_on_slope.yaml's
// default) the ball holds: the gravity load comes at once, and the springs' approach stays
// within the 10% margin.
TEST(RollingResistance, ABallSetDownOnASlopeBelowItsThresholdStays) {
  const io::Scene scene = io::loadScene(kSlope, {"duration=4"});
  double x_settled = 0.0, x_end = 0.0;
  run(scene, [&](const State& s, const BodyState& b) {
    if (std::abs(s.time - 2.0) < 0.5e-4) x_settled = b.position.x();
    x_end = b.position.x();
  });
  std::printf("set down at 0.9: x at 2 s %.3e m, at 4 s %.3e m\n", x_settled, x_end);
  EXPECT_LT(std::abs(x_settled), 1e-4);  // the springs' give: 14 um measured
  EXPECT_LT(std::abs(x_end - x_settled), 1e-12);
}

TEST(RollingResistance, AboveItsThresholdTheBallAcceleratesAsTheHeldMomentSays) {
  const double ratio = 1.5, r = 0.05, mu_r = 0.002;
  const io::Scene scene = io::loadScene(kSlope, {set("ratio", ratio), "duration=3"});
  const double alpha = std::atan(ratio * mu_r / r), r_e = lever(r, alpha);
  const double a =
      kG * (std::sin(alpha) - mu_r * std::cos(alpha) / r_e) / (1 + 0.4 * r * r / (r_e * r_e));
  double v1 = 0.0, v3 = 0.0;
  run(scene, [&](const State& s, const BodyState& b) {
    if (std::abs(s.time - 1.0) < 0.5e-4) v1 = b.velocity.x();
    v3 = b.velocity.x();
  });
  std::printf("ratio 1.5: a %.6f m/s^2 (closed form %.6f)\n", (v3 - v1) / 2.0, a);
  EXPECT_NEAR((v3 - v1) / 2.0, a, 1e-4 * a);
}

TEST(RollingResistance, ARollingBallStopsWhereTheClosedFormSaysAndStays) {
  for (const Size& size : kSizes) {
    SCOPED_TRACE("m " + std::to_string(size.m) + " r " + std::to_string(size.r));
    const double mu_r = 0.04 * size.r, v0 = 0.5, r_e = lever(size.r, 0.0);
    const double a = kG * mu_r / r_e / (1 + 0.4 * size.r * size.r / (r_e * r_e));  // 0.28 m/s^2
    const double stop = v0 / a, distance = v0 * v0 / (2 * a);
    // On the flat (ratio 0): launched rolling, w = v0 / r about +y.
    const io::Scene scene =
        io::loadScene(kSlope, {set("m", size.m), set("r", size.r), set("rolling_length", mu_r),
                               "ratio=0", set("duration", stop + 1.0)});
    Simulator sim(scene.model);
    const std::size_t ball = static_cast<std::size_t>(scene.model->findBody("ball")->value);
    State start = sim.state();
    start.bodies[ball].velocity = Vec3(v0, 0, 0);
    start.bodies[ball].angular_velocity = Vec3(0, v0 / r_e, 0);  // rolling, not slipping
    sim.setState(start);
    double x_stop = 0.0;
    const long steps = std::lround((stop + 1.0) / scene.model->options.time_step);
    for (long i = 0; i < steps; ++i) {
      ASSERT_TRUE(sim.step().ok);
      if (std::abs(sim.state().time - (stop + 0.5)) < 0.5e-4)
        x_stop = sim.state().bodies[ball].position.x();
    }
    const BodyState& b = sim.state().bodies[ball];
    std::printf("m %5.1f r %.2f: stopped after %.6f m (closed form %.6f), then moved %.2e m\n",
                size.m, size.r, x_stop, distance, b.position.x() - x_stop);
    EXPECT_NEAR(x_stop, distance, 1e-3 * distance);
    EXPECT_LT(std::abs(b.position.x() - x_stop), 1e-9);
    EXPECT_LT(b.angular_velocity.norm(), 1e-6);
  }
}

TEST(RollingResistance, ASpinningBallSpinsDownLinearlyStopsAndStays) {
  const double m = 1.0, r = 0.05, w0 = 20.0, moment = 0.3 * 0.005 * m * kG;
  const double inertia = 0.4 * m * r * r, rate = moment / inertia;
  const double t_stop = w0 / rate, turned_expected = w0 * w0 / (2 * rate);
  const io::Scene scene = io::loadScene(kSpin);
  double turned = 0.0, w_half = 0.0, w_end = 0.0, previous = w0;
  const double dt = scene.model->options.time_step;
  run(scene, [&](const State& s, const BodyState& b) {
    const double w = b.angular_velocity.z();
    turned += 0.5 * (w + previous) * dt;  // the trapezoid of the step's ends
    previous = w;
    if (std::abs(s.time - 0.5 * t_stop) < 0.5 * dt) w_half = w;
    w_end = w;
  });
  std::printf("spin: w at t_stop / 2 %.6f (closed form %.6f), turned %.6f rad (%.6f), end %.2e\n",
              w_half, 0.5 * w0, turned, turned_expected, w_end);
  EXPECT_NEAR(w_half, 0.5 * w0, 1e-3 * w0);
  EXPECT_NEAR(turned, turned_expected, 1e-3 * turned_expected);
  // The moment's work, mu_spin r_c m g times the angle turned, is the kinetic energy lost.
  EXPECT_NEAR(moment * turned, 0.5 * inertia * w0 * w0, 1e-3 * 0.5 * inertia * w0 * w0);
  EXPECT_LT(std::abs(w_end), 1e-6);
}

TEST(RollingResistance, ACylinderOnASlopeHoldsBelowItsThresholdAndRollsAboveIt) {
  // Held at 0.9 (set down at once, as the ball): its springs' give, then nothing.
  double x1 = 0.0, x3 = 0.0, v1 = 0.0, v3 = 0.0;
  auto sample = [&](const State& s, const BodyState& b) {
    if (std::abs(s.time - 1.0) < 0.5e-4) {
      x1 = b.position.x();
      v1 = b.velocity.x();
    }
    x3 = b.position.x();
    v3 = b.velocity.x();
  };
  run(io::loadScene(kCylinder, {"ratio=0.9", "duration=3"}), sample, "cylinder");
  std::printf("cylinder at 0.9: x at 1 s %.3e m, at 3 s %.3e m\n", x1, x3);
  EXPECT_LT(std::abs(x1), 1e-4);
  EXPECT_LT(std::abs(x3 - x1), 1e-12);
  // Rolling at 1.5: two points share the load, so each sinks by d = m g cos(alpha) / (2 k)
  // and the lever is r - d / 2.
  run(io::loadScene(kCylinder, {"ratio=1.5", "duration=3"}), sample, "cylinder");
  const double r = 0.05, mu_r = 0.002, alpha = std::atan(1.5 * mu_r / r);
  const double r_e = r - 0.25 * kG * std::cos(alpha) / 1e5;
  const double a =
      kG * (std::sin(alpha) - mu_r * std::cos(alpha) / r_e) / (1 + 0.5 * r * r / (r_e * r_e));
  std::printf("cylinder at 1.5: a %.7f m/s^2 (closed form %.7f)\n", (v3 - v1) / 2.0, a);
  EXPECT_NEAR((v3 - v1) / 2.0, a, 1e-4 * a);
}

// Three tops: mass, disc radius and the tip's patch radius r_c, each over a decade or two.
struct Top {
  double m, R, r_c;
};
constexpr Top kTops[3] = {{0.2, 0.02, 0.002}, {1.0, 0.04, 0.005}, {20.0, 0.2, 0.02}};

std::vector<std::string> topOverrides(const Top& top, std::vector<std::string> more) {
  more.push_back(set("m", top.m));
  more.push_back(set("R", top.R));
  more.push_back(set("contact_radius", top.r_c));
  return more;
}

TEST(RollingResistance, ASpinningTopSpinsDownByItsTipsSpinningFrictionAndStays) {
  for (const Top& top : kTops) {
    SCOPED_TRACE("m " + std::to_string(top.m) + " R " + std::to_string(top.R));
    const double w0 = 30.0, moment = 0.3 * top.r_c * top.m * kG;
    const double inertia = 0.5 * top.m * top.R * top.R, rate = moment / inertia;
    const double t_stop = w0 / rate, turned_expected = w0 * w0 / (2 * rate);
    const io::Scene scene = io::loadScene(kTop, topOverrides(top, {set("duration", 1.3 * t_stop)}));
    const double dt = scene.model->options.time_step;
    double turned = 0.0, w_half = 0.0, w_end = 0.0, previous = w0;
    run(
        scene,
        [&](const State& s, const BodyState& b) {
          const double w = b.angular_velocity.z();
          turned += 0.5 * (w + previous) * dt;
          previous = w;
          if (std::abs(s.time - 0.5 * t_stop) < 0.5 * dt) w_half = w;
          w_end = w;
        },
        "top");
    std::printf(
        "top m %.1f R %.2f r_c %.3f: stop %.3f s; w at half %.6f (%.6f), turned %.5f rad "
        "(%.5f), end %.2e\n",
        top.m, top.R, top.r_c, t_stop, w_half, 0.5 * w0, turned, turned_expected, w_end);
    // The tip's sliding friction has no lever about the spindle: only the spinning moment
    // decelerates it, linearly.
    EXPECT_NEAR(w_half, 0.5 * w0, 1e-3 * w0);
    EXPECT_NEAR(turned, turned_expected, 1e-3 * turned_expected);
    // Energy: the kinetic energy it lost is the resisting moment's work over that angle.
    EXPECT_NEAR(moment * turned, 0.5 * inertia * w0 * w0, 1e-3 * 0.5 * inertia * w0 * w0);
    EXPECT_LT(std::abs(w_end), 1e-6);
  }
}

// A twist ramped in over 4 s to 0.999 of the spinning threshold is held by the angular
// spring (its give M / k, then no creep); at 1.001 the spindle lets go near the ramp's end
// and turns at the excess 1e-3 M / I.
TEST(RollingResistance, ATopTwistedTo0999OfItsSpinningThresholdHoldsAndAt1001Turns) {
  for (const Top& top : kTops) {
    const double threshold = 0.3 * top.r_c * top.m * kG, inertia = 0.5 * top.m * top.R * top.R;
    const double k = 20.0 * top.m * top.R * top.R / 1.6e-3;  // the scene's spin_stiffness
    for (double ratio : {0.999, 1.001}) {
      SCOPED_TRACE("m " + std::to_string(top.m) + " ratio " + std::to_string(ratio));
      const io::Scene scene = io::loadScene(
          kTop,
          topOverrides(top, {"w0=0", set("twist", ratio * threshold), "ramp=4", "duration=10"}));
      double angle = 0.0, angle_6 = 0.0, w_end = 0.0, t_turning = -1.0;
      const double dt = scene.model->options.time_step;
      run(
          scene,
          [&](const State& s, const BodyState& b) {
            angle += b.angular_velocity.z() * dt;
            if (std::abs(s.time - 6.0) < 0.5 * dt) angle_6 = angle;
            // Turning: past twice the spring's give at the threshold.
            if (t_turning < 0.0 && angle > 2.0 * threshold / k) t_turning = s.time;
            w_end = b.angular_velocity.z();
          },
          "top");
      std::printf(
          "top m %.1f twist %.3f of mu_spin r_c m g: angle at 6 s %.3e rad, at 10 s "
          "%.3e, w %.2e rad/s, turning from %.3f s\n",
          top.m, ratio, angle_6, angle, w_end, t_turning);
      if (ratio < 1.0) {
        const double give = ratio * threshold / k;
        EXPECT_NEAR(angle_6, give, 0.01 * give);
        EXPECT_LT(std::abs(angle - angle_6), 1e-12);
        EXPECT_LT(std::abs(w_end), 1e-12);
        EXPECT_LT(t_turning, 0.0);
      } else {
        // The twist passes the threshold at 0.93 of the ramp; from then on the excess
        // accelerates it at no more than 1e-3 M / I (less until the ramp ends).
        EXPECT_GT(t_turning, 3.0);
        EXPECT_LT(t_turning, 5.0);
        const double excess = 1e-3 * threshold / inertia;
        EXPECT_GT(w_end, 0.5 * excess * (10.0 - 4.0));
        EXPECT_LT(w_end, excess * (10.0 - 3.0));
      }
    }
  }
}

}  // namespace
}  // namespace tribo
