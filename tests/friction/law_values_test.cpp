// Law-specific values against closed forms computed here from the formulas of Roh & Yoo 2007
// (Table 1 parameters unless stated).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "friction/adams_law.hpp"
#include "friction/coulomb_law.hpp"
#include "friction/friction_law.hpp"
#include "friction/recurdyn_law.hpp"
#include "friction/roh_yoo_law.hpp"
#include "friction/stribeck_law.hpp"

namespace tribo::friction {
namespace {

constexpr double kMuS = 0.35;
constexpr double kMuK = 0.3;
constexpr double kVs = 0.01;
constexpr double kVd = 0.15;
constexpr double kA = 1.5;
constexpr double kBeta = 1.0 / 3.0;

std::unique_ptr<const FrictionLaw> stepLaw(const std::string& name) {
  return makeFrictionLaw({name, {{"mu_s", kMuS}, {"mu_k", kMuK}, {"v_s", kVs}, {"v_d", kVd}}, {}});
}

std::unique_ptr<const FrictionLaw> rohYoo(double beta = kBeta) {
  return makeFrictionLaw(
      {"roh_yoo", {{"mu_s", kMuS}, {"mu_k", kMuK}, {"v_s", kVs}, {"a", kA}, {"beta", beta}}, {}});
}

// ---- RecurDyn and ADAMS ----------------------------------------------------------------

class FrictionStepLawValues : public testing::TestWithParam<std::string> {};

TEST_P(FrictionStepLawValues, PeakIsMuSAtVs) {
  const auto law = stepLaw(GetParam());
  EXPECT_NEAR(law->coefficient(kVs), kMuS, 1e-12 * kMuS);
  EXPECT_NEAR(law->coefficient(-kVs), -kMuS, 1e-12 * kMuS);
  EXPECT_DOUBLE_EQ(law->maxCoefficient(10.0), kMuS);
  EXPECT_EQ(law->stickSpeed(), kVs);
  EXPECT_EQ(law->breakpoints(), (std::vector<double>{kVs, kVd}));
}

TEST_P(FrictionStepLawValues, ExactlyMuKFromVdOn) {
  const auto law = stepLaw(GetParam());
  for (const double v : {kVd, 0.2, 1.5, 100.0, 1e9}) {
    EXPECT_EQ(law->coefficient(v), kMuK) << v;
    EXPECT_EQ(law->coefficient(-v), -kMuK) << v;
    EXPECT_EQ(law->slope(v), 0.0) << v;
  }
}

TEST_P(FrictionStepLawValues, MidpointsOfBothSteps) {
  const auto law = stepLaw(GetParam());
  EXPECT_NEAR(law->coefficient(0.5 * kVs), 0.5 * kMuS, 1e-15);
  EXPECT_NEAR(law->coefficient(0.5 * (kVs + kVd)), 0.5 * (kMuS + kMuK), 1e-15);
}

TEST_P(FrictionStepLawValues, FlatAtZeroSoALoadedBodyCreeps) {
  // The fault the seed paper names: zero slope at v = 0.
  EXPECT_EQ(stepLaw(GetParam())->slope(0.0), 0.0);
}

INSTANTIATE_TEST_SUITE_P(RecurDynAndAdams, FrictionStepLawValues,
                         testing::Values("recurdyn", "adams"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(FrictionRecurDyn, QuarterPointsFollowTheHaversine) {
  const auto law = stepLaw("recurdyn");
  const double quarter = (1.0 - std::cos(std::numbers::pi / 4.0)) / 2.0;
  EXPECT_NEAR(law->coefficient(0.25 * kVs), kMuS * quarter, 1e-15);
  EXPECT_NEAR(law->coefficient(kVs + 0.25 * (kVd - kVs)), kMuS + (kMuK - kMuS) * quarter, 1e-15);
}

TEST(FrictionAdams, QuarterPointsFollowTheCubicStep) {
  const auto law = stepLaw("adams");
  EXPECT_NEAR(law->coefficient(0.25 * kVs), kMuS * 0.15625, 1e-15);
  EXPECT_NEAR(law->coefficient(kVs + 0.25 * (kVd - kVs)), kMuS + (kMuK - kMuS) * 0.15625, 1e-15);
}

// ---- Roh & Yoo ---------------------------------------------------------------------------

TEST(FrictionRohYoo, PeakIsMuSAtVs) {
  const auto law = rohYoo();
  EXPECT_NEAR(law->coefficient(kVs), kMuS, 1e-12 * kMuS);
  EXPECT_NEAR(law->coefficient(-kVs), -kMuS, 1e-12 * kMuS);
  EXPECT_NEAR(law->maxCoefficient(3.0), kMuS, 1e-12 * kMuS);
  EXPECT_EQ(law->stickSpeed(), kVs);
  EXPECT_EQ(law->breakpoints(), (std::vector<double>{kVs}));
}

TEST(FrictionRohYoo, CubeRootRiseBelowVs) {
  const auto law = rohYoo();
  // (1/8)^(1/3) = 1/2.
  EXPECT_NEAR(law->coefficient(kVs / 8.0), kMuS / 2.0, 1e-14);
  EXPECT_NEAR(law->coefficient(-kVs / 1000.0), -kMuS / 10.0, 1e-14);
}

TEST(FrictionRohYoo, OffsetBMatchesClosedForm) {
  const RohYooLaw law({.mu_s = kMuS, .mu_k = kMuK, .v_s = kVs, .a = kA, .beta = kBeta});
  const double b = -std::log(kMuS - kMuK) / std::log(kA) - kVs;
  EXPECT_NEAR(law.b(), b, 1e-14 * std::abs(b));
  EXPECT_NEAR(law.b(), 7.378385, 1e-6);  // -ln(0.05)/ln(1.5) - 0.01, by hand
}

TEST(FrictionRohYoo, MatchesThePaperFormAboveVs) {
  const auto law = rohYoo();
  const double b = -std::log(kMuS - kMuK) / std::log(kA) - kVs;
  for (const double v : {0.011, 0.05, 0.15, 1.0, 1.5, 5.0, 30.0}) {
    EXPECT_NEAR(law->coefficient(v), std::pow(kA, -(v + b)) + kMuK, 1e-13) << v;
    EXPECT_NEAR(law->coefficient(-v), -std::pow(kA, -v - b) - kMuK, 1e-13) << v;
  }
}

TEST(FrictionRohYoo, TendsToMuKAtLargeSpeed) {
  const auto law = rohYoo();
  EXPECT_NEAR(law->coefficient(200.0), kMuK, 1e-9);
  EXPECT_NEAR(law->coefficient(-200.0), -kMuK, 1e-9);
  EXPECT_GT(law->coefficient(50.0), kMuK);  // approached from above (1.5^-50 still shows)
}

TEST(FrictionRohYoo, SlopeAtBeltSpeedMatchesSeed) {
  const auto law = rohYoo();
  const double v_b = 1.5;
  const double expected = -std::log(kA) * (kMuS - kMuK) * std::pow(kA, -(v_b - kVs));
  EXPECT_NEAR(law->slope(v_b), expected, 1e-14);
  EXPECT_NEAR(law->slope(-v_b), expected, 1e-14);
  EXPECT_LT(expected, 0.0);
}

TEST(FrictionRohYoo, SlopeIsNegativeEverywhereAboveVs) {
  const auto law = rohYoo();
  for (double v = 1.001 * kVs; v < 50.0; v *= 1.1) EXPECT_LT(law->slope(v), 0.0) << v;
}

TEST(FrictionRohYoo, SlopeAtZeroDependsOnBeta) {
  EXPECT_EQ(rohYoo(kBeta)->slope(0.0), std::numeric_limits<double>::infinity());
  EXPECT_NEAR(rohYoo(1.0)->slope(0.0), kMuS / kVs, 1e-12);
  EXPECT_EQ(rohYoo(2.0)->slope(0.0), 0.0);
  // Finite everywhere else, and the left-hand value at the kink.
  EXPECT_TRUE(std::isfinite(rohYoo(kBeta)->slope(1e-300)));
  EXPECT_NEAR(rohYoo(kBeta)->slope(kVs), kMuS * kBeta / kVs, 1e-12);
}

// ---- Coulomb -----------------------------------------------------------------------------

std::unique_ptr<const FrictionLaw> coulomb(const std::string& regularization) {
  return makeFrictionLaw(
      {"coulomb", {{"mu", 0.3}, {"v_eps", 1e-3}}, {{"regularization", regularization}}});
}

TEST(FrictionCoulomb, DefaultsAreTanhWithVeps1e4) {
  const auto law = makeFrictionLaw({"coulomb", {{"mu", 0.3}}, {}});
  EXPECT_EQ(law->stickSpeed(), 1e-4);
  EXPECT_DOUBLE_EQ(law->coefficient(1e-4), 0.3 * std::tanh(1.0));
  const auto& typed = dynamic_cast<const CoulombLaw&>(*law);
  EXPECT_EQ(typed.params().regularization, CoulombRegularization::kTanh);
}

TEST(FrictionCoulomb, EachRegularization) {
  EXPECT_EQ(coulomb("none")->coefficient(1e-300), 0.3);
  EXPECT_EQ(coulomb("none")->coefficient(-1e-300), -0.3);
  EXPECT_DOUBLE_EQ(coulomb("linear")->coefficient(0.5e-3), 0.15);
  EXPECT_EQ(coulomb("linear")->coefficient(2e-3), 0.3);
  EXPECT_DOUBLE_EQ(coulomb("linear")->slope(0.5e-3), 300.0);
  EXPECT_DOUBLE_EQ(coulomb("tanh")->coefficient(2e-3), 0.3 * std::tanh(2.0));
  EXPECT_NEAR(coulomb("havsin")->coefficient(0.5e-3), 0.15, 1e-15);
  EXPECT_EQ(coulomb("havsin")->coefficient(1e-3), 0.3);
  for (const std::string r : {"none", "linear", "tanh", "havsin"}) {
    EXPECT_EQ(coulomb(r)->stickSpeed(), 1e-3) << r;
    EXPECT_NEAR(coulomb(r)->coefficient(1.0), 0.3, 1e-15) << r;
  }
}

TEST(FrictionCoulomb, ZeroFrictionIsAllowed) {
  const auto law = makeFrictionLaw({"coulomb", {{"mu", 0.0}}, {}});
  EXPECT_EQ(law->coefficient(1.0), 0.0);
  EXPECT_EQ(law->maxCoefficient(1.0), 0.0);
}

// ---- Stribeck ----------------------------------------------------------------------------

std::unique_ptr<const FrictionLaw> stribeck(double viscous, double delta = 2.0) {
  return makeFrictionLaw(
      {"stribeck",
       {{"mu_s", kMuS}, {"mu_k", kMuK}, {"v_st", 0.1}, {"viscous", viscous}, {"delta", delta}},
       {}});
}

TEST(FrictionStribeck, ValuesOnceTheRegularizationHasSaturated) {
  // tanh(v / 1e-4) == 1 in double precision for v >= 0.01.
  const auto law = stribeck(0.01);
  EXPECT_NEAR(law->coefficient(0.1), kMuK + (kMuS - kMuK) / std::numbers::e + 0.001, 1e-15);
  EXPECT_NEAR(law->coefficient(3.0), kMuK + 0.03, 1e-15);
  EXPECT_NEAR(law->coefficient(-3.0), -kMuK - 0.03, 1e-15);
  EXPECT_NEAR(stribeck(0.0, 1.0)->coefficient(0.2), kMuK + (kMuS - kMuK) * std::exp(-2.0), 1e-15);
  EXPECT_EQ(law->stickSpeed(), 1e-4);
  EXPECT_TRUE(law->breakpoints().empty());
}

TEST(FrictionStribeck, MaxCoefficientIncludesTheViscousTerm) {
  const auto law = stribeck(0.01);
  // At 100 m/s the viscous term dominates: mu = 0.3 + 1.0.
  EXPECT_GE(law->maxCoefficient(100.0), 1.3);
  EXPECT_NEAR(law->maxCoefficient(100.0), 1.3, 1e-6 * 1.3);
  // Without it the largest value is just under mu_s, near the end of the tanh ramp.
  const double peak = stribeck(0.0)->maxCoefficient(3.0);
  EXPECT_LE(peak, kMuS * (1.0 + 1e-6));
  EXPECT_GT(peak, kMuS * 0.999);
  EXPECT_EQ(law->maxCoefficient(std::numeric_limits<double>::infinity()),
            std::numeric_limits<double>::infinity());
  const double sup = stribeck(0.0)->maxCoefficient(std::numeric_limits<double>::infinity());
  EXPECT_NEAR(sup, peak, 1e-6 * peak);
}

TEST(FrictionStribeck, DefaultShapeIsGaussian) {
  const auto defaults =
      makeFrictionLaw({"stribeck", {{"mu_s", kMuS}, {"mu_k", kMuK}, {"v_st", 0.1}}, {}});
  const auto explicit_two = stribeck(0.0, 2.0);
  const auto near_two = stribeck(0.0, 2.0 + 1e-12);  // the general pow path
  for (const double v : {1e-5, 1e-3, 0.05, 0.1, 0.3}) {
    EXPECT_EQ(defaults->coefficient(v), explicit_two->coefficient(v)) << v;
    EXPECT_NEAR(near_two->coefficient(v), explicit_two->coefficient(v), 1e-12) << v;
    EXPECT_NEAR(near_two->slope(v), explicit_two->slope(v),
                1e-9 * (1.0 + std::abs(explicit_two->slope(v))))
        << v;
  }
}

}  // namespace
}  // namespace tribo::friction
