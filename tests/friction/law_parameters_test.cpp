// Parameter errors: each rule throws FrictionParameterError naming the law, the key and the
// value found; unknown and missing keys list the accepted keys; unknown laws list the known.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <string>
#include <vector>

#include "friction/friction_law.hpp"
#include "friction/roh_yoo_law.hpp"
#include "support/table1_laws.hpp"

namespace tribo::friction {
namespace {

using test::table1;

LawSpec with(const std::string& name, const std::string& key, double value) {
  LawSpec spec = table1(name);
  spec.values[key] = value;
  return spec;
}

LawSpec without(const std::string& name, const std::string& key) {
  LawSpec spec = table1(name);
  spec.values.erase(key);
  return spec;
}

// The message of the FrictionParameterError thrown for spec ("" and a failure if none).
std::string errorFor(const LawSpec& spec) {
  try {
    makeFrictionLaw(spec);
  } catch (const FrictionParameterError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no FrictionParameterError for " << spec.name;
  return "";
}

using testing::HasSubstr;

TEST(FrictionParameters, Table1SpecsAreAccepted) {
  for (const std::string& name : knownFrictionLaws()) {
    EXPECT_NO_THROW(makeFrictionLaw(table1(name))) << name;
  }
}

TEST(FrictionParameters, RohYooNeedsABaseAboveOne) {
  EXPECT_EQ(errorFor(with("roh_yoo", "a", 0.9)), "roh_yoo: a must be > 1 (got 0.9)");
  EXPECT_THAT(errorFor(with("roh_yoo", "a", 1.0)), HasSubstr("a must be > 1 (got 1)"));
}

TEST(FrictionParameters, RohYooNeedsMuSAboveMuK) {
  const std::string message = errorFor(with("roh_yoo", "mu_k", 0.35));
  EXPECT_THAT(message, HasSubstr("roh_yoo: mu_s must exceed mu_k for roh_yoo"));
  EXPECT_THAT(message, HasSubstr("mu_s = 0.35, mu_k = 0.35"));
  EXPECT_THAT(errorFor(with("roh_yoo", "mu_k", 0.4)), HasSubstr("mu_s must exceed mu_k"));
}

TEST(FrictionParameters, OtherRohYooRules) {
  EXPECT_THAT(errorFor(with("roh_yoo", "beta", 0.0)), HasSubstr("beta must be > 0 (got 0)"));
  EXPECT_THAT(errorFor(with("roh_yoo", "v_s", -0.01)), HasSubstr("v_s must be > 0 (got -0.01)"));
  EXPECT_THAT(errorFor(with("roh_yoo", "mu_k", -0.1)), HasSubstr("mu_k must be >= 0"));
}

TEST(FrictionParameters, StepLawsNeedVsBelowVd) {
  for (const std::string name : {"recurdyn", "adams"}) {
    const std::string message = errorFor(with(name, "v_s", 0.15));
    EXPECT_THAT(message, HasSubstr(name + ": v_d must be > v_s"));
    EXPECT_THAT(message, HasSubstr("v_s = 0.15, v_d = 0.15"));
    EXPECT_THAT(errorFor(with(name, "v_s", 0.0)), HasSubstr("v_s must be > 0"));
  }
}

TEST(FrictionParameters, StepLawsNeedMuSAtLeastMuK) {
  for (const std::string name : {"recurdyn", "adams"}) {
    EXPECT_THAT(errorFor(with(name, "mu_k", 0.4)),
                HasSubstr("mu_s must be >= mu_k (got mu_s = 0.35, mu_k = 0.4)"));
    EXPECT_THAT(errorFor(with(name, "mu_k", -0.3)), HasSubstr("mu_k must be >= 0 (got -0.3)"));
    EXPECT_NO_THROW(makeFrictionLaw(with(name, "mu_k", 0.35)));  // equal is fine
  }
}

TEST(FrictionParameters, NegativeCoefficients) {
  EXPECT_EQ(errorFor(with("coulomb", "mu", -0.1)), "coulomb: mu must be >= 0 (got -0.1)");
  EXPECT_THAT(errorFor(with("coulomb", "v_eps", 0.0)), HasSubstr("v_eps must be > 0"));
  EXPECT_THAT(errorFor(with("stribeck", "mu_k", -0.1)), HasSubstr("mu_k must be >= 0"));
  EXPECT_THAT(errorFor(with("stribeck", "viscous", -0.01)),
              HasSubstr("viscous must be >= 0 (got -0.01)"));
}

TEST(FrictionParameters, StribeckRules) {
  EXPECT_THAT(errorFor(with("stribeck", "mu_k", 0.4)), HasSubstr("mu_s must be >= mu_k"));
  EXPECT_THAT(errorFor(with("stribeck", "v_st", 0.0)), HasSubstr("v_st must be > 0"));
  EXPECT_THAT(errorFor(with("stribeck", "delta", -2.0)), HasSubstr("delta must be > 0"));
  EXPECT_THAT(errorFor(with("stribeck", "v_eps", -1e-4)), HasSubstr("v_eps must be > 0"));
}

TEST(FrictionParameters, NonFiniteValuesAreRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const std::string& name : knownFrictionLaws()) {
    for (const auto& [key, value] : table1(name).values) {
      for (const double bad : {nan, inf, -inf}) {
        const std::string message = errorFor(with(name, key, bad));
        EXPECT_THAT(message, HasSubstr(name + ": " + key + " must be a finite number"));
      }
    }
  }
  EXPECT_THAT(errorFor(with("roh_yoo", "a", nan)), HasSubstr("(got nan)"));
}

TEST(FrictionParameters, UnknownKeyNamesTheKeyAndTheAcceptedOnes) {
  const std::string message = errorFor(with("roh_yoo", "alpha", 1.0));
  EXPECT_THAT(message, HasSubstr("roh_yoo: unknown key 'alpha'"));
  EXPECT_THAT(message, HasSubstr("accepted keys: mu_s, mu_k, v_s, a, beta"));
  EXPECT_THAT(errorFor(with("coulomb", "mu_s", 0.3)), HasSubstr("unknown key 'mu_s'"));
  EXPECT_THAT(errorFor(with("recurdyn", "a", 1.5)), HasSubstr("recurdyn: unknown key 'a'"));
}

TEST(FrictionParameters, MissingKeyIsNamed) {
  for (const std::string& name : knownFrictionLaws()) {
    for (const auto& [key, value] : table1(name).values) {
      if (key == "viscous") continue;  // optional
      EXPECT_THAT(errorFor(without(name, key)),
                  HasSubstr(name + ": missing required key '" + key + "'"));
    }
  }
}

TEST(FrictionParameters, OptionsAreChecked) {
  LawSpec spec = table1("coulomb");
  spec.options["regularization"] = "cubic";
  EXPECT_THAT(errorFor(spec),
              HasSubstr("regularization must be one of none, linear, tanh, havsin (got 'cubic')"));
  spec.options = {{"smoothing", "tanh"}};
  EXPECT_THAT(errorFor(spec), HasSubstr("coulomb: unknown option 'smoothing'"));
  LawSpec roh_yoo = table1("roh_yoo");
  roh_yoo.options["regularization"] = "tanh";
  EXPECT_THAT(errorFor(roh_yoo), HasSubstr("roh_yoo: unknown option 'regularization'"));
}

TEST(FrictionParameters, UnknownLawListsTheKnownOnes) {
  const std::string message = errorFor({"karnopp", {}, {}});
  EXPECT_THAT(message, HasSubstr("unknown friction law 'karnopp'"));
  EXPECT_THAT(message, HasSubstr("coulomb, recurdyn, adams, roh_yoo, stribeck, elastic_stick, "
                                 "lugre, dahl, elasto_plastic, gms, rate_state)"));
}

// The three name lists come from one table: no law in two of them, and each law's kind is
// what its list says (memoryless: neither stateful nor dynamic).
TEST(FrictionParameters, EachLawIsInTheListOfItsKind) {
  std::set<std::string> seen;
  for (const auto* list :
       {&knownFrictionLaws(), &knownStatefulFrictionLaws(), &knownDynamicFrictionLaws()})
    for (const std::string& name : *list) EXPECT_TRUE(seen.insert(name).second) << name;
  EXPECT_EQ(seen.size(), 11u);
  for (const std::string& name : knownStatefulFrictionLaws()) {
    const auto law =
        makeFrictionLaw({name, {{"mu_s", 0.5}, {"mu_k", 0.4}, {"stiffness", 1e5}}, {}});
    EXPECT_TRUE(law->stateful()) << name;
    EXPECT_EQ(law->dynamic(), nullptr) << name;
  }
  for (const std::string& name : knownDynamicFrictionLaws()) {
    const auto law = makeFrictionLaw({name, {}, {}});  // every dynamic law has defaults
    EXPECT_FALSE(law->stateful()) << name;
    EXPECT_NE(law->dynamic(), nullptr) << name;
  }
  for (const std::string& name : knownFrictionLaws()) {
    const auto law = makeFrictionLaw(table1(name));
    EXPECT_FALSE(law->stateful()) << name;
    EXPECT_EQ(law->dynamic(), nullptr) << name;
  }
}

TEST(FrictionParameters, DirectConstructionValidatesToo) {
  EXPECT_THROW(RohYooLaw({.mu_s = 0.35, .mu_k = 0.3, .v_s = 0.01, .a = 0.5, .beta = 1.0}),
               FrictionParameterError);
}

}  // namespace
}  // namespace tribo::friction
