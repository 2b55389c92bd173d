// The same eigenvalues whether a scene is written with joints or as free bodies.
// Box on the belt (scenes/belt.yaml, scenes/belt_free_box.yaml): with a prismatic joint the
// box has its one coordinate x, with the planar joint x and z. The spring is level at the
// steady state and the contact forces do not depend on x (the belt is a plane), so z's
// equation has no x term: the system is block triangular with the x block
// m x'' + N mu'(v_b) x' + k x = 0 in both, whose pair must agree to the finite differences'
// accuracy. The free box (six coordinates) is not block triangular: see the second test.
// Pendulum pressed on a belt (scenes/pendulum_on_belt.yaml, *_free.yaml): the free rod's
// hinge is two points held by springs of stiffness k. The joint is the limit k -> infinity,
// and the slow pair is a regular function of eps = 1 / k near 0 (the hinge points' motion is
// the reaction over k): lambda(eps) = lambda_J + a eps + O(eps^2). So the deviation from the
// jointed pair falls tenfold per decade of k, and the Richardson extrapolation
// (10 lambda(eps / 10) - lambda(eps)) / 9 = lambda_J + O(eps^2) removes nearly all of it.
#include <gtest/gtest.h>

#include <complex>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "support/scene_text.hpp"

namespace tribo::study {
namespace {

std::string scenePath(const std::string& name) {
  return std::string(TRIBO_SOURCE_DIR) + "/scenes/" + name + ".yaml";
}

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The mode whose largest motion is `coordinate` (the slowest such, skipping real roots).
const Mode& moving(const ModesResult& r, const std::string& coordinate) {
  const Mode* best = nullptr;
  for (const Mode& m : r.modes)
    if (m.dominant.rfind(coordinate, 0) == 0 && m.frequency > 0 &&
        (!best || m.frequency < best->frequency))
      best = &m;
  if (!best) {
    ADD_FAILURE() << "no oscillating mode moves " << coordinate << " most";
    return r.modes.front();
  }
  return *best;
}

struct BoxCase {
  std::string law;
  double m, k, v_b;
  bool coupled;  // the slope steep enough for the pitch coupling to show (else: below the
                 // finite differences' accuracy, 1e-6 of |lambda|, at k_c = 2.5e5)
};

std::vector<std::string> boxSettings(const BoxCase& c, double contact_stiffness) {
  // The box starts at its static depth (the scenes start it at rest).
  const double z0 = 0.05 - c.m * 9.81 / (4 * contact_stiffness);
  return {"friction=" + c.law,  "m=" + text(c.m), "k=" + text(c.k),
          "v_b=" + text(c.v_b), "z0=" + text(z0), "contact_stiffness=" + text(contact_stiffness)};
}

class BoxJointsVsFree : public ::testing::TestWithParam<BoxCase> {};

TEST_P(BoxJointsVsFree, InPlanePairIsTheSame) {
  const BoxCase& c = GetParam();
  const std::vector<std::string> set = boxSettings(c, 2.5e5);
  const std::string prismatic = test::replaced(fileText(scenePath("belt")),
                                               "type: planar_translation, parent: world, child: "
                                               "box,\n     anchor: [$x0, 0, $z0], axis: [0, 1, 0]",
                                               "type: prismatic, parent: world, child: box,\n"
                                               "     anchor: [$x0, 0, $z0], axis: [1, 0, 0]");
  const ModesResult prismatic_r =
      analyzeModes(io::loadSceneFromString(prismatic, scenePath("belt"), set));
  const ModesResult planar_r = analyzeModes(io::loadScene(scenePath("belt"), set));
  ASSERT_EQ(prismatic_r.coordinates, 1);
  ASSERT_EQ(planar_r.coordinates, 2);
  const std::complex<double> lambda_j = prismatic_r.modes.front().eigenvalue;
  const std::complex<double> planar = moving(planar_r, "box.x").eigenvalue;
  EXPECT_NEAR(planar.real(), lambda_j.real(), 1e-6 * std::abs(lambda_j.real()));
  EXPECT_NEAR(planar.imag(), lambda_j.imag(), 1e-7 * lambda_j.imag());
}

// The free box pitches: its bottom corners slip at x' - h ry' (h the half height), so the
// friction's slope couples x and the rocking, whose stiffness is the contacts'. Like the
// hinge springs below, the contacts' stiffness k_c plays the constraint: the free box's pair
// tends to the jointed one like 1 / k_c (tenfold per decade), shown where the slope is
// steep enough for the coupling to stand above the finite differences (low belt speeds).
TEST_P(BoxJointsVsFree, FreeBoxTendsToTheJointAsItsContactsStiffen) {
  const BoxCase& c = GetParam();
  const ModesResult joint = analyzeModes(io::loadScene(scenePath("belt"), boxSettings(c, 2.5e5)));
  const std::complex<double> lambda_j = moving(joint, "box.x").eigenvalue;
  std::vector<std::complex<double>> lambda;
  for (const double kc : {2.5e5, 2.5e6}) {
    const ModesResult r =
        analyzeModes(io::loadScene(scenePath("belt_free_box"), boxSettings(c, kc)));
    ASSERT_EQ(r.coordinates, 6);
    lambda.push_back(moving(r, "box.x").eigenvalue);
  }
  const double d5 = std::abs(lambda[0] - lambda_j), d6 = std::abs(lambda[1] - lambda_j);
  std::printf("box %s v_b=%g: prismatic %.10g%+.10gi; free k_c=2.5e5 %+.3g, 2.5e6 %+.3g\n",
              c.law.c_str(), c.v_b, lambda_j.real(), lambda_j.imag(), d5, d6);
  const double noise = 1e-6 * std::abs(lambda_j);  // the finite differences' accuracy
  if (!c.coupled) {
    EXPECT_LT(d5, noise);
    return;
  }
  EXPECT_GT(d5, 3 * noise);
  EXPECT_GT(d5 / d6, 7.0);
  EXPECT_LT(d5 / d6, 13.0);
  const std::complex<double> extrapolated = (10.0 * lambda[1] - lambda[0]) / 9.0;
  EXPECT_LT(std::abs(extrapolated - lambda_j), 0.2 * d6 + 2 * noise);
}

// Laws, masses, spring stiffnesses and belt speeds; roh_yoo's gentle slopes leave the
// coupling below the differences' accuracy, the steep low-speed slopes of stribeck, recurdyn
// and adams show it.
INSTANTIATE_TEST_SUITE_P(Cases, BoxJointsVsFree,
                         ::testing::Values(BoxCase{"roh_yoo", 10, 300, 1.5, false},
                                           BoxCase{"roh_yoo", 2, 800, 0.5, false},
                                           BoxCase{"stribeck", 5, 100, 0.1, true},
                                           BoxCase{"recurdyn", 20, 2000, 0.05, true},
                                           BoxCase{"adams", 8, 500, 0.08, true},
                                           BoxCase{"roh_yoo", 3, 1000, 0.05, false}),
                         [](const auto& info) { return "case" + std::to_string(info.index); });

struct PendulumCase {
  std::string law;
  double m, L, v_b, contact_damping;
};

class PendulumJointsVsFree : public ::testing::TestWithParam<PendulumCase> {};

TEST_P(PendulumJointsVsFree, StiffHingeSpringsTendToTheHinge) {
  const PendulumCase& c = GetParam();
  const std::vector<std::string> set{"friction=" + c.law, "m=" + text(c.m), "L=" + text(c.L),
                                     "v_b=" + text(c.v_b),
                                     "contact_damping=" + text(c.contact_damping)};
  const ModesResult joint = analyzeModes(io::loadScene(scenePath("pendulum_on_belt"), set));
  ASSERT_EQ(joint.coordinates, 1);
  const std::complex<double> lambda_j = joint.modes.front().eigenvalue;
  // Hinge springs anchored 10 m away round their accelerations at some 1e-7 m/s^2 at
  // k = 1e8 (eps * k * 10 m / m); a steady state to 1e-5 m/s^2 is within 1e-9 rad of the
  // exact one, far below what moves the eigenvalues here.
  ModesSpec spec;
  spec.steady.tolerance = 1e-5;
  std::vector<std::complex<double>> lambda;
  for (const double k : {1e6, 1e7, 1e8}) {
    std::vector<std::string> with_k = set;
    with_k.push_back("k_pivot=" + text(k));
    const ModesResult r =
        analyzeModes(io::loadScene(scenePath("pendulum_on_belt_free"), with_k), spec);
    ASSERT_EQ(r.coordinates, 6);
    lambda.push_back(moving(r, "rod.ry").eigenvalue);
  }
  const std::complex<double> d6 = lambda[0] - lambda_j, d7 = lambda[1] - lambda_j,
                             d8 = lambda[2] - lambda_j;
  std::printf("pendulum %s m=%g L=%g: hinge %.8g%+.8gi; free k=1e6 %+.3g, 1e7 %+.3g, 1e8 %+.3g\n",
              c.law.c_str(), c.m, c.L, lambda_j.real(), lambda_j.imag(), std::abs(d6), std::abs(d7),
              std::abs(d8));
  // First order in 1 / k: tenfold per decade.
  EXPECT_NEAR(std::abs(d6) / std::abs(d7), 10.0, 1.0);
  EXPECT_NEAR(std::abs(d7) / std::abs(d8), 10.0, 0.5);
  // Extrapolated to the rigid hinge: the O(eps) term gone, what is left a few percent of it.
  const std::complex<double> extrapolated = (10.0 * lambda[2] - lambda[1]) / 9.0;
  EXPECT_LT(std::abs(extrapolated - lambda_j), 0.05 * std::abs(d8));
  EXPECT_LT(std::abs(d8), 1e-3 * std::abs(lambda_j));
}

// Laws, masses, rod lengths, belt speeds and contact damping (undamped normal contact: the
// falling law's slope shows; damped: the normal damping, through friction, dominates).
INSTANTIATE_TEST_SUITE_P(Cases, PendulumJointsVsFree,
                         ::testing::Values(PendulumCase{"roh_yoo", 1.0, 0.5, 1.5, 5.0},
                                           PendulumCase{"roh_yoo", 2.0, 0.3, 0.5, 0.0},
                                           PendulumCase{"stribeck", 0.5, 0.8, 0.1, 20.0},
                                           PendulumCase{"coulomb", 1.0, 0.5, 2.0, 5.0}),
                         [](const auto& info) { return "case" + std::to_string(info.index); });

}  // namespace
}  // namespace tribo::study
