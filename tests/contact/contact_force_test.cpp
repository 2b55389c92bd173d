// The contact stages' per-point arithmetic written on components (contact/contact_force.hpp:
// contactKinematics, contactWrench) against the vector formulas they stand for, written here
// with Eigen's own products: the same bits over random points, motions and forces from 1e-9 to
// 1e3 in every quantity; and the physics they must keep (the slip lies in the tangent plane, a
// body sliding on a resting one slips at its own tangential speed, the moments on A and B
// differ by the moment of the force's arm between their origins).
#include "contact/contact_force.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tribo::contact {
namespace {

class RandomContact {
 public:
  explicit RandomContact(unsigned seed) : rng_(seed) {}
  // A magnitude between 1e-9 and 1e3, either sign; exactly zero one time in ten.
  double value() {
    if (std::uniform_int_distribution<int>(0, 9)(rng_) == 0) return 0.0;
    const double m = std::pow(10.0, std::uniform_real_distribution<double>(-9.0, 3.0)(rng_));
    return std::bernoulli_distribution(0.5)(rng_) ? m : -m;
  }
  Eigen::Vector3d vector() { return {value(), value(), value()}; }
  Eigen::Vector3d unit() {
    std::normal_distribution<double> g;
    Eigen::Vector3d n(g(rng_), g(rng_), g(rng_));
    return n.normalized();
  }
  GeometryMotion motion() { return {vector(), vector(), vector(), vector()}; }
  // A record after the friction stage: a point, its load, friction force and (optionally)
  // rolling moment.
  ContactRecord loaded(bool with_moment) {
    ContactRecord rec;
    rec.point = point();
    rec.normal_force = std::abs(value());
    rec.friction_force = vector();
    if (with_moment) rec.moment = vector();
    return rec;
  }
  ContactPoint point() {
    ContactPoint cp;
    cp.pair = 3;
    cp.feature = 5;
    cp.position = vector();
    cp.normal = unit();
    cp.depth = std::abs(value());
    return cp;
  }

 private:
  std::mt19937_64 rng_;
};

// The bit patterns of two vectors, component by component (+0 and -0 count as equal, as the
// sums that use them do).
void expectSameBits(const Eigen::Vector3d& got, const Eigen::Vector3d& want, const char* what,
                    int k) {
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(got[c], want[c]) << what << " component " << c << " case " << k;
}

TEST(ContactForce, KinematicsOnComponentsEqualTheVectorFormulaBitForBit) {
  RandomContact random(11);
  for (int k = 0; k < 20000; ++k) {
    const ContactPoint cp = random.point();
    const GeometryMotion a = random.motion(), b = random.motion();
    ContactRecord rec;
    rec.moment = random.vector();  // the stage clears it
    contactKinematics(cp, a, b, rec);
    // The formulas of the header's comment, on Eigen's vectors.
    const Eigen::Vector3d v_rel = (b.velocity + b.angular_velocity.cross(cp.position - b.origin)) -
                                  (a.velocity + a.angular_velocity.cross(cp.position - a.origin));
    const Eigen::Vector3d v_slide = v_rel + b.surface_velocity - a.surface_velocity;
    EXPECT_EQ(rec.depth_rate, -cp.normal.dot(v_rel)) << "case " << k;
    expectSameBits(rec.slip, v_slide - cp.normal.dot(v_slide) * cp.normal, "slip", k);
    expectSameBits(rec.moment, Eigen::Vector3d::Zero(), "moment", k);
    EXPECT_EQ(rec.point.pair, 3);
    EXPECT_EQ(rec.point.feature, 5);
    EXPECT_EQ(rec.point.depth, cp.depth);
    expectSameBits(rec.point.position, cp.position, "position", k);
    // In the tangent plane to the rounding of the slip's largest term.
    const double scale = v_slide.cwiseAbs().maxCoeff();
    EXPECT_LE(std::abs(cp.normal.dot(rec.slip)), 1e-14 * scale) << "case " << k;
  }
}

TEST(ContactForce, BodySlidingOnARestingOneSlipsAtItsTangentialSpeed) {
  // B translates at v over A at rest (no spin): the slip is v's tangential part and the depth
  // rate minus its normal part, for speeds from 1e-9 to 1e3 m/s and any normal.
  RandomContact random(12);
  for (int k = 0; k < 2000; ++k) {
    const ContactPoint cp = random.point();
    GeometryMotion a, b;
    a.origin = random.vector();
    b.origin = random.vector();
    b.velocity = random.vector();
    ContactRecord rec;
    contactKinematics(cp, a, b, rec);
    const Eigen::Vector3d& n = cp.normal;
    const double vn = n.dot(b.velocity);
    const double scale = b.velocity.norm();
    EXPECT_NEAR(rec.depth_rate, -vn, 1e-15 * scale) << "case " << k;
    EXPECT_LE((rec.slip - (b.velocity - vn * n)).norm(), 1e-15 * scale) << "case " << k;
  }
}

TEST(ContactForce, WrenchOnComponentsEqualsTheVectorFormulaBitForBit) {
  RandomContact random(13);
  for (int k = 0; k < 20000; ++k) {
    const ContactRecord rec = random.loaded(k % 3 != 0);
    const Eigen::Vector3d oa = random.vector(), ob = random.vector();
    Eigen::Vector3d force, torque_b, force_a, torque_a;
    contactWrench(rec, ob, true, force, torque_b);
    contactWrench(rec, oa, false, force_a, torque_a);
    const Eigen::Vector3d f = rec.normal_force * rec.point.normal + rec.friction_force;
    expectSameBits(force, f, "force", k);
    expectSameBits(force, rec.force(), "force()", k);
    expectSameBits(force_a, -f, "force on A", k);
    expectSameBits(torque_b, (rec.point.position - ob).cross(f) + rec.moment, "torque on B", k);
    expectSameBits(torque_a, (rec.point.position - oa).cross(-f) - rec.moment, "torque on A", k);
  }
}

TEST(ContactForce, WrenchMomentsBalanceAboutAnyPoint) {
  // The force on B at p and its opposite on A at p: the moments about B's and A's origins sum
  // to (o_A - o_B) x f, the force's moment over the arm between the origins; the rolling
  // moment cancels (B gets +M, A gets -M).
  RandomContact random(14);
  for (int k = 0; k < 2000; ++k) {
    const ContactRecord rec = random.loaded(true);
    const Eigen::Vector3d oa = random.vector(), ob = random.vector();
    Eigen::Vector3d force, torque_b, force_a, torque_a;
    contactWrench(rec, ob, true, force, torque_b);
    contactWrench(rec, oa, false, force_a, torque_a);
    const Eigen::Vector3d arm = (oa - ob).cross(force);
    const Eigen::Vector3d balance = torque_b + torque_a - arm;
    // Each moment rounds to its own largest term, the force's moment or the rolling one.
    const double scale =
        (rec.point.position.norm() + oa.norm() + ob.norm()) * force.norm() + rec.moment.norm();
    EXPECT_LE(balance.norm(), 1e-14 * scale) << "case " << k;
  }
}

}  // namespace
}  // namespace tribo::contact
