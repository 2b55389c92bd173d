#include "core/stability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

#include "core/constraint_rows.hpp"
#include "core/joint_forces.hpp"
#include "core/prescribed_motion.hpp"
#include "core/resting_contact.hpp"
#include "friction/dynamic_law.hpp"

namespace tribo {

namespace {

using Mat2 = Eigen::Matrix2d;
using stability_detail::RestingFace;
using stability_detail::restingFace;
using stability_detail::rockingPerPointStiffness;
using stability_detail::RoundContact;
using stability_detail::roundContact;
using stability_detail::TurnCheck;
using stability_detail::yawPerPointStiffness;

constexpr int kSlopeSamples = 16;  // per piece of the curve between its breakpoints
// Slip speeds a driven stick-slip reaches, in units of the fastest driven speed: 3.5 in
// the LuGre block of scenes/lugre_stick_slip.yaml (0.35 m/s peak slip at a 0.1 m/s pull).
constexpr double kSlipSpeedFactor = 4.0;
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

// Moment of inertia of body i about an axis through its centre of mass (unit, world, at the
// initial pose); infinite for the world and kinematic bodies.
double axisInertia(const Model& model, BodyIndex i, const Vec3& axis) {
  if (std::isinf(bodyMass(model, i))) return std::numeric_limits<double>::infinity();
  const Body& b = model.bodies[i.value];
  const Vec3 local = b.orientation.conjugate() * axis;
  return local.dot(b.inertia * local);
}

// Two bodies turning against each other about one axis: I_a I_b / (I_a + I_b).
double reducedInertia(const Model& model, BodyIndex a, BodyIndex b, const Vec3& axis) {
  const double ia = axisInertia(model, a, axis), ib = axisInertia(model, b, axis);
  if (std::isinf(ia)) return ib;
  if (std::isinf(ib)) return ia;
  return ia * ib / (ia + ib);
}

double reducedMass(const Model& model, BodyIndex a, BodyIndex b) {
  const double ma = bodyMass(model, a), mb = bodyMass(model, b);
  if (std::isinf(ma)) return mb;
  if (std::isinf(mb)) return ma;
  return ma * mb / (ma + mb);
}

// The smaller of the two bodies' smallest principal moments of inertia [kg m^2] (infinite for
// the world and kinematic bodies): what an angular spring between them turns.
double smallestInertia(const Model& model, BodyIndex a, BodyIndex b) {
  auto of = [&](BodyIndex i) {
    if (std::isinf(bodyMass(model, i))) return std::numeric_limits<double>::infinity();
    return Eigen::SelfAdjointEigenSolver<Mat3>(model.bodies[i.value].inertia,
                                               Eigen::EigenvaluesOnly)
        .eigenvalues()
        .minCoeff();
  };
  return std::min(of(a), of(b));
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

// Depth at which the elastic part k d^p carries `load` [N].
double depthAtLoad(const contact::NormalLaw& law, double load) {
  return std::pow(load / law.stiffness, 1.0 / law.elasticExponent());
}

Tangent tangentAt(const contact::NormalLaw& law, double depth) {
  const double p = law.elasticExponent();
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

// The speeds where a law's sticking slope matters: up to where mu first reaches the largest
// value a load can ask of it before breakaway. The stick speed, extended over the
// breakpoints to which the curve still rises (a table rising to its last point has its stick
// speed at its first point, yet a block creeps wherever mu(v) meets its load ratio).
double risingSpeed(const friction::FrictionLaw& law) {
  double top = law.stickSpeed();
  std::vector<double> breaks = law.breakpoints();
  std::sort(breaks.begin(), breaks.end());
  for (const double b : breaks)
    if (b > top && law.coefficient(b) > law.coefficient(top)) top = b;
  return top;
}

// Largest of f over [lo, hi] near the sample `at` (golden-section search on the bracket of
// its neighbours, for a unimodal f there: a table's slope is quadratic on each piece).
template <class F>
double refinedMax(const F& f, double lo, double hi, double at) {
  constexpr double kGolden = 0.6180339887498949;
  double a = lo, b = hi;
  for (int i = 0; i < 60 && b - a > 1e-12 * hi; ++i) {
    const double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
    (f(c) < f(d) ? a : b) = (f(c) < f(d) ? c : d);
  }
  return std::max(f(at), f(0.5 * (a + b)));
}

// Steepest rise d mu / dv of a law over [0, v_max]: kSlopeSamples samples on each piece
// between its breakpoints (a table's points), the steepest refined between its neighbours.
// 16 samples over [0, v_max] alone miss a table's short steep segment (see stability.hpp).
double steepestSlope(const friction::FrictionLaw& law, double v_max) {
  auto slope = [&](double v) { return law.slope(v); };
  std::vector<double> edges{0.0, v_max};
  for (const double b : law.breakpoints())
    if (b > 0.0 && b < v_max) edges.push_back(b);
  std::sort(edges.begin(), edges.end());
  double best = slope(0.0);
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    const double lo = edges[k], step = (edges[k + 1] - lo) / kSlopeSamples;
    int arg = 0;
    double piece = slope(lo);
    for (int i = 1; i <= kSlopeSamples; ++i) {
      const double value = slope(lo + i * step);
      if (value > piece) {
        piece = value;
        arg = i;
      }
    }
    const double at = lo + arg * step;
    best = std::max(
        best, refinedMax(slope, std::max(lo, at - step), std::min(edges[k + 1], at + step), at));
  }
  return best;
}

// " friction (rate_state direct effect at slip speed 1e-05 m/s)".
std::string directEffect(const friction::DynamicFrictionLaw& law, double v_ref) {
  std::ostringstream e;
  e << " friction (" << law.name() << " direct effect at slip speed " << v_ref << " m/s)";
  return e.str();
}

// The direct effect grows without bound as the slip slows (rate-and-state's a / v): below
// v_ref explicit steps chatter, within about the speed where the limit equals the step.
std::string directEffectNote(const std::string& who, const friction::DynamicFrictionLaw& law,
                             double v_ref) {
  std::ostringstream note;
  note << who << ": friction law " << law.name()
       << " damps the slip at frozen state by its direct effect, " << law.directSlope(v_ref)
       << " s/m per unit load at the reference slip speed " << v_ref
       << " m/s (the fastest drive, or the law's stick speed) and more at slower slip; its "
          "limit uses that speed, so at that step explicit chatter stays below it";
  return note.str();
}

// Semi-implicit Euler advances a dynamic law's state from the step's starting slip
// (DynamicFrictionLaw::stableStep at frozen slip v_n; stuck, a bristle moves with the slip:
// z_{n+1} = z_n + h v_n) while the velocity takes the force at z_n. On the presliding mode
// y'' + c y' + k y = 0 (k, c: the bristles' stiffness and damping over the mass) the one-step
// matrix on (v, y) is then explicit Euler's, not semi-implicit Euler's:
//   [v+]   [1 - h c   -h k] [v]
//   [y+] = [h          1  ] [y],    det = 1 - h (c - h k),  trace = 2 - h c,
// so the update cancels h k of the damping c (semi-implicit Euler's own det is 1 - h c). Its
// spectral radius stays <= 1 for h <= c / k (Jury: det <= 1, and 1 + det >= |trace|, which
// overdamped, c^2 > 4 k, is h <= 4 / (c + sqrt(c^2 - 4 k)) >= 2 / c, never below semi-implicit
// Euler's own limit, 2x2 above); the step keeps half of the damping, h k <= c / 2, as the
// creep a ringing bristle leaves (friction/lugre_law.hpp: a stuck contact drifts while it
// moves) grows as the inverse of the ring's decay rate c - h k (a disc of 0.01 kg m^2 on a
// lugre pin, I_q / (N r^2) = 10 s^2/m: near h = c / k its ring decays 15 times slower than at
// small steps and at 0.9 c / k it creeps 2.1 times the reference's 18 um, at c / (2 k) 1.3
// times; measured in tests/core/stability_laws_test.cpp: off at 1.08 c / (2 k)).
// In units of the law: h <= sigma_d / (2 sigma0), whatever the load and mass (1.6 ms for
// lugre's defaults); it binds only an underdamped mode (c^2 < 4 k: c / (2 k) < 2 / c). An
// undamped bristle (dahl, sigma_d = 0) rings with growing amplitude at every step until its
// hysteresis holds it: no step is stable in this sense (a note, not a limit).
double explicitStateStep(const friction::DynamicFrictionLaw::Presliding& p) {
  return p.damping / (2.0 * p.stiffness);
}

std::string explicitStateNote(const std::string& who, const friction::DynamicFrictionLaw& law) {
  return who + ": friction law " + std::string(law.name()) +
         " has an undamped presliding spring; semi-implicit Euler advances its state from the "
         "step's starting slip, which feeds its ring at any step (the law's hysteresis bounds "
         "it): its creep converges only at first order in the step (use rk4)";
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
  // And a law's steepest rise (about 30 000 instructions: a scan of its slope) once per law,
  // not once per pair: the laws are the model's, immutable (the 32 000-sphere chute's 64 000
  // pairs of one material spent 1.8 G instructions here).
  std::map<const friction::FrictionLaw*, double> steepest;
  auto steepestOf = [&](const friction::FrictionLaw& law) {
    const auto [it, added] = steepest.try_emplace(&law, 0.0);
    if (added) it->second = steepestSlope(law, risingSpeed(law));
    return it->second;
  };
  // A bound found otherwise (the explicit bristle update below).
  auto considerStep = [&](double step, const auto& element) {
    if (step < report.limit.max_step) report.limit = {step, element()};
  };
  std::vector<bool> noted(model.materials.size(), false);  // one note per material
  double drive_speed = 0.0;  // fastest prescribed motion: kinematic bodies, moving surfaces
  for (const Body& b : model.bodies) {
    drive_speed = std::max(drive_speed, b.surfaceSpeedBound(model.options.duration));
    if (b.kind != BodyKind::kDynamic) drive_speed = std::max(drive_speed, b.velocity.norm());
    if (b.motion) drive_speed = std::max(drive_speed, b.motion->speedBound(model.options.duration));
  }
  for (const Joint& joint : model.joints)  // a slider driven along its axis
    if (joint.type == JointType::kPrismatic && joint.elements.drive)
      drive_speed =
          std::max(drive_speed, joint.elements.drive->signal
                                    ? joint.elements.drive->speedBound(model.options.duration)
                                    : std::abs(joint.elements.drive->velocity(0.0)));
  std::optional<TurnCheck> turns;                           // built at the first box pair
  std::vector<int> geometry_count(model.bodies.size(), 0);  // geometries per body (rolling)
  for (const Geometry& geometry : model.geometries)
    if (!geometry.body.isWorld()) ++geometry_count[geometry.body.value];
  for (const ContactPair& pair : contactPairsToCheck(model)) {
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
    auto tangent_at = [&] {
      if (!nonlinear) return std::string();
      std::ostringstream e;
      e << " (" << contact::normalLawName(law.type) << " at "
        << (load > 0.0 ? "its static depth " : "the stated depth ") << depth << " m)";
      return e.str();
    };
    consider(kPoints * normal.stiffness / m, kPoints * normal.damping / m,
             [&] { return who() + " normal" + tangent_at(); });

    // Rocking of a box on its face, about the face's two edges, on the same corners; its yaw
    // about the normal (friction's share, below).
    const std::optional<RestingFace> face = restingFace(model, pair);
    double yaw = 0.0;  // per unit tangential stiffness of each point
    if (face) {
      if (!turns) turns.emplace(model);
      // Only a face that carries the weight (its normal within 60 degrees of gravity): two
      // boxes side by side (a grid's neighbours, taken to touch) press on each other with no
      // load for friction.
      if (g > 0.0 && std::abs(face->normal.dot(model.options.gravity)) > 0.5 * g)
        yaw = yawPerPointStiffness(model, *turns, ga.body, gb.body, *face);
      for (int i = 0; i < 2; ++i) {
        const double per_point =
            rockingPerPointStiffness(model, *turns, ga.body, gb.body, *face, face->axes[i]);
        if (!(per_point > 0.0)) continue;
        consider(normal.stiffness * per_point, normal.damping * per_point, [&] {
          return who() + " rocking about " + model.geometries[face->box].name + "'s " +
                 "xyz"[face->axis_index[i]] + " axis" + tangent_at();
        });
      }
    }
    if (nonlinear && !(load > 0.0) && first_of_material) {
      std::ostringstream note;
      note << who() << ": normal law " << contact::normalLawName(law.type)
           << " carries no weight (no gravity); its limit uses the tangent stiffness at the "
              "stated depth "
           << kUnloadedDepth << " m (deeper contacts are stiffer: the limit scales as depth^-"
           << (law.elasticExponent() - 1.0) / 2.0 << ")";
      report.notes.push_back(note.str());
    }

    // Rolling and spinning resistance: the stuck angular spring-damper per point turning the
    // body that turns more easily (contact/rolling_resistance.hpp).
    for (const auto& [part, what] : {std::pair{mat.resistance.rolling.get(), "rolling"},
                                     std::pair{mat.resistance.spinning.get(), "spinning"}}) {
      if (part == nullptr) continue;
      const double inertia = smallestInertia(model, ga.body, gb.body);
      if (!(inertia > 0.0) || std::isinf(inertia)) continue;
      const friction::ElasticStickParams& p = part->params();
      const char* name = what;
      consider(kPoints * p.stiffness / inertia, kPoints * p.damping / inertia,
               [&] { return who() + " " + name + " resistance (angular stick spring)"; });
    }
    // Friction: every tangent stiffness and damping of the law, times r^2 for the largest
    // ratio r of an anisotropic material (contact/anisotropy.hpp: the law acts in the plane
    // scaled by R, so its stiffness along an axis is r^2 times the law's).
    const contact::Anisotropy& an = mat.anisotropy;
    const double r_max =
        an.active ? std::max({an.forward[0], an.forward[1], an.backward[0], an.backward[1]}) : 1.0;
    auto considerFriction = [&](double k, double c, auto&& what) {
      if (r_max == 1.0) return consider(k, c, what);
      consider(r_max * r_max * k, r_max * r_max * c, [&] {
        std::ostringstream e;
        e << what() << " x " << r_max * r_max << " (anisotropy's largest ratio, squared)";
        return e.str();
      });
    };
    // The slip of a round shape that rolls meets the inverse mass 1/m + r^2/I, not 1/m: each
    // friction element acting on the slip (not the state's own decay) scales by that factor.
    const RoundContact round = [&] {
      Vec3 normal = face ? face->normal : Vec3::Zero();
      for (const Geometry* geometry : {&ga, &gb})
        if (geometry->shape.type == contact::ShapeType::kHalfSpace) {
          const Mat3 r =
              geometry->body.isWorld()
                  ? Mat3::Identity()
                  : model.bodies[geometry->body.value].orientation.normalized().toRotationMatrix();
          normal = r * geometry->local_pose.linear().col(2);
        }
      if (normal.isZero() && g > 0.0) normal = model.options.gravity / g;
      if (normal.isZero()) return RoundContact{};
      if (!turns) turns.emplace(model);
      return roundContact(model, *turns, pair, normal, geometry_count);
    }();
    const double rolling = round.slip_factor;
    // A shape lying on its side yaws on its line's two ends (per unit point stiffness on the
    // kPoints points the load is shared on here: the two ends carry half the load each).
    if (!face && round.yaw > 0.0 && g > 0.0) yaw = round.yaw * kPoints / round.points;
    auto considerSlip = [&](double k, double c, auto&& what) {
      if (rolling == 1.0) return considerFriction(k, c, what);
      considerFriction(rolling * k, rolling * c, [&] {
        std::ostringstream e;
        e << what() << " x " << rolling << " (rolling: the slip's inverse mass 1/m + r^2/I)";
        return e.str();
      });
    };
    // Friction: a stateful law's stick spring-damper on the same points, tangentially.
    const friction::FrictionLaw& friction_law = *mat.friction;
    // The same per-point tangential stiffness and damping turning the body about the normal.
    auto consider_yaw = [&](double k_point, double c_point, const char* what) {
      if (yaw > 0.0)
        considerFriction(k_point * yaw, c_point * yaw, [&] {
          return who() + " friction (" + std::string(friction_law.name()) + what + ", yaw)";
        });
    };
    const double total = load * kPoints;
    if (const friction::DynamicFrictionLaw* dynamic = friction_law.dynamic()) {
      // The bristles' presliding spring-damper under the resting load, and the decay rate
      // of the internal state at the expected slip speeds (not for semi-implicit Euler,
      // whose update of the state is exact at frozen slip).
      const friction::DynamicFrictionLaw::Presliding p = dynamic->presliding();
      if (total > 0.0 && p.stiffness > 0.0) {
        considerSlip(p.stiffness * total / m, p.damping * total / m, [&] {
          return who() + " friction (" + std::string(friction_law.name()) + " presliding)";
        });
        consider_yaw(p.stiffness * load, p.damping * load, " presliding");
        if (integrator == IntegratorType::kSemiImplicitEuler && p.damping > 0.0)
          considerStep(explicitStateStep(p), [&] {
            return who() + " friction (" + std::string(friction_law.name()) +
                   " presliding, state update from the starting slip)";
          });
        else if (integrator == IntegratorType::kSemiImplicitEuler && first_of_material)
          report.notes.push_back(explicitStateNote(who(), *dynamic));
      }
      if (integrator != IntegratorType::kSemiImplicitEuler) {
        const double v = kSlipSpeedFactor * std::max(drive_speed, friction_law.stickSpeed());
        considerFriction(0.0, dynamic->stateStiffness(v), [&] {
          std::ostringstream e;
          e << who() << " friction (" << friction_law.name() << " internal state at slip speed "
            << v << " m/s)";
          return e.str();
        });
      }
      // The direct effect: the slip's damping at frozen state, at the reference slip speed.
      const double v_ref = std::max(drive_speed, friction_law.stickSpeed());
      const double direct = dynamic->directSlope(v_ref);
      if (total > 0.0 && direct > 0.0 && std::isfinite(direct)) {
        considerSlip(0.0, direct * total / m,
                     [&] { return who() + directEffect(*dynamic, v_ref); });
        consider_yaw(0.0, direct * load, " direct effect");
      }
      if (direct > 0.0 && first_of_material)
        report.notes.push_back(directEffectNote(who(), *dynamic, v_ref));
      // Across the slip, a law without bristles turns its force with the slip's direction at
      // once: damping mu(v) / v per unit load (rate_state: mu0 / a = 20 times its direct
      // effect). A memoryless law's mu(v) / v is a secant of its curve, within its slope.
      // Only for a body free to slide across (not one on a slide or planar_translation joint)
      // and, in yaw, for one free to turn.
      const double across = friction_law.coefficient(v_ref) / v_ref;
      if (!turns) turns.emplace(model);
      const Vec3 normal = face ? face->normal : Vec3(model.options.gravity.normalized());
      const bool slides = g > 0.0 && (turns->canSlideAcross(model, ga.body, normal) ||
                                      turns->canSlideAcross(model, gb.body, normal));
      if (total > 0.0 && p.stiffness == 0.0 && across > 0.0 && std::isfinite(across) && slides)
        considerSlip(0.0, across * total / m, [&] {
          std::ostringstream e;
          e << who() << " friction (" << friction_law.name() << " across the slip at " << v_ref
            << " m/s)";
          return e.str();
        });
      if (total > 0.0 && p.stiffness == 0.0 && across > 0.0 && std::isfinite(across))
        consider_yaw(0.0, std::max(across, direct) * load, " across the slip");
    }
    if (friction_law.stateful()) {
      const Tangent stick = stickTangent(friction_law);
      considerSlip(kPoints * stick.stiffness / m, kPoints * stick.damping / m, [&] {
        return who() + " friction (" + std::string(friction_law.name()) + " stick spring)";
      });
      consider_yaw(stick.stiffness, stick.damping, " stick spring");
    }
    // ... and the sticking slope of its mu(v) curve (a memoryless law's only stiffness).
    const double stick_speed = friction_law.stickSpeed();
    double slope = friction_law.slope(0.0);
    if (std::isfinite(slope)) {
      // Steepest rise where mu still rises (a haversine step is steepest mid-way).
      slope = steepestOf(friction_law);
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
    if (std::isfinite(slope) && slope > 0.0) {
      considerSlip(0.0, slope * g,
                   [&] { return who() + " friction (" + std::string(friction_law.name()) + ")"; });
      consider_yaw(0.0, slope * load, "");
    }
  }
  for (const SpringDamper& s : model.springs) {
    const double m = reducedMass(model, s.body_a, s.body_b);
    consider(s.stiffness / m, s.damping / m, [&] { return "spring '" + s.name + "'"; });
  }
  // Bushings: per axis of frame A (at the initial pose), translation on the reduced mass and
  // rotation on the reduced moment about that axis.
  for (const Bushing& bushing : model.bushings) {
    const double m = reducedMass(model, bushing.body_a, bushing.body_b);
    const Quat frame_a =
        (bushing.body_a.isWorld() ? Quat::Identity()
                                  : model.bodies[bushing.body_a.value].orientation) *
        bushing.orientation_a;
    for (int i = 0; i < 3; ++i) {
      const char* axis_name[] = {"x", "y", "z"};
      auto who = [&](const char* what) {
        return "bushing '" + bushing.name + "' " + what + " " + axis_name[i];
      };
      consider(bushing.stiffness[i] / m, bushing.damping[i] / m, [&] { return who("along"); });
      const double inertia =
          reducedInertia(model, bushing.body_a, bushing.body_b, frame_a * Vec3::Unit(i));
      consider(bushing.rotational_stiffness[i] / inertia, bushing.rotational_damping[i] / inertia,
               [&] { return who("about"); });
    }
  }
  for (const TorsionalSpring& spring : model.torsional_springs) {
    const Quat to_world =
        spring.body_a.isWorld() ? Quat::Identity() : model.bodies[spring.body_a.value].orientation;
    const double inertia =
        reducedInertia(model, spring.body_a, spring.body_b, to_world * spring.axis_a);
    consider(spring.stiffness / inertia, spring.damping / inertia,
             [&] { return "torsional spring '" + spring.name + "'"; });
  }
  // Joint elements on the coordinate's inertia (core/joint_forces.hpp): spring and limit
  // stiffness, damping and the friction's sticking slope (both held to I_q / (2 h) at fixed
  // steps), a servo's gains.
  const bool fixed_step =
      integrator == IntegratorType::kRk4 || integrator == IntegratorType::kSemiImplicitEuler;
  const double h = model.options.time_step;
  const std::vector<int> joint_of_child = jointOfChild(model);
  // A dynamic law on a joint (not capped: core/joint_forces.hpp) as on a contact, on the
  // coordinate: slip r q', force N times the law's, torque r times the force, so its
  // stiffness and damping per unit load act with N r^2 on I_q (`per_inertia` = N r^2 / I_q).
  auto considerDynamicJointFriction = [&](const friction::DynamicFrictionLaw& law,
                                          double per_inertia, const auto& who) {
    if (!(per_inertia > 0.0)) return;
    const friction::DynamicFrictionLaw::Presliding p = law.presliding();
    if (p.stiffness > 0.0) {
      consider(p.stiffness * per_inertia, p.damping * per_inertia,
               [&] { return who("presliding"); });
      // Semi-implicit Euler's state update from the starting slip (explicitStateStep).
      if (integrator == IntegratorType::kSemiImplicitEuler && p.damping > 0.0)
        considerStep(explicitStateStep(p),
                     [&] { return who("presliding, state update from the starting slip"); });
      else if (integrator == IntegratorType::kSemiImplicitEuler)
        report.notes.push_back(explicitStateNote(who("presliding"), law));
    }
    // The state's decay, as on a contact (not for semi-implicit Euler: exact at frozen slip).
    const double v_ref = std::max(drive_speed, law.stickSpeed());
    const double v = kSlipSpeedFactor * v_ref;
    if (integrator != IntegratorType::kSemiImplicitEuler)
      consider(0.0, law.stateStiffness(v), [&] {
        std::ostringstream e;
        e << "internal state at slip speed " << v << " m/s";
        return who(e.str().c_str());
      });
    const double direct = law.directSlope(v_ref);
    if (direct > 0.0 && std::isfinite(direct)) {
      consider(0.0, direct * per_inertia, [&] {
        std::ostringstream e;
        e << "direct effect at slip speed " << v_ref << " m/s";
        return who(e.str().c_str());
      });
      report.notes.push_back(directEffectNote(who("direct effect"), law, v_ref));
    }
  };
  for (int ji = 0; ji < static_cast<int>(model.joints.size()); ++ji) {
    const Joint& joint = model.joints[ji];
    const JointElements& el = joint.elements;
    if (!hasScalarCoordinate(joint.type) || !el.hasForces()) continue;
    const double inertia = coordinateInertia(model, ji, joint_of_child);
    if (!(inertia > 0.0) || std::isinf(inertia)) continue;
    const double cap = fixed_step && h > 0.0 ? kDissipativeSlopeShare * inertia / h
                                             : std::numeric_limits<double>::infinity();
    double slope = 0.0;  // friction: d tau / d q' at sticking [N m s/rad or N s/m]
    if (el.friction) {
      const JointFriction& f = *el.friction;
      const double r = isAngular(joint.type) ? f.radius : 1.0;
      double load = f.load == JointFrictionLoad::kConstant ? f.normal_force : 0.0;
      if (f.load == JointFrictionLoad::kReaction) {
        // The reaction carries at least the child's weight.
        load = model.bodies[joint.child.value].mass * g;
      }
      const double mu_slope = std::isfinite(f.law->slope(0.0))
                                  ? steepestSlope(*f.law, risingSpeed(*f.law))
                                  : f.law->slope(0.0);
      if (std::isfinite(mu_slope)) slope = mu_slope * load * r * r;
      if (const friction::DynamicFrictionLaw* dynamic = f.law->dynamic())
        considerDynamicJointFriction(*dynamic, load * r * r / inertia, [&](const char* what) {
          std::ostringstream e;
          e << "joint '" << joint.name << "' friction (" << f.law->name() << " " << what
            << ") on body '" << model.bodies[joint.child.value].name << "' (coordinate inertia "
            << inertia << ", load " << load << " N)";
          return e.str();
        });
    }
    const double damping = std::min(el.damping + slope, cap);
    if (el.damping + slope > cap)
      report.held_joints.push_back(
          {ji, el.damping + slope, cap, kDissipativeSlopeShare * inertia / (el.damping + slope)});
    auto who = [&](const char* what) {
      std::ostringstream e;
      e << "joint '" << joint.name << "' " << what << " on body '"
        << model.bodies[joint.child.value].name << "' (coordinate inertia " << inertia << ")";
      return e.str();
    };
    if (el.spring)
      consider(el.spring->stiffness / inertia, damping / inertia, [&] { return who("spring"); });
    if (el.limit && el.limit->stiffness > 0.0)
      consider(el.limit->stiffness / inertia, el.limit->damping / inertia,
               [&] { return who("limit"); });
    if (damping > 0.0)
      consider(0.0, damping / inertia,
               [&] { return who(el.friction ? "damping and friction" : "damping"); });
    // A servo: a spring kp and damper kd to its target (core/joint_actuator.hpp), not capped.
    if (const auto& a = el.actuator; a && a->kind != ActuatorKind::kMotor)
      consider(a->kp / inertia, a->kd / inertia,
               [&] { return who(("actuator '" + a->name + "'").c_str()); });
  }
  return report;
}

}  // namespace tribo
