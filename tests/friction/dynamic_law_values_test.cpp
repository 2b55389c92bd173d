// Closed-form and published behaviour of the dynamic friction laws, each problem set up and
// integrated here (RK4 written in the test, dynamic_law_support.hpp):
//   lugre           presliding under a slow force ramp: x = -(mu_s / sigma0) ln(1 - F / (mu_s F_n))
//   dahl            energy per cycle of x = +-X: 4 F_c X - (4 F_c^2 / (sigma0 F_n)) tanh(sigma0 X /
//                   mu_c) (alpha = 1); virgin curve for alpha = 2
//   elasto_plastic  no drift under an oscillating sub-break-away load on a 1-DOF mass, where
//                   lugre drifts
//   gms             virgin curve sum_i min(k_i x, alpha_i S(v)) and Masing unloading
//   rate_state      velocity step V1 -> V2: direct effect a ln(V2 / V1), steady shift (a - b)
//                   ln(V2 / V1) (aging and slip); theta's closed-form evolution; healing at rest
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "dynamic_law_support.hpp"
#include "friction/friction_law.hpp"
#include "friction/rate_state_law.hpp"

namespace tribo::friction {
namespace {

using test::buildDynamic;
using test::StateVector;

constexpr double kGravity = 9.81;

// A block of mass m on the ground (load F_n = m g) pushed along x by f(t), the friction law's
// state integrated with it: y = [x, v, z...]. RK4 with a fixed step.
class Block {
 public:
  Block(const DynamicFrictionLaw& law, double mass, std::function<double(double)> push)
      : law_(law), mass_(mass), push_(std::move(push)), y_(2 + law.stateSize(), 0.0) {
    law.initialState(y_.data() + 2);
  }

  StateVector& state() { return y_; }
  double x() const { return y_[0]; }
  double v() const { return y_[1]; }
  double t() const { return t_; }

  void step(double h) {
    const std::size_t n = y_.size();
    auto shifted = [&](const StateVector& k, double c) {
      StateVector out(n);
      for (std::size_t i = 0; i < n; ++i) out[i] = y_[i] + c * k[i];
      return out;
    };
    const StateVector k1 = derivative(t_, y_);
    const StateVector k2 = derivative(t_ + 0.5 * h, shifted(k1, 0.5 * h));
    const StateVector k3 = derivative(t_ + 0.5 * h, shifted(k2, 0.5 * h));
    const StateVector k4 = derivative(t_ + h, shifted(k3, h));
    for (std::size_t i = 0; i < n; ++i)
      y_[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    t_ += h;
  }

 private:
  StateVector derivative(double t, const StateVector& y) const {
    StateVector dy(y.size());
    const Eigen::Vector3d slip(y[1], 0.0, 0.0);
    const double fn = mass_ * kGravity;
    law_.rate(y.data() + 2, slip, fn, dy.data() + 2);
    const Eigen::Vector3d friction = law_.force(y.data() + 2, dy.data() + 2, slip, fn, nullptr);
    dy[0] = y[1];
    dy[1] = (push_(t) + friction.x()) / mass_;
    return dy;
  }

  const DynamicFrictionLaw& law_;
  double mass_;
  std::function<double(double)> push_;
  StateVector y_;
  double t_ = 0.0;
};

TEST(LuGrePresliding, DisplacementUnderASlowRampIsTheLogarithm) {
  const auto built = buildDynamic({"lugre", {}, {}});  // the paper's Table I per newton
  const double sigma0 = 1e5, sigma1 = std::sqrt(1e5), sigma2 = 0.4, mu_s = 1.5;
  const double mass = 1.0, fn = mass * kGravity, ramp = 0.1;  // [N/s]
  Block block(*built.law, mass, [&](double t) { return ramp * t; });
  const double h = 1e-4;  // resolves the presliding mode sqrt(sigma0 g) ~ 990 rad/s
  double worst = 0.0;
  for (const double share : {0.2, 0.5, 0.8, 0.9}) {
    const double force = share * mu_s * fn;
    while (block.t() < force / ramp - 0.5 * h) block.step(h);
    const double expected = -(mu_s / sigma0) * std::log(1.0 - share);
    // Quasi-static error: the damping force (sigma1 + sigma2) F_n dz/dt, |dz/dt| <= v, with
    // v = (dx/dF) ramp, shifts x by dx/dF times it; the Stribeck drop mu_s - g(v) is
    // (v / v_s)^2 / 2 ~ 1e-7 relative. Twice the damping term.
    const double dx_df = 1.0 / (sigma0 * fn * (1.0 - share));
    const double tol = 2.0 * dx_df * (sigma1 + sigma2) * fn * dx_df * ramp + 1e-6 * expected;
    EXPECT_NEAR(block.x(), expected, tol) << "F / (mu_s F_n) = " << share;
    worst = std::max(worst, std::abs(block.x() / expected - 1.0));
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("lugre presliding: worst relative error %.3g\n", worst);
}

// Dissipated energy over one cycle of x = X sin(2 pi t) once the loop has closed.
double dahlCycleEnergy(const DynamicFrictionLaw& law, double x_amplitude, double fn) {
  const int per_cycle = 20000;
  const double h = 1.0 / per_cycle;
  StateVector z = test::initialState(law);
  double energy = 0.0;
  auto slipAt = [&](double t) {
    return Eigen::Vector3d(
        2.0 * std::numbers::pi * x_amplitude * std::cos(2.0 * std::numbers::pi * t), 0.0, 0.0);
  };
  // y = [z, W], dW/dt = -F_t . s (power dissipated), RK4 with the time-varying slip.
  auto derivative = [&](double t, const StateVector& y) {
    const Eigen::Vector3d s = slipAt(t);
    StateVector dy(y.size());
    law.rate(y.data(), s, fn, dy.data());
    dy.back() = -law.force(y.data(), dy.data(), s, fn, nullptr).dot(s);
    return dy;
  };
  StateVector y = z;
  y.push_back(0.0);
  const int cycles = 6;
  for (int i = 0; i < cycles * per_cycle; ++i) {
    if (i == (cycles - 1) * per_cycle) y.back() = 0.0;  // the last cycle only
    const double t = i * h;
    auto shifted = [&](const StateVector& k, double c) {
      StateVector out(y.size());
      for (std::size_t j = 0; j < y.size(); ++j) out[j] = y[j] + c * k[j];
      return out;
    };
    const StateVector k1 = derivative(t, y);
    const StateVector k2 = derivative(t + 0.5 * h, shifted(k1, 0.5 * h));
    const StateVector k3 = derivative(t + 0.5 * h, shifted(k2, 0.5 * h));
    const StateVector k4 = derivative(t + h, shifted(k3, h));
    for (std::size_t j = 0; j < y.size(); ++j)
      y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  energy = y.back();
  return energy;
}

TEST(DahlHysteresis, EnergyPerCycleIsTheClosedForm) {
  const double sigma0 = 1e5, mu_c = 0.4;
  const auto built = buildDynamic({"dahl", {{"sigma0", sigma0}, {"mu_c", mu_c}}, {}});
  for (const double fn : {1.0, 30.0}) {
    for (const double reach : {0.3, 2.0, 6.0}) {  // sigma0 X / mu_c
      const double x_amplitude = reach * mu_c / sigma0;
      const double fc = mu_c * fn;
      const double expected =
          4.0 * fc * x_amplitude - 4.0 * fc * fc / (sigma0 * fn) * std::tanh(reach);
      const double energy = dahlCycleEnergy(*built.law, x_amplitude, fn);
      // The loop forgets its start by exp(-2 reach) per reversal (10 reversals before the
      // last cycle: <= e^-6 for reach 0.3), RK4 at 2e4 steps a cycle adds ~1e-12: the
      // memory term bounds the tolerance.
      const double tol = std::max(1e-9, 2.0 * std::exp(-20.0 * reach)) * expected;
      EXPECT_NEAR(energy, expected, tol) << "F_n = " << fn << ", sigma0 X / mu_c = " << reach;
      std::printf("dahl cycle energy: F_n %g, sigma0 X / mu_c %g: %.12g J (closed form %.12g)\n",
                  fn, reach, energy, expected);
    }
  }
}

TEST(DahlHysteresis, VirginCurveForAlphaTwo) {
  // dF/dx = sigma0 F_n (1 - F / F_c)^2 from F = 0: F = F_c (1 - 1 / (1 + sigma0 x / mu_c)).
  const double sigma0 = 2e5, mu_c = 0.5, v = 1e-3;
  const auto built =
      buildDynamic({"dahl", {{"sigma0", sigma0}, {"mu_c", mu_c}, {"alpha", 2.0}}, {}});
  StateVector z = test::initialState(*built.law);
  const Eigen::Vector3d slip(0.0, v, 0.0);
  double x = 0.0;
  for (const double target : {1e-6, 5e-6, 2e-5, 1e-4}) {
    const double t = (target - x) / v;
    test::rk4(*built.law, z, slip, 1.0, t, 20000);
    x = target;
    double mu = 0.0;
    test::forceAt(*built.law, z, slip, 1.0, &mu);
    const double expected = mu_c * (1.0 - 1.0 / (1.0 + sigma0 * x / mu_c));
    // RK4 with k h <= sigma0 * 1e-4 / 2e4 / mu_c ~ 2e-3: ~1e-13 relative; 1e-10 with margin.
    EXPECT_NEAR(mu, expected, 1e-10 * expected) << "x = " << x;
  }
}

TEST(ElastoPlasticDrift, NoDriftBelowBreakAwayWhereLuGreDrifts) {
  // A block under 0.25 mu_c F_n +- 0.2 mu_c F_n at 5 Hz (well below the presliding mode),
  // starting at rest in equilibrium: the load stays under the break-away force 0.7 mu_c F_n.
  const double mass = 1.0, fn = mass * kGravity, mu_c = 1.0, sigma0 = 1e5;
  const double omega = 2.0 * std::numbers::pi * 5.0;
  auto push = [&](double t) { return fn * mu_c * (0.25 + 0.2 * std::sin(omega * t)); };
  auto drifts = [&](const std::string& name) {
    const auto built = buildDynamic({name, {}, {}});
    Block block(*built.law, mass, push);
    block.state()[2] = 0.25 * mu_c / sigma0;  // the bristle holding the initial load
    const double start = block.x() - block.state()[2];
    std::vector<double> per_cycle;
    double largest_z = 0.0;
    const int steps_per_cycle = 20000;  // h = 1e-5 s
    for (int cycle = 0; cycle < 10; ++cycle) {
      for (int i = 0; i < steps_per_cycle; ++i) {
        block.step(0.2 / steps_per_cycle);
        largest_z = std::max(largest_z, std::abs(block.state()[2]));
      }
      per_cycle.push_back(block.x() - block.state()[2] - start);  // slip beyond the bristle
    }
    if (name == "elasto_plastic") {
      EXPECT_LT(largest_z, 0.7 * mu_c / sigma0);
    }
    return per_cycle;
  };
  const std::vector<double> plastic = drifts("elasto_plastic");
  const std::vector<double> lugre = drifts("lugre");
  // Elastic: dz/dt = dx/dt exactly, so x - z keeps its value to rounding (1e-12 of the
  // break-away deflection 7e-6 m is far above RK4's rounding, far below any drift).
  for (const double d : plastic) EXPECT_LT(std::abs(d), 1e-12 * 0.7 * mu_c / sigma0);
  // LuGre: d(x - z)/dt = sigma0 |v| z / g > 0 while z > 0: it creeps forward every cycle.
  for (std::size_t i = 1; i < lugre.size(); ++i) EXPECT_GT(lugre[i], lugre[i - 1]);
  EXPECT_GT(lugre.back(), 1e-3 * mu_c / sigma0);
  std::printf("drift after 10 cycles: elasto_plastic %.3g m, lugre %.3g m\n", plastic.back(),
              lugre.back());
}

// Sum of min(k_i x, alpha_i S): the GMS virgin curve from rest at constant slip speed.
double gmsVirgin(const std::vector<double>& k, const std::vector<double>& alpha, double s,
                 double x) {
  double f = 0.0;
  for (std::size_t i = 0; i < k.size(); ++i) f += std::min(k[i] * x, alpha[i] * s);
  return f;
}

TEST(GmsPresliding, VirginCurveAndMasingUnloading) {
  const std::vector<double> k = {4e5, 1e5, 5e4};
  const std::vector<double> alpha = {0.2, 0.3, 0.5};
  const double mu_c = 0.3, mu_s = 0.45, v_s = 1e-3, v = 1e-4;
  const auto built = buildDynamic({"gms",
                                   {{"elements", 3.0},
                                    {"k_1", k[0]},
                                    {"k_2", k[1]},
                                    {"k_3", k[2]},
                                    {"alpha_1", alpha[0]},
                                    {"alpha_2", alpha[1]},
                                    {"alpha_3", alpha[2]},
                                    {"mu_c", mu_c},
                                    {"mu_s", mu_s},
                                    {"v_s", v_s}},
                                   {}});
  const double s = mu_c + (mu_s - mu_c) * std::exp(-(v / v_s) * (v / v_s));  // S(v), constant
  StateVector z = test::initialState(*built.law);
  const Eigen::Vector3d forward(v, 0.0, 0.0);
  // RK4 step: 1e-4 of the first break-away deflection; at each switch the rate jumps by v.
  const double h = 1e-4 * alpha[0] * s / k[0] / v;
  const double k_total = k[0] + k[1] + k[2];
  double x = 0.0;
  auto advance = [&](const Eigen::Vector3d& slip, double to) {
    const double t = std::abs(to - x) / v;
    test::rk4(*built.law, z, slip, 1.0, t, static_cast<long>(std::ceil(t / h)));
    x = to;
  };
  const double x_max = 1.5 * alpha[2] * s / k[2];  // every element sliding
  for (const double target : {0.5e-7, 1e-6, 2e-6, 5e-6, x_max}) {
    advance(forward, target);
    double mu = 0.0;
    test::forceAt(*built.law, z, forward, 1.0, &mu);
    // Three switches, each off by <= k_i v h; RK4 is exact on the linear pieces.
    EXPECT_NEAR(mu, gmsVirgin(k, alpha, s, x), 3.0 * k_total * v * h) << "x = " << x;
  }
  double f_max = 0.0;
  test::forceAt(*built.law, z, forward, 1.0, &f_max);
  // Masing: unloading from x_max follows F_max - 2 F_virgin((x_max - x) / 2).
  for (const double back : {1e-6, 3e-6, 8e-6, 2.0 * x_max}) {
    advance(-forward, x_max - back);
    const Eigen::Vector3d f = test::forceAt(*built.law, z, -forward, 1.0);
    const double expected = f_max - 2.0 * gmsVirgin(k, alpha, s, back / 2.0);
    EXPECT_NEAR(-f.x(), expected, 3.0 * k_total * v * h) << "back by " << back;
  }
}

class RateStateStep : public testing::TestWithParam<std::string> {};

TEST_P(RateStateStep, DirectEffectAndSteadyShift) {
  const double a = 0.011, b = 0.016, d_c = 2e-5, v0 = 1e-6;
  const auto built = buildDynamic(
      {"rate_state", {{"a", a}, {"b", b}, {"d_c", d_c}, {"v0", v0}}, {{"evolution", GetParam()}}});
  const auto& law = *built.law;
  for (const auto& [v1, v2] :
       {std::pair{1e-5, 1e-4}, std::pair{1e-4, 1e-5}, std::pair{1e-6, 1e-3}}) {
    const Eigen::Vector3d s1(v1, 0.0, 0.0), s2(0.0, v2, 0.0);
    // Steady at V1: settle by RK4 from the initial state (40 d_c / V1 is e^-40 away).
    StateVector z = test::initialState(law);
    test::rk4(law, z, s1, 1.0, 60.0 * d_c / v1, 60000);
    double mu1 = 0.0, direct = 0.0, mu2 = 0.0;
    test::forceAt(law, z, s1, 1.0, &mu1);
    test::forceAt(law, z, s2, 1.0, &direct);  // the state has not moved yet
    // After 60 d_c of slip at V2.
    test::rk4(law, z, s2, 1.0, 60.0 * d_c / v2, 60000);
    test::forceAt(law, z, s2, 1.0, &mu2);
    const double log_ratio = std::log(v2 / v1);
    // The arcsinh differs from the logarithm by ~exp(-2 mu / a) ~ e^-100 here: rounding and
    // the e^-60 transients are what is left.
    EXPECT_NEAR(direct - mu1, a * log_ratio, 1e-12) << v1 << " -> " << v2;
    EXPECT_NEAR(mu2 - mu1, (a - b) * log_ratio, 1e-12) << v1 << " -> " << v2;
    EXPECT_NEAR(mu1, law.coefficient(v1), 1e-12);
    std::printf(
        "rate_state %s %g -> %g: direct %.9f (a ln = %.9f), steady %.9f ((a-b) ln = %.9f)\n",
        GetParam().c_str(), v1, v2, direct - mu1, a * log_ratio, mu2 - mu1, (a - b) * log_ratio);
  }
}

TEST_P(RateStateStep, ThetaFollowsItsClosedFormEvolution) {
  const double d_c = 1e-7, v0 = 1e-6, theta0 = 3.0, v = 2e-5;
  const auto built = buildDynamic(
      {"rate_state", {{"d_c", d_c}, {"v0", v0}, {"theta0", theta0}}, {{"evolution", GetParam()}}});
  const auto* law = dynamic_cast<const RateStateLaw*>(built.law);
  ASSERT_NE(law, nullptr);
  StateVector z = test::initialState(*law);
  EXPECT_NEAR(law->thetaOf(z[0]), theta0, 1e-15 * theta0);
  const Eigen::Vector3d slip(v, 0.0, 0.0);
  const double theta_ss = d_c / v;
  double t = 0.0;
  for (const double until : {0.1, 1.0, 5.0, 20.0}) {  // in units of d_c / v
    const double dt = until * d_c / v - t;
    test::rk4(*law, z, slip, 1.0, dt, 20000);
    t += dt;
    const double x = v * t / d_c;
    double expected = 0.0;
    if (GetParam() == "aging") {
      // dtheta/dt = 1 - v theta / d_c: linear.
      expected = theta_ss + (theta0 - theta_ss) * std::exp(-x);
    } else {
      // d ln(v theta / d_c) / dx = -ln(v theta / d_c): ln(v theta / d_c) decays as e^-x.
      expected = theta_ss * std::exp(std::log(theta0 / theta_ss) * std::exp(-x));
    }
    // RK4 at 2e4 steps over <= 20 relaxation lengths: ~1e-13 relative; 1e-9 with margin.
    EXPECT_NEAR(law->thetaOf(z[0]), expected, 1e-9 * expected) << "t v / d_c = " << until;
    StateVector exact = test::initialState(*law);
    law->stableStep(exact.data(), slip, 1.0, t);
    EXPECT_NEAR(law->thetaOf(exact[0]), expected, 1e-12 * expected) << "stableStep";
  }
}

INSTANTIATE_TEST_SUITE_P(Evolution, RateStateStep, testing::Values("aging", "slip"));

TEST(RateState, AgingHealsLinearlyAtRestAndStartsFromRest) {
  const auto built = buildDynamic({"rate_state", {{"theta0", 2.0}}, {}});
  const auto* law = dynamic_cast<const RateStateLaw*>(built.law);
  StateVector z = test::initialState(*law);
  law->stableStep(z.data(), Eigen::Vector3d::Zero(), 1.0, 1e6);
  EXPECT_NEAR(law->thetaOf(z[0]), 2.0 + 1e6, 1e-12 * 1e6);  // dtheta/dt = 1 at rest
  // Zero force at rest; linear in v at tiny v (the regularization), so a contact can start.
  EXPECT_EQ(law->mu(0.0, z[0]), 0.0);
  const double tiny = 1e-60;  // arcsinh argument ~1e-21: asinh(y) = y (1 - y^2 / 6)
  const double slope = law->mu(tiny, z[0]) / tiny;
  EXPECT_NEAR(law->mu(2.0 * tiny, z[0]), 2.0 * tiny * slope, 1e-9 * 2.0 * tiny * slope);
  // The slip law does not heal at rest.
  const auto slip_law = buildDynamic({"rate_state", {}, {{"evolution", "slip"}}});
  StateVector w = test::initialState(*slip_law.law);
  const double before = w[0];
  slip_law.law->stableStep(w.data(), Eigen::Vector3d::Zero(), 1.0, 1e6);
  EXPECT_EQ(w[0], before);
}

}  // namespace
}  // namespace tribo::friction
