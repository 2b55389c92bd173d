// The adaptive integrators stop at the inputs' breakpoints (core/input_breakpoints.hpp,
// core/sundials_stepper.hpp): a force stepped from 0 to F at t_s on a free body in zero
// gravity, x(t) = 0 before t_s and F (t - t_s)^2 / (2 m) after it (v = F (t - t_s) / m): on each
// side a polynomial. With the step declared (Signal::step) bdf and dopri5 at loose tolerances
// end a step at t_s and restart there, and match the closed form far more closely than with
// the same force given as a function that reports no breakpoint (so the methods step across
// the jump): both are asserted, at three step times and three force magnitudes. Also: a
// breakpoint on an output time, and the breakpoints gathered from every kind of input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "core/input_breakpoints.hpp"
#include "core/integrator.hpp"
#include "core/model_builder.hpp"

namespace tribo {
namespace {

constexpr double kMass = 2.0;
constexpr double kEnd = 1.0;  // [s]

// x(T) and v(T) of the body pushed by `force` (x component) with `integrator` at rtol 1e-3 and
// an absolute tolerance of 1e-6 on the scale of `magnitude` [N].
std::pair<double, double> pushed(IntegratorType integrator, const Signal& force, double interval,
                                 double magnitude) {
  ModelBuilder b;
  Body body;
  body.name = "block";
  body.mass = kMass;
  AppliedLoad load;
  load.name = "push";
  load.body = b.addBody(body);
  load.force = {force, Signal(), Signal()};
  b.addLoad(load);
  b.options().gravity = Vec3::Zero();
  b.options().integrator = integrator;
  b.options().time_step = interval;
  b.options().duration = kEnd;
  b.options().relative_tolerance = 1e-3;
  b.options().absolute_tolerance = 1e-6 * magnitude / kMass;
  // The integrator alone (no divergence checks: the energy guard would stop a run whose
  // method smears the jump, which is what is measured here).
  const std::shared_ptr<const Model> model = b.build();
  Dynamics dynamics(model);
  const std::unique_ptr<Integrator> method = makeIntegrator(integrator, *model);
  State state = dynamics.initialState();
  for (int i = 0; i < static_cast<int>(std::lround(kEnd / interval)); ++i) {
    const IntegratorStatus r = method->step(dynamics, state, interval, false);
    EXPECT_TRUE(r.ok) << r.message;
    if (!r.ok) break;
  }
  return {state.bodies[0].position.x(), state.bodies[0].velocity.x()};
}

// The same step as a function of t with no breakpoint: the methods are not told of it.
Signal hiddenStep(double time, double force) {
  return Signal::function([=](double t) { return t < time ? 0.0 : force; },
                          [](double) { return 0.0; });
}

// Relative error of `got` against `want`.
double error(double got, double want) { return std::abs(got - want) / std::abs(want); }

// With the stop, dopri5 (fifth order) integrates each quadratic piece exactly: x and v to
// rounding. bdf restarts at order 1 (backward Euler), exact for v' = F / m but not for x' = v,
// so its x is as good as the error control (rtol 1e-3) and its v exact to rounding: the
// quantity that shows the stop there is v. Across the jump, both are only as good as the
// error control makes them.
TEST(IntegratorBreakpoints, AForceStepIsIntegratedExactlyOnlyWhenTheMethodStopsAtIt) {
  for (const IntegratorType integrator : {IntegratorType::kBdf, IntegratorType::kDopri5}) {
    const bool bdf = integrator == IntegratorType::kBdf;
    for (const double ts : {0.123456, 0.5, 0.731}) {
      for (const double force : {1e-3, 1.0, 1e3}) {
        const double s = kEnd - ts;
        const double x = force * s * s / (2 * kMass), v = force * s / kMass;
        // A communication interval the step times 0.123456 and 0.731 do not fall on.
        const auto [x_stop, v_stop] = pushed(integrator, Signal::step(ts, 0.0, force), 0.1, force);
        const auto [x_over, v_over] = pushed(integrator, hiddenStep(ts, force), 0.1, force);
        const std::string what = std::string(bdf ? "bdf" : "dopri5") + " t_s " +
                                 std::to_string(ts) + " F " + std::to_string(force);
        EXPECT_LT(error(v_stop, v), 1e-12) << what;
        EXPECT_GT(error(v_over, v), 1e-8) << what;  // measured 5e-7 .. 4e-4
        if (bdf) {
          EXPECT_LT(error(x_stop, x), 1e-3) << what;  // rtol: measured 2e-5 .. 1.4e-4
        } else {
          EXPECT_LT(error(x_stop, x), 1e-11) << what;
          EXPECT_GT(error(x_over, x), 1e-6) << what;  // measured 1.5e-4 .. 9e-4
        }
      }
    }
  }
}

TEST(IntegratorBreakpoints, ABreakpointOnAnOutputTimeEndsThatInterval) {
  // t_s = 0.5 on the 0.1 s grid (reached as 0.1 + 0.1 + ... up to rounding).
  for (const IntegratorType integrator : {IntegratorType::kBdf, IntegratorType::kDopri5}) {
    const auto [x, v] = pushed(integrator, Signal::step(0.5, 0.0, 1.0), 0.1, 1.0);
    EXPECT_LT(error(v, 0.5 / kMass), 1e-12);
    if (integrator == IntegratorType::kDopri5) {
      EXPECT_LT(error(x, 0.25 / (2 * kMass)), 1e-11);
    }
  }
}

TEST(IntegratorBreakpoints, GatheredFromLoadsActuatorsAndSurfaceVelocities) {
  ModelBuilder b;
  Body block;
  block.name = "block";
  const BodyIndex i = b.addBody(block);
  Body belt;
  belt.name = "belt";
  belt.kind = BodyKind::kKinematic;
  belt.surface_velocity_signal = std::make_shared<const std::array<Signal, 3>>(
      std::array<Signal, 3>{Signal::table({{0.2, 1.0}, {0.9, 2.0}}), Signal(), Signal()});
  b.addBody(belt);
  AppliedLoad load;
  load.name = "push";
  load.body = i;
  load.force = {Signal::ramp(1.0, 0.4), Signal::step(0.9, 0.0, 1.0), Signal()};
  load.torque = {Signal(), Signal(), Signal::smoothStep(0.1, 0.0, 0.3, 1.0)};
  b.addLoad(load);
  b.options().gravity = Vec3::Zero();
  const std::vector<double> want = {0.1, 0.2, 0.3, 0.4, 0.9};
  EXPECT_EQ(inputBreakpoints(*b.build()), want);
}

}  // namespace
}  // namespace tribo
