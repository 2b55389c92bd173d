// The closed-form joint solve for bodies held to the world with their rotations locked
// (core/locked_rotation_solve.hpp), over random bodies (masses 1 g to 1 t, sizes 1 mm to
// 10 m, anchors up to 10 m from the centre of mass, joint frames at random, states off the
// constraints): against the dense factorization of the same rows, and against the equations
// themselves (Newton-Euler with the constraint wrench, J a = b at acceleration level); joint
// friction's resolve; a locked-up state and the models it must leave to the factorization.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/dynamics.hpp"
#include "core/model_builder.hpp"
#include "core/simulator.hpp"
#include "friction/friction_law.hpp"

namespace tribo {
namespace {

struct Case {
  JointType type;
  double mass;    // [kg]
  double size;    // the body's edges, up to 2x this [m]
  double offset;  // the anchor's distance from the centre of mass [m]
  int bodies;
};

Vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

Eigen::Quaterniond randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

// Bodies in a row, each on its own joint to the world, each pulled by a spring fixed in the
// world at a point off its centre (a force and a moment), under gravity.
std::shared_ptr<const Model> heldBodies(const Case& c, ConstraintSolverKind solver, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.5, 2.0);
  ModelBuilder b;
  b.options().gravity = Vec3(0, 0, -9.81);
  b.options().constraints.solver = solver;
  for (int k = 0; k < c.bodies; ++k) {
    Body body;
    body.name = "body" + std::to_string(k);
    body.mass = c.mass * u(rng);
    const double x = c.size * u(rng), y = c.size * u(rng), z = c.size * u(rng);
    body.inertia =
        (body.mass / 12.0 * Vec3(y * y + z * z, x * x + z * z, x * x + y * y)).asDiagonal();
    body.position = Vec3(3.0 * k * (c.size + c.offset), 0.0, 0.0);
    body.orientation = randomRotation(rng);
    body.velocity = randomUnit(rng);
    const BodyIndex i = b.addBody(body);
    b.addJoint("hold" + std::to_string(k), c.type, BodyIndex::world(), i,
               body.position + c.offset * randomUnit(rng), randomUnit(rng));
    const Vec3 on_body = body.position + 0.5 * c.size * randomUnit(rng);
    b.addSpring("pull" + std::to_string(k), BodyIndex::world(), on_body + c.size * Vec3::UnitX(), i,
                on_body, 100.0 * body.mass, 0.1 * body.mass, 0.0);
  }
  return b.build();
}

// The initial state moved off the constraints: every body shifted, turned and spun a little.
State offTheConstraints(const Dynamics& d, const Case& c, unsigned seed) {
  std::mt19937 rng(seed + 1000);
  State s = d.initialState();
  for (BodyState& bs : s.bodies) {
    bs.position += 1e-3 * c.size * randomUnit(rng);
    bs.orientation = (Eigen::AngleAxisd(1e-3, randomUnit(rng)) * bs.orientation).normalized();
    bs.angular_velocity = 0.1 * randomUnit(rng);
  }
  return s;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (JointType type : {JointType::kPlanarTranslation, JointType::kPrismatic, JointType::kFixed})
    for (double mass : {1e-3, 1.0, 1e3})
      for (double size : {1e-3, 1.0, 10.0})
        for (double offset : {0.0, 1.0, 10.0})
          for (int bodies : {1, 3}) out.push_back({type, mass, size, offset, bodies});
  return out;
}

std::string describe(const Case& c) {
  return jointTypeName(c.type) + " m " + std::to_string(c.mass) + " size " +
         std::to_string(c.size) + " offset " + std::to_string(c.offset) + " bodies " +
         std::to_string(c.bodies);
}

TEST(LockedRotationSolve, AgreesWithTheFactorizationAndTheEquations) {
  unsigned seed = 1;
  double worst[2] = {0.0, 0.0};  // the largest differences seen, well and ill conditioned
  for (const Case& c : cases()) {
    ++seed;
    auto closed = heldBodies(c, ConstraintSolverKind::kAuto, seed);
    auto dense = heldBodies(c, ConstraintSolverKind::kDense, seed);
    Dynamics dc(closed), dd(dense);
    const State s = offTheConstraints(dc, c, seed);
    const Workspace& a = dc.evaluate(s);
    ASSERT_TRUE(dc.constraintSolver().lastSolveClosedForm()) << describe(c);
    const Workspace& b = dd.evaluate(s);
    ASSERT_FALSE(dd.constraintSolver().lastSolveClosedForm());
    const Model& m = *closed;

    // Against the factorization, relative to the largest acceleration and wrench: the dense
    // Cholesky's own rounding grows with the condition of J M^-1 J^T (a 1 mm body 10 m from
    // its anchor: about 1e8).
    double acc_scale = 0, acc_diff = 0, f_scale = 0, f_diff = 0;
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      const double L = std::max(c.size, c.offset);  // the lever that turns spin into speed
      acc_scale = std::max(
          {acc_scale, b.linear_acceleration[i].norm(), L * b.angular_acceleration[i].norm()});
      acc_diff = std::max({acc_diff, (a.linear_acceleration[i] - b.linear_acceleration[i]).norm(),
                           L * (a.angular_acceleration[i] - b.angular_acceleration[i]).norm()});
      f_scale = std::max(
          {f_scale, b.constraint_wrench[i].force.norm(), b.constraint_wrench[i].torque.norm() / L});
      f_diff =
          std::max({f_diff, (a.constraint_wrench[i].force - b.constraint_wrench[i].force).norm(),
                    (a.constraint_wrench[i].torque - b.constraint_wrench[i].torque).norm() / L});
    }
    const bool ill = c.offset > 100 * c.size;
    EXPECT_LT(acc_diff, (ill ? 1e-6 : 1e-10) * acc_scale) << describe(c);
    worst[ill] = std::max({worst[ill], acc_diff / acc_scale, f_diff / f_scale});
    EXPECT_LT(f_diff, (ill ? 1e-6 : 1e-10) * f_scale) << describe(c);
    // Each multiplier against the dense one, on the scale of its row's force or moment.
    const Eigen::VectorXd& la = dc.constraintSolver().multipliers();
    const Eigen::VectorXd& lb = dd.constraintSolver().multipliers();
    ASSERT_EQ(la.size(), lb.size());
    for (Eigen::Index r = 0; r < la.size(); ++r) {
      const bool rotation =
          dc.constraintSolver().rows()[r].kind == ConstraintRow::Kind::kPerpendicular;
      const double lever = rotation ? std::max(c.size, c.offset) : 1.0;
      EXPECT_LT(std::abs(la(r) - lb(r)) / lever, (ill ? 1e-6 : 1e-10) * f_scale)
          << describe(c) << " row " << r;
    }
    for (int j = 0; j < c.bodies; ++j)
      EXPECT_LT(
          (dc.constraintSolver().reactionForce(j) - dd.constraintSolver().reactionForce(j)).norm(),
          (ill ? 1e-6 : 1e-10) * f_scale)
          << describe(c);

    // Against the equations, at the closed form's own precision.
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      const Body& body = m.bodies[i];
      const BodyState& bs = s.bodies[i];
      const Vec3 f = a.spring_wrench[i].force + a.constraint_wrench[i].force;
      const Vec3 lhs = body.mass * (a.linear_acceleration[i] - m.options.gravity);
      EXPECT_LT((lhs - f).norm(), 1e-12 * (f.norm() + body.mass * 9.81)) << describe(c);
      const Mat3 r = bs.orientation.toRotationMatrix();
      const Mat3 inertia = r * body.inertia * r.transpose();
      const Vec3& w = bs.angular_velocity;
      const Vec3 tau = a.spring_wrench[i].torque + a.constraint_wrench[i].torque;
      const Vec3 euler = inertia * a.angular_acceleration[i] + w.cross(inertia * w);
      EXPECT_LT((euler - tau).norm(), 1e-11 * (tau.norm() + (inertia * w).norm() * w.norm()))
          << describe(c);
    }
    std::vector<Mat3> rotations;
    for (const BodyState& bs : s.bodies) rotations.push_back(bs.orientation.toRotationMatrix());
    const std::vector<ConstraintRow> rows = constraintRows(m);
    std::vector<RowValue> values(rows.size());
    evaluateRows(rows, rowGroups(rows), MotionView(s, rotations), 0.0, values);
    const double alpha = m.options.baumgarte_alpha, beta = m.options.baumgarte_beta;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const RowValue& v = values[r];
      const auto body = static_cast<std::size_t>(rows[r].body[0]);
      const double rhs = -v.bias - 2.0 * alpha * v.phi_dot - beta * beta * v.phi;
      const double ja = v.j[0].head<3>().dot(a.linear_acceleration[body]) +
                        v.j[0].tail<3>().dot(a.angular_acceleration[body]);
      // The rounding is that of the accelerations before the constraint moved them, which
      // can be far larger than after (a fixed body under gravity): those enter the scale.
      const Body& b0 = m.bodies[body];
      const Mat3 r0 = s.bodies[body].orientation.toRotationMatrix();
      const Vec3& w0 = s.bodies[body].angular_velocity;
      const Mat3 i0 = r0 * b0.inertia * r0.transpose();
      const Vec3 a_free = a.spring_wrench[body].force / b0.mass + m.options.gravity;
      const Vec3 alpha_free = i0.inverse() * (a.spring_wrench[body].torque - w0.cross(i0 * w0));
      const double scale =
          v.j[0].head<3>().norm() * (a.linear_acceleration[body].norm() + a_free.norm()) +
          v.j[0].tail<3>().norm() * (a.angular_acceleration[body].norm() + alpha_free.norm()) +
          std::abs(rhs);
      EXPECT_LE(std::abs(ja - rhs), 1e-12 * scale) << describe(c) << " row " << r;
    }
  }
  std::printf("largest difference from the factorization: %.1e (conditioned), %.1e (ill)\n",
              worst[0], worst[1]);
}

std::shared_ptr<const friction::FrictionLaw> coulomb(double mu) {
  return friction::makeFrictionLaw(
      {"coulomb", {{"mu", mu}, {"v_eps", 1e-4}}, {{"regularization", "tanh"}}});
}

// A slider on a tilted rail whose friction is loaded by the rail's reaction: the resolve
// after the friction force (ConstraintSolver::addForcesAndResolve).
std::shared_ptr<const Model> frictionSlider(ConstraintSolverKind solver, const Vec3& axis) {
  ModelBuilder b;
  b.options().gravity = Vec3(0, 0, -9.81);
  b.options().constraints.solver = solver;
  b.options().time_step = 1e-3;
  b.options().integrator = IntegratorType::kRk4;  // exact for a constant deceleration
  Body body;
  body.name = "slider";
  body.mass = 2.0;
  body.inertia = Vec3(0.01, 0.02, 0.03).asDiagonal();
  body.velocity = 2.0 * axis;
  const BodyIndex i = b.addBody(body);
  const int j =
      b.addJoint("rail", JointType::kPrismatic, BodyIndex::world(), i, Vec3(0.1, 0.2, 0.0), axis);
  b.setJointFriction(j, {coulomb(0.3), JointFrictionLoad::kReaction, 0.0, 1.0});
  return b.build();
}

TEST(LockedRotationSolve, JointFrictionResolvesAsTheFactorizationDoes) {
  const Vec3 axis = Vec3(1.0, 0.3, 0.4).normalized();
  Simulator closed(frictionSlider(ConstraintSolverKind::kAuto, axis));
  Simulator dense(frictionSlider(ConstraintSolverKind::kDense, axis));
  for (int n = 0; n < 250; ++n) {
    ASSERT_TRUE(closed.step().ok);
    ASSERT_TRUE(dense.step().ok);
  }
  // The rail carries the weight's normal part: it slows at g (mu |n x z| + axis . z) while
  // it slides, closed form or not.
  const double v0 = 2.0, g = 9.81, t = 0.25;  // it stops at 0.32 s
  const double decel = g * (0.3 * axis.cross(Vec3::UnitZ()).norm() + axis.z());
  EXPECT_NEAR(closed.state().bodies[0].position.dot(axis), v0 * t - 0.5 * decel * t * t, 1e-6);
  EXPECT_LT((closed.state().bodies[0].position - dense.state().bodies[0].position).norm(), 1e-12);
  EXPECT_LT((closed.state().bodies[0].velocity - dense.state().bodies[0].velocity).norm(), 1e-12);
}

TEST(LockedRotationSolve, ALockedUpStateIsLeftToTheFactorization) {
  // Turned 90 degrees about the joint's axis, the child's y axis lies along the parent's x:
  // the equation x_P . y_C = 0 no longer constrains a rotation and the three rotation rows
  // are dependent. The closed form refuses; the factorization then meets a singular
  // J M^-1 J^T as it always did, and the accelerations are NaN (which the simulator reports).
  const Case c{JointType::kPlanarTranslation, 1.0, 0.1, 0.0, 1};
  auto closed = heldBodies(c, ConstraintSolverKind::kAuto, 5);
  auto dense = heldBodies(c, ConstraintSolverKind::kDense, 5);
  Dynamics dc(closed), dd(dense);
  State s = dc.initialState();
  const Vec3 axis = closed->joints[0].axes_in_parent.col(2);  // z, in the world (its parent)
  s.bodies[0].orientation = Eigen::AngleAxisd(std::numbers::pi / 2, axis) * s.bodies[0].orientation;
  const Workspace& a = dc.evaluate(s);
  EXPECT_FALSE(dc.constraintSolver().lastSolveClosedForm());
  const Workspace& b = dd.evaluate(s);
  EXPECT_EQ(std::isnan(a.linear_acceleration[0].x()), std::isnan(b.linear_acceleration[0].x()));
  EXPECT_TRUE(std::isnan(a.angular_acceleration[0].x()));
  // Back on the constraints, the closed form is taken again.
  dc.evaluate(dc.initialState());
  EXPECT_TRUE(dc.constraintSolver().lastSolveClosedForm());
}

TEST(LockedRotationSolve, JointsThatLeaveARotationOrJoinBodiesAreFactorized) {
  auto lone = [](JointType type, bool chain, bool drive) {
    ModelBuilder b;
    b.options().gravity = Vec3(0, 0, -9.81);
    Body body;
    body.name = "a";
    body.mass = 1.0;
    body.inertia = Mat3::Identity() * 0.1;
    const BodyIndex a = b.addBody(body);
    const int j = b.addJoint("ja", type, BodyIndex::world(), a, Vec3::Zero(), Vec3::UnitX());
    if (drive) b.setJointDrive(j, JointDrive{});
    if (chain) {
      body.name = "b";
      body.position = Vec3(1, 0, 0);
      const BodyIndex c = b.addBody(body);
      b.addJoint("jb", JointType::kPrismatic, a, c, Vec3(1, 0, 0), Vec3::UnitX());
    }
    Dynamics d(b.build());
    d.evaluate(d.initialState());
    return d.constraintSolver().lastSolveClosedForm();
  };
  EXPECT_TRUE(lone(JointType::kPrismatic, false, false));
  EXPECT_FALSE(lone(JointType::kRevolute, false, false));  // a rotation free
  EXPECT_FALSE(lone(JointType::kPrismatic, true, false));  // a joint between two bodies
  EXPECT_FALSE(lone(JointType::kPrismatic, false, true));  // a drive's row
}

}  // namespace
}  // namespace tribo
