// The a-priori step limit for friction laws, in the class: tabulated curves of several shapes
// and the dynamic laws (lugre, dahl, elasto_plastic, rate_state), on a contact (a box held on
// an incline) and on revolute and prismatic joints (a constant load, an effort below what
// friction holds), over masses and inertias two orders of magnitude apart, for semi-implicit
// Euler and RK4. For each: at 0.9 of the estimate the run is stable and agrees with the same
// run at a tenth of the step (final displacement, peak speed over the second half, fraction
// of steps below the law's stick speed), and the step where it stops agreeing, found by
// bisection, lies within 4 times the estimate (the estimate is not absurdly conservative).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "friction/tabulated_law.hpp"
#include "support/test_models.hpp"

namespace tribo {
namespace {

using Law = std::shared_ptr<const friction::FrictionLaw>;

constexpr double kG = 9.81;
const double kTheta = std::atan(0.364);  // incline: load ratio 0.364 (20 degrees)
constexpr double kLoad = 10.0;           // joints' constant normal load [N]

Law tabulated(std::vector<double> v, std::vector<double> mu) {
  return std::make_shared<friction::TabulatedLaw>(std::move(v), std::move(mu));
}

Law law(const std::string& name, std::map<std::string, double> values) {
  return friction::makeFrictionLaw({name, std::move(values), {}});
}

// A law, and how a run starts with it: the initial speed and the load ratio it must carry.
// rate_state has no static friction: it slides at v0 from the start (its state at steady
// state there, theta0 = d_c / v0), under a load ratio mu0 + (a - b) ln 2 that speeds it up to
// 2 v0 (velocity strengthening, a > b: steady sliding is stable).
struct LawCase {
  std::string name;
  Law law;
  double speed = 0.0;    // initial slip speed [m/s]
  double ratio = 0.364;  // load ratio (tan of the incline, effort / (N r))
};

std::vector<LawCase> laws() {
  const double rs_ratio = 0.3 + 0.005 * std::log(2.0);
  return {
      // A Stribeck peak: steep rise to 1 mm/s, the peak at 1 cm/s.
      {"tabulated stribeck",
       tabulated({1e-3, 2e-3, 1e-2, 0.1, 1.0}, {0.30, 0.42, 0.45, 0.35, 0.30})},
      // A short steep segment (1.0 to 1.1 mm/s) below the peak: where the block creeps.
      // (The load ratio 0.2 creeps mid-segment, at its steepest.)
      {"tabulated narrow step", tabulated({1e-3, 1.1e-3, 1e-2, 0.1}, {0.05, 0.40, 0.45, 0.35}), 0.0,
       0.2},
      // Rising to its last point: the stick speed is the first point's, the creep beyond it.
      {"tabulated rising", tabulated({1e-3, 2e-3, 0.1}, {0.01, 0.40, 0.45})},
      // A regularized Coulomb law.
      {"tabulated coulomb", tabulated({1e-3, 1.0}, {0.4, 0.4})},
      {"lugre", law("lugre", {{"mu_c", 0.4}, {"mu_s", 0.5}})},
      {"dahl", law("dahl", {{"mu_c", 0.45}})},
      {"elasto_plastic", law("elasto_plastic", {{"mu_c", 0.4}, {"mu_s", 0.5}})},
      {"rate_state",
       law("rate_state",
           {{"mu0", 0.3}, {"a", 0.015}, {"b", 0.01}, {"d_c", 1e-5}, {"v0", 1e-4}, {"theta0", 0.1}}),
       1e-4, rs_ratio},
  };
}

// A free box (0.2 x 0.2 x 0.1 m, mass m) on the ground with gravity tilted by the incline's
// angle (its load ratio along +x); linear contact, stiffness and damping in proportion to the
// mass (the same normal and rocking modes for every mass). Friction's damping is stiffest in
// its yaw (3 times its translation's): held against turning it used to be stable at the old,
// translational estimate, free it crept 29% too fast at 0.9 of it.
ModelBuilder incline(const LawCase& c, double m, IntegratorType integrator, double dt) {
  const double theta = std::atan(c.ratio);
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  b.options().gravity = kG * Vec3(std::sin(theta), 0, -std::cos(theta));
  const double k = 1e5 * m;
  Body box;
  box.name = "box";
  box.mass = m;
  box.inertia = test::boxInertia(m, Vec3(0.2, 0.2, 0.1));
  box.position = Vec3(0, 0, 0.05 - m * kG * std::cos(theta) / (4 * k));
  box.velocity = Vec3(c.speed, 0, 0);
  const BodyIndex ib = b.addBody(box);
  contact::Material material;
  material.normal = {contact::NormalLawType::kLinear, k, 100.0 * m};
  material.friction = c.law;
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(Vec3(0.1, 0.1, 0.05)));
  b.addContactPair(ground, shape, b.addMaterial(material));
  return b;
}

// A body on a joint to the world without gravity: a slider of mass m on a prismatic joint
// along x, or a disc of moment I = m about a revolute joint along z (pin radius 0.01 m), under
// a constant friction load and an effort of ratio N r.
ModelBuilder onJoint(const LawCase& c, double m, JointType type, IntegratorType integrator,
                     double dt) {
  const bool revolute = type == JointType::kRevolute;
  const double r = revolute ? 0.01 : 1.0;
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  // Gravity along z, across the slide and along the disc's axis (no force on the coordinate),
  // and a geometry give the energy guard its floor m g L (core/energy.hpp): the bristles'
  // energy is not in its account, so without it the presliding swing from rest reads as a
  // rise at step 1.
  b.options().gravity = Vec3(0, 0, -kG);
  Body body;
  body.name = "body";
  body.mass = revolute ? 1.0 : m;
  body.inertia = revolute ? Mat3(Vec3(m, m, m).asDiagonal()) : Mat3(Mat3::Identity() * m);
  if (revolute)
    body.angular_velocity = Vec3(0, 0, c.speed / r);
  else
    body.velocity = Vec3(c.speed, 0, 0);
  const BodyIndex ib = b.addBody(body);
  b.addGeometry("body_shape", ib, contact::Shape::box(Vec3(0.05, 0.05, 0.05)));
  const int j = b.addJoint("joint", type, BodyIndex::world(), ib, Vec3::Zero(),
                           revolute ? Vec3::UnitZ() : Vec3::UnitX());
  b.setJointFriction(j, {c.law, JointFrictionLoad::kConstant, kLoad, r});
  b.setJointEffort(j, c.ratio * kLoad * r);
  return b;
}

// What a run shows: its slip (the box's or slider's x, the disc's angle times r) at the end,
// its fastest slip over the second half, and the fraction of the second half's steps
// slower than the law's stick speed.
struct Outcome {
  bool stopped = false;
  std::string message;  // why it stopped
  double displacement = 0.0, peak = 0.0, stuck = 0.0;
};

Outcome run(ModelBuilder b, double seconds, double r, double stick_speed) {
  Simulator sim(b.build());
  const double h = sim.model().options.time_step;
  const long steps = std::lround(seconds / h);
  Outcome out;
  double angle = 0.0;
  long stuck = 0;
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      out.stopped = true;
      out.message = status.message;
      return out;
    }
    const BodyState& s = sim.state().bodies[0];
    const double speed = r == 0.0 ? s.velocity.head<2>().norm() : r * s.angular_velocity.z();
    angle += h * speed;  // slip as integrated speed (the disc's angle wraps)
    if (2 * i >= steps) {
      out.peak = std::max(out.peak, std::abs(speed));
      stuck += std::abs(speed) < stick_speed;
    }
    if (!std::isfinite(speed)) {
      out.stopped = true;
      return out;
    }
  }
  out.displacement = angle;
  out.stuck = static_cast<double>(stuck) / static_cast<double>(steps - steps / 2);
  return out;
}

// Agreement with the reference: displacement within 5% (plus the bristles' scale 5e-6 m),
// peak speed within 20% (plus 1e-6 m/s) and the stuck fraction within 0.05.
bool agrees(const Outcome& o, const Outcome& ref, std::string* why) {
  const bool ok =
      !o.stopped &&
      std::abs(o.displacement - ref.displacement) <= 0.05 * std::abs(ref.displacement) + 5e-6 &&
      std::abs(o.peak - ref.peak) <= 0.2 * ref.peak + 1e-6 && std::abs(o.stuck - ref.stuck) <= 0.05;
  if (why != nullptr)
    *why = "displacement " + std::to_string(o.displacement) + " (reference " +
           std::to_string(ref.displacement) + "), peak speed " + std::to_string(o.peak) + " (" +
           std::to_string(ref.peak) + "), stuck " + std::to_string(o.stuck) + " (" +
           std::to_string(ref.stuck) + ")" + (o.stopped ? ", stopped: " + o.message : "");
  return ok;
}

// What is asserted of a case: agreement at 0.9 of the estimate, and disagreement by 4 times
// it. Measured, not asserted (the report's figures):
// - by 4 times: the narrow step's chatter stays within its 0.1 mm/s segment (a speed error
//   below 5%), and the heavy disc (I 0.01 kg m^2) on a lugre or elasto_plastic pin never
//   slips at the speed 4 v_stick whose state decay bounds RK4 there (conservative).
// dahl's presliding spring is undamped: the step from rest leaves a ring that only the law's
// hysteresis damps, and it ratchets the body along by an amount each method's numerical
// damping sets, so agreement is not what is asserted (`bounded`):
// - RK4: the reference is converged (a tenth and a twentieth of the estimate agree); at 0.9
//   of the estimate the run is stable and creeps no further than the reference and no faster
//   (RK4's damping of the ring only shortens the creep: 0.4-0.6 of the reference's on joints);
// - semi-implicit Euler: its state update from the step's starting slip feeds the ring
//   (core/stability.cpp), so the creep converges at first order only (the slider's 3.1, 1.6,
//   0.8 mm at steps of 20, 10, 5 us): no reference to agree with; at 0.9 of
//   the estimate the run is bounded, the energy guard (core/energy.hpp) never stopping it.
struct Expect {
  bool agrees_below = true;
  bool off_by_4 = true;
  bool bounded = false;  // dahl: the checks above instead of agreement
};

Expect expectFor(const LawCase& c, bool heavy_disc, IntegratorType integrator) {
  if (c.name == "dahl") return {false, false, true};
  if (c.name == "tabulated narrow step") return {true, false};
  if (heavy_disc && (c.name == "lugre" || c.name == "elasto_plastic"))
    return {true, integrator == IntegratorType::kSemiImplicitEuler};
  return {};
}

// The check on one model family `make(dt)`: the estimate, the runs at 0.9 of it and at a
// tenth of it, and the first step where the run stops agreeing (bisection between 0.1 and 4
// times the estimate); returns that threshold over the estimate.
double checkCase(const std::function<ModelBuilder(double)>& make, double r, double stick_speed,
                 const std::string& who, const Expect& expect) {
  const StabilityReport report = estimateStableStep(*make(1e-4).build());
  const double limit = report.limit.max_step;
  EXPECT_TRUE(std::isfinite(limit)) << who;
  if (!std::isfinite(limit)) return 0.0;
  const double seconds = 2000 * limit;
  const Outcome ref = run(make(0.1 * limit), seconds, r, stick_speed);
  EXPECT_FALSE(ref.stopped) << who << ": " << ref.message;
  std::string why;
  const Outcome at = run(make(0.9 * limit), seconds, r, stick_speed);
  if (expect.bounded) {
    EXPECT_FALSE(at.stopped) << who << " at 0.9 x " << limit << " s: " << at.message;
    EXPECT_TRUE(std::isfinite(at.displacement) && std::isfinite(at.peak)) << who;
    if (make(limit).build()->options.integrator == IntegratorType::kRk4) {
      const Outcome finer = run(make(0.05 * limit), seconds, r, stick_speed);
      EXPECT_TRUE(agrees(ref, finer, &why)) << who << ": reference not converged: " << why;
      EXPECT_LE(std::abs(at.displacement), 1.05 * std::abs(ref.displacement) + 5e-6) << who;
      EXPECT_LE(at.peak, 1.2 * ref.peak + 1e-6) << who;
    }
  }
  if (expect.agrees_below) {
    EXPECT_TRUE(agrees(at, ref, &why))
        << who << " at 0.9 x " << limit << " s (" << report.limit.element << "): " << why;
  }
  double lo = 0.1, hi = 4.0;
  if (agrees(run(make(hi * limit), seconds, r, stick_speed), ref, &why)) {
    if (expect.off_by_4)
      ADD_FAILURE() << who << ": still agrees at 4 x the estimate " << limit << " s ("
                    << report.limit.element << "): " << why;
    return hi;
  }
  for (int i = 0; i < 8; ++i) {
    const double mid = std::sqrt(lo * hi);
    (agrees(run(make(mid * limit), seconds, r, stick_speed), ref, nullptr) ? lo : hi) = mid;
  }
  return hi;
}

const IntegratorType kIntegrators[] = {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4};

TEST(StabilityLaws, ABoxOnAnInclineIsStableAtTheEstimateForEveryLaw) {
  for (const LawCase& c : laws()) {
    for (const double m : {0.1, 10.0}) {
      for (IntegratorType integrator : kIntegrators) {
        const std::string who =
            "incline, " + c.name + ", m " + std::to_string(m) + ", " + integratorName(integrator);
        const double ratio =
            checkCase([&](double dt) { return incline(c, m, integrator, dt); }, 0.0,
                      c.law->stickSpeed(), who, expectFor(c, false, integrator));
        std::printf("%-60s threshold / estimate %.2f\n", who.c_str(), ratio);
      }
    }
  }
}

// A memoryless law on a joint is held to I_q / (2 h) at a fixed step (core/joint_forces.hpp):
// never the limit there, so only the dynamic laws, whose force is not held.
TEST(StabilityLaws, ASliderAndADiscOnJointsAreStableAtTheEstimateForEveryDynamicLaw) {
  for (const LawCase& c : laws()) {
    if (c.law->dynamic() == nullptr) continue;
    for (const JointType type : {JointType::kPrismatic, JointType::kRevolute}) {
      const bool revolute = type == JointType::kRevolute;
      for (const double m :
           revolute ? std::vector<double>{1e-4, 1e-2} : std::vector<double>{0.01, 1.0}) {
        for (IntegratorType integrator : kIntegrators) {
          const std::string who = std::string(jointTypeName(type)) + ", " + c.name + ", " +
                                  (revolute ? "I " : "m ") + std::to_string(m) + ", " +
                                  integratorName(integrator);
          const double ratio = checkCase(
              [&](double dt) { return onJoint(c, m, type, integrator, dt); }, revolute ? 0.01 : 0.0,
              c.law->stickSpeed(), who, expectFor(c, revolute && m > 1e-3, integrator));
          std::printf("%-60s threshold / estimate %.2f\n", who.c_str(), ratio);
        }
      }
    }
  }
}

}  // namespace
}  // namespace tribo
