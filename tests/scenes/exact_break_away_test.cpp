// Exact break-away: blocks of 0.2, 2 and 20 kg on the ground, each pushed along x by a load
// that rises smoothly (the cubic STEP over 10 s, so that nothing rings) to r mu_s m g and
// then holds. For a law that sticks, r = 0.999 must hold every block to 100 s and r = 1.001
// must set it sliding. What each law promises, from its equations alone:
// - elastic_stick (friction/elastic_stick_law.hpp): the corners' anchored springs take the
//   load, each k_t u = F / 4; the block stays at F / (4 k_t) and moves no further, to
//   rounding; at 1.001 the springs' force passes mu_s F_n and every corner lets go.
// - lugre (friction/lugre_law.hpp): quasi-static presliding z' = v (1 - sigma0 z / mu_s) per
//   unit load moves the block by x = -(mu_s / sigma0) ln(1 - F / (mu_s m g)) (the law's
//   Property 1; 6.9 mu_s / sigma0 at 0.999), and then nothing more under the held load: at
//   rest z' = 0 whatever z is, and the equilibrium z = F / (sigma0 m g) < mu_s / sigma0 is
//   stable (a small slip dx raises the force by sigma0 (1 - r) m g dx). At 1.001 there is no
//   equilibrium (sigma0 z would have to exceed g(0) = mu_s) and it slides.
// - elasto_plastic (friction/elasto_plastic_law.hpp): elastic below its break-away
//   deflection z_ba, then LuGre-like presliding with its alpha ramp (the integral below).
// The regularized memoryless laws cannot promise this: they creep at any load (docs/creep.md).
// Creep is the displacement from t = 20 s (10 s after the ramp's end) to 100 s; its bound
// is stated per law below, with what was measured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/simulator.hpp"
#include "io/scene_loader.hpp"

namespace tribo {
namespace {

constexpr double kG = 9.81, kMuS = 0.35, kMuK = 0.3;
constexpr double kKt = 1e5;      // elastic_stick: tangential stiffness per corner and kg
constexpr double kSigma0 = 1e4;  // lugre, elasto_plastic: bristle stiffness per newton [1/m]
// The load rises over kRamp seconds, then holds to kHold; creep is measured from kSettled.
constexpr double kRamp = 10.0, kSettled = 20.0, kHold = 100.0;

std::string number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

constexpr double kMasses[3] = {0.2, 2.0, 20.0};  // [kg]

// Three blocks of kMasses, 10 m apart along y, each on the ground and each pushed at its
// bottom face by a load that rises over kRamp to `ratio` mu_s m g. Contact stiffness and
// damping per corner scale with the mass (1e5 m N/m, 100 m N s/m; elastic_stick's
// tangential spring alike), so that rk4 at 1 ms is inside every block's stable step and the
// static depth m g / (4 k) is the same for all.
// With a grain (`anisotropy`, a material's mapping text) the push is `sense` (+1 or -1) times
// `ratio` r_axis mu_s m g along x, r_axis the grain's ratio for that sense.
std::string scene(const std::string& law, double ratio, double duration,
                  const std::string& anisotropy = "", double sense = 1.0, double r_axis = 1.0) {
  std::string bodies, loads, materials, contacts;
  for (int i = 0; i < 3; ++i) {
    const double m = kMasses[i];
    const std::string n = std::to_string(i), y = number(10.0 * i);
    bodies += "  - {name: block" + n + ", mass: " + number(m) + ", position: [0, " + y + ", " +
              number(0.05 - 9.81 / 4e5) + "], geometry: [{name: box" + n +
              ", shape: box, size: [0.2, 0.2, 0.1]}]}\n";
    loads += "  - {name: push" + n + ", body: block" + n +
             ", frame: world, point: [0, 0, -0.05], force: [{smooth_step: {start: 0, before: "
             "0, end: " +
             number(kRamp) + ", after: " + number(sense * ratio * r_axis * kMuS * m * kG) +
             "}}, 0, 0]}\n";
    const std::string friction =
        law == "elastic_stick" ? "elastic_stick" + n
                               : law;  // the bristle laws' stiffness is per newton of load already
    materials += "  - {name: m" + n + ", normal: {law: linear, stiffness: " + number(1e5 * m) +
                 ", damping: " + number(100 * m) + "}, friction: " + friction +
                 (anisotropy.empty() ? "" : ", anisotropy: " + anisotropy) + "}\n";
    contacts += "  - {a: floor, b: box" + n + ", material: m" + n + "}\n";
  }
  std::string laws;
  if (law == "elastic_stick") {
    for (int i = 0; i < 3; ++i)
      laws += "  elastic_stick" + std::to_string(i) + ": {law: elastic_stick, mu_s: 0.35, " +
              "mu_k: 0.3, stiffness: " + number(kKt * kMasses[i]) +
              ", damping: " + number(100 * kMasses[i]) + "}\n";
  } else {  // per unit normal force
    laws = "  " + law + ": {sigma0: " + number(kSigma0) +
           ", sigma1: 10, sigma2: 0.01, mu_c: 0.3, mu_s: 0.35, v_s: 0.01}\n";
  }
  return "simulation: {duration: " + number(duration) +
         ", time_step: 0.001, integrator: rk4, gravity: [0, 0, -9.81]}\n"
         "bodies:\n"
         "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n" +
         bodies + "loads:\n" + loads + "friction_laws:\n" + laws + "materials:\n" + materials +
         "contacts:\n" + contacts;
}

struct Outcome {
  double x_settled[3] = {}, x_end[3] = {}, v_end[3] = {};
  double t_fast[3] = {-1, -1, -1};  // when each block first went faster than kSliding
};

// Faster than any stuck block goes (a stuck one creeps at 1e-9 m/s at most, below).
constexpr double kSliding = 0.05;  // [m/s]

// Runs the three blocks to `duration`, or (stop_when_all_slide) until all three pass
// kSliding: the bristle laws' state equation stiffens with the slip speed (sigma0 |v| / g,
// 1.7e3 /s at 0.05 m/s, 3e4 /s at 1 m/s), beyond what rk4 at 1 ms follows.
Outcome run(const std::string& law, double ratio, double duration, bool stop_when_all_slide,
            const std::string& anisotropy = "", double sense = 1.0, double r_axis = 1.0,
            double settled_at = kSettled) {
  const io::Scene s =
      io::loadSceneFromString(scene(law, ratio, duration, anisotropy, sense, r_axis), "push.yaml");
  Simulator sim(s.model);
  std::size_t block[3];
  double x0[3];
  for (int i = 0; i < 3; ++i) {
    block[i] = static_cast<std::size_t>(s.model->findBody("block" + std::to_string(i))->value);
    x0[i] = sim.state().bodies[block[i]].position.x();
  }
  Outcome r;
  const long steps = std::lround(duration / 1e-3);
  const long settled = std::lround(settled_at / 1e-3);
  for (long k = 0; k < steps; ++k) {
    const StepStatus status = sim.step();
    EXPECT_TRUE(status.ok) << status.message;
    if (!status.ok) break;
    bool all = true;
    for (int i = 0; i < 3; ++i) {
      const BodyState& b = sim.state().bodies[block[i]];
      if (k + 1 == settled) r.x_settled[i] = b.position.x() - x0[i];
      if (r.t_fast[i] < 0.0 && sense * b.velocity.x() > kSliding) r.t_fast[i] = sim.state().time;
      all = all && r.t_fast[i] >= 0.0;
    }
    if (stop_when_all_slide && all) break;
  }
  for (int i = 0; i < 3; ++i) {
    r.x_end[i] = sim.state().bodies[block[i]].position.x() - x0[i];
    r.v_end[i] = sim.state().bodies[block[i]].velocity.x();
  }
  return r;
}

// Where a law holds the block under r mu_s m g after a slow loading (header comment): the
// same at every mass, the stiffnesses being per kilogram (elastic_stick here) or per newton
// of load (the bristle laws).
double heldAt(const std::string& law, double ratio) {
  if (law == "elastic_stick") return ratio * kMuS * kG / (4 * kKt);
  if (law == "lugre") return -(kMuS / kSigma0) * std::log(1 - ratio);
  // elasto_plastic: x = int_0^z dz / (1 - alpha(z) sigma0 z / mu_s) up to sigma0 z = r mu_s,
  // alpha the law's sine ramp from z_ba = 0.7 mu_c / sigma0 to z_ss = mu_s / sigma0 at rest;
  // composite Simpson on 2e5 panels (the integrand is smooth; its largest value 1 / (1 - r)).
  const double z_ba = 0.7 * kMuK / kSigma0, z_ss = kMuS / kSigma0, z_end = ratio * z_ss;
  auto integrand = [&](double z) {
    const double alpha =
        z <= z_ba
            ? 0.0
            : 0.5 * (1 + std::sin(std::acos(-1.0) * (z - 0.5 * (z_ss + z_ba)) / (z_ss - z_ba)));
    return 1.0 / (1.0 - alpha * z / z_ss);
  };
  const int n = 200000;
  const double h = z_end / n;
  double sum = integrand(0.0) + integrand(z_end);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(i * h);
  return sum * h / 3.0;
}

// The bristle laws' block by hand: every corner carries m g / 4 and slips alike, so per
// unit mass x'' = r mu_s g S(t / kRamp) - g (sigma0 z + sigma1 z' + sigma2 v) with
// z' = v - alpha sigma0 |v| z / g_s(v), g_s(v) = mu_c + (mu_s - mu_c) exp(-(v / v_s)^2), alpha = 1
// for lugre and the elasto-plastic ramp (friction/elasto_plastic_law.hpp) otherwise; S the
// cubic STEP. RK4 at 1e-4 s (a tenth of the scene's step) to `until`; returns x.
double bristleBlock(const std::string& law, double ratio, double until) {
  const double sigma1 = 10.0, sigma2 = 0.01, v_s = 0.01;
  auto gs = [&](double v) { return kMuK + (kMuS - kMuK) * std::exp(-(v / v_s) * (v / v_s)); };
  auto zdot = [&](double v, double z) {
    double alpha = 1.0;
    if (law == "elasto_plastic") {
      const double z_ba = 0.7 * kMuK / kSigma0, z_ss = gs(std::abs(v)) / kSigma0;
      const double a = std::abs(z);
      alpha =
          (a <= z_ba || z * v <= 0.0) ? 0.0
          : a >= z_ss
              ? 1.0
              : 0.5 * (1 + std::sin(std::acos(-1.0) * (a - 0.5 * (z_ss + z_ba)) / (z_ss - z_ba)));
    }
    return v - alpha * kSigma0 * std::abs(v) * z / gs(std::abs(v));
  };
  auto push = [&](double t) {
    const double u = std::clamp(t / kRamp, 0.0, 1.0);
    return ratio * kMuS * kG * u * u * (3 - 2 * u);
  };
  struct Y {
    double x, v, z;
  };
  auto rate = [&](double t, const Y& y) {
    const double dz = zdot(y.v, y.z);
    return Y{y.v, push(t) - kG * (kSigma0 * y.z + sigma1 * dz + sigma2 * y.v), dz};
  };
  const double h = 1e-4;
  Y y{0, 0, 0};
  const long steps = std::lround(until / h);
  for (long i = 0; i < steps; ++i) {
    const double t = i * h;
    auto plus = [](const Y& a, const Y& b, double c) {
      return Y{a.x + c * b.x, a.v + c * b.v, a.z + c * b.z};
    };
    const Y k1 = rate(t, y), k2 = rate(t + h / 2, plus(y, k1, h / 2));
    const Y k3 = rate(t + h / 2, plus(y, k2, h / 2)), k4 = rate(t + h, plus(y, k3, h));
    y.x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
    y.v += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
    y.z += h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z);
  }
  return y.x;
}

TEST(ExactBreakAway, AtPoint999TheBlocksHoldFor100sAndAt1Point001TheySlide) {
  for (const char* law : {"elastic_stick", "lugre", "elasto_plastic"}) {
    SCOPED_TRACE(law);
    const bool stick = std::string(law) == "elastic_stick";
    const Outcome held = run(law, 0.999, kHold, false);
    const Outcome slid = run(law, 1.001, kRamp + 2.0, true);
    const double expected = heldAt(law, 0.999);
    const double by_hand = stick ? expected : bristleBlock(law, 0.999, kSettled);
    for (int i = 0; i < 3; ++i) {
      SCOPED_TRACE(number(kMasses[i]) + " kg");
      const double creep = std::abs(held.x_end[i] - held.x_settled[i]);
      std::printf(
          "%-15s m %5.1f kg: held at %.6e m (by hand %.6e, quasi-static %.6e), creep %g-%g s "
          "%.3e m, v %.3e m/s; at 1.001 past %.2f m/s at t = %.3f s\n",
          law, kMasses[i], held.x_end[i], by_hand, expected, kSettled, kHold, creep, held.v_end[i],
          kSliding, slid.t_fast[i]);
      EXPECT_LT(held.t_fast[i], 0.0) << "slid at " << held.t_fast[i] << " s";
      // elastic_stick: its springs' give F / (4 k_t) (measured 6e-5 below it: the ramp's
      // damping force c_t u' is gone at rest, the corners' depths differ by the push's
      // moment), and not a picometre more (measured 2e-13 m over 80 s).
      // The bristle laws: where the block's own equations put it (0.3% measured: near
      // break-away the compliance is 1 / (sigma0 m g (1 - r)), a thousand times the first,
      // so a 1e-6 difference in the force balance, the penalty contact's, moves x by 1e-3);
      // 20% (lugre) and 35% (elasto_plastic) beyond the quasi-static curve, which the last
      // approach overshoots; then the held block stays to 1e-10 m over 80 s (measured
      // 2e-12 m, 6e-12 m).
      if (stick) {
        EXPECT_NEAR(held.x_end[i], expected, 1e-3 * expected);
        EXPECT_LT(creep, 1e-12);
      } else {
        EXPECT_NEAR(held.x_end[i], by_hand, 0.01 * by_hand);
        EXPECT_GT(held.x_end[i], 1.1 * expected);
        EXPECT_LT(creep, 1e-10);
      }
      EXPECT_LT(std::abs(held.v_end[i]), 1e-12);
      // At 1.001 each block lets go near the ramp's end (within the last 5% of its time,
      // where the push passes mu_s m g) and is sliding fast within 2 s.
      EXPECT_GT(slid.t_fast[i], 0.95 * kRamp);
      EXPECT_LT(slid.t_fast[i], kRamp + 2.0);
    }
  }
}

// With a grain (contact/anisotropy.hpp: ratio 0.5 along +x, 2 along -x) the threshold is
// r mu_s m g in each sense: 0.999 of it holds, 1.001 slides. elastic_stick's springs act in
// the law's scaled plane, so each corner's stiffness along x is r^2 k_t and the block holds
// at F / (4 r^2 k_t); LuGre's presliding there is the isotropic one's in X = r x, so the
// block holds beyond its quasi-static curve x = -(mu_s / (sigma0 r)) ln(1 - F / (r mu_s m g))
// (by the approach's overshoot, 20% in the isotropic case above) and then stays.
TEST(ExactBreakAway, WithAGrainTheThresholdIsItsRatioOfMuSInEachSense) {
  const std::string grain = "{axis: [1, 0, 0], ratio: [0.5, 1], backward: [2, 1]}";
  for (const char* law : {"elastic_stick", "lugre"}) {
    for (const auto& [sense, r] : {std::pair{1.0, 0.5}, std::pair{-1.0, 2.0}}) {
      SCOPED_TRACE(std::string(law) + " sense " + number(sense));
      const bool stick = std::string(law) == "elastic_stick";
      // LuGre along the grain's soft sense (r = 0.5) has a 4 times softer bristle there and
      // ends its approach later (measured: 1.7e-9 m after 20 s, nothing after 30 s): the
      // creep is measured from 40 s.
      const Outcome held = run(law, 0.999, kHold, false, grain, sense, r, 40.0);
      const Outcome slid = run(law, 1.001, kRamp + 2.0, true, grain, sense, r);
      const double expected =
          stick ? 0.999 * kMuS * kG / (4 * kKt * r) : -(kMuS / (kSigma0 * r)) * std::log(1 - 0.999);
      for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(number(kMasses[i]) + " kg");
        const double x = sense * held.x_end[i];
        const double creep = std::abs(held.x_end[i] - held.x_settled[i]);
        std::printf(
            "%-13s r %.1f m %5.1f kg: held at %.6e m (quasi-static %.6e), creep %.3e m; "
            "at 1.001 fast at t = %.3f s\n",
            law, r, kMasses[i], x, expected, creep, slid.t_fast[i]);
        EXPECT_LT(held.t_fast[i], 0.0) << "slid at " << held.t_fast[i] << " s";
        if (stick) {
          EXPECT_NEAR(x, expected, 1e-3 * expected);
          EXPECT_LT(creep, 1e-12);
        } else {
          EXPECT_GT(x, expected);
          EXPECT_LT(x, 1.5 * expected);
          EXPECT_LT(creep, 1e-10);
        }
        EXPECT_GT(slid.t_fast[i], 0.95 * kRamp);
        EXPECT_LT(slid.t_fast[i], kRamp + 2.0);
      }
    }
  }
}

}  // namespace
}  // namespace tribo
