#include "core/stability.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace tribo {

namespace {

using Mat2 = Eigen::Matrix2d;

constexpr int kSlopeSamples = 16;  // slope samples over (0, stick speed]

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

double reducedMass(const Model& model, BodyIndex a, BodyIndex b) {
  auto mass = [&](BodyIndex i) {
    return (i.isWorld() || model.bodies[i.value].kind != BodyKind::kDynamic)
               ? std::numeric_limits<double>::infinity()
               : model.bodies[i.value].mass;
  };
  const double ma = mass(a), mb = mass(b);
  if (std::isinf(ma)) return mb;
  if (std::isinf(mb)) return ma;
  return ma * mb / (ma + mb);
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
  auto consider = [&](double k_over_m, double c_over_m, const std::string& element) {
    const double h = stableStep(integrator, k_over_m, c_over_m);
    if (h < report.limit.max_step) report.limit = {h, element};
  };
  for (const ContactPair& pair : model.contact_pairs) {
    const Geometry& ga = model.geometries[pair.geometry_a];
    const Geometry& gb = model.geometries[pair.geometry_b];
    const std::string who = "contact pair (" + ga.name + ", " + gb.name + ")";
    const double m = reducedMass(model, ga.body, gb.body);
    const contact::Material& mat = model.materials[pair.material];
    constexpr double kPoints = 4.0;
    double k = kPoints * mat.normal.stiffness, c = kPoints * mat.normal.damping;
    if (mat.normal.type == contact::NormalLawType::kHuntCrossley) {
      const double p = mat.normal.exponent;
      const double depth = std::pow(m * std::max(g, 1e-3) / k, 1.0 / p);
      const double f = k * std::pow(depth, p);
      k = p * f / depth;           // dF/dd at the static depth
      c = f * mat.normal.damping;  // dF/dd' = k d^p alpha
    }
    consider(k / m, c / m, who + " normal");
    const friction::FrictionLaw& law = *mat.friction;
    const double stick = law.stickSpeed();
    double slope = law.slope(0.0);
    if (std::isfinite(slope)) {
      // Steepest rise on [0, stick speed] (a haversine step is steepest mid-way).
      for (int i = 1; i <= kSlopeSamples; ++i)
        slope = std::max(slope, law.slope(stick * i / kSlopeSamples));
    } else {
      slope = law.slope(stick);
      std::ostringstream note;
      note << who << ": friction law " << law.name()
           << " has an unbounded slope at zero slip; its limit uses the slope at the stick "
              "speed "
           << stick << " m/s, so at that step explicit chatter stays below the stick speed";
      report.notes.push_back(note.str());
    }
    if (std::isfinite(slope) && slope > 0.0)
      consider(0.0, slope * g, who + " friction (" + std::string(law.name()) + ")");
  }
  for (const SpringDamper& s : model.springs) {
    const double m = reducedMass(model, s.body_a, s.body_b);
    consider(s.stiffness / m, s.damping / m, "spring '" + s.name + "'");
  }
  return report;
}

}  // namespace tribo
