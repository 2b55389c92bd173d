// Normal-force laws: values, no pulling, parameter checks, and the Hunt-Crossley restitution
// relation against a direct integration of one impact (an independent reference).
#include "contact/normal_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tribo::contact {
namespace {

// Restitution of one impact m d'' = -F(d, d') at speed v_in, integrated with RK4 at a step
// far below the contact time (the reference the closed form must meet).
double integratedRestitution(const NormalLaw& law, double m, double v_in) {
  double d = 0.0, v = v_in;
  const double h = 1e-7;
  auto acc = [&](double dd, double vv) { return -law.force(dd, vv) / m; };
  for (long i = 0; i < 100000000; ++i) {
    const double k1v = acc(d, v), k1d = v;
    const double k2v = acc(d + 0.5 * h * k1d, v + 0.5 * h * k1v), k2d = v + 0.5 * h * k1v;
    const double k3v = acc(d + 0.5 * h * k2d, v + 0.5 * h * k2v), k3d = v + 0.5 * h * k2v;
    const double k4v = acc(d + h * k3d, v + h * k3v), k4d = v + h * k3v;
    const double d_next = d + h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d);
    const double v_next = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (d_next <= 0.0 && v_next < 0.0) {
      // Interpolate the exit speed at d = 0 (the last fraction of a step).
      const double s = d / (d - d_next);
      return -(v + s * (v_next - v)) / v_in;
    }
    d = d_next;
    v = v_next;
  }
  return std::nan("");
}

TEST(NormalLaw, ValuesOfEachLaw) {
  const NormalLaw linear{NormalLawType::kLinear, 1e5, 1e3};
  EXPECT_DOUBLE_EQ(linear.force(1e-3, 0.05), 150.0);
  const NormalLaw hertz{NormalLawType::kHertz, 1e9, 0.0};
  EXPECT_NEAR(hertz.force(1e-4, 123.0), 1e9 * 1e-6, 1e-6);  // rate-independent
  const NormalLaw hc{NormalLawType::kHuntCrossley, 1e7, 0.2, 1.5};
  EXPECT_NEAR(hc.force(1e-4, 0.5), 1e7 * std::pow(1e-4, 1.5) * 1.1, 1e-9);
  NormalLaw rd{NormalLawType::kRecurDyn, 1e6, 50.0, 1.2, 1e-3};
  // Damping ramps in by the haversine step: none at the surface, half at d_max / 2, full
  // from d_max on.
  EXPECT_NEAR(rd.force(1e-5, 1.0),
              1e6 * std::pow(1e-5, 1.2) + 50.0 * std::pow(std::sin(std::numbers::pi / 2 * 1e-2), 2),
              1e-9);
  EXPECT_NEAR(rd.force(5e-4, 1.0), 1e6 * std::pow(5e-4, 1.2) + 25.0, 1e-9);
  EXPECT_NEAR(rd.force(2e-3, 1.0), 1e6 * std::pow(2e-3, 1.2) + 50.0, 1e-9);
}

TEST(NormalLaw, NoLawPulls) {
  const std::vector<NormalLaw> laws{{NormalLawType::kLinear, 1e5, 1e3},
                                    {NormalLawType::kHertz, 1e9, 0.0},
                                    {NormalLawType::kHuntCrossley, 1e7, 0.5, 1.5},
                                    {NormalLawType::kRecurDyn, 1e6, 1e4, 1.5, 1e-4}};
  for (const auto& law : laws) {
    for (double d : {-1e-3, 0.0, 1e-6, 1e-4, 1e-2})
      for (double rate : {-100.0, -1.0, 0.0, 1.0}) {
        EXPECT_GE(law.force(d, rate), 0.0) << normalLawName(law.type);
        if (d <= 0.0) {
          EXPECT_EQ(law.force(d, rate), 0.0);
        }
      }
  }
}

TEST(NormalLaw, ParametersAreChecked) {
  auto message = [](const NormalLaw& law) {
    try {
      law.validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({NormalLawType::kLinear, -1.0})
                .find("normal law: stiffness must be > 0 (got -1.000000, law linear)"),
            std::string::npos);
  EXPECT_NE(message({NormalLawType::kHertz, 1e9, 5.0}).find("damping must be 0 (Hertz is elastic"),
            std::string::npos);
  EXPECT_NE(message({NormalLawType::kHuntCrossley, 1e9, 0.1, 0.5}).find("exponent must be >= 1"),
            std::string::npos);
  EXPECT_NE(message({NormalLawType::kRecurDyn, 1e9, 0.1, 1.5, 0.0}).find("max_depth must be > 0"),
            std::string::npos);
  EXPECT_EQ(message({NormalLawType::kRecurDyn, 1e9, 0.1, 1.5, 1e-4}), "");
  EXPECT_EQ(normalLawFromName("hertz"), NormalLawType::kHertz);
  EXPECT_EQ(normalLawFromName("recurdyn"), NormalLawType::kRecurDyn);
  EXPECT_THROW(normalLawFromName("hertzian"), std::invalid_argument);
}

TEST(HuntCrossley, RestitutionRelationMatchesADirectIntegrationOfTheImpact) {
  // Any mass, stiffness and exponent: e depends on alpha v_in alone.
  for (double e : {0.3, 0.6, 0.8, 0.95}) {
    for (double v_in : {0.5, 3.0}) {
      const double alpha = huntCrossleyDamping(e, v_in);
      EXPECT_NEAR(huntCrossleyRestitution(alpha * v_in), e, 1e-12);
      for (double p : {1.0, 1.5}) {
        const NormalLaw law{NormalLawType::kHuntCrossley, p == 1.0 ? 1e5 : 1e7, alpha, p};
        EXPECT_NEAR(integratedRestitution(law, 0.7, v_in), e, 2e-6)
            << "e " << e << " v_in " << v_in << " p " << p;
      }
    }
  }
}

TEST(HuntCrossley, NearlyElasticImpactsFollowHuntAndCrossleysLinearization) {
  // alpha ~ 3 (1 - e) / (2 v_in) as e -> 1, with an error of order (1 - e)^2.
  for (double e : {0.99, 0.999}) {
    const double alpha = huntCrossleyDamping(e, 2.0);
    const double linear = 3 * (1 - e) / (2 * 2.0);
    EXPECT_NEAR(alpha / linear, 1.0, 2 * (1 - e));
  }
  EXPECT_EQ(huntCrossleyDamping(1.0, 2.0), 0.0);
  EXPECT_THROW(huntCrossleyDamping(0.0, 2.0), std::invalid_argument);
  EXPECT_THROW(huntCrossleyDamping(0.5, 0.0), std::invalid_argument);
}

TEST(Hertz, ElasticImpactReturnsAllItsEnergyAndStiffnessFollowsTheMaterials) {
  const NormalLaw law{NormalLawType::kHertz, 1e9, 0.0};
  EXPECT_NEAR(integratedRestitution(law, 0.5, 1.0), 1.0, 1e-6);
  // Steel ball (R = 10 mm) on a steel plane: E* = E / (2 (1 - nu^2)), k = 4/3 E* sqrt(R).
  const double e_star = 210e9 / (2 * (1 - 0.09));
  EXPECT_NEAR(hertzStiffness(210e9, 0.3, 210e9, 0.3, 0.01, INFINITY) /
                  (4.0 / 3.0 * e_star * std::sqrt(0.01)),
              1.0, 1e-14);
  EXPECT_THROW(hertzStiffness(210e9, 0.3, 210e9, 0.3, INFINITY, INFINITY), std::invalid_argument);
}

TEST(NormalLaw, EnergyIsTheIntegralOfTheElasticForce) {
  for (const NormalLaw& law :
       {NormalLaw{NormalLawType::kLinear, 1e5}, NormalLaw{NormalLawType::kHertz, 1e9, 0.0},
        NormalLaw{NormalLawType::kHuntCrossley, 1e7, 0.0, 1.3}}) {
    const double d = 2e-4;
    double integral = 0.0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) integral += law.force((i + 0.5) * d / n, 0.0) * d / n;
    EXPECT_NEAR(law.energy(d) / integral, 1.0, 1e-8) << normalLawName(law.type);
  }
}

// The exponent the energy guard and the stability estimate use is the force's own: the
// elastic force at rest, F(d) = k d^p, gives p = ln(F(d2) / F(d1)) / ln(d2 / d1), for every
// law (hertz ignores the `exponent` field, whatever it holds).
TEST(NormalLaw, ElasticExponentIsTheSlopeOfTheForceOnLogAxes) {
  for (const NormalLaw& law : {NormalLaw{NormalLawType::kLinear, 1e5, 10.0, 2.7},
                               NormalLaw{NormalLawType::kHertz, 1e9, 0.0, 2.7},
                               NormalLaw{NormalLawType::kHuntCrossley, 1e7, 0.3, 1.3},
                               NormalLaw{NormalLawType::kRecurDyn, 1e7, 50.0, 2.2, 1e-4}}) {
    for (double d1 : {1e-7, 1e-5, 1e-3}) {
      const double d2 = 3.0 * d1;
      const double slope = std::log(law.force(d2, 0.0) / law.force(d1, 0.0)) / std::log(3.0);
      EXPECT_NEAR(law.elasticExponent(), slope, 1e-12) << normalLawName(law.type) << " at " << d1;
    }
  }
}

}  // namespace
}  // namespace tribo::contact
