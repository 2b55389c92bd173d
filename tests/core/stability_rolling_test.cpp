// The a-priori step limit for friction on round shapes that roll (core/stability.hpp,
// "rolling"): a sphere (solid and thin-walled), a solid cylinder and a capsule lying on their
// sides, rolling down an incline under a regularized Coulomb law, over masses and radii two
// orders of magnitude apart, with semi-implicit Euler and RK4.
//
// The reference is derived here, not taken from a run. The contact points sit midway through
// the overlap (contact/primitive_contacts.cpp), so friction acts on the lever
// rho = r - d / 2 below the centre, d = N / (n k) the static depth on n points. Rolling with a
// steady micro-slip s = v - w rho (a = alpha rho + s', s' = 0): m a = m g sin(theta) - F and
// I alpha = F rho give
//   a = g sin(theta) m rho^2 / (m rho^2 + I),
//   F / N = tan(theta) I / (m rho^2 + I) = mu tanh(s / v_eps)
// so s = v_eps atanh(tan(theta) I / ((m rho^2 + I) mu)), and the centre's displacement from
// rest is a t^2 / 2 (plus the slip's fast start, below 1e-7 m here). At 0.9 of the estimate every
// run must give both within 1%; at 0.9 of what the estimate was without the rolling term
// (its factor m r^2 / I + 1 larger) the slip chatters or the run is stopped, so the term is
// needed; and the step where the run stops agreeing lies within 2 times the estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "core/stability.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;
constexpr double kTheta = 0.3;  // incline [rad]
constexpr double kMu = 0.5;
constexpr double kVeps = 1e-3;  // tanh regularization [m/s]

struct RollingCase {
  std::string name;
  contact::ShapeType shape;
  double inertia_ratio;  // I about the rolling axis over m r^2
};

const std::vector<RollingCase> kCases = {
    {"solid sphere", contact::ShapeType::kSphere, 0.4},
    {"thin-walled sphere", contact::ShapeType::kSphere, 2.0 / 3.0},
    {"solid cylinder on its side", contact::ShapeType::kCylinder, 0.5},
    {"capsule on its side", contact::ShapeType::kCapsule, 0.45},
};

// The round body on the ground, gravity tilted by the incline's angle (downhill +x); a
// cylinder's or capsule's axis along y (it rolls about it). Linear contact, stiffness and
// damping in proportion to the mass (the normal mode far from limiting the step).
ModelBuilder incline(const RollingCase& c, double m, double r, IntegratorType integrator,
                     double dt) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  b.options().gravity = kG * Vec3(std::sin(kTheta), 0, -std::cos(kTheta));
  const double k = 1e5 * m;
  const bool sphere = c.shape == contact::ShapeType::kSphere;
  const double points = sphere ? 1.0 : 2.0;  // a lying cylinder or capsule: two rim points
  Body body;
  body.name = "round";
  body.mass = m;
  const double i_roll = c.inertia_ratio * m * r * r;
  // The axis of a lying shape is y; its other moments (about x, z) do not enter rolling.
  body.inertia = sphere ? Mat3(Mat3::Identity() * i_roll) : Mat3(Vec3(0.6, 1.0, 0.6).asDiagonal());
  if (!sphere) body.inertia(1, 1) = i_roll, body.inertia(0, 0) = body.inertia(2, 2) = 2 * i_roll;
  body.position = Vec3(0, 0, r - m * kG * std::cos(kTheta) / (points * k));
  const BodyIndex ib = b.addBody(body);
  contact::Material material;
  material.normal = {contact::NormalLawType::kLinear, k, 100.0 * m};
  material.friction = friction::makeFrictionLaw({"coulomb", {{"mu", kMu}, {"v_eps", kVeps}}, {}});
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  Eigen::Isometry3d lying = Eigen::Isometry3d::Identity();
  lying.linear() = Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()).toRotationMatrix();  // z -> y
  int shape = -1;
  if (sphere)
    shape = b.addGeometry("round_shape", ib, contact::Shape::sphere(r));
  else if (c.shape == contact::ShapeType::kCylinder)
    shape = b.addGeometry("round_shape", ib, contact::Shape::cylinder(r, 2 * r), lying);
  else
    shape = b.addGeometry("round_shape", ib, contact::Shape::capsule(r, 2 * r), lying);
  b.addContactPair(ground, shape, b.addMaterial(material));
  return b;
}

struct Expected {
  double accel = 0.0;  // of the centre down the incline [m/s^2]
  double slip = 0.0;   // steady micro-slip at the contact point [m/s]
};

Expected expected(const RollingCase& c, double r) {
  const double points = c.shape == contact::ShapeType::kSphere ? 1.0 : 2.0;
  const double rho = r - 0.5 * kG * std::cos(kTheta) / (points * 1e5);  // d = m g cos / (n k)
  const double i_over_m = c.inertia_ratio * r * r;
  const double share = i_over_m / (rho * rho + i_over_m);  // I / (m rho^2 + I)
  return {kG * std::sin(kTheta) * (1.0 - share),
          kVeps * std::atanh(std::tan(kTheta) * share / kMu)};
}

struct Outcome {
  bool stopped = false;
  std::string message;
  double accel = 0.0;      // 2 x / t^2 at the end
  double slip_mean = 0.0;  // contact point's slip over the second half
  double slip_peak = 0.0;  // largest |slip - mean| over the second half
};

Outcome run(ModelBuilder b, double seconds, double r) {
  Simulator sim(b.build());
  const double h = sim.model().options.time_step;
  const long steps = std::lround(seconds / h);
  Outcome out;
  std::vector<double> slips;
  for (long i = 0; i < steps; ++i) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      out.stopped = true;
      out.message = status.message;
      return out;
    }
    const BodyState& s = sim.state().bodies[0];
    // The contact point sits rho = (r + z) / 2 below the centre (midway through the overlap
    // r - z): its velocity v + w x (-rho z).
    const double rho = 0.5 * (r + s.position.z());
    const double slip = s.velocity.x() + s.angular_velocity.cross(Vec3(0, 0, -rho)).x();
    if (!std::isfinite(slip)) {
      out.stopped = true;
      out.message = "non-finite slip";
      return out;
    }
    if (2 * i >= steps) slips.push_back(slip);
  }
  const double t = static_cast<double>(steps) * h;

  out.accel = 2.0 * sim.state().bodies[0].position.x() / (t * t);
  for (double s : slips) out.slip_mean += s / static_cast<double>(slips.size());
  for (double s : slips) out.slip_peak = std::max(out.slip_peak, std::abs(s - out.slip_mean));
  return out;
}

bool agrees(const Outcome& o, const Expected& e, std::string* why) {
  const bool ok = !o.stopped && std::abs(o.accel - e.accel) <= 0.01 * e.accel &&
                  std::abs(o.slip_mean - e.slip) <= 0.01 * e.slip && o.slip_peak <= 0.01 * e.slip;
  if (why != nullptr)
    *why = "acceleration " + std::to_string(o.accel) + " (expected " + std::to_string(e.accel) +
           "), slip " + std::to_string(o.slip_mean) + " +- " + std::to_string(o.slip_peak) +
           " (expected " + std::to_string(e.slip) + ")" +
           (o.stopped ? ", stopped: " + o.message : "");
  return ok;
}

TEST(StabilityRolling, ARollingBodyIsStableAtTheEstimateAndNotAtTheTranslationalOne) {
  for (const RollingCase& c : kCases) {
    for (const double m : {0.05, 20.0}) {
      for (const double r : {0.01, 0.2}) {
        for (const IntegratorType integrator :
             {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
          const std::string who = c.name + ", m " + std::to_string(m) + ", r " + std::to_string(r) +
                                  ", " + integratorName(integrator);
          auto make = [&](double dt) { return incline(c, m, r, integrator, dt); };
          const StabilityReport report = estimateStableStep(*make(1e-4).build());
          const double limit = report.limit.max_step;
          ASSERT_TRUE(std::isfinite(limit)) << who;
          EXPECT_TRUE(report.limit.element.find("rolling") != std::string::npos ||
                      report.limit.element.find("yaw") != std::string::npos)
              << who << ": " << report.limit.element;
          const Expected e = expected(c, r);
          const double seconds = 0.3;
          std::string why;
          EXPECT_TRUE(agrees(run(make(0.9 * limit), seconds, r), e, &why))
              << who << " at 0.9 x " << limit << " s: " << why;
          // Without the rolling and yaw terms the estimate was friction's translational
          // sticking slope on the body's mass: c / m = g mu'(0) = g mu / v_eps.
          const double translational = stableStep(integrator, 0.0, kG * kMu / kVeps);
          EXPECT_FALSE(agrees(run(make(0.9 * translational), seconds, r), e, &why))
              << who << ": still right at 0.9 of the translational estimate " << translational
              << " s: " << why;
          double lo = 0.9, hi = 2.0;
          if (agrees(run(make(hi * limit), seconds, r), e, &why)) {
            ADD_FAILURE() << who << ": still agrees at 2 x the estimate " << limit << " s ("
                          << report.limit.element << "): " << why;
            continue;
          }
          for (int i = 0; i < 6; ++i) {
            const double mid = std::sqrt(lo * hi);
            (agrees(run(make(mid * limit), seconds, r), e, nullptr) ? lo : hi) = mid;
          }
          std::printf("%-60s threshold / estimate %.2f\n", who.c_str(), hi);
        }
      }
    }
  }
}

}  // namespace
}  // namespace tribo
