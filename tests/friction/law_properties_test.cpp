// Properties every friction law must have, checked over all laws built through the factory
// with the paper's Table 1 values (Roh & Yoo 2007), every coulomb regularization, and the same
// laws with tiny transition speeds: odd symmetry, mu(0) = 0, continuity (at breakpoints and
// on a dense grid), the maxCoefficient bound, slope against finite differences, and the
// tangential force (dissipative, proportional to the load, magnitude mu * F_n).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "friction/friction_law.hpp"

namespace tribo::friction {
namespace {

struct LawCase {
  std::string label;
  LawSpec spec;
  bool continuous_at_zero = true;  // false only for unregularized Coulomb
};

void PrintTo(const LawCase& c, std::ostream* os) { *os << c.label; }

LawSpec table1(const std::string& name) {
  if (name == "coulomb") return {"coulomb", {{"mu", 0.3}}, {}};
  if (name == "recurdyn" || name == "adams") {
    return {name, {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"v_d", 0.15}}, {}};
  }
  if (name == "roh_yoo") {
    return {
        name, {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_s", 0.01}, {"a", 1.5}, {"beta", 1.0 / 3.0}}, {}};
  }
  if (name == "stribeck") {
    return {name, {{"mu_s", 0.35}, {"mu_k", 0.3}, {"v_st", 0.1}, {"viscous", 0.01}}, {}};
  }
  ADD_FAILURE() << "no Table 1 spec for " << name;
  return {};
}

LawSpec withRegularization(const std::string& regularization, double v_eps) {
  return {"coulomb", {{"mu", 0.3}, {"v_eps", v_eps}}, {{"regularization", regularization}}};
}

LawSpec withValue(LawSpec spec, const std::string& key, double value) {
  spec.values[key] = value;
  return spec;
}

std::vector<LawCase> allCases() {
  std::vector<LawCase> cases;
  for (const std::string& name : knownFrictionLaws()) cases.push_back({name, table1(name)});
  for (const std::string r : {"none", "linear", "tanh", "havsin"}) {
    cases.push_back({"coulomb_" + r, withRegularization(r, 1e-4), r != "none"});
  }
  // Tiny transition speeds.
  for (const std::string r : {"linear", "tanh", "havsin"}) {
    cases.push_back({"tiny_coulomb_" + r, withRegularization(r, 1e-6)});
  }
  cases.push_back({"tiny_recurdyn", withValue(table1("recurdyn"), "v_s", 1e-6)});
  cases.push_back({"tiny_adams", withValue(table1("adams"), "v_s", 1e-6)});
  cases.push_back({"tiny_roh_yoo", withValue(table1("roh_yoo"), "v_s", 1e-6)});
  cases.push_back(
      {"tiny_stribeck", withValue(withValue(table1("stribeck"), "v_eps", 1e-6), "v_st", 1e-5)});
  // Other shapes: Stribeck with exponential decay, Roh-Yoo with a linear and a convex rise.
  cases.push_back({"stribeck_delta_half", withValue(table1("stribeck"), "delta", 0.5)});
  cases.push_back({"roh_yoo_beta_1", withValue(table1("roh_yoo"), "beta", 1.0)});
  cases.push_back({"roh_yoo_beta_2", withValue(table1("roh_yoo"), "beta", 2.0)});
  return cases;
}

// Positive speeds: a geometric grid over [1e-10, 100] m/s (200 points a decade), plus the
// law's breakpoints and points just around them.
std::vector<double> speedGrid(const FrictionLaw& law) {
  std::vector<double> grid;
  for (int i = -2000; i <= 400; ++i) grid.push_back(std::pow(10.0, i / 200.0));
  for (const double bp : law.breakpoints()) {
    for (const double f : {1.0 - 1e-6, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.0 + 1e-6}) {
      grid.push_back(bp * f);
    }
  }
  std::sort(grid.begin(), grid.end());
  return grid;
}

// Distance from v > 0 to the nearest place where the law may be non-smooth (0 or a
// breakpoint).
double distanceToKink(const FrictionLaw& law, double v) {
  double d = std::abs(v);
  for (const double bp : law.breakpoints()) d = std::min(d, std::abs(v - bp));
  return d;
}

class FrictionLawProperties : public testing::TestWithParam<LawCase> {
 protected:
  void SetUp() override {
    law_ = makeFrictionLaw(GetParam().spec);
    grid_ = speedGrid(*law_);
  }
  std::unique_ptr<const FrictionLaw> law_;
  std::vector<double> grid_;
};

TEST_P(FrictionLawProperties, NameIsTheSceneName) { EXPECT_EQ(law_->name(), GetParam().spec.name); }

TEST_P(FrictionLawProperties, CoefficientIsOddAndSlopeIsEven) {
  for (const double v : grid_) {
    EXPECT_EQ(law_->coefficient(-v), -law_->coefficient(v)) << "v = " << v;
    EXPECT_EQ(law_->slope(-v), law_->slope(v)) << "v = " << v;
  }
}

TEST_P(FrictionLawProperties, CoefficientIsNonNegativeForPositiveSlip) {
  for (const double v : grid_) EXPECT_GE(law_->coefficient(v), 0.0) << "v = " << v;
}

TEST_P(FrictionLawProperties, ZeroAtZeroSlip) {
  EXPECT_EQ(law_->coefficient(0.0), 0.0);
  EXPECT_EQ(law_->coefficient(-0.0), 0.0);
  if (GetParam().continuous_at_zero) {
    const double v = 1e-30 * law_->stickSpeed();
    EXPECT_LT(std::abs(law_->coefficient(v)), 1e-9);
    EXPECT_LT(std::abs(law_->coefficient(-v)), 1e-9);
  }
}

TEST_P(FrictionLawProperties, BreakpointsArePositiveAndSorted) {
  const std::vector<double> bps = law_->breakpoints();
  EXPECT_TRUE(std::is_sorted(bps.begin(), bps.end()));
  for (const double bp : bps) EXPECT_GT(bp, 0.0);
  EXPECT_GT(law_->stickSpeed(), 0.0);
}

TEST_P(FrictionLawProperties, ContinuousAtEveryBreakpoint) {
  for (const double bp : law_->breakpoints()) {
    const double at = law_->coefficient(bp);
    const double tol = 1e-12 * std::abs(at);
    for (const double v : {bp * (1.0 - 1e-13), bp * (1.0 + 1e-13), std::nextafter(bp, 0.0),
                           std::nextafter(bp, 2.0 * bp)}) {
      EXPECT_NEAR(law_->coefficient(v), at, tol) << "breakpoint " << bp << ", v = " << v;
      EXPECT_NEAR(law_->coefficient(-v), -at, tol) << "breakpoint " << -bp << ", v = " << -v;
    }
  }
}

TEST_P(FrictionLawProperties, NoJumpsOnADenseGrid) {
  // Mean value theorem: a step between neighbours must be explained by the slope there.
  for (std::size_t i = 0; i + 1 < grid_.size(); ++i) {
    const double a = grid_[i];
    const double b = grid_[i + 1];
    const double max_slope = std::max(
        {std::abs(law_->slope(a)), std::abs(law_->slope(b)), std::abs(law_->slope(0.5 * (a + b)))});
    EXPECT_LE(std::abs(law_->coefficient(b) - law_->coefficient(a)),
              2.0 * max_slope * (b - a) + 1e-14)
        << "between " << a << " and " << b;
  }
}

TEST_P(FrictionLawProperties, BoundedByMaxCoefficientAndTight) {
  std::vector<double> limits = {
      0.5 * law_->stickSpeed(), law_->stickSpeed(), 0.05, 0.5, 1.5, 3.0, 100.0};
  for (const double bp : law_->breakpoints()) limits.push_back(bp);
  double previous_bound = 0.0;
  std::sort(limits.begin(), limits.end());
  EXPECT_EQ(law_->maxCoefficient(0.0), 0.0);
  for (const double v_max : limits) {
    const double bound = law_->maxCoefficient(v_max);
    EXPECT_EQ(law_->maxCoefficient(-v_max), bound) << "v_max = " << v_max;
    // Monotone in v_max (up to the 1e-6 relative slack of a numerically found maximum).
    EXPECT_GE(bound, previous_bound * (1.0 - 1e-6)) << "not monotone at v_max = " << v_max;
    previous_bound = bound;
    double largest = std::abs(law_->coefficient(v_max));
    for (const double v : grid_) {
      if (v > v_max) break;
      largest =
          std::max({largest, std::abs(law_->coefficient(v)), std::abs(law_->coefficient(-v))});
    }
    EXPECT_GE(bound, largest) << "v_max = " << v_max;
    // Not a loose bound either (the grid can miss a smooth peak by a little).
    EXPECT_LE(bound, largest * (1.0 + 1e-3)) << "v_max = " << v_max;
  }
}

TEST_P(FrictionLawProperties, SlopeMatchesCentralDifferences) {
  for (const double v0 : grid_) {
    const double d = distanceToKink(*law_, v0);
    if (d < 1e-3 * v0) continue;  // too close to a kink for a clean difference
    const double h = 1e-4 * d;
    for (const double v : {v0, -v0}) {
      const double lo = v - h;
      const double hi = v + h;
      const double fd = (law_->coefficient(hi) - law_->coefficient(lo)) / (hi - lo);
      const double slope = law_->slope(v);
      ASSERT_TRUE(std::isfinite(slope)) << "v = " << v;
      const double tol = 1e-6 * (std::abs(slope) + std::abs(law_->coefficient(v)) / d);
      EXPECT_NEAR(slope, fd, tol) << "v = " << v;
    }
  }
}

TEST_P(FrictionLawProperties, TangentialForceOpposesSlipWithMagnitudeMuFn) {
  std::mt19937 rng(12345);
  std::normal_distribution<double> normal;
  for (const double fn : {1.0, 98.1, 1e4}) {
    for (std::size_t i = 0; i < grid_.size(); i += 7) {
      const double speed = grid_[i];
      Eigen::Vector3d direction(normal(rng), normal(rng), normal(rng));
      if (i % 2 == 0) direction.z() = 0.0;  // in-plane slips too
      const Eigen::Vector3d slip = speed * direction.normalized();
      double mu = std::numeric_limits<double>::quiet_NaN();
      const Eigen::Vector3d force = tangentialForce(*law_, slip, fn, &mu);
      const double expected_mu = law_->coefficient(slip.norm());
      EXPECT_EQ(mu, expected_mu);
      EXPECT_LE(force.dot(slip), 0.0) << "not dissipative at speed " << speed;
      EXPECT_NEAR(force.norm(), expected_mu * fn, 1e-12 * expected_mu * fn) << speed;
      EXPECT_LE(force.cross(slip).norm(), 1e-12 * force.norm() * slip.norm()) << speed;
      EXPECT_LE(force.norm(), law_->maxCoefficient(speed) * fn * (1.0 + 1e-12)) << speed;
    }
  }
}

TEST_P(FrictionLawProperties, TangentialForceIsZeroAtZeroLoadAndZeroSlip) {
  double mu = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d slip(0.3, -0.4, 0.0);
  EXPECT_EQ(tangentialForce(*law_, slip, 0.0, &mu).norm(), 0.0);
  EXPECT_EQ(mu, law_->coefficient(0.5));
  mu = std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d force = tangentialForce(*law_, Eigen::Vector3d::Zero(), 98.1, &mu);
  EXPECT_EQ(force, Eigen::Vector3d::Zero());
  EXPECT_EQ(mu, 0.0);
  EXPECT_EQ(tangentialForce(*law_, Eigen::Vector3d::Zero(), 98.1), Eigen::Vector3d::Zero());
}

TEST_P(FrictionLawProperties, NaNSlipIsNotHidden) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(law_->coefficient(nan)));
  EXPECT_TRUE(std::isnan(law_->slope(nan)));
  EXPECT_TRUE(tangentialForce(*law_, Eigen::Vector3d(nan, 0.0, 0.0), 1.0).hasNaN());
}

INSTANTIATE_TEST_SUITE_P(AllLaws, FrictionLawProperties, testing::ValuesIn(allCases()),
                         [](const testing::TestParamInfo<LawCase>& info) {
                           return info.param.label;
                         });

TEST(FrictionLawCases, EveryKnownLawIsCovered) {
  std::set<std::string> covered;
  for (const LawCase& c : allCases()) covered.insert(c.spec.name);
  for (const std::string& name : knownFrictionLaws()) EXPECT_EQ(covered.count(name), 1u) << name;
  EXPECT_EQ(knownFrictionLaws(),
            (std::vector<std::string>{"coulomb", "recurdyn", "adams", "roh_yoo", "stribeck"}));
}

}  // namespace
}  // namespace tribo::friction
