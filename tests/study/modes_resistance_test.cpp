// tribo modes with rolling and spinning resistance (contact/rolling_resistance.hpp): the
// angular springs, anchored at the steady state, appear in K and C, against equations
// derived here and solved with Eigen:
//   the spinning top at rest on its tip (scenes/experiments/spinning_top.yaml, its spindle
//   in a cylindrical joint: coordinates z and the spin): I l^2 + c_s l + k_s = 0 for the spin
//   (I = m R^2 / 2) and m l^2 + c_n l + k_n = 0 for the bounce on the tip, at three spin
//   stiffnesses and dampings (no spring: the spin would be a pair of zeros);
//   a ball at rest on a flat floor (scenes/experiments/ball_on_slope.yaml at ratio 0) with a
//   memoryless tanh law, whose slope at zero slip is a viscous d = mu m g / v_eps at the
//   contact point, lever r_e = r - d_n / 2 below the centre (the point midway into the
//   depth d_n = m g / k_n), and a rolling spring (k_r, c_r) about the tangent axes:
//     m x'' = -d (x' - r_e th'),
//     I th'' = r_e d (x' - r_e th') - k_r th - c_r th',  I = (2/5) m r^2,
//   twice (x with the turn about y, y with the turn about x), the bounce as above and a
//   free spin (two zeros: this material has no spinning part).
// Under elastic_stick the analysis is refused (its linear anchors are not linearized), so
// both scenes take a memoryless tangential law here.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "support/scene_text.hpp"

namespace tribo::study {
namespace {

const std::string kExperiments = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/";
constexpr double kG = 9.81;

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// `file`'s text with its elastic_stick friction replaced by a tanh Coulomb law (mu, v_eps).
std::string withTanhLaw(const std::string& file, double mu, double v_eps) {
  std::ifstream in(kExperiments + file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string yaml =
      test::replaced(text.str(), "friction_laws:\n",
                     "friction_laws:\n  coulomb: {mu: " + number(mu) +
                         ", regularization: tanh, v_eps: " + number(v_eps) + "}\n");
  return test::replaced(yaml, "    friction: elastic_stick\n", "    friction: coulomb\n");
}

// The roots of a l^2 + b l + c.
std::vector<std::complex<double>> roots(double a, double b, double c) {
  const std::complex<double> d = std::sqrt(std::complex<double>(b * b - 4 * a * c));
  return {(-b + d) / (2 * a), (-b - d) / (2 * a)};
}

// Every expected eigenvalue is a mode's (a pair listed once) and every mode an expected one,
// relative to the eigenvalue's size (absolute below 1 /s, for the zeros).
void expectModes(const ModesResult& r, const std::vector<std::complex<double>>& expected) {
  auto tolerance = [](std::complex<double> l) { return 1e-6 * std::max(std::abs(l), 1.0); };
  for (const Mode& m : r.modes) {
    double nearest = INFINITY;
    for (const auto& e : expected)
      nearest =
          std::min({nearest, std::abs(m.eigenvalue - e), std::abs(std::conj(m.eigenvalue) - e)});
    EXPECT_LT(nearest, tolerance(m.eigenvalue)) << "mode " << m.eigenvalue << " not expected";
  }
  for (const auto& e : expected) {
    double nearest = INFINITY;
    for (const Mode& m : r.modes)
      nearest =
          std::min({nearest, std::abs(m.eigenvalue - e), std::abs(std::conj(m.eigenvalue) - e)});
    std::printf("  expected %+.9f %+.9fi, nearest mode at %.2e\n", e.real(), e.imag(), nearest);
    EXPECT_LT(nearest, tolerance(e));
  }
}

TEST(ResistanceModes, TheTopsSpinSpringIsInKAndItsDamperInC) {
  const std::string yaml = withTanhLaw("spinning_top.yaml", 0.4, 0.01);
  const double m = 1.0, R = 0.04, inertia = 0.5 * m * R * R, k_n = 1e5 * m, c_n = 300 * m;
  for (const auto& [k_s, c_s] : {std::pair{20.0, 0.0}, {20.0, 0.05}, {500.0, 2.0}}) {
    SCOPED_TRACE("k_s " + number(k_s) + " c_s " + number(c_s));
    std::printf("top: k_s %g N m/rad, c_s %g N m s/rad\n", k_s, c_s);
    const ModesResult r = analyzeModes(io::loadSceneFromString(
        yaml, kExperiments + "spinning_top.yaml",
        {"w0=0", "spin_stiffness=" + number(k_s), "spin_damping=" + number(c_s)}));
    ASSERT_EQ(r.coordinates, 2);
    std::vector<std::complex<double>> expected = roots(inertia, c_s, k_s);
    for (const auto& l : roots(m, c_n, k_n)) expected.push_back(l);
    expectModes(r, expected);
  }
}

TEST(ResistanceModes, TheBallsRollingSpringCouplesItsTurnWithItsSlide) {
  const double mu = 0.4, v_eps = 0.01;
  const std::string yaml = withTanhLaw("ball_on_slope.yaml", mu, v_eps);
  for (const auto& [m, r] : {std::pair{1.0, 0.05}, {20.0, 0.2}}) {
    for (const double c_r : {0.0, 1e-3}) {
      const double k_n = 1e5 * m, c_n = 300 * m, k_r = 2e4 * m * r * r;
      SCOPED_TRACE("m " + number(m) + " r " + number(r) + " c_r " + number(c_r));
      std::printf("ball: m %g kg, r %g m, k_r %g N m/rad, c_r %g N m s/rad\n", m, r, k_r, c_r);
      const ModesResult res = analyzeModes(io::loadSceneFromString(
          yaml, kExperiments + "ball_on_slope.yaml",
          {"ratio=0", "m=" + number(m), "r=" + number(r), "rolling_damping=" + number(c_r)}));
      ASSERT_EQ(res.coordinates, 6);
      const double inertia = 0.4 * m * r * r, d = mu * m * kG / v_eps;
      const double r_e = r - 0.5 * m * kG / k_n;
      Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
      a(0, 2) = a(1, 3) = 1.0;
      a(2, 2) = -d / m;
      a(2, 3) = r_e * d / m;
      a(3, 1) = -k_r / inertia;
      a(3, 2) = r_e * d / inertia;
      a(3, 3) = -(r_e * r_e * d + c_r) / inertia;
      const Eigen::Vector4cd rolling = a.eigenvalues();
      std::vector<std::complex<double>> expected;
      for (int twice = 0; twice < 2; ++twice)
        for (int i = 0; i < 4; ++i) expected.push_back(rolling[i]);
      for (const auto& l : roots(m, c_n, k_n)) expected.push_back(l);
      expected.insert(expected.end(), 2, 0.0);  // the free spin
      expectModes(res, expected);
    }
  }
}

}  // namespace
}  // namespace tribo::study
