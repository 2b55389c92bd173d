// The a-priori step limit against the integrators' known stability boundaries, and against
// what actually happens when the model is stepped just below and just above it.
#include "core/stability.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/simulator.hpp"
#include "support/test_models.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81;
constexpr double kRk4RealAxis = 2.785293563;  // root of |1 + z + z^2/2 + z^3/6 + z^4/24| = 1

// A 1 kg box (0.2 x 0.2 x 0.1 m) on the ground, translating in the x-z plane (no rotation:
// one mass on the normal and one on the tangential contact spring), `depth` into it.
ModelBuilder boxWith(const contact::Material& material, IntegratorType integrator, double dt,
                     double depth, const Vec3& velocity = Vec3::Zero()) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  Body box;
  box.name = "box";
  box.mass = 1.0;
  box.inertia = test::boxInertia(1.0, Vec3(0.2, 0.2, 0.1));
  box.position = Vec3(0, 0, 0.05 - depth);
  box.velocity = velocity;
  const BodyIndex ib = b.addBody(box);
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(Vec3(0.1, 0.1, 0.05)));
  b.addContactPair(ground, shape, b.addMaterial(material));
  b.addJoint("slide", JointType::kPlanarTranslation, BodyIndex::world(), ib, box.position,
             Vec3::UnitY());
  return b;
}

contact::Material frictionless(const contact::NormalLaw& law) {
  contact::Material m = test::coulombMaterial(0.0, 1.0, 0.0);
  m.normal = law;
  return m;
}

contact::Material elasticStick(double k_t, double c_t) {
  contact::Material m;
  m.normal = {contact::NormalLawType::kLinear, 1e4, 0.0};  // soft: the stick spring limits
  m.friction = friction::makeFrictionLaw(
      {"elastic_stick", {{"mu_s", 0.6}, {"mu_k", 0.5}, {"stiffness", k_t}, {"damping", c_t}}, {}});
  return m;
}

// Depth where the law carries a quarter of the 1 kg box's weight (bisection on the law).
double staticDepth(const contact::NormalLaw& law) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (law.force(mid, 0.0) < kG / 4 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Closed-form limits of x'' + c x' + k x = 0 (per unit mass). Semi-implicit Euler: the
// one-step matrix has trace 2 - h c - h^2 k and determinant 1 - h c, inside the unit circle
// while k h^2 + 2 c h <= 4. RK4: 2 sqrt(2) / w undamped; overdamped (real eigenvalues), the
// real-axis limit over the fastest rate.
double semiImplicitLimit(double k, double c) { return 4.0 / (c + std::sqrt(c * c + 4.0 * k)); }
double rk4UndampedLimit(double k) { return 2.0 * std::sqrt(2.0) / std::sqrt(k); }
double rk4OverdampedLimit(double k, double c) {
  EXPECT_GT(c * c, 4.0 * k) << "not overdamped";
  return kRk4RealAxis / (0.5 * (c + std::sqrt(c * c - 4.0 * k)));
}

TEST(StableStep, MatchesKnownBoundariesOfTheUndampedOscillator) {
  const double w = 50.0;
  // RK4 on the imaginary axis: |z| <= 2 sqrt(2); semi-implicit Euler: h w <= 2.
  EXPECT_NEAR(stableStep(IntegratorType::kRk4, w * w, 0.0) * w, 2 * std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(stableStep(IntegratorType::kSemiImplicitEuler, w * w, 0.0) * w, 2.0, 1e-6);
}

TEST(StableStep, PureDecayMatchesTheRealAxisBoundary) {
  // v' = -r v: explicit Euler h r <= 2; RK4 h r <= 2.785293563 (root of 1+z+z^2/2+z^3/6+z^4/24 =
  // 1).
  const double r = 1e4;
  EXPECT_NEAR(stableStep(IntegratorType::kSemiImplicitEuler, 0.0, r) * r, 2.0, 1e-6);
  EXPECT_NEAR(stableStep(IntegratorType::kRk4, 0.0, r) * r, 2.785293563, 1e-6);
}

TEST(StabilityEstimate, NamesTheStiffestElementAndPredictsTheContactLimit) {
  const double m = 1.0, k = 1e6;
  ModelBuilder b = test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.3, k, 0.0, IntegratorType::kRk4,
                                     1e-3, -0.05);
  const auto model = b.build();
  const StabilityReport report = estimateStableStep(*model);
  EXPECT_NE(report.limit.element.find("contact pair (ground, box_shape)"), std::string::npos)
      << report.limit.element;
  const double w = std::sqrt(4 * k / m);
  // The coulomb tanh law (v_eps 1e-4) is stiffer than the contact: g mu / v_eps = 29430/s.
  EXPECT_LT(report.limit.max_step, 2 * std::sqrt(2.0) / w);
  EXPECT_NE(report.limit.element.find("friction"), std::string::npos);
}

TEST(StabilityEstimate, UndampedContactBouncesStablyBelowAndBlowsUpAboveTheLimit) {
  // Frictionless box dropped on the ground with no contact damping: energy conserving, so
  // the bounce height must stay bounded below the limit and grow above it.
  const double m = 1.0, k = 1e6;
  auto run = [&](double h) {
    ModelBuilder b =
        test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.0, k, 0.0, IntegratorType::kRk4, h, -0.5);
    Simulator sim(b.build());
    double vmax = 0;
    for (int i = 0; i < std::lround(0.5 / h); ++i) {
      if (!sim.step().ok) return std::numeric_limits<double>::infinity();
      vmax = std::max(vmax, sim.state().bodies[0].velocity.norm());
    }
    return vmax;
  };
  ModelBuilder probe =
      test::boxOnGround(m, Vec3(0.2, 0.2, 0.1), 0.0, 0.0, k, 0.0, IntegratorType::kRk4, 1e-3);
  const double limit = estimateStableStep(*probe.build()).limit.max_step;
  EXPECT_NEAR(limit * std::sqrt(4 * k / m), 2 * std::sqrt(2.0), 1e-6);
  EXPECT_LT(run(0.5 * limit), 0.51);  // never faster than the impact speed (plus gravity)
  EXPECT_GT(run(1.2 * limit), 1.0);   // energy grows without a source
}

TEST(StabilityEstimate, NonlinearNormalLawsUseTheirTangentAtTheStaticDepth) {
  // Each law's tangent (dF/dd, dF/dd') at the depth where the four corners share the weight,
  // found here by bisection and central differences on the law itself, against the closed-
  // form limits: Hertz undamped (RK4 2 sqrt(2)/w), RecurDyn overdamped by its ramped-in
  // damping (RK4 2.785/rate), all three under semi-implicit Euler.
  using contact::NormalLawType;
  const contact::NormalLaw hertz{NormalLawType::kHertz, 1e9, 0.0};
  const contact::NormalLaw hc{NormalLawType::kHuntCrossley, 1e9, 0.3, 1.5};
  const contact::NormalLaw recurdyn{NormalLawType::kRecurDyn, 1e7, 2000.0, 1.3, 2e-5};
  for (const contact::NormalLaw& law : {hertz, hc, recurdyn}) {
    const std::string name = contact::normalLawName(law.type);
    const double d0 = staticDepth(law), dd = 1e-6 * d0;
    const double k = 4 * (law.force(d0 + dd, 0) - law.force(d0 - dd, 0)) / (2 * dd);
    const double c = 4 * (law.force(d0, 1e-3) - law.force(d0, -1e-3)) / 2e-3;
    for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
      const StabilityReport r =
          estimateStableStep(*boxWith(frictionless(law), integrator, 1e-4, d0).build());
      EXPECT_NE(r.limit.element.find("normal (" + name + " at its static depth"), std::string::npos)
          << r.limit.element;
      double expected = semiImplicitLimit(k, c);
      if (integrator == IntegratorType::kRk4)
        expected = law.type == NormalLawType::kHertz      ? rk4UndampedLimit(k)
                   : law.type == NormalLawType::kRecurDyn ? rk4OverdampedLimit(k, c)
                                                          : stableStep(integrator, k, c);
      EXPECT_NEAR(r.limit.max_step / expected, 1.0, 1e-6) << name << " " << r.limit.element;
    }
  }
  // The linear law at the same place is independent of depth: 2 sqrt(2) / sqrt(4 k / m).
  const contact::NormalLaw linear{NormalLawType::kLinear, 1e6, 0.0};
  EXPECT_NEAR(
      estimateStableStep(*boxWith(frictionless(linear), IntegratorType::kRk4, 1e-4, 0).build())
              .limit.max_step /
          rk4UndampedLimit(4e6),
      1.0, 1e-6);
}

TEST(StabilityEstimate, WithoutGravityANonlinearLawIsTakenAtTheStatedDepthWithANote) {
  const contact::NormalLaw hertz{contact::NormalLawType::kHertz, 1e9, 0.0};
  ModelBuilder b = boxWith(frictionless(hertz), IntegratorType::kRk4, 1e-4, 0.0);
  b.options().gravity = Vec3::Zero();
  const StabilityReport r = estimateStableStep(*b.build());
  EXPECT_NE(r.limit.element.find("stated depth 0.0001 m"), std::string::npos) << r.limit.element;
  EXPECT_NEAR(r.limit.max_step / rk4UndampedLimit(4 * 1.5 * 1e9 * std::sqrt(1e-4)), 1.0, 1e-6);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("no gravity"), std::string::npos) << r.notes[0];
}

TEST(StabilityEstimate, ElasticStickSpringIsATangentialSpringDamperOnTheBody) {
  // Four corners' stick springs on the 1 kg box: k = 4 k_t, c = 4 c_t per unit mass.
  struct Case {
    double k_t, c_t;
  };
  for (const Case& s : {Case{1e6, 0.0}, Case{1e6, 2e4}}) {
    const double k = 4 * s.k_t, c = 4 * s.c_t;
    for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
      const StabilityReport r = estimateStableStep(
          *boxWith(elasticStick(s.k_t, s.c_t), integrator, 1e-4, kG / 4e4).build());
      EXPECT_NE(r.limit.element.find("friction (elastic_stick stick spring)"), std::string::npos)
          << r.limit.element;
      const double expected = integrator == IntegratorType::kSemiImplicitEuler
                                  ? semiImplicitLimit(k, c)
                                  : (c == 0 ? rk4UndampedLimit(k) : rk4OverdampedLimit(k, c));
      EXPECT_NEAR(r.limit.max_step / expected, 1.0, 1e-6) << s.c_t << " " << r.limit.element;
    }
  }
}

// Largest speed over `seconds` of the box stepped at h, and whether the run was stopped (a
// failed step: the energy guard or a non-finite state) or a contact broke loose.
struct Probe {
  double vmax = 0.0;
  bool stopped = false, slid = false;
};

Probe probe(ModelBuilder b, double seconds) {
  Simulator sim(b.build());
  Probe p;
  const double h = sim.model().options.time_step;
  for (long i = 0; i < std::lround(seconds / h); ++i) {
    if (!sim.step().ok) {
      p.stopped = true;
      return p;
    }
    p.vmax = std::max(p.vmax, sim.state().bodies[0].velocity.norm());
    for (const auto& a : sim.state().stick_anchors) p.slid = p.slid || a.sliding;
  }
  return p;
}

// Steps the box nudged at v0 from rest at 0.5, 0.99, 1.01 and 1.05 times the estimate. The
// nudge is small (the linear regime the estimate is for): both modes are undamped, so a
// stable step keeps the speed at the nudge (semi-implicit Euler's step-end speed swings up to
// 1/sqrt(1 - (h w / 2)^2) of it: 1.15 at 0.5, 7.1 at 0.99), and past the limit it grows
// until the contact's nonlinearity (no pull; breakaway at mu_s F_n) caps it or the run is
// stopped.
void expectTheEstimateSeparatesStableFromUnstable(
    const std::function<ModelBuilder(IntegratorType, double, const Vec3&)>& box, const Vec3& nudge,
    const char* what) {
  const double v0 = nudge.norm();
  for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
    const std::string who = std::string(what) + ", " + integratorName(integrator);
    const double limit =
        estimateStableStep(*box(integrator, 1e-4, Vec3::Zero()).build()).limit.max_step;
    const bool euler = integrator == IntegratorType::kSemiImplicitEuler;
    for (const double f : {0.5, 0.99}) {
      const Probe p = probe(box(integrator, f * limit, nudge), 0.5);
      EXPECT_FALSE(p.stopped || p.slid) << who << " at " << f;
      EXPECT_LT(p.vmax, (euler ? 1.01 / std::sqrt(1.0 - f * f) : 1.01) * v0) << who << " at " << f;
    }
    for (const double f : {1.01, 1.05}) {
      const Probe p = probe(box(integrator, f * limit, nudge), 0.5);
      EXPECT_TRUE(p.stopped || p.vmax > 30 * v0) << who << " at " << f << ": vmax " << p.vmax;
    }
  }
}

TEST(StabilityEstimate, HertzContactAtRestIsStableBelowAndDivergesJustPastTheEstimate) {
  // Undamped Hertz box at its static depth (1.8 um), nudged down at 10 um/s (amplitude 0.2%
  // of the depth).
  const contact::NormalLaw hertz{contact::NormalLawType::kHertz, 1e9, 0.0};
  const double d0 = staticDepth(hertz);
  expectTheEstimateSeparatesStableFromUnstable(
      [&](IntegratorType integrator, double h, const Vec3& v) {
        return boxWith(frictionless(hertz), integrator, h, d0, v);
      },
      Vec3(0, 0, -1e-5), "hertz");
}

TEST(StabilityEstimate, StuckElasticStickContactHoldsBelowAndChattersJustPastTheEstimate) {
  // A box held by four undamped stick springs, nudged sideways at 10 um/s: the elongation
  // (5e-9 m) is far below what mu_s holds (1.5e-6 m), so a stable step keeps it stuck.
  expectTheEstimateSeparatesStableFromUnstable(
      [&](IntegratorType integrator, double h, const Vec3& v) {
        return boxWith(elasticStick(1e6, 0.0), integrator, h, kG / 4e4, v);
      },
      Vec3(1e-5, 0, 0), "elastic_stick");
}

// A 1 kg box of edges 0.3 x 0.2 x 0.1 m resting on its 0.3 x 0.2 face on the ground at its
// static depth, frictionless, linear contact (k, c per corner), turning at `spin` (world);
// free, or held by `joint` at its centre (axis `axis`). Rocking per unit point stiffness,
// sum of squared lever arms over the inertia: about x 4 (0.1)^2 / (0.05 / 12) = 9.6, about y
// 4 (0.15)^2 / (0.1 / 12) = 10.8, against 4 for the normal translation: rocking about y is
// the fastest mode, 1.64 times the normal frequency.
const Vec3 kSlab(0.3, 0.2, 0.1);
constexpr double kRockX = 9.6, kRockY = 10.8;

ModelBuilder slabOnGround(IntegratorType integrator, double dt, double k, double c,
                          const Vec3& spin = Vec3::Zero(),
                          std::optional<JointType> joint = std::nullopt,
                          const Vec3& axis = Vec3::UnitY()) {
  ModelBuilder b;
  b.options().integrator = integrator;
  b.options().time_step = dt;
  Body box;
  box.name = "box";
  box.mass = 1.0;
  box.inertia = test::boxInertia(1.0, kSlab);
  box.position = Vec3(0, 0, kSlab.z() / 2 - kG / (4 * k));
  box.angular_velocity = spin;
  const BodyIndex ib = b.addBody(box);
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  const int shape = b.addGeometry("box_shape", ib, contact::Shape::box(kSlab / 2));
  b.addContactPair(ground, shape, b.addMaterial(test::coulombMaterial(0.0, k, c)));
  if (joint) b.addJoint("hold", *joint, BodyIndex::world(), ib, box.position, axis);
  return b;
}

// The closed-form limit of x'' + c x' + k x = 0 (per unit mass) for either fixed-step method.
double closedFormLimit(IntegratorType integrator, double k, double c) {
  if (integrator == IntegratorType::kSemiImplicitEuler) return semiImplicitLimit(k, c);
  return c == 0.0 ? rk4UndampedLimit(k) : rk4OverdampedLimit(k, c);
}

TEST(StabilityEstimate, AFreeBoxIsBoundedByRockingOnItsCorners) {
  // Undamped, and overdamped in rocking (2000 N s/m per corner: 21600/s against 2 w = 6573/s).
  const double k = 1e6;
  for (const double c : {0.0, 2000.0}) {
    for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
      const std::string who = integratorName(integrator) + ", c " + std::to_string(c);
      const StabilityReport r = estimateStableStep(*slabOnGround(integrator, 1e-4, k, c).build());
      EXPECT_EQ(r.limit.element,
                "contact pair (ground, box_shape) rocking about box_shape's y axis")
          << who;
      EXPECT_NEAR(r.limit.max_step / closedFormLimit(integrator, kRockY * k, kRockY * c), 1.0, 1e-6)
          << who;
      // Below the normal translation's limit, which it used to report.
      EXPECT_LT(r.limit.max_step, closedFormLimit(integrator, 4 * k, 4 * c)) << who;
    }
  }
}

TEST(StabilityEstimate, ABoxHeldAgainstRotationKeepsTheTranslationalLimit) {
  const double k = 1e6, c = 2000.0;
  for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
    const std::string name = integratorName(integrator);
    // planar_translation in the x-z plane (the belt box), prismatic along z: no rotation.
    for (const auto& [joint, axis] : {std::pair{JointType::kPlanarTranslation, Vec3::UnitY()},
                                      std::pair{JointType::kPrismatic, Vec3::UnitZ()}}) {
      const StabilityReport r = estimateStableStep(
          *slabOnGround(integrator, 1e-4, k, c, Vec3::Zero(), joint, axis).build());
      EXPECT_EQ(r.limit.element, "contact pair (ground, box_shape) normal") << name;
      EXPECT_NEAR(r.limit.max_step / closedFormLimit(integrator, 4 * k, 4 * c), 1.0, 1e-6)
          << name << " " << jointTypeName(joint);
    }
    // A revolute joint along x through the centre of mass lets it rock about x only.
    const StabilityReport r = estimateStableStep(
        *slabOnGround(integrator, 1e-4, k, c, Vec3::Zero(), JointType::kRevolute, Vec3::UnitX())
             .build());
    EXPECT_EQ(r.limit.element, "contact pair (ground, box_shape) rocking about box_shape's x axis")
        << name;
    EXPECT_NEAR(r.limit.max_step / closedFormLimit(integrator, kRockX * k, kRockX * c), 1.0, 1e-6)
        << name;
  }
}

TEST(StabilityEstimate, ABoxOnABoxRocksOnTheSmallerFaceWithBothInertias) {
  // On a fixed 1 x 1 x 0.2 m box the slab rocks as on the ground (the patch is its own face);
  // two equal free slabs stacked rock against each other with half the inertia: the upper
  // pair's rocking about y has twice the stiffness per inertia, 2 x 10.8.
  const double k = 1e6;
  const contact::Material material = test::coulombMaterial(0.0, k, 0.0);
  for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
    const std::string name = integratorName(integrator);
    auto slab = [&](ModelBuilder& b, const std::string& body, double z) {
      Body box;
      box.name = body;
      box.inertia = test::boxInertia(1.0, kSlab);
      box.position = Vec3(0, 0, z);
      return b.addGeometry(body + "_shape", b.addBody(box), contact::Shape::box(kSlab / 2));
    };
    {
      ModelBuilder b;
      b.options().integrator = integrator;
      Eigen::Isometry3d below = Eigen::Isometry3d::Identity();
      below.translation() = Vec3(0, 0, -0.1);
      const int table = b.addGeometry("table", BodyIndex::world(),
                                      contact::Shape::box(Vec3(0.5, 0.5, 0.1)), below);
      b.addContactPair(table, slab(b, "box", 0.05), b.addMaterial(material));
      const StabilityReport r = estimateStableStep(*b.build());
      EXPECT_EQ(r.limit.element, "contact pair (table, box_shape) rocking about box_shape's y axis")
          << name;
      EXPECT_NEAR(r.limit.max_step / closedFormLimit(integrator, kRockY * k, 0.0), 1.0, 1e-6)
          << name;
    }
    {
      ModelBuilder b;
      b.options().integrator = integrator;
      const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
      const int lower = slab(b, "lower", 0.05), upper = slab(b, "upper", 0.15);
      const int mat = b.addMaterial(material);
      b.addContactPair(ground, lower, mat);
      b.addContactPair(lower, upper, mat);
      const StabilityReport r = estimateStableStep(*b.build());
      EXPECT_EQ(r.limit.element,
                "contact pair (lower_shape, upper_shape) rocking about upper_shape's y axis")
          << name;
      EXPECT_NEAR(r.limit.max_step / closedFormLimit(integrator, 2 * kRockY * k, 0.0), 1.0, 1e-6)
          << name;
    }
  }
}

TEST(StabilityEstimate, ARockingBoxIsStableBelowAndDivergesPastTheEstimate) {
  // The free undamped box nudged about y at 1e-4 rad/s (corner swing 5 nm, 0.2% of the
  // static depth): at 0.9 and 0.99 of the estimate its spin stays within the nudge
  // (semi-implicit Euler within its step-end swing 1 / sqrt(1 - f^2): 2.29, 7.09), at 1.01 and
  // 1.1 it grows until the corners lift or the run is stopped. At 1.1 the old, translational
  // estimate (1.64 times longer) called the step safe.
  const double k = 1e6, w0 = 1e-4;
  const Vec3 nudge = w0 * Vec3::UnitY();
  for (IntegratorType integrator : {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4}) {
    const bool euler = integrator == IntegratorType::kSemiImplicitEuler;
    const double limit =
        estimateStableStep(*slabOnGround(integrator, 1e-4, k, 0.0).build()).limit.max_step;
    EXPECT_LT(1.1 * limit, closedFormLimit(integrator, 4 * k, 0.0)) << integratorName(integrator);
    for (const double f : {0.9, 0.99, 1.01, 1.1}) {
      const std::string who = integratorName(integrator) + " at " + std::to_string(f);
      Simulator sim(slabOnGround(integrator, f * limit, k, 0.0, nudge).build());
      double wmax = 0.0;
      bool stopped = false;
      for (long i = 0; i < std::lround(0.5 / (f * limit)) && !stopped; ++i) {
        stopped = !sim.step().ok;
        if (!stopped) wmax = std::max(wmax, sim.state().bodies[0].angular_velocity.norm());
      }
      if (f < 1.0) {
        EXPECT_FALSE(stopped) << who;
        EXPECT_LT(wmax, (euler ? 1.01 / std::sqrt(1.0 - f * f) : 1.01) * w0) << who;
        // Semi-implicit Euler conserves the mode's (modified) energy; RK4 damps it (by
        // |R(2.55 i)| = 0.53 a step at 0.9).
        if (euler) {
          EXPECT_GT(wmax, 0.99 * w0) << who;
        }
      } else {
        EXPECT_TRUE(stopped || wmax > 30 * w0) << who << ": wmax " << wmax;
      }
    }
  }
}

// Boxes on the ground (mass m, free), box i on a Coulomb tanh law at mu 0.3 and v_eps[i]
// (one material a v_eps). Friction's slope at sticking, mu / v_eps, sets the limit.
std::shared_ptr<const Model> boxesOnLaws(const std::vector<double>& v_eps, double m) {
  ModelBuilder b;
  b.options().integrator = IntegratorType::kSemiImplicitEuler;
  b.options().time_step = 1e-6;
  const double k = 1e5 * m;  // the same normal and rocking modes for every mass
  const Vec3 size(0.2, 0.2, 0.1);
  const int ground = b.addGeometry("ground", BodyIndex::world(), contact::Shape::halfSpace());
  std::map<double, int> material_of;  // one material (one law object) per v_eps
  for (std::size_t i = 0; i < v_eps.size(); ++i) {
    Body box;
    box.name = "box" + std::to_string(i);
    box.mass = m;
    box.inertia = test::boxInertia(m, size);
    box.position = Vec3(0.5 * static_cast<double>(i), 0, size.z() / 2 - m * 9.81 / (4 * k));
    const BodyIndex body = b.addBody(box);
    const int shape =
        b.addGeometry("shape" + std::to_string(i), body, contact::Shape::box(size / 2));
    const auto [it, added] = material_of.try_emplace(v_eps[i], 0);
    if (added) it->second = b.addMaterial(test::coulombMaterial(0.3, k, 0.0, v_eps[i]));
    b.addContactPair(ground, shape, it->second);
  }
  return b.build();
}

TEST(StabilityEstimate, EveryLawSetsItsOwnLimitWhateverThePairsBeforeIt) {
  // The steepest rise of each law is found once and reused for its later pairs: a pair of
  // another law, before or after, many pairs of one law, must each give the limit of the
  // steepest law alone. Masses 1 g to 1 t, v_eps two to three decades apart.
  for (const double m : {1e-3, 1.0, 1e3}) {
    for (const auto& [gentle, steep] : {std::pair{1e-3, 1e-5}, std::pair{1e-2, 1e-4}}) {
      const StabilityReport alone = estimateStableStep(*boxesOnLaws({steep}, m));
      // Friction's damping at sticking per unit mass is g mu / v_eps (at least; its yaw adds):
      // semi-implicit Euler's decay limit 2 / c is an upper bound.
      EXPECT_LE(alone.limit.max_step, 2.0 / (9.81 * 0.3 / steep) * (1 + 1e-9));
      EXPECT_NE(alone.limit.element.find("friction"), std::string::npos) << alone.limit.element;
      for (const std::vector<double>& order :
           {std::vector<double>{gentle, gentle, gentle, steep},
            std::vector<double>{steep, gentle, steep, gentle}, std::vector<double>(40, steep)}) {
        const StabilityReport report = estimateStableStep(*boxesOnLaws(order, m));
        // Equal to rounding: each box's yaw arms differ in their last bits with its place.
        EXPECT_NEAR(report.limit.max_step, alone.limit.max_step, 1e-12 * alone.limit.max_step)
            << "m " << m << " v_eps " << steep;
        bool named_steep = false;  // the limit names a pair of the steep law
        for (std::size_t i = 0; i < order.size(); ++i)
          named_steep =
              named_steep ||
              (order[i] == steep &&
               report.limit.element.find("shape" + std::to_string(i) + ")") != std::string::npos);
        EXPECT_TRUE(named_steep) << report.limit.element;
      }
      // And the gentle law alone allows a longer step (so the steep one did decide above).
      EXPECT_GT(estimateStableStep(*boxesOnLaws({gentle}, m)).limit.max_step,
                1.5 * alone.limit.max_step);
    }
  }
}

}  // namespace
}  // namespace tribo
