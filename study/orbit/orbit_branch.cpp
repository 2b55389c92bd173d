#include "study/orbit/orbit_branch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <thread>
#include <utility>

#include "io/file_read.hpp"
#include "io/scene_parameters.hpp"
#include "study/csv_text.hpp"
#include "study/modes/modes.hpp"
#include "study/orbit/branch_switch.hpp"
#include "study/orbit/forcing.hpp"
#include "study/orbit/hopf_start.hpp"
#include "study/orbit/orbit_coordinates.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study {

namespace {

// An orbit whose amplitude falls below this fraction of the first one's has collapsed.
constexpr double kCollapsed = 1e-6;
// A turn of the parameter where the amplitude has a minimum below this fraction of the
// branch's largest is a Hopf point, not a fold.
constexpr double kHopfAmplitude = 0.2;
// The step grows after a corrector that converged in at most 2 iterations, or in 3 that moved
// the prediction by at most this fraction of the step (the branch is nearly straight there).
constexpr double kStraight = 0.02;
// Locating a bifurcation to switch at: orbits corrected at fixed p at most, and |g| enough.
constexpr int kLocateEvaluations = 12;
constexpr double kLocated = 1e-9;

std::string assignment(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

// A forced branch's period: K forcing periods of the scene at p (`given` as forcingPeriod
// takes it: a period the user gave, or 0 to read it from the inputs).
struct ForcedPeriod {
  int periods = 1;
  double given = 0;
};

// The shooting rows and their Jacobian at z = (y0, T, p), the scene reloaded at p and p +- dp:
// the orbit closing, then the phase (autonomous) or the period fixed by the forcing (forced).
class BranchShooter {
 public:
  BranchShooter(const io::SceneDocument& document, std::vector<std::string> overrides,
                std::string parameter, const OrbitCoordinates& coords, Eigen::Index phase,
                Eigen::VectorXd floor, double fd_step, double dp, unsigned threads,
                std::optional<ForcedPeriod> forced)
      : document_(document),
        overrides_(std::move(overrides)),
        parameter_(std::move(parameter)),
        coords_(coords),
        phase_(phase),
        floor_(std::move(floor)),
        fd_step_(fd_step),
        dp_(dp),
        threads_(threads),
        forced_(forced) {}

  // The same rows for orbits `factor` times as long: a forced orbit spans factor K forcing
  // periods (an autonomous one's period is an unknown anyway).
  BranchShooter withPeriods(int factor) const {
    BranchShooter twin = *this;
    if (twin.forced_) twin.forced_->periods *= factor;
    return twin;
  }

  io::Scene sceneAt(double p) const {
    std::vector<std::string> o = overrides_;
    o.push_back(assignment(parameter_, p));
    return document_.load(o);
  }

  // F (n + 1: the orbit closing; the phase, or for a forced orbit T - K P(p)), A = dF/dz
  // ((n + 1) x (n + 2)) and the monodromy matrix. Throws OrbitError (a failed step, no
  // forcing period) or io::SceneError (p outside the scene's range).
  void evaluate(const Eigen::VectorXd& z, Eigen::VectorXd& F, Eigen::MatrixXd& A,
                Eigen::MatrixXd& monodromy) const {
    const Eigen::Index n = coords_.size();
    const Eigen::VectorXd y = z.head(n);
    const double T = z[n], p = z[n + 1];
    const io::Scene at = sceneAt(p), up_p = sceneAt(p + dp_), down_p = sceneAt(p - dp_);
    const shooting::Flow flow(at.model, coords_), flow_up(up_p.model, coords_),
        flow_down(down_p.model, coords_);
    F.resize(n + 1);
    F.head(n) = flow(y, T) - y;
    auto period = [&](const io::Scene& scene) {
      return forced_->periods * forcingPeriod(*scene.model, forced_->given);
    };
    F[n] = forced_ ? T - period(at) : y[phase_];
    A = Eigen::MatrixXd::Zero(n + 1, n + 2);
    shooting::parallelColumns(n + 2, threads_, [&](Eigen::Index j) {
      // Central differences, as periodic_orbit.cpp takes them.
      if (j < n) {
        const double d = fd_step_ * std::max(std::abs(y[j]), floor_[j]);
        Eigen::VectorXd up = y, down = y;
        up[j] += d;
        down[j] -= d;
        A.col(j).head(n) = (flow(up, T) - flow(down, T)) / (2 * d);
      } else if (j == n) {
        const double d = fd_step_ * T;
        A.col(n).head(n) = (flow(y, T + d) - flow(y, T - d)) / (2 * d);
      } else {
        A.col(n + 1).head(n) = (flow_up(y, T) - flow_down(y, T)) / (2 * dp_);
      }
    });
    monodromy = A.topLeftCorner(n, n);
    A.topLeftCorner(n, n) -= Eigen::MatrixXd::Identity(n, n);
    if (forced_) {
      A(n, n) = 1.0;
      A(n, n + 1) = -(period(up_p) - period(down_p)) / (2 * dp_);
    } else {
      A(n, phase_) = 1.0;
    }
  }

 private:
  const io::SceneDocument& document_;
  std::vector<std::string> overrides_;
  std::string parameter_;
  const OrbitCoordinates& coords_;
  Eigen::Index phase_;
  Eigen::VectorXd floor_;
  double fd_step_, dp_;
  unsigned threads_;
  std::optional<ForcedPeriod> forced_;
};

// The unit tangent of the branch at a point with Jacobian A, in the scaled unknowns z / w:
// A diag(w) t = 0, |t| = 1, oriented along `along` (scaled too).
Eigen::VectorXd unitTangent(const Eigen::MatrixXd& A, const Eigen::VectorXd& along,
                            const Eigen::VectorXd& w) {
  const Eigen::Index rows = A.rows(), cols = A.cols();
  Eigen::MatrixXd J(rows + 1, cols);
  J.topRows(rows) = A * w.asDiagonal();
  J.row(rows) = along.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows + 1);
  rhs[rows] = 1.0;
  Eigen::VectorXd t = J.colPivHouseholderQr().solve(rhs);
  t.normalize();
  if (t.dot(along) < 0.0) t = -t;
  return t;
}

struct Correction {
  bool ok = false;
  std::string why;
  Eigen::VectorXd z, F;
  Eigen::MatrixXd A, monodromy;
  int iterations = 0;
  double residual = 0;
};

// Newton from z0 on the closing and phase rows and one linear row, row . z = value: the
// arclength row of a continuation step (row d, value d . z_pred) or the amplitude row of a
// Hopf start (row e_obs, value the fixed peak, hopf_start.hpp). A correction farther than
// `reach` from z0 in the norm of the weights w fails.
Correction newtonWithRow(const BranchShooter& shooter, const Eigen::VectorXd& z0,
                         const Eigen::VectorXd& row, double value, double reach,
                         const Eigen::VectorXd& w, int max_iterations, double tolerance) {
  Correction c;
  c.z = z0;
  const Eigen::Index n = z0.size() - 2;
  for (int it = 0;; ++it) {
    try {
      shooter.evaluate(c.z, c.F, c.A, c.monodromy);
    } catch (const std::exception& e) {  // OrbitError, io::SceneError
      c.why = e.what();
      return c;
    }
    c.iterations = it;
    const double gap = row.dot(c.z) - value;
    c.residual = std::hypot(c.F.norm(), gap) / (1.0 + c.z.head(n).norm());
    if (c.residual <= tolerance) {
      c.ok = true;
      return c;
    }
    if (it == max_iterations) {
      c.why = "Newton's iteration did not converge in " + std::to_string(max_iterations) +
              " iterations (residual " + shooting::messageNumber(c.residual) + ")";
      return c;
    }
    Eigen::MatrixXd J(n + 2, n + 2);
    J.topRows(n + 1) = c.A;
    J.row(n + 1) = row.transpose();
    Eigen::VectorXd rhs(n + 2);
    rhs.head(n + 1) = -c.F;
    rhs[n + 1] = -gap;
    const Eigen::VectorXd dz = J.colPivHouseholderQr().solve(rhs);
    // A damped step: the period changes by at most a quarter of itself.
    const double T = c.z[n];
    const double scale = std::min(1.0, 0.25 * T / std::max(std::abs(dz[n]), 1e-300));
    c.z += scale * dz;
    if (!(c.z[n] > 0.0) || !c.z.allFinite()) {
      c.why =
          "Newton's iteration left the orbit (period " + shooting::messageNumber(c.z[n]) + " s)";
      return c;
    }
    const double moved = (c.z - z0).cwiseQuotient(w).norm();
    if (moved > reach) {
      c.why = "the correction (" + shooting::messageNumber(moved) +
              ") went farther than the step (" + shooting::messageNumber(reach) + ")";
      return c;
    }
  }
}

// The corrector of a continuation step from the prediction z_pred = z_k + ds w d (d a unit
// direction in the scaled unknowns z / w): the correction normal to d there, no longer than ds.
Correction correct(const BranchShooter& shooter, const Eigen::VectorXd& z_pred,
                   const Eigen::VectorXd& d, double ds, const Eigen::VectorXd& w,
                   int max_iterations, double tolerance) {
  const Eigen::VectorXd row = d.cwiseQuotient(w);
  return newtonWithRow(shooter, z_pred, row, row.dot(z_pred), ds, w, max_iterations, tolerance);
}

// The first orbit of a Hopf start: z[index] = value keeps it off the equilibrium.
Correction solveFixedAmplitude(const BranchShooter& shooter, const Eigen::VectorXd& z0,
                               Eigen::Index index, double value, int max_iterations,
                               double tolerance) {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(z0.size());
  row[index] = 1.0;
  return newtonWithRow(shooter, z0, row, value, INFINITY, Eigen::VectorXd::Ones(z0.size()),
                       max_iterations, tolerance);
}

// Modulus of the largest multiplier among the non-trivial ones that `pick` selects (0: none).
template <typename Pick>
double largestOf(const BranchPoint& p, Pick pick) {
  double m = 0.0;
  for (std::size_t i = 0; i < p.multipliers.size(); ++i)
    if (static_cast<int>(i) != p.trivial && pick(p.multipliers[i]))
      m = std::max(m, std::abs(p.multipliers[i]));
  return m;
}

bool isReal(std::complex<double> mu) {
  return std::abs(mu.imag()) <= 1e-9 * std::max(1.0, std::abs(mu));
}

template <typename Pick>
int countOf(const BranchPoint& p, Pick pick) {
  int count = 0;
  for (std::size_t i = 0; i < p.multipliers.size(); ++i)
    if (static_cast<int>(i) != p.trivial && pick(p.multipliers[i])) ++count;
  return count;
}

// Where g (a multiplier's modulus) crosses 1 between points a and b, by linear interpolation
// in the parameter (clamped to the interval).
double crossing(const BranchPoint& a, const BranchPoint& b, double ga, double gb) {
  double s = gb != ga ? (1.0 - ga) / (gb - ga) : 0.5;
  s = std::clamp(s, 0.0, 1.0);
  return a.parameter + s * (b.parameter - a.parameter);
}

// The scaled norm's weight of each state entry: its range along the orbit from y0 over T,
// at least 1e-3 of the largest range of its kind (positions, rotations, velocities, angular
// velocities, friction states: by the entry's name, "box.x", "box.rx", "box.vx", "box.wx",
// "z3") and 1e-3 of `floor` (the finite differences' scale: 10 um, 10 um/s, 10 urad), so that
// an entry that does not move (a box's turn on a flat belt, its rounding 1e-19) weighs
// nothing.
Eigen::VectorXd stateScales(const shooting::Flow& flow, const OrbitCoordinates& coords,
                            const Eigen::VectorXd& y0, double T, const Eigen::VectorXd& floor) {
  Eigen::VectorXd lo = y0, hi = y0;
  flow(y0, T, [&](double, const State& state) {
    const Eigen::VectorXd y = coords.toVector(state);
    lo = lo.cwiseMin(y);
    hi = hi.cwiseMax(y);
  });
  const Eigen::VectorXd range = hi - lo;
  auto kind = [&](Eigen::Index i) { return coords.kind(i); };
  std::map<char, double> largest;
  for (Eigen::Index i = 0; i < range.size(); ++i)
    largest[kind(i)] = std::max(largest[kind(i)], range[i]);
  Eigen::VectorXd w(range.size());
  for (Eigen::Index i = 0; i < range.size(); ++i) {
    const double group = largest[kind(i)];
    w[i] = std::max({range[i], 1e-3 * group, 1e-3 * floor[i]});
  }
  return w;
}

}  // namespace

std::string arclengthNormName(ArclengthNorm norm) {
  return norm == ArclengthNorm::kScaled ? "scaled" : "si";
}

std::string branchEventName(BranchEventKind kind) {
  switch (kind) {
    case BranchEventKind::kFold:
      return "fold";
    case BranchEventKind::kPeriodDoubling:
      return "period_doubling";
    case BranchEventKind::kTorus:
      return "torus";
    case BranchEventKind::kStabilityChange:
      return "stability_change";
    case BranchEventKind::kGrazing:
      return "grazing";
    case BranchEventKind::kHopf:
      return "hopf";
  }
  return "unknown";
}

std::vector<BranchEvent> detectBranchEvents(const std::vector<BranchPoint>& points,
                                            double stick_speed, bool autonomous) {
  std::vector<BranchEvent> events;
  auto below_minus_one = [](std::complex<double> mu) { return isReal(mu) && mu.real() < -1.0; };
  auto real_negative = [](std::complex<double> mu) { return isReal(mu) && mu.real() < 0.0; };
  auto complex_outside = [](std::complex<double> mu) { return !isReal(mu) && std::abs(mu) > 1.0; };
  auto complex_any = [](std::complex<double> mu) { return !isReal(mu); };
  auto any = [](std::complex<double>) { return true; };
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const BranchPoint &a = points[i], &b = points[i + 1];
    if (a.dp_ds * b.dp_ds < 0.0) {
      // dp/ds linear in s between the points: zero at sigma = a ds / (a - b) past point i,
      // where p(s), its integral, has its vertex p_i + a sigma / 2.
      const double ds = b.arclength - a.arclength;
      const double sigma = a.dp_ds * ds / (a.dp_ds - b.dp_ds);
      // Through a Hopf point the branch passes the steady state (amplitude zero) and p(s)
      // turns like at a fold: p - p_H ~ eps^2 for the orbit of amplitude eps, which the phase
      // condition also meets with -eps (the same orbit from its minimum). Told apart by the
      // amplitude: falling into the interval, rising after it, small against the branch's.
      double largest = 0.0;
      for (const BranchPoint& q : points) largest = std::max(largest, q.amplitude_pp);
      const bool falls = i > 0 && points[i - 1].amplitude_pp > a.amplitude_pp;
      const bool rises = i + 2 >= points.size() || points[i + 2].amplitude_pp > b.amplitude_pp;
      const bool hopf = autonomous && falls && rises &&
                        std::min(a.amplitude_pp, b.amplitude_pp) < kHopfAmplitude * largest;
      events.push_back({hopf ? BranchEventKind::kHopf : BranchEventKind::kFold, i, i + 1,
                        a.parameter + 0.5 * a.dp_ds * sigma});
    }
    bool explained = false;
    if (countOf(a, below_minus_one) != countOf(b, below_minus_one)) {
      events.push_back({BranchEventKind::kPeriodDoubling, i, i + 1,
                        crossing(a, b, largestOf(a, real_negative), largestOf(b, real_negative))});
      explained = true;
    }
    if (countOf(a, complex_outside) != countOf(b, complex_outside)) {
      events.push_back({BranchEventKind::kTorus, i, i + 1,
                        crossing(a, b, largestOf(a, complex_any), largestOf(b, complex_any))});
      explained = true;
    }
    if (a.stable != b.stable && !explained)
      events.push_back({BranchEventKind::kStabilityChange, i, i + 1,
                        crossing(a, b, largestOf(a, any), largestOf(b, any))});
    if (stick_speed > 0.0 && std::isfinite(a.min_slip) && std::isfinite(b.min_slip) &&
        (a.min_slip < stick_speed) != (b.min_slip < stick_speed))
      events.push_back({BranchEventKind::kGrazing, i, i + 1,
                        crossing(a, b, a.min_slip / stick_speed, b.min_slip / stick_speed)});
  }
  return events;
}

BranchResult continueOrbit(const std::string& path, const std::vector<std::string>& overrides,
                           const BranchSpec& spec,
                           const std::function<void(const BranchPoint&, std::size_t)>& progress) {
  std::string text;
  try {
    text = io::readFileBounded(path, "scene file", io::kMaxSceneBytes);
  } catch (const io::FileReadError& e) {
    throw io::SceneError(e.what());
  }
  return continueOrbitFromText(text, path, overrides, spec, progress);
}

BranchResult continueOrbitFromText(
    const std::string& yaml, const std::string& path, const std::vector<std::string>& overrides,
    const BranchSpec& spec, const std::function<void(const BranchPoint&, std::size_t)>& progress) {
  const auto wall = std::chrono::steady_clock::now();
  if (!std::isfinite(spec.from) || !std::isfinite(spec.to) || spec.from == spec.to)
    throw std::invalid_argument("the branch's range " + shooting::messageNumber(spec.from) + ":" +
                                shooting::messageNumber(spec.to) + " is empty or not finite");
  const io::SceneDocument document(yaml, path);
  std::string forced;  // why the scene is forced (study/orbit/forcing.hpp), empty if autonomous
  {
    const io::Scene base = document.load(overrides);
    const auto it = std::find_if(base.parameters.begin(), base.parameters.end(),
                                 [&](const auto& kv) { return kv.first == spec.parameter; });
    if (it == base.parameters.end()) {
      std::string names;
      for (const auto& [name, value] : base.parameters) {
        if (!names.empty()) names += ", ";
        names += name;
      }
      throw io::SceneError("'" + spec.parameter + "' is not a parameter of " + path +
                           " (expected one of: " + names + ")");
    }
    if (!io::parseNumber(it->second))
      throw io::SceneError("parameter '" + spec.parameter + "' of " + path + " is '" + it->second +
                           "': expected a number to continue in");
    forced = nonAutonomous(*base.model);
  }
  BranchResult r;
  r.forced = !forced.empty();
  r.periods = spec.orbit.periods;
  if (r.forced && spec.from_hopf)
    throw OrbitError(
        "a Hopf point of steady sliding starts a branch of autonomous orbits; in "
        "this scene " +
        forced + ": start the branch from the forced orbit at " +
        shooting::messageNumber(spec.from) + " (without --from-hopf)");
  if (!r.forced && (spec.orbit.period > 0.0 || spec.orbit.periods != 1))
    throw OrbitError(
        "--period and --periods apply to forced scenes; this one is autonomous (no input "
        "varies in time)");
  const auto sceneAt = [&](double p) {
    std::vector<std::string> o = overrides;
    o.push_back(assignment(spec.parameter, p));
    return document.load(o);
  };
  // The start: the orbit a settling run leads Newton to at `from`, or the Hopf point of steady
  // sliding in the range (its orbit is solved for below, once the shooter is set up).
  std::unique_ptr<OrbitResult> orbit;
  std::unique_ptr<HopfPoint> hopf;
  if (spec.from_hopf) {
    hopf = std::make_unique<HopfPoint>(locateHopf(sceneAt, spec.from, spec.to));
    r.hopf_parameter = hopf->parameter;
    r.hopf_omega = hopf->omega;
    r.hopf_analyses = hopf->analyses;
  } else {
    // (An equilibrium Newton may find instead, from a damped settling run, is refused there.)
    orbit = std::make_unique<OrbitResult>(findPeriodicOrbit(sceneAt(spec.from), spec.orbit));
  }
  const double p0 = hopf ? hopf->parameter : spec.from;
  const io::Scene first = sceneAt(p0);
  const int body = r.forced ? shooting::observedBody(first) : shooting::shootableBody(first);
  const int axis = first.output.summary.coordinate;
  r.observed = first.output.summary.body + "." + std::string(1, "xyz"[axis]);
  // A forced orbit's start is taken at t = 0, a whole number of forcing periods whatever the
  // parameter makes the period (the settling run ended at one).
  State reference = hopf ? hopf->steady : orbit->reference;
  if (r.forced) reference.time = 0.0;
  const OrbitCoordinates coords(*first.model, reference);
  r.coordinates = coords.names();
  const Eigen::Index n = coords.size();
  // The Hopf start's guess: steady sliding plus eps times the mode's real part.
  const double eps = spec.hopf_amplitude > 0.0 ? spec.hopf_amplitude : kDefaultHopfAmplitude;
  const Eigen::Index amplitude_index = coords.positionIndex(body, axis);
  Eigen::VectorXd y_steady, y0;
  double T0 = 0;
  if (hopf) {
    y_steady = coords.toVector(hopf->steady);
    y0 = y_steady + eps * hopfDirection(*hopf, *first.model, coords, body, axis);
    T0 = 2.0 * std::numbers::pi / hopf->omega;
  } else {
    y0 = orbit->start;
    T0 = orbit->period;
  }
  const double range = std::abs(spec.to - spec.from);
  const double fd_step = shooting::fdStepFor(*first.model, spec.orbit.fd_step);
  const double dp =
      spec.fd_parameter > 0.0 ? spec.fd_parameter : fd_step * std::max(std::abs(spec.from), range);
  const unsigned threads =
      std::max(1u, spec.orbit.threads ? spec.orbit.threads : std::thread::hardware_concurrency());
  const Eigen::VectorXd floor = shooting::fdFloor(y0, reference.friction_values.size());
  const BranchShooter shooter(
      document, overrides, spec.parameter, coords, coords.velocityIndex(body, axis), floor, fd_step,
      dp, threads,
      r.forced ? std::optional<ForcedPeriod>({spec.orbit.periods, spec.orbit.period})
               : std::nullopt);
  // The arclength's weights w: ones (SI), or each unknown's scale (orbit_branch.hpp).
  const bool scaled = spec.norm == ArclengthNorm::kScaled;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(n + 2);
  if (scaled) {
    w.head(n) =
        hopf ? floor : stateScales(shooting::Flow(first.model, coords), coords, y0, T0, floor);
    w[n] = T0;
    w[n + 1] = range;
  }
  r.norm = spec.norm;
  r.weights = w;
  const double step = spec.step > 0.0 ? spec.step : scaled ? 0.1 : range / 10.0;
  const double min_step = spec.min_step > 0.0 ? spec.min_step : step / 64.0;
  const double max_step = spec.max_step > 0.0 ? spec.max_step : 4.0 * step;
  const double direction = spec.to > spec.from ? 1.0 : -1.0;
  const double stick_speed = first.output.summary.stick_speed;
  r.stick_speed = stick_speed;

  // A converged point: its multipliers, tangent and the sampled orbit's amplitude.
  auto makePoint = [&](const BranchShooter& shooter, const Eigen::VectorXd& z,
                       const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& tangent,
                       const Eigen::VectorXd& w) {
    BranchPoint pt;
    pt.start = z.head(n);
    pt.period = z[n];
    pt.parameter = z[n + 1];
    pt.dp_ds = w[n + 1] * tangent[n + 1];
    shooting::Floquet f = shooting::floquet(monodromy, !r.forced);
    pt.multipliers = std::move(f.multipliers);
    pt.trivial = f.trivial;
    pt.trivial_error = f.trivial_error;
    pt.stable = f.stable;
    pt.largest = f.largest;
    const io::Scene at = shooter.sceneAt(pt.parameter);
    const shooting::Flow flow(at.model, coords);
    const auto b = static_cast<std::size_t>(body);
    std::vector<double>& x = pt.x;
    pt.t.push_back(0.0);
    x.push_back(coords.fromVector(pt.start).bodies[b].position[axis]);
    // The slip speed as the run summary takes it: the largest over the body's contact points,
    // counted where the body touches (normal force > 0); each sample weighs its step.
    double t_prev = 0.0, dt = 0.0, stuck = 0.0, touching = 0.0, min_slip = INFINITY;
    flow(
        pt.start, pt.period,
        [&](double t, const State& s) {
          pt.t.push_back(t);
          x.push_back(s.bodies[b].position[axis]);
          dt = t - t_prev;
          t_prev = t;
        },
        [&](const Workspace& ws) {
          double slip = 0.0, normal = 0.0;
          for (const auto& c : ws.contacts) {
            const ContactPair pair = at.model->contactPair(c.point.pair);
            if (at.model->geometries[pair.geometry_a].body.value != body &&
                at.model->geometries[pair.geometry_b].body.value != body)
              continue;
            slip = std::max(slip, c.slip.stableNorm());
            normal += c.normal_force;
          }
          if (!(normal > 0.0)) return;
          touching += dt;
          min_slip = std::min(min_slip, slip);
          if (slip < stick_speed) stuck += dt;
        });
    if (touching > 0.0) {
      pt.min_slip = min_slip;
      pt.stick_fraction = stuck / pt.period;
    }
    // A forced orbit peaks anywhere between samples: refined as the minimum is (an autonomous
    // one starts at its peak).
    std::vector<double> negated(x.size());
    std::transform(x.begin(), x.end(), negated.begin(), [](double v) { return -v; });
    pt.x_max =
        r.forced ? -shooting::refinedMinimum(negated) : *std::max_element(x.begin(), x.end());
    pt.x_min = shooting::refinedMinimum(x);
    pt.amplitude_pp = pt.x_max - pt.x_min;
    // Steady sliding at the same parameter, as `tribo modes` analyses it: the branch beside
    // the orbits (none where the scene has no steady state or the analysis fails, nor for a
    // forced scene, whose inputs keep it from resting in any state).
    pt.steady_growth = NAN;
    if (!r.forced) {
      try {
        pt.steady_growth = analyzeModes(at).leading().growth_rate;
      } catch (const std::exception&) {
        pt.steady_growth = NAN;
      }
    }
    return pt;
  };

  // The first point: the orbit found, its Jacobian with the parameter's column for the tangent;
  // from a Hopf point, the orbit of amplitude eps solved for first, and the tangent on which
  // the amplitude grows.
  Eigen::VectorXd z(n + 2);
  z << y0, T0, p0;
  Eigen::VectorXd F;
  Eigen::MatrixXd A, monodromy;
  Eigen::VectorXd along = Eigen::VectorXd::Zero(n + 2);
  int first_iterations = 0;
  if (hopf) {
    const Correction c = solveFixedAmplitude(
        shooter, z, amplitude_index, y_steady[amplitude_index] + eps,
        std::max(spec.max_corrector, spec.orbit.max_iterations), spec.orbit.tolerance);
    if (!c.ok)
      throw OrbitError("no orbit of amplitude " + shooting::messageNumber(eps) +
                       " at the Hopf point " + spec.parameter + " ~ " +
                       shooting::messageNumber(hopf->parameter) + ": " + c.why +
                       " (a smaller --hopf-amplitude, or a time step the scene's laws "
                       "resolve, may help)");
    z = c.z;
    F = c.F;
    A = c.A;
    monodromy = c.monodromy;
    first_iterations = c.iterations;
    along[amplitude_index] = 1.0;
  } else {
    shooter.evaluate(z, F, A, monodromy);
    first_iterations = orbit->iterations;
    along[n + 1] = direction;
  }
  Eigen::VectorXd tangent = unitTangent(A, along.cwiseQuotient(w), w);
  {
    BranchPoint pt = makePoint(shooter, z, monodromy, tangent, w);
    pt.iterations = first_iterations;
    pt.residual = F.norm() / (1.0 + z.head(n).norm());
    r.points.push_back(std::move(pt));
    if (progress) progress(r.points.back(), 0);
  }
  const double low = std::min(spec.from, spec.to), high = std::max(spec.from, spec.to);

  // Follows a branch from its first point (in r.points, at z with `tangent`) on `shooter`,
  // in the norm of w: towards `to` (or, `either_way`, until p leaves [from, to]); with
  // `switch_at`, until the first such bifurcation between the last two points.
  std::unique_ptr<BranchShooter> secondary;  // a switch's: orbits twice as long, or the same
  auto follow = [&](const BranchShooter& shooter, Eigen::VectorXd z, Eigen::VectorXd tangent,
                    const Eigen::VectorXd& w, bool either_way, BranchSwitch switch_at) {
    Eigen::VectorXd d = tangent;  // the predictor's direction: the tangent, then the secant
    double ds = step;
    while (true) {
      if (spec.stop && spec.stop->load()) {
        r.interrupted = true;
        r.stop_reason = "interrupted after " + std::to_string(r.points.size()) + " points, at " +
                        spec.parameter + " = " + shooting::messageNumber(r.points.back().parameter);
        break;
      }
      if (static_cast<int>(r.points.size()) >= spec.max_points) {
        r.stop_reason = "the largest number of points (" + std::to_string(spec.max_points) +
                        ") was reached before " + shooting::messageNumber(spec.to);
        break;
      }
      const Eigen::VectorXd z_pred = z + ds * w.cwiseProduct(d);
      Correction c = correct(shooter, z_pred, d, ds, w, spec.max_corrector, spec.orbit.tolerance);
      Eigen::VectorXd t;
      BranchPoint pt;
      if (c.ok) {
        t = unitTangent(c.A, tangent, w);
        pt = makePoint(shooter, c.z, c.monodromy, t, w);
        // An equilibrium closes on itself for any T: a branch whose orbit shrinks to nothing
        // has left the orbits (steady sliding or sticking), not found one. (A forced orbit's
        // period is fixed: a small response is an orbit.)
        if (!r.forced && !(pt.amplitude_pp > kCollapsed * r.points.front().amplitude_pp)) {
          c.ok = false;
          c.why = "the orbit collapsed onto an equilibrium at " + spec.parameter + " = " +
                  shooting::messageNumber(pt.parameter) + " (amplitude " +
                  shooting::messageNumber(pt.amplitude_pp) + ")";
        }
      }
      if (!c.ok) {
        ds /= 2;
        if (ds < min_step) {
          r.lost = true;
          r.stop_reason = "the branch was lost after " + spec.parameter + " = " +
                          shooting::messageNumber(z[n + 1]) +
                          ": the corrector failed with the step at its " + "smallest (" +
                          shooting::messageNumber(2 * ds) + "): " + c.why;
          break;
        }
        continue;
      }
      pt.iterations = c.iterations;
      pt.residual = c.residual;
      pt.step = ds;
      pt.arclength = r.points.back().arclength + (c.z - z).cwiseQuotient(w).norm();
      const double p = pt.parameter;
      r.points.push_back(std::move(pt));
      if (progress) progress(r.points.back(), r.points.size() - 1);
      d = (c.z - z).cwiseQuotient(w).normalized();
      z = c.z;
      tangent = t;
      if (either_way && (p <= low || p >= high)) {  // a Hopf start's branch goes either way
        r.reached_end = true;
        r.stop_reason = "reached " + spec.parameter + " = " +
                        shooting::messageNumber(p <= low ? low : high) + " (the range's end)";
        break;
      }
      if (!either_way && (p - spec.to) * direction >= 0.0) {
        r.reached_end = true;
        r.stop_reason = "reached " + spec.parameter + " = " + shooting::messageNumber(spec.to);
        break;
      }
      if (!either_way && (p - spec.from) * direction < 0.0) {
        r.stop_reason =
            "the branch turned back past the start value " + shooting::messageNumber(spec.from);
        break;
      }
      const std::vector<BranchEvent> events = detectBranchEvents(r.points, stick_speed, !r.forced);
      if (!events.empty() && events.back().kind == BranchEventKind::kHopf &&
          events.back().after + 1 == r.points.size()) {
        r.stop_reason = "the orbit shrank onto the steady state at a Hopf point, " +
                        spec.parameter + " ~ " + shooting::messageNumber(events.back().parameter) +
                        " (past it the branch retraces itself)";
        break;
      }
      if (const std::optional<BranchEvent> e = switchEvent(events, switch_at);
          e && e->after + 1 == r.points.size()) {
        r.switched.kind = e->kind;
        r.switched.before = e->before;
        r.switched.after = e->after;
        r.stop_reason = branchEventName(e->kind) + " at " + spec.parameter + " ~ " +
                        shooting::messageNumber(e->parameter) + ": switching branches there";
        break;
      }
      const double off = (c.z - z_pred).cwiseQuotient(w).norm() / ds;
      if (c.iterations <= 2 || (c.iterations == 3 && off <= kStraight))
        ds = std::min(1.5 * ds, max_step);
    }
  };
  follow(shooter, z, tangent, w, hopf != nullptr, spec.switch_at);
  r.events = detectBranchEvents(r.points, r.stick_speed, !r.forced);
  if (spec.switch_at != BranchSwitch::kNone && !r.interrupted && !r.lost) {
    if (r.switched.after == 0) {  // the primary ended without the bifurcation asked for
      r.stop_reason += "; no " + switchWords(spec.switch_at) + " on it to switch at";
    } else {
      r.events = detectBranchEvents(r.points, stick_speed, !r.forced);
      // Locate it: g(p) = |mu(p)| - 1 between the two points, each g from the orbit corrected
      // at fixed p (the parameter's row), by Illinois' regula falsi.
      const BranchPoint &pa = r.points[r.switched.before], &pb = r.points[r.switched.after];
      auto zOf = [&](const BranchPoint& q) {
        Eigen::VectorXd zq(n + 2);
        zq << q.start, q.period, q.parameter;
        return zq;
      };
      const Eigen::VectorXd za = zOf(pa), zb = zOf(pb);
      Eigen::VectorXd p_row = Eigen::VectorXd::Zero(n + 2);
      p_row[n + 1] = 1.0;
      struct Probe {
        double p = 0, g = NAN;
        Correction c;
        CriticalMode mode;
      };
      auto probe = [&](double p) {
        Probe q;
        q.p = p;
        const double s = (p - pa.parameter) / (pb.parameter - pa.parameter);
        q.c = newtonWithRow(
            shooter, za + s * (zb - za), p_row, p, INFINITY, Eigen::VectorXd::Ones(n + 2),
            std::max(spec.max_corrector, spec.orbit.max_iterations), spec.orbit.tolerance);
        ++r.switched.evaluations;
        if (q.c.ok) {
          q.mode = criticalMode(q.c.monodromy, q.c.A.col(n).head(n), spec.switch_at, !r.forced);
          if (q.mode.ok) q.g = std::abs(q.mode.mu) - 1.0;
        }
        return q;
      };
      Probe a = probe(pa.parameter), b = probe(pb.parameter);
      Probe best = std::abs(a.g) < std::abs(b.g) ? a : b;
      std::string why;
      if (!(a.g * b.g <= 0.0)) {
        why = "the critical multiplier's modulus does not cross 1 between the points (" +
              shooting::messageNumber(a.g + 1.0) + ", " + shooting::messageNumber(b.g + 1.0) + ")";
      } else {
        int side = 0;  // Illinois: halve the g of an end kept twice
        for (int k = 0; k < kLocateEvaluations && std::abs(best.g) > kLocated; ++k) {
          double p = b.p - b.g * (b.p - a.p) / (b.g - a.g);
          if (!std::isfinite(p) || p == a.p || p == b.p) p = 0.5 * (a.p + b.p);
          Probe q = probe(p);
          if (!std::isfinite(q.g)) q = probe(0.5 * (a.p + b.p));
          if (!std::isfinite(q.g)) {
            why = "the orbit at " + spec.parameter + " = " + shooting::messageNumber(q.p) +
                  " was not found: " + q.c.why;
            break;
          }
          if (std::abs(q.g) < std::abs(best.g)) best = q;
          if (q.g * b.g < 0.0) {
            a = b;
            b = q;
            side = 0;
          } else {
            b = q;
            if (side == 1) a.g /= 2;
            side = 1;
          }
        }
      }
      r.switched.parameter = best.p;
      r.switched.multiplier = best.mode.mu;
      r.switched.residual = std::abs(best.g);
      if (why.empty() && std::isfinite(best.g) && best.mode.ok) {
        // The secondary's first orbit, a off the located one along v, the row r . z fixed
        // with r = (v, 0, 0) less its part along the primary's tangent there.
        const bool doubled = spec.switch_at == BranchSwitch::kPeriodDoubling;
        const double a_off =
            spec.switch_amplitude > 0.0 ? spec.switch_amplitude : kDefaultSwitchAmplitude;
        r.switched.amplitude = a_off;
        r.switched.period = best.c.z[n];
        const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n + 2);
        Eigen::VectorXd old_tangent = unitTangent(best.c.A, (zb - za).normalized(), ones);
        if (doubled) old_tangent[n] *= 2.0;  // the primary traversed twice
        old_tangent.normalize();
        const Eigen::VectorXd v =
            normalizedMode(best.mode.v, coords, coords.positionIndex(body, axis));
        Eigen::VectorXd row = Eigen::VectorXd::Zero(n + 2);
        row.head(n) = v;
        row -= row.dot(old_tangent) * old_tangent;
        Eigen::VectorXd z1 = best.c.z;
        z1.head(n) += a_off * v;
        if (doubled) z1[n] *= 2.0;
        secondary = std::make_unique<BranchShooter>(shooter.withPeriods(doubled ? 2 : 1));
        const Correction c1 = newtonWithRow(*secondary, z1, row, row.dot(z1), INFINITY, ones,
                                            std::max(spec.max_corrector, spec.orbit.max_iterations),
                                            spec.orbit.tolerance);
        if (c1.ok) {
          r.switched.found = true;
          r.primary = std::move(r.points);
          r.primary_events = std::move(r.events);
          r.points.clear();
          r.events.clear();
          // The scaled norm's weights: the primary's, or where the critical mode moves an
          // entry more, that motion at 1000 a (1 m or rad in the mode's largest position
          // entry by default): an entry the primary did not move (a hanging pendulum's
          // swing, its weight 1e-3 of its kind's range) must not measure the new motion.
          Eigen::VectorXd w2 = w;
          if (scaled) {
            w2.head(n) = w.head(n).cwiseMax(1000.0 * a_off * v.cwiseAbs());
            if (doubled) w2[n] *= 2.0;
            r.weights = w2;
          }
          const Eigen::VectorXd t1 = unitTangent(c1.A, row.cwiseProduct(w2), w2);
          BranchPoint pt = makePoint(*secondary, c1.z, c1.monodromy, t1, w2);
          pt.iterations = c1.iterations;
          pt.residual = c1.residual;
          r.points.push_back(std::move(pt));
          if (progress) progress(r.points.back(), 0);
          r.stop_reason.clear();
          follow(*secondary, c1.z, t1, w2, true, BranchSwitch::kNone);
        } else {
          why = "no orbit " + shooting::messageNumber(a_off) +
                " off the located one along "
                "its critical mode: " +
                c1.why + " (another --switch-amplitude may help)";
        }
      }
      if (!r.switched.found) {
        r.lost = true;
        r.stop_reason = "the " + switchWords(spec.switch_at) + " between " + spec.parameter +
                        " = " + shooting::messageNumber(pa.parameter) + " and " +
                        shooting::messageNumber(pb.parameter) +
                        " gave no secondary branch: " + (why.empty() ? "it was not located" : why);
      }
    }
  }
  r.events = detectBranchEvents(r.points, r.stick_speed, !r.forced);
  // The secondary's first orbit is a off the bifurcation, where its critical multiplier is
  // still 1 or -1 to O(a^2) and dp/ds 0 to O(a): a fold or stability change between it and
  // the next point is that bifurcation, reported as the switch, not a second one.
  if (r.switched.found)
    std::erase_if(r.events, [](const BranchEvent& e) {
      return e.before == 0 &&
             (e.kind == BranchEventKind::kFold || e.kind == BranchEventKind::kStabilityChange);
    });
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  return r;
}

namespace {

std::string pointsCsvText(const std::vector<BranchPoint>& points,
                          const std::vector<BranchEvent>& branch_events) {
  std::string csv =
      "index,parameter,period,amplitude_pp,largest_multiplier,stable,stick_fraction,min_slip,"
      "x_min,x_max,dp_ds,arclength,iterations,residual,trivial_error,steady_growth_rate,"
      "event\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const BranchPoint& p = points[i];
    std::string events;
    for (const BranchEvent& e : branch_events)
      if (e.after == i) {
        if (!events.empty()) events += ';';
        events += branchEventName(e.kind);
      }
    csv += std::to_string(i) + "," + csvNumber(p.parameter, 17) + "," + csvNumber(p.period, 17) +
           "," + csvNumber(p.amplitude_pp, 17) + "," + csvNumber(p.largest, 17) + "," +
           (p.stable ? "1" : "0") + "," + csvNumber(p.stick_fraction, 6) + "," +
           csvNumber(p.min_slip, 6) + "," + csvNumber(p.x_min, 17) + "," + csvNumber(p.x_max, 17) +
           "," + csvNumber(p.dp_ds, 17) + "," + csvNumber(p.arclength, 17) + "," +
           std::to_string(p.iterations) + "," + csvNumber(p.residual, 6) + "," +
           csvNumber(p.trivial_error, 6) + "," + csvNumber(p.steady_growth, 17) + "," + events +
           "\n";
  }
  return csv;
}

}  // namespace

std::string branchCsvText(const BranchResult& r) { return pointsCsvText(r.points, r.events); }

std::string primaryBranchCsvText(const BranchResult& r) {
  return pointsCsvText(r.primary, r.primary_events);
}

std::string branchOrbitsCsvText(const BranchResult& r) {
  std::string csv = "point,t," + r.observed + "\n";
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    for (std::size_t k = 0; k < p.t.size(); ++k)
      csv += std::to_string(i) + "," + csvNumber(p.t[k], 17) + "," + csvNumber(p.x[k], 17) + "\n";
  }
  return csv;
}

std::string branchJsonText(const std::string& scene_path, const BranchSpec& spec,
                           const BranchResult& r) {
  nlohmann::ordered_json j;
  j["scene"] = scene_path;
  j["parameter"] = spec.parameter;
  j["from"] = spec.from;
  j["to"] = spec.to;
  j["observed"] = r.observed;
  j["status"] = r.reached_end   ? "reached_end"
                : r.lost        ? "lost"
                : r.interrupted ? "interrupted"
                                : "stopped";
  j["stop_reason"] = r.stop_reason;
  j["stick_speed"] = r.stick_speed;
  j["forced"] = r.forced;
  if (r.forced) j["periods"] = r.periods;
  if (spec.from_hopf) {  // where the branch started, located by the modes analysis
    j["start"] = "hopf";
    j["hopf"] = {
        {"parameter", r.hopf_parameter},
        {"omega", r.hopf_omega},
        {"period", 2.0 * std::numbers::pi / r.hopf_omega},
        {"amplitude", spec.hopf_amplitude > 0.0 ? spec.hopf_amplitude : kDefaultHopfAmplitude},
        {"analyses", r.hopf_analyses}};
  } else {
    j["start"] = "orbit";
  }
  if (spec.switch_at != BranchSwitch::kNone) {
    // Where the secondary branch (this one) left the primary (primary_branch.csv).
    j["switch"] = {{"at", branchSwitchName(spec.switch_at)},
                   {"found", r.switched.found},
                   {"primary_points", r.switched.found ? r.primary.size() : r.points.size()}};
    if (r.switched.after > 0) {
      j["switch"]["between"] = {r.switched.before, r.switched.after};
      j["switch"]["evaluations"] = r.switched.evaluations;
    }
    if (r.switched.found) {
      j["switch"]["parameter"] = r.switched.parameter;
      j["switch"]["multiplier"] = {{"re", r.switched.multiplier.real()},
                                   {"im", r.switched.multiplier.imag()}};
      j["switch"]["residual"] = r.switched.residual;
      j["switch"]["primary_period"] = r.switched.period;
      j["switch"]["amplitude"] = r.switched.amplitude;
      nlohmann::ordered_json primary_events = nlohmann::ordered_json::array();
      for (const BranchEvent& e : r.primary_events)
        primary_events.push_back({{"kind", branchEventName(e.kind)},
                                  {"parameter", e.parameter},
                                  {"between", {e.before, e.after}}});
      j["switch"]["primary_events"] = primary_events;
    }
  }
  j["points"] = r.points.size();
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const BranchEvent& e : r.events)
    events.push_back({{"kind", branchEventName(e.kind)},
                      {"parameter", e.parameter},
                      {"between", {e.before, e.after}},
                      {"located", "interpolated between the two points"}});
  j["events"] = events;
  nlohmann::ordered_json pts = nlohmann::ordered_json::array();
  for (const BranchPoint& p : r.points) {
    nlohmann::ordered_json mu = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < p.multipliers.size(); ++i)
      if (static_cast<int>(i) != p.trivial)
        mu.push_back({{"re", p.multipliers[i].real()}, {"im", p.multipliers[i].imag()}});
    pts.push_back({{"parameter", p.parameter},
                   {"period", p.period},
                   {"amplitude_pp", p.amplitude_pp},
                   {"stable", p.stable},
                   {"stick_fraction", std::isfinite(p.stick_fraction)
                                          ? nlohmann::ordered_json(p.stick_fraction)
                                          : nlohmann::ordered_json()},
                   {"min_slip", std::isfinite(p.min_slip) ? nlohmann::ordered_json(p.min_slip)
                                                          : nlohmann::ordered_json()},
                   {"trivial_multiplier_error", p.trivial_error},
                   {"steady_growth_rate", std::isfinite(p.steady_growth)
                                              ? nlohmann::ordered_json(p.steady_growth)
                                              : nlohmann::ordered_json()},
                   {"multipliers", mu}});
  }
  j["branch"] = pts;
  j["settings"] = {{"max_points", spec.max_points},
                   {"step", spec.step},
                   {"min_step", spec.min_step},
                   {"max_step", spec.max_step},
                   {"tolerance", spec.orbit.tolerance},
                   {"fd_step", spec.orbit.fd_step},
                   {"arclength_norm", arclengthNormName(spec.norm)},
                   {"switch_amplitude", spec.switch_amplitude}};
  // The scaled norm's weights of the period and the parameter (the state's are per entry).
  if (spec.norm == ArclengthNorm::kScaled && r.weights.size() >= 2)
    j["settings"]["weights"] = {{"period", r.weights[r.weights.size() - 2]},
                                {"parameter", r.weights[r.weights.size() - 1]}};
  j["seconds"] = r.seconds;
  return j.dump(2);
}

}  // namespace tribo::study
