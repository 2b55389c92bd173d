// The batched tangential forces (friction/tangential_batch.hpp) against the point-by-point
// tangentialForce (friction/friction_law.hpp), bit for bit, and against the law itself
// (magnitude mu(|s|) fn, opposing the slip): every law the factory knows (the
// memoryless ones with the paper's Table 1 values, every coulomb regularization, tiny and
// large transition speeds; the dynamic ones through their steady curve), a tabulated law and a
// law that keeps the default coefficientsAt (a virtual call per speed). Random slips in every
// direction with speeds from 1e-12 to 1e3 m/s, exact zeros among them and runs of five equal
// slips (the points of a body that translates), loads from 1e-6 to 1e6 N, batches of 1, 7,
// 255 and 256 points. And a run of equal speeds asks the law once (coefficientsOf).
#include "friction/tangential_batch.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "friction/tabulated_law.hpp"
#include "support/same_bits.hpp"
#include "support/table1_laws.hpp"

namespace tribo::friction {
namespace {

struct BatchCase {
  std::string label;
  std::shared_ptr<const FrictionLaw> law;
};

void PrintTo(const BatchCase& c, std::ostream* os) { *os << c.label; }

// A law whose coefficientsAt is FrictionLaw's default (as a law written outside this folder).
class DefaultBatchLaw final : public FrictionLaw {
 public:
  double coefficient(double v) const override { return 0.4 * v / (std::abs(v) + 0.02); }
  double slope(double v) const override { return 0.4 * 0.02 / std::pow(std::abs(v) + 0.02, 2); }
  double maxCoefficient(double v_max) const override { return std::abs(coefficient(v_max)); }
  double stickSpeed() const override { return 0.02; }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return "default_batch"; }
};

std::vector<BatchCase> allCases() {
  std::vector<BatchCase> cases;
  for (const std::string& name : knownFrictionLaws())
    cases.push_back({name, makeFrictionLaw(test::table1(name))});
  for (const std::string r : {"none", "linear", "tanh", "havsin"})
    for (const double v_eps : {1e-9, 1e-4, 0.5})
      cases.push_back(
          {"coulomb_" + r + "_" + std::to_string(v_eps),
           makeFrictionLaw({"coulomb", {{"mu", 0.3}, {"v_eps", v_eps}}, {{"regularization", r}}})});
  cases.push_back(
      {"roh_yoo_sharp",
       makeFrictionLaw({"roh_yoo",
                        {{"mu_s", 0.5}, {"mu_k", 0.2}, {"v_s", 1e-7}, {"a", 3.0}, {"beta", 0.5}},
                        {}})});
  for (const std::string& name : knownDynamicFrictionLaws())
    cases.push_back({name + "_steady", makeFrictionLaw({name, {}, {}})});
  cases.push_back(
      {"tabulated", std::make_shared<TabulatedLaw>(std::vector<double>{1e-3, 0.01, 0.1, 1.0},
                                                   std::vector<double>{0.2, 0.45, 0.3, 0.25})});
  cases.push_back({"default_batch", std::make_shared<DefaultBatchLaw>()});
  return cases;
}

using test::sameBits;

class TangentialBatchLaws : public testing::TestWithParam<BatchCase> {};

TEST_P(TangentialBatchLaws, EveryPointIsTangentialForceBitForBit) {
  const FrictionLaw& law = *GetParam().law;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), decade(-12.0, 3.0), load(-6.0, 6.0);
  TangentialBatch batch;
  for (const std::size_t size : {1u, 7u, 255u, 256u}) {
    for (int round = 0; round < 8; ++round) {
      std::vector<Eigen::Vector3d> slips(size);
      std::vector<double> fn(size);
      batch.clear();
      for (std::size_t k = 0; k < size; ++k) {
        Eigen::Vector3d direction(unit(rng), unit(rng), unit(rng));
        if (k % 3 == 0) direction.z() = 0.0;  // in a horizontal tangent plane
        slips[k] = k % 11 == 5
                       ? Eigen::Vector3d::Zero()
                       : Eigen::Vector3d(direction.normalized() * std::pow(10.0, decade(rng)));
        if (k % 13 >= 9) slips[k] = slips[k - 1];  // runs of five equal slips
        fn[k] = std::pow(10.0, load(rng));
        batch.add(slips[k]);
      }
      ASSERT_EQ(batch.full(), size == TangentialBatch::kCapacity);
      batch.evaluate(law);
      for (std::size_t k = 0; k < size; ++k) {
        double mu_batch = -1.0, mu = -1.0;
        const Eigen::Vector3d b = batch.force(k, slips[k], fn[k], &mu_batch);
        const Eigen::Vector3d f = tangentialForce(law, slips[k], fn[k], &mu);
        ASSERT_TRUE(sameBits(b.x(), f.x()) && sameBits(b.y(), f.y()) && sameBits(b.z(), f.z()) &&
                    sameBits(mu_batch, mu))
            << "point " << k << " of " << size << ": slip " << slips[k].transpose() << ", fn "
            << fn[k] << ": batch " << b.transpose() << " mu " << mu_batch << ", point by point "
            << f.transpose() << " mu " << mu;
        // And the force is the law's: magnitude mu fn against the slip (independent of both
        // code paths' shared pieces).
        if (slips[k].norm() > 0.0) {
          const double expected = law.coefficient(slips[k].norm()) * fn[k];
          EXPECT_NEAR(b.norm(), std::abs(expected), 1e-12 * std::abs(expected) + 1e-300) << k;
          EXPECT_LE(b.dot(slips[k]), 0.0) << k;
        } else {
          EXPECT_EQ(b.norm(), 0.0);
          EXPECT_EQ(mu_batch, 0.0);
        }
      }
    }
  }
}

TEST_P(TangentialBatchLaws, CoefficientsAtAreTheCoefficientsExceptAtZero) {
  const FrictionLaw& law = *GetParam().law;
  std::vector<double> v = {0.0, -0.0, 1e-12, -1e-9, -1e-9, 1e-4, -0.01, 0.3,
                           0.3, 0.3,  -2.0,  0.0,   -2.0,  -2.0, 1e3,   1e3};
  std::vector<double> mu(v.size(), -7.0);
  law.coefficientsAt(v, mu);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] == 0.0)
      EXPECT_EQ(mu[i], 0.0) << i;
    else
      EXPECT_TRUE(sameBits(mu[i], law.coefficient(v[i]))) << "v " << v[i];
  }
}

// A law of this folder's kind (its coefficientsAt is coefficientsOf) that counts its calls.
class CountedLaw final : public FrictionLaw {
 public:
  double coefficient(double v) const override {
    ++calls;
    return 0.5 * v / (std::abs(v) + 1e-3);
  }
  void coefficientsAt(std::span<const double> v, std::span<double> mu) const override {
    coefficientsOf(*this, v, mu);
  }
  double slope(double) const override { return 0.0; }
  double maxCoefficient(double) const override { return 0.5; }
  double stickSpeed() const override { return 1e-3; }
  std::vector<double> breakpoints() const override { return {}; }
  std::string_view name() const override { return "counted"; }
  mutable int calls = 0;
};

TEST(CoefficientsOf, ARunOfEqualSpeedsAsksTheLawOnceAndGivesItsCoefficientToEach) {
  // A box's four corners sliding alike, then a different speed, the first again (a new run),
  // a zero between two equal speeds (each side its own run), a pair, and -0.5 after 0.5.
  const std::vector<double> v = {0.25, 0.25, 0.25, 0.25, 1e-6, 0.25,
                                 0.0,  0.25, 2.0,  2.0,  0.5,  -0.5};
  std::vector<double> mu(v.size(), -1.0);
  const CountedLaw law;
  law.coefficientsAt(v, mu);
  EXPECT_EQ(law.calls, 7);  // 0.25, 1e-6, 0.25, 0.25, 2.0, 0.5, -0.5; 0 never asked
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double expected = v[i] == 0.0 ? 0.0 : 0.5 * v[i] / (std::abs(v[i]) + 1e-3);
    EXPECT_TRUE(sameBits(mu[i], expected)) << "v " << v[i] << ": " << mu[i];
  }
}

INSTANTIATE_TEST_SUITE_P(AllLaws, TangentialBatchLaws, testing::ValuesIn(allCases()),
                         [](const testing::TestParamInfo<BatchCase>& info) {
                           std::string name = info.param.label;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace tribo::friction
