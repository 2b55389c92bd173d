// Parameter errors of the dynamic laws: each rule throws FrictionParameterError naming the law,
// the key, the rule and the value; unknown keys and options list the accepted ones; every
// default spec is accepted; non-finite values are rejected for every key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "friction/friction_law.hpp"
#include "friction/gms_law.hpp"
#include "friction/rate_state_law.hpp"

namespace tribo::friction {
namespace {

using testing::HasSubstr;

std::string errorFor(const LawSpec& spec) {
  try {
    makeFrictionLaw(spec);
  } catch (const FrictionParameterError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no FrictionParameterError for " << spec.name;
  return "";
}

LawSpec with(const std::string& name, const std::string& key, double value) {
  return {name, {{key, value}}, {}};
}

TEST(DynamicLawParameters, DefaultsAreAccepted) {
  for (const std::string& name : knownDynamicFrictionLaws())
    EXPECT_NO_THROW(makeFrictionLaw({name, {}, {}})) << name;
}

TEST(DynamicLawParameters, EveryKeyMustBeFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::map<std::string, std::vector<std::string>> keys = {
      {"dahl", {"sigma0", "mu_c", "alpha"}},
      {"elasto_plastic", {"sigma0", "sigma1", "sigma2", "mu_c", "mu_s", "v_s", "z_ba_fraction"}},
      {"gms", {"stiffness", "mu_c", "mu_s", "v_s", "delta", "attraction", "sigma1", "sigma2"}},
      {"rate_state", {"mu0", "a", "b", "d_c", "v0", "theta0"}}};
  for (const auto& [name, list] : keys) {
    for (const std::string& key : list) {
      for (const double bad : {nan, inf, -inf}) {
        EXPECT_THAT(errorFor(with(name, key, bad)), HasSubstr(name + ": " + key + " must be"))
            << key << " = " << bad;
      }
    }
  }
  EXPECT_THAT(errorFor(with("gms", "elements", nan)), HasSubstr("gms: elements must be"));
}

TEST(DynamicLawParameters, DahlRules) {
  EXPECT_EQ(errorFor(with("dahl", "sigma0", 0.0)), "dahl: sigma0 must be > 0 [1/m] (got 0)");
  EXPECT_EQ(errorFor(with("dahl", "mu_c", -0.1)), "dahl: mu_c must be > 0 (got -0.1)");
  EXPECT_EQ(errorFor(with("dahl", "alpha", 0.5)), "dahl: alpha must be >= 1 (got 0.5)");
  EXPECT_THAT(errorFor(with("dahl", "mu_s", 1.0)), HasSubstr("dahl: unknown key 'mu_s'"));
  EXPECT_THAT(errorFor(with("dahl", "mu_s", 1.0)), HasSubstr("accepted keys: sigma0, mu_c, alpha"));
}

TEST(DynamicLawParameters, ElastoPlasticRules) {
  const std::string name = "elasto_plastic";
  EXPECT_EQ(errorFor(with(name, "sigma0", -1.0)),
            "elasto_plastic: sigma0 must be > 0 [1/m] (got -1)");
  EXPECT_THAT(errorFor(with(name, "sigma1", -1.0)),
              HasSubstr("sigma1 must be >= 0 [s/m] (got -1)"));
  EXPECT_THAT(errorFor(with(name, "sigma2", -1.0)),
              HasSubstr("sigma2 must be >= 0 [s/m] (got -1)"));
  EXPECT_THAT(errorFor(with(name, "mu_s", 0.5)),
              HasSubstr("mu_s must be >= mu_c (got mu_s = 0.5, mu_c = 1)"));
  EXPECT_THAT(errorFor(with(name, "v_s", 0.0)), HasSubstr("v_s must be > 0 [m/s] (got 0)"));
  for (const double bad : {0.0, 1.0, 1.2, -0.5}) {
    EXPECT_THAT(errorFor(with(name, "z_ba_fraction", bad)),
                HasSubstr("elasto_plastic: z_ba_fraction must be in (0, 1)"));
  }
  EXPECT_NO_THROW(makeFrictionLaw(with(name, "z_ba_fraction", 0.999)));
}

TEST(DynamicLawParameters, GmsRules) {
  EXPECT_THAT(errorFor(with("gms", "elements", 0.0)),
              HasSubstr("gms: elements must be an integer in 1..8 (got 0)"));
  EXPECT_THAT(errorFor(with("gms", "elements", 2.5)), HasSubstr("(got 2.5)"));
  EXPECT_THAT(errorFor(with("gms", "elements", 9.0)), HasSubstr("(got 9)"));
  EXPECT_THAT(errorFor(with("gms", "stiffness", 0.0)), HasSubstr("gms: stiffness must be > 0"));
  EXPECT_THAT(errorFor(with("gms", "delta", 0.0)), HasSubstr("gms: delta must be > 0"));
  EXPECT_THAT(errorFor(with("gms", "attraction", 0.0)),
              HasSubstr("gms: attraction must be > 0 [1/s] (got 0)"));
  EXPECT_THAT(errorFor(with("gms", "mu_s", 0.9)), HasSubstr("mu_s must be >= mu_c"));
  // Per-element keys: all of 1..N or none, none beyond N, alphas summing to 1.
  EXPECT_THAT(errorFor({"gms", {{"elements", 2.0}, {"k_1", 1e5}}, {}}),
              HasSubstr("gms: missing k_2: give k_1..k_N for all N = 2 elements or none"));
  EXPECT_THAT(errorFor({"gms", {{"elements", 2.0}, {"k_3", 1e5}}, {}}),
              HasSubstr("gms: k_3 given for 2 elements"));
  EXPECT_THAT(errorFor({"gms", {{"elements", 1.0}, {"k_1", 1e5}, {"stiffness", 1e5}}, {}}),
              HasSubstr("gms: give stiffness or k_1..k_N, not both"));
  EXPECT_THAT(errorFor({"gms", {{"elements", 2.0}, {"alpha_1", 0.5}, {"alpha_2", 0.6}}, {}}),
              HasSubstr("gms: alpha_1..alpha_N must sum to 1 (got 1.1)"));
  EXPECT_THAT(errorFor({"gms", {{"elements", 2.0}, {"alpha_1", 1.5}, {"alpha_2", -0.5}}, {}}),
              HasSubstr("gms: alpha_2 must be > 0 (got -0.5)"));
  EXPECT_THAT(errorFor({"gms", {{"elements", 2.0}, {"k_1", 1e5}, {"k_2", 0.0}}, {}}),
              HasSubstr("gms: k_2 must be > 0 [1/m] (got 0)"));
  EXPECT_THAT(errorFor(with("gms", "k_9", 1.0)), HasSubstr("gms: unknown key 'k_9'"));
  EXPECT_NO_THROW(
      makeFrictionLaw({"gms", {{"elements", 2.0}, {"alpha_1", 0.25}, {"alpha_2", 0.75}}, {}}));
  // Direct construction checks the vectors' sizes.
  GmsParams p;
  p.elements = 3;
  p.k = {1.0, 2.0};
  EXPECT_THROW(GmsLaw{p}, FrictionParameterError);
}

TEST(DynamicLawParameters, RateStateRules) {
  EXPECT_EQ(errorFor(with("rate_state", "a", 0.0)), "rate_state: a must be > 0 (got 0)");
  EXPECT_EQ(errorFor(with("rate_state", "b", -0.01)), "rate_state: b must be >= 0 (got -0.01)");
  EXPECT_EQ(errorFor(with("rate_state", "mu0", -0.6)), "rate_state: mu0 must be >= 0 (got -0.6)");
  EXPECT_EQ(errorFor(with("rate_state", "d_c", 0.0)), "rate_state: d_c must be > 0 [m] (got 0)");
  EXPECT_EQ(errorFor(with("rate_state", "v0", -1.0)), "rate_state: v0 must be > 0 [m/s] (got -1)");
  EXPECT_EQ(errorFor(with("rate_state", "theta0", 0.0)),
            "rate_state: theta0 must be > 0 [s] (got 0)");
  LawSpec spec{"rate_state", {}, {{"evolution", "ruina"}}};
  EXPECT_EQ(errorFor(spec), "rate_state: evolution must be one of aging, slip (got 'ruina')");
  spec.options = {{"law", "slip"}};
  EXPECT_THAT(errorFor(spec), HasSubstr("rate_state: unknown option 'law'"));
  EXPECT_THAT(errorFor(spec), HasSubstr("options: evolution"));
  EXPECT_NO_THROW(makeFrictionLaw({"rate_state", {}, {{"evolution", "aging"}}}));
  EXPECT_THROW(RateStateLaw({.mu0 = 0.6, .a = 0.01, .b = 0.01, .d_c = -1.0}),
               FrictionParameterError);
}

TEST(DynamicLawParameters, UnknownLawListsTheDynamicOnes) {
  const std::string message = errorFor({"karnopp", {}, {}});
  EXPECT_THAT(message, HasSubstr("unknown friction law 'karnopp'"));
  EXPECT_THAT(message, HasSubstr("lugre, dahl, elasto_plastic, gms, rate_state"));
}

}  // namespace
}  // namespace tribo::friction
