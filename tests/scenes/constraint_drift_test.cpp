// A run whose joints come apart is never called complete without a word: chains of 2 to 6
// links falling from horizontal at steps from 1 to 20 ms, under semi-implicit Euler (whose
// explicit velocity update drifts at first order in the step, docs/joints.md) and under rk4
// with Baumgarte off (the drift accumulates), so that some stay below
// constraints.drift_warning, some pass it and some pass drift_stop. The drift is
// measured here from the bodies' poses: for each pin, the gap between the parent's and the
// child's anchor points and the tilt of the child's axis off the parent's (the norm of its
// part normal to the axis). The engine's largest |Phi| is a component of these in the joint's
// frame, so it lies between D / sqrt(3) and D, D the larger of the two norms. A run warns
// exactly when its |Phi| passed drift_warning, and it stops, naming the joint and the child
// body, at the step where it passed drift_stop.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "core/simulator.hpp"
#include "study/scene_run.hpp"
#include "support/joint_test_models.hpp"

namespace tribo {
namespace {

constexpr double kLength = 0.1;

// D: the largest pin gap [m] or axis tilt [-] of the chain at `s`.
double measuredDrift(const Model& m, const State& s) {
  double d = 0.0;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyState& child = s.bodies[i];
    const Vec3 child_anchor = child.position + child.orientation * Vec3(-0.5 * kLength, 0.0, 0.0);
    Vec3 parent_anchor = Vec3::Zero();
    Vec3 parent_axis = Vec3::UnitY();
    if (i > 0) {
      const BodyState& parent = s.bodies[i - 1];
      parent_anchor = parent.position + parent.orientation * Vec3(0.5 * kLength, 0.0, 0.0);
      parent_axis = parent.orientation * Vec3::UnitY();
    }
    const Vec3 child_axis = child.orientation * Vec3::UnitY();
    const Vec3 tilt = child_axis - child_axis.dot(parent_axis) * parent_axis;
    d = std::max({d, (child_anchor - parent_anchor).norm(), tilt.norm()});
  }
  return d;
}

struct Measured {
  double largest = 0.0;  // D over the steps taken
  bool stopped = false;  // the engine stopped the run
  StepStatus status;     // the stop
  double at_stop = 0.0;  // D at the stopped step's state
  double engine = 0.0;   // the engine's max |Phi| over the run
};

Measured stepThrough(const std::shared_ptr<const Model>& model) {
  Simulator sim(model);
  Measured out;
  const long steps = std::lround(model->options.duration / model->options.time_step);
  for (long n = 0; n < steps; ++n) {
    const StepStatus status = sim.step();
    if (!status.ok) {
      out.stopped = true;
      out.status = status;
      break;
    }
    out.largest = std::max(out.largest, measuredDrift(*model, sim.state()));
  }
  out.engine = sim.stats().max_constraint_error;
  return out;
}

// Semi-implicit Euler with Baumgarte (its drift stays bounded), or rk4 with no Baumgarte
// (nothing pulls the joints back: the drift of a coarse step accumulates).
std::shared_ptr<const Model> chain(int links, double dt, bool baumgarte) {
  ModelBuilder b = test::revoluteChain(
      links, baumgarte ? IntegratorType::kSemiImplicitEuler : IntegratorType::kRk4, dt,
      ConstraintSolverKind::kAuto, kLength, 0.1);
  b.options().gravity = Vec3(0, 0, -9.81);
  b.options().duration = 3.0;
  if (!baumgarte) b.options().baumgarte_alpha = b.options().baumgarte_beta = 0.0;
  return b.build();
}

TEST(ConstraintDrift, WarnedPastTheWarningAndStoppedPastTheStop) {
  int quiet = 0, warned = 0, stopped = 0;
  for (const bool baumgarte : {true, false}) {
    for (const int links : {2, 4, 6}) {
      for (const double dt : {1e-3, 4e-3, 1e-2, 2e-2}) {
        const auto model = chain(links, dt, baumgarte);
        const ConstraintOptions& c = model->options.constraints;
        const Measured m = stepThrough(model);
        std::ostringstream what;
        what << links << " links at " << dt << " s (Baumgarte " << baumgarte << "): D " << m.largest
             << ", engine " << m.engine;
        // Never past the stop unnoticed, whichever guard ends the run (D over the steps
        // before the stop: a failed step's state is not kept).
        EXPECT_LE(m.largest / std::sqrt(3.0), c.drift_stop) << what.str();
        if (m.stopped) {
          if (m.status.quantity != "constraint_drift") continue;  // the energy guard, first
          ++stopped;
          EXPECT_NE(m.status.message.find("joint 'pin"), std::string::npos) << m.status.message;
          EXPECT_NE(m.status.message.find("body 'link"), std::string::npos) << m.status.message;
          EXPECT_GT(m.engine, c.drift_stop) << what.str();  // the failed step's |Phi|
          continue;
        }
        // The engine's measure is a component of D's vectors in the joint frames.
        EXPECT_LE(m.engine, m.largest * (1 + 1e-9) + 1e-15) << what.str();
        EXPECT_GE(m.engine, m.largest / std::sqrt(3.0) * (1 - 1e-9)) << what.str();
        io::Scene scene;
        scene.path = "chain";
        scene.model = model;
        scene.output.interval = dt;
        const study::RunResult r = study::runScene(scene);
        ASSERT_TRUE(r.complete) << r.message;
        bool warning = false;
        for (const std::string& w : r.warnings)
          if (w.find("drifted") != std::string::npos) {
            warning = true;
            EXPECT_NE(w.find("joint 'pin"), std::string::npos) << w;
          }
        EXPECT_EQ(warning, r.stats.max_constraint_error > c.drift_warning) << what.str();
        if (m.largest / std::sqrt(3.0) > c.drift_warning) {
          EXPECT_TRUE(warning) << what.str();
        }
        if (m.largest < c.drift_warning) {
          EXPECT_FALSE(warning) << what.str();
        }
        ++(warning ? warned : quiet);
      }
    }
  }
  // Every outcome is exercised.
  EXPECT_GT(quiet, 0);
  EXPECT_GT(warned, 0);
  EXPECT_GT(stopped, 0);
}

// Projection holds the joints: the rk4 chains without Baumgarte that drifted past the
// stop above stay at the projection's tolerance and never warn or stop.
TEST(ConstraintDrift, ProjectionKeepsTheDriftingChainsQuiet) {
  for (const int links : {4, 6}) {
    for (const double dt : {1e-2, 2e-2}) {
      ModelBuilder b = test::revoluteChain(links, IntegratorType::kRk4, dt,
                                           ConstraintSolverKind::kAuto, kLength, 0.1);
      b.options().gravity = Vec3(0, 0, -9.81);
      b.options().duration = 3.0;
      b.options().baumgarte_alpha = b.options().baumgarte_beta = 0.0;
      b.options().constraints.projection = true;
      const Measured m = stepThrough(b.build());
      EXPECT_FALSE(m.stopped) << links << " links at " << dt << ": " << m.status.message;
      EXPECT_LT(m.largest, 1e-8) << links << " links at " << dt;
    }
  }
}

}  // namespace
}  // namespace tribo
