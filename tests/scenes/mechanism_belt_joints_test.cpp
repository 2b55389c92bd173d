// The paper's belt scene re-expressed with the general joints gives the result of
// scenes/belt.yaml: (1) scenes/belt_joint_friction.yaml, a box on a prismatic joint to a
// moving belt with the joint's friction loaded by its reaction, against the converged
// one-degree-of-freedom reference and the contact scene; (2) the contact scene with the box
// on a `planar` joint (free to pitch on its four contact corners) instead of
// `planar_translation`.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "friction/friction_law.hpp"
#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"
#include "support/one_dof_belt.hpp"

namespace tribo {
namespace {

const std::string kJointBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt_joint_friction.yaml";
const std::string kContactBelt = std::string(TRIBO_SOURCE_DIR) + "/scenes/belt.yaml";
constexpr double kM = 10.0, kK = 300.0, kG = 9.81, kVb = 1.5, kVs = 0.01;

study::RunResult run(const io::Scene& scene) {
  study::RunResult r = study::runScene(scene);
  EXPECT_TRUE(r.complete) << r.message;
  return r;
}

// Share of the recorded samples in which the box moves with the belt (|v - v_b| < v_s).
double stuckFraction(const study::TrajectoryRecorder& t) {
  const auto v = t.column(t.columnIndex("box.vx"));
  double stuck = 0;
  for (double x : v) stuck += std::abs(kVb - x) < kVs;
  return stuck / static_cast<double>(v.size());
}

TEST(BeltOnJoints, PrismaticJointFrictionGivesTheLimitCycleOfTheReferenceAndOfTheContacts) {
  const auto law = friction::makeFrictionLaw(
      {"roh_yoo",
       {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", kVs}, {"a", 1.5}, {"beta", 1.0 / 3}},
       {}});
  test::OneDofBelt reference{kM, kK, kVb, kG, law.get()};
  double x = 0.0, v = 0.0, lo = 1e9, hi = -1e9;
  long stuck = 0;
  const double h = 1e-5;
  const long n = std::lround(60.0 / h);
  reference.run(x, v, h, n, [&](double t, double xs, double vs) {
    if (t > 50.0) lo = std::min(lo, xs), hi = std::max(hi, xs);
    stuck += std::abs(kVb - vs) < kVs;
  });
  const double expected = hi - lo;

  const study::RunResult joint = run(io::loadScene(kJointBelt));
  const study::RunResult contact = run(io::loadScene(kContactBelt));
  // Measured: joint 0.562476 m, reference 0.5624760 m, contacts 0.562460 m (whose normal
  // force is a penalty spring's, not exactly m g).
  EXPECT_NEAR(joint.summary.amplitude_pp, expected, 1e-4 * expected);
  EXPECT_NEAR(joint.summary.amplitude_pp, contact.summary.amplitude_pp, 1e-4 * expected);
  EXPECT_NEAR(joint.summary.period, contact.summary.period, 1e-3 * contact.summary.period);
  const double reference_stuck = static_cast<double>(stuck) / static_cast<double>(n);
  EXPECT_NEAR(stuckFraction(joint.trajectory), reference_stuck, 0.05 * reference_stuck);
  EXPECT_LT(joint.stats.max_constraint_error, 1e-9);
}

TEST(BeltOnJoints, RecurDynLawThroughTheJointDoesNotGrowEither) {
  // Flat beyond v_d: the oscillation keeps 2 mu_k m g / k peak to peak.
  const study::RunResult r = run(io::loadScene(kJointBelt, {"friction=recurdyn"}));
  const double expected = 2 * 0.3 * kM * kG / kK;
  EXPECT_NEAR(r.summary.amplitude_pp, expected, 1e-3 * expected);
}

TEST(BeltOnJoints, PlanarJointOnTheContactsGivesTheSameLimitCycle) {
  std::ifstream in(kContactBelt);
  std::string yaml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = yaml.find("type: planar_translation");
  ASSERT_NE(at, std::string::npos);
  yaml.replace(at, 24, "type: planar");
  const study::RunResult pitching = run(io::loadSceneFromString(yaml, "belt_planar.yaml"));
  const study::RunResult original = run(io::loadScene(kContactBelt));
  // The box now pitches by the friction moment over its corners' stiffness (1e-4 rad).
  EXPECT_NEAR(pitching.summary.amplitude_pp, original.summary.amplitude_pp,
              1e-3 * original.summary.amplitude_pp);
}

}  // namespace
}  // namespace tribo
