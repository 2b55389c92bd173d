// Direction-dependent friction (contact/anisotropy.hpp) at one contact point, against the
// limit-surface description it states: with ratios r_i+ / r_i- along two axes,
// - the force of a memoryless law is F = -mu(|R s|) F_n R^2 s / |R s| (closed form);
// - it lies on the half-ellipses (F_1 / r_1)^2 + (F_2 / r_2)^2 = (mu F_n)^2;
// - among all forces on that limit surface it is the one that dissipates most (maximum
//   dissipation, checked against 3600 forces sampled around the surface);
// - it never gains energy (F . s <= 0) and is continuous where the slip crosses an axis;
// - the axes follow the frame geometry's rotation and its sense (frame a or b);
// - a stuck elastic_stick spring has the stiffness r_i^2 k along axis i, and its break-away
//   force along t_i is r_i mu_s F_n.
#include "contact/anisotropy.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "contact/contact_force.hpp"
#include "friction/elastic_stick_law.hpp"

namespace tribo::contact {
namespace {

using Eigen::Vector3d;

constexpr double kMu = 0.4;

Anisotropy ratios(double f1, double b1, double f2, double b2) {
  Anisotropy an;
  an.active = true;
  an.forward = {f1, f2};
  an.backward = {b1, b2};
  an.validate();
  return an;
}

Material coulomb() {
  Material m;
  m.friction = friction::makeFrictionLaw({"coulomb", {{"mu", kMu}}, {{"regularization", "none"}}});
  return m;
}

// The friction force on b for slip s and load fn, through the anisotropic stage.
Vector3d force(const Material& m, const Anisotropy& an, const SlipAxes& axes, const Vector3d& s,
               double fn, double* mu = nullptr) {
  ContactRecord rec;
  rec.point.normal = Vector3d::UnitZ();
  rec.slip = s;
  rec.normal_force = fn;
  const Vector3d slip = enterLawPlane(an, axes, rec);
  frictionForce(m, rec);
  leaveLawPlane(an, axes, slip, rec);
  if (mu != nullptr) *mu = rec.mu;
  EXPECT_EQ(rec.slip, s);
  return rec.friction_force;
}

TEST(Anisotropy, CoulombForceIsTheClosedFormOnTheLimitSurfaceAndDissipatesMost) {
  const Material m = coulomb();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Anisotropy& an :
       {ratios(1.0, 1.0, 0.2, 0.2), ratios(0.5, 1.5, 1.0, 0.3), ratios(3.0, 0.7, 0.05, 2.0)}) {
    const SlipAxes axes = slipAxes(an, Eigen::Matrix3d::Identity(), Vector3d::UnitZ());
    ASSERT_TRUE(axes.t1.isApprox(Vector3d::UnitX()));
    ASSERT_TRUE(axes.t2.isApprox(Vector3d::UnitY()));
    for (int trial = 0; trial < 200; ++trial) {
      const Vector3d s(u(rng), u(rng), 0.0);
      const double fn = 5.0 + 5.0 * u(rng);
      double mu = 0.0;
      const Vector3d f = force(m, an, axes, s, fn, &mu);
      const double r1 = s.x() >= 0 ? an.forward[0] : an.backward[0];
      const double r2 = s.y() >= 0 ? an.forward[1] : an.backward[1];
      // Closed form.
      const Vector3d rs(r1 * s.x(), r2 * s.y(), 0.0);
      const Vector3d expected = -kMu * fn * Vector3d(r1 * rs.x(), r2 * rs.y(), 0.0) / rs.norm();
      EXPECT_LT((f - expected).norm(), 1e-13 * fn);
      EXPECT_NEAR(mu, f.norm() / fn, 1e-15);
      // On the limit surface.
      EXPECT_NEAR(std::hypot(f.x() / r1, f.y() / r2), kMu * fn, 1e-12 * fn);
      // Dissipates most among the forces on the limit surface.
      const double power = f.dot(s);
      EXPECT_LT(power, 0.0);
      for (int k = 0; k < 3600; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 3600;
        const double c = std::cos(a), d = std::sin(a);
        const Vector3d g(kMu * fn * c * (c >= 0 ? an.backward[0] : an.forward[0]),
                         kMu * fn * d * (d >= 0 ? an.backward[1] : an.forward[1]), 0.0);
        EXPECT_LE(power, g.dot(s) + 1e-12 * fn);
      }
    }
  }
}

TEST(Anisotropy, ForceIsContinuousWhereTheSlipCrossesAnAxis) {
  const Material m = coulomb();
  const Anisotropy an = ratios(0.5, 1.5, 1.0, 0.3);
  const SlipAxes axes = slipAxes(an, Eigen::Matrix3d::Identity(), Vector3d::UnitZ());
  for (const Vector3d& on_axis : {Vector3d(0.0, 0.3, 0.0), Vector3d(0.0, -0.3, 0.0),
                                  Vector3d(0.3, 0.0, 0.0), Vector3d(-0.3, 0.0, 0.0)}) {
    const Vector3d across = on_axis.cross(Vector3d::UnitZ()).normalized();
    const Vector3d left = force(m, an, axes, on_axis - 1e-9 * across, 10.0);
    const Vector3d right = force(m, an, axes, on_axis + 1e-9 * across, 10.0);
    EXPECT_LT((left - right).norm(), 1e-6);
  }
}

TEST(Anisotropy, AxesTurnWithTheFrameGeometryAndTheSenseWithItsSide) {
  const Material m = coulomb();
  Anisotropy an = ratios(0.5, 1.5, 1.0, 0.3);
  an.axis = Vector3d(1.0, 1.0, 0.0);  // a direction: normalised
  an.validate();
  EXPECT_NEAR(an.axis.norm(), 1.0, 1e-15);
  for (double yaw : {0.0, 0.3, 1.2, 2.5}) {
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw, Vector3d::UnitZ()).toRotationMatrix();
    const SlipAxes axes = slipAxes(an, turn, Vector3d::UnitZ());
    EXPECT_LT((axes.t1 - turn * an.axis).norm(), 1e-15);
    // The same slip in the frame's own axes gives the same force in them.
    const Vector3d s_local(0.2, -0.7, 0.0);
    const Vector3d f_local =
        force(m, an, slipAxes(an, Eigen::Matrix3d::Identity(), Vector3d::UnitZ()), s_local, 7.0);
    const Vector3d f = force(m, an, axes, turn * s_local, 7.0);
    EXPECT_LT((turn.transpose() * f - f_local).norm(), 1e-14);
  }
  // Frame a: the frame geometry's motion relative to b is -s, so a slip of b along +t1 is
  // a's backward motion.
  Anisotropy on_a = ratios(0.5, 1.5, 1.0, 1.0);
  on_a.frame_is_b = false;
  const SlipAxes axes_a = slipAxes(on_a, Eigen::Matrix3d::Identity(), Vector3d::UnitZ());
  EXPECT_NEAR(force(m, on_a, axes_a, Vector3d(0.1, 0, 0), 2.0).x(), -1.5 * kMu * 2.0, 1e-15);
  EXPECT_NEAR(force(m, on_a, axes_a, Vector3d(-0.1, 0, 0), 2.0).x(), 0.5 * kMu * 2.0, 1e-15);
  // An axis along the normal: the frame's next axis takes its place, still in the plane.
  Anisotropy upright = ratios(0.5, 0.5, 1.0, 1.0);
  upright.axis = Vector3d::UnitZ();
  const SlipAxes axes_up = slipAxes(upright, Eigen::Matrix3d::Identity(), Vector3d::UnitZ());
  EXPECT_NEAR(axes_up.t1.dot(Vector3d::UnitZ()), 0.0, 1e-15);
  EXPECT_NEAR(axes_up.t1.norm(), 1.0, 1e-15);
}

TEST(Anisotropy, BadRatiosAndAxesAreRefusedByName) {
  for (double bad : {0.0, -1.0, std::nan(""), static_cast<double>(INFINITY)}) {
    Anisotropy an;
    an.active = true;
    an.backward[1] = bad;
    try {
      an.validate();
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("backward ratio across the axis"), std::string::npos)
          << e.what();
    }
  }
  Anisotropy zero;
  zero.axis = Vector3d::Zero();
  EXPECT_THROW(zero.validate(), std::invalid_argument);
}

TEST(Anisotropy, StuckSpringIsStifferAlongTheRoughAxisAndBreaksAwayAtItsRatio) {
  const friction::ElasticStickParams p{
      .mu_s = 0.35, .mu_k = 0.3, .stiffness = 1e5, .damping = 0.0, .stick_speed = 1e-4};
  const friction::ElasticStickLaw law(p);
  const Anisotropy an = ratios(2.0, 0.5, 0.25, 0.25);
  const SlipAxes axes = slipAxes(an, Eigen::Matrix3d::Identity(), Vector3d::UnitZ());
  const double fn = 10.0;
  auto stuckForce = [&](const Vector3d& u) {
    const friction::StickView view{true, false, toLawPlane(an, axes, u)};
    return forceFromLawPlane(an, axes, law.stickForce(Vector3d::Zero(), fn, view, nullptr));
  };
  // Stiffness r_i^2 k, per axis and sense, while stuck.
  EXPECT_NEAR(stuckForce(Vector3d(1e-6, 0, 0)).x(), -4.0 * p.stiffness * 1e-6, 1e-15);
  EXPECT_NEAR(stuckForce(Vector3d(-1e-6, 0, 0)).x(), 0.25 * p.stiffness * 1e-6, 1e-15);
  EXPECT_NEAR(stuckForce(Vector3d(0, 1e-6, 0)).y(), -0.0625 * p.stiffness * 1e-6, 1e-15);
  // The largest force the spring holds along each axis is r_i mu_s F_n.
  for (const auto& [dir, r] :
       {std::pair{Vector3d(1, 0, 0), 2.0}, std::pair{Vector3d(-1, 0, 0), 0.5},
        std::pair{Vector3d(0, 1, 0), 0.25}}) {
    const double limit = r * p.mu_s * fn / (r * r * p.stiffness);  // elongation at the limit
    const Vector3d held = stuckForce(0.999 * limit * dir);
    EXPECT_NEAR(held.norm(), 0.999 * r * p.mu_s * fn, 1e-9 * fn);
    const Vector3d broken = stuckForce(1.001 * limit * dir);
    EXPECT_NEAR(broken.norm(), r * p.mu_k * fn, 1e-9 * fn);  // slides at r mu_k F_n
    // Back from the law's plane: the elongation a stateful law keeps is R^-1 of its own.
    const Vector3d u = 0.5 * limit * dir;
    EXPECT_LT((fromLawPlane(an, axes, toLawPlane(an, axes, u)) - u).norm(), 1e-20);
  }
}

}  // namespace
}  // namespace tribo::contact
