#include "core/stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

namespace tribo {

namespace {

using Mat2 = Eigen::Matrix2d;

constexpr int kSlopeSamples = 16;        // slope samples over (0, stick speed]
constexpr double kPoints = 4.0;          // points sharing a pair's load (a box on a face)
constexpr double kUnloadedDepth = 1e-4;  // [m] nonlinear laws without gravity

// One-step matrix of the integrator on (x, v) for the system matrix a.
Mat2 stepMatrix(IntegratorType integrator, const Mat2& a, double h) {
  if (integrator == IntegratorType::kRk4) {
    const Mat2 z = h * a;
    const Mat2 z2 = z * z;
    return Mat2::Identity() + z + z2 / 2 + z2 * z / 6 + z2 * z2 / 24;
  }
  if (integrator == IntegratorType::kDopri5) {
    // Stability function of Dormand-Prince 5(4), the fifth-order solution (Hairer & Wanner,
    // Solving ODEs II, IV.2): R(z) = sum_{k<=5} z^k/k! + z^6/600.
    const Mat2 z = h * a;
    const Mat2 z2 = z * z, z3 = z2 * z;
    return Mat2::Identity() + z + z2 / 2 + z3 / 6 + z3 * z / 24 + z3 * z2 / 120 + z3 * z3 / 600;
  }
  // v+ = v + h (a10 x + a11 v);  x+ = x + h v+
  Mat2 s;
  s.row(1) = Eigen::RowVector2d(h * a(1, 0), 1 + h * a(1, 1));
  s.row(0) = Eigen::RowVector2d(1, 0) + h * s.row(1);
  return s;
}

bool stable(IntegratorType integrator, const Mat2& a, double h) {
  const double rho = stepMatrix(integrator, a, h).eigenvalues().cwiseAbs().maxCoeff();
  return rho <= 1.0 + 1e-12;
}

double bodyMass(const Model& model, BodyIndex i) {
  return (i.isWorld() || model.bodies[i.value].kind != BodyKind::kDynamic)
             ? std::numeric_limits<double>::infinity()
             : model.bodies[i.value].mass;
}

double reducedMass(const Model& model, BodyIndex a, BodyIndex b) {
  const double ma = bodyMass(model, a), mb = bodyMass(model, b);
  if (std::isinf(ma)) return mb;
  if (std::isinf(mb)) return ma;
  return ma * mb / (ma + mb);
}

// The load a contact pair carries at rest [N]: the weight of its dynamic body, or of the
// heavier one when both are dynamic (whichever rests on the other; a stack's lower contacts
// carry more and are stiffer than this).
double restingLoad(const Model& model, BodyIndex a, BodyIndex b, double g) {
  const double ma = bodyMass(model, a), mb = bodyMass(model, b);
  const double m = std::isinf(ma) ? mb : (std::isinf(mb) ? ma : std::max(ma, mb));
  return m * g;
}

// Tangent of a normal law at one contact point, at depth d and rest (d' = 0).
struct Tangent {
  double stiffness = 0.0;  // dF/dd [N/m]
  double damping = 0.0;    // dF/dd' [N s/m]
};

double exponentOf(const contact::NormalLaw& law) {
  return law.type == contact::NormalLawType::kLinear  ? 1.0
         : law.type == contact::NormalLawType::kHertz ? 1.5
                                                      : law.exponent;
}

// Depth at which the elastic part k d^p carries `load` [N].
double depthAtLoad(const contact::NormalLaw& law, double load) {
  return std::pow(load / law.stiffness, 1.0 / exponentOf(law));
}

Tangent tangentAt(const contact::NormalLaw& law, double depth) {
  const double p = exponentOf(law);
  const double f = law.stiffness * std::pow(depth, p);  // elastic part at d
  switch (law.type) {
    case contact::NormalLawType::kLinear:
      return {law.stiffness, law.damping};
    case contact::NormalLawType::kHertz:
      return {p * f / depth, 0.0};
    case contact::NormalLawType::kHuntCrossley:
      return {p * f / depth, f * law.damping};  // k d^p (1 + alpha d'): alpha k d^p
    case contact::NormalLawType::kRecurDyn:
      return {p * f / depth, friction::havsin(depth, 0.0, 0.0, law.max_depth, law.damping)};
  }
  return {};
}

// The stick spring-damper of a stateful law per contact point, read off its stuck force: a
// tiny elongation (then a tiny slip) under a load far above any breakaway. Zero for a law
// that never holds (mu_s = 0).
Tangent stickTangent(const friction::FrictionLaw& law) {
  constexpr double kDelta = 1e-9, kLoad = 1e30;
  friction::StickView view;
  view.anchored = true;
  view.elongation = Eigen::Vector3d(kDelta, 0.0, 0.0);
  const double k = -law.stickForce(Eigen::Vector3d::Zero(), kLoad, view, nullptr).x() / kDelta;
  view.elongation.setZero();
  const double c =
      -law.stickForce(Eigen::Vector3d(kDelta, 0.0, 0.0), kLoad, view, nullptr).x() / kDelta;
  return {std::max(k, 0.0), std::max(c, 0.0)};
}

}  // namespace

double stableStep(IntegratorType integrator, double k_over_m, double c_over_m) {
  if (integrator == IntegratorType::kBdf) return std::numeric_limits<double>::infinity();
  Mat2 a;
  a << 0, 1, -k_over_m, -c_over_m;
  const double rate = std::sqrt(k_over_m) + c_over_m;  // bounds |eigenvalue|
  if (!(rate > 0)) return std::numeric_limits<double>::infinity();
  // Grow h until unstable, then bisect (all explicit regions here are bounded).
  double lo = 1e-3 / rate, hi = lo;
  while (stable(integrator, a, hi)) {
    lo = hi;
    hi *= 1.5;
    if (hi > 1e3 / rate) return std::numeric_limits<double>::infinity();
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stable(integrator, a, mid) ? lo : hi) = mid;
  }
  return lo;
}

StabilityReport estimateStableStep(const Model& model) {
  StabilityReport report;
  report.limit.max_step = std::numeric_limits<double>::infinity();
  const IntegratorType integrator = model.options.integrator;
  const double g = model.options.gravity.norm();
  // Automatic contacts give thousands of pairs sharing a few materials and masses: each
  // distinct test system is bounded once.
  std::map<std::pair<double, double>, double> bounded;
  auto consider = [&](double k_over_m, double c_over_m, const auto& element) {
    const auto [it, added] = bounded.try_emplace({k_over_m, c_over_m}, 0.0);
    if (added) it->second = stableStep(integrator, k_over_m, c_over_m);
    if (it->second < report.limit.max_step) report.limit = {it->second, element()};
  };
  std::vector<bool> noted(model.materials.size(), false);  // one note per material
  for (const ContactPair& pair : model.contact_pairs) {
    const Geometry& ga = model.geometries[pair.geometry_a];
    const Geometry& gb = model.geometries[pair.geometry_b];
    auto who = [&] { return "contact pair (" + ga.name + ", " + gb.name + ")"; };
    const double m = reducedMass(model, ga.body, gb.body);
    const contact::Material& mat = model.materials[pair.material];
    const bool first_of_material = !noted[pair.material];
    noted[pair.material] = true;

    // Normal: the law's tangent at the depth where kPoints points share the resting load.
    const contact::NormalLaw& law = mat.normal;
    const bool nonlinear = law.type != contact::NormalLawType::kLinear;
    const double load = restingLoad(model, ga.body, gb.body, g) / kPoints;
    const double depth = load > 0.0 ? depthAtLoad(law, load) : kUnloadedDepth;
    const Tangent normal = tangentAt(law, depth);
    consider(kPoints * normal.stiffness / m, kPoints * normal.damping / m, [&] {
      if (!nonlinear) return who() + " normal";
      std::ostringstream e;
      e << who() << " normal (" << contact::normalLawName(law.type) << " at "
        << (load > 0.0 ? "its static depth " : "the stated depth ") << depth << " m)";
      return e.str();
    });
    if (nonlinear && !(load > 0.0) && first_of_material) {
      std::ostringstream note;
      note << who() << ": normal law " << contact::normalLawName(law.type)
           << " carries no weight (no gravity); its limit uses the tangent stiffness at the "
              "stated depth "
           << kUnloadedDepth << " m (deeper contacts are stiffer: the limit scales as depth^-"
           << (exponentOf(law) - 1.0) / 2.0 << ")";
      report.notes.push_back(note.str());
    }

    // Friction: a stateful law's stick spring-damper on the same points, tangentially.
    const friction::FrictionLaw& friction_law = *mat.friction;
    if (friction_law.stateful()) {
      const Tangent stick = stickTangent(friction_law);
      consider(kPoints * stick.stiffness / m, kPoints * stick.damping / m, [&] {
        return who() + " friction (" + std::string(friction_law.name()) + " stick spring)";
      });
    }
    // ... and the sticking slope of its mu(v) curve (a memoryless law's only stiffness).
    const double stick_speed = friction_law.stickSpeed();
    double slope = friction_law.slope(0.0);
    if (std::isfinite(slope)) {
      // Steepest rise on [0, stick speed] (a haversine step is steepest mid-way).
      for (int i = 1; i <= kSlopeSamples; ++i)
        slope = std::max(slope, friction_law.slope(stick_speed * i / kSlopeSamples));
    } else {
      slope = friction_law.slope(stick_speed);
      if (first_of_material) {
        std::ostringstream note;
        note << who() << ": friction law " << friction_law.name()
             << " has an unbounded slope at zero slip; its limit uses the slope at the stick "
                "speed "
             << stick_speed << " m/s, so at that step explicit chatter stays below the stick speed";
        report.notes.push_back(note.str());
      }
    }
    if (std::isfinite(slope) && slope > 0.0)
      consider(0.0, slope * g,
               [&] { return who() + " friction (" + std::string(friction_law.name()) + ")"; });
  }
  for (const SpringDamper& s : model.springs) {
    const double m = reducedMass(model, s.body_a, s.body_b);
    consider(s.stiffness / m, s.damping / m, [&] { return "spring '" + s.name + "'"; });
  }
  return report;
}

}  // namespace tribo
