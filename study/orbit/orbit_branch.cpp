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
#include "study/orbit/branch_grazing.hpp"
#include "study/orbit/branch_return_map.hpp"
#include "study/orbit/branch_shooter.hpp"
#include "study/orbit/branch_switch.hpp"
#include "study/orbit/forcing.hpp"
#include "study/orbit/hopf_start.hpp"
#include "study/orbit/orbit_coordinates.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study {

namespace {

// An orbit whose amplitude falls below this fraction of the first one's has collapsed.
constexpr double kCollapsed = 1e-6;
// The step grows after a corrector that converged in at most 2 iterations, or in 3 that moved
// the prediction by at most this fraction of the step (the branch is nearly straight there).
constexpr double kStraight = 0.02;
// Locating a bifurcation to switch at: orbits corrected at fixed p at most, and |g| enough.
constexpr int kLocateEvaluations = 12;
constexpr double kLocated = 1e-9;
// A step by the return map (branch_return_map.hpp) is tried after a point whose non-trivial
// multipliers are all below this, and kept when its own estimates are.
constexpr double kReturnMapBelow = 0.05;
// A corrector that fails where the last orbit's smallest slip speed is within this fraction of
// the stick speed has met grazing: the orbits on either side of it are bracketed at fixed
// parameters (branch_grazing.hpp), the bracket a thousandth of the last step wide, in at
// most these probes (the first ones stepping out 1/4, 1/2, ... of the last step).
constexpr double kNearGrazing = 0.05;
constexpr double kGrazingWidth = 1e-3;
constexpr int kGrazingExpansions = 4;
constexpr int kGrazingProbes = 24;
// Past the bracket, the branch goes on from the far orbit with a step this many times the
// bracket's length.
constexpr double kGrazingRestart = 100.0;
// A corrected point whose tangent turns from the last one's by more than this angle (its
// cosine) was reached by jumping to another branch at the same parameter (a step too long for
// where the branch bends, as near a grazing fold): the step is halved and tried again.
constexpr double kMaxTurnCos = 0.7;  // 45.6 degrees
// The sticking cycles beside slipping ones are looked for where the last orbit slips within
// this fraction of the stick speed (the corrector can fail that far from the kink: its
// curvature shrinks Newton's reach as the orbit's slowest slip nears it).
constexpr double kBesideSlip = 0.25;
// The settling runs for the sticking cycle beside start this fraction of the last orbit's
// amplitude outside it.
constexpr double kBesidePush = 0.1;
// How much lower the smallest step goes where slipping cycles approach grazing.
constexpr double kApproachSteps = 64.0;
// A stable sticking orbit past which none is found ends the branch at grazing when its
// smallest slip speed is within this fraction below the stick speed.
constexpr double kGrazingEnd = 1e-3;

using branch::assignment;
using branch::BranchShooter;
using branch::correct;
using branch::Correction;
using branch::ForcedPeriod;
using branch::newtonWithRow;
using branch::solveFixedAmplitude;
using branch::stateScales;
using branch::unitTangent;

}  // namespace

std::string arclengthNormName(ArclengthNorm norm) {
  return norm == ArclengthNorm::kScaled ? "scaled" : "si";
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
  const double max_step = spec.max_step > 0.0 ? spec.max_step : 4.0 * step;
  const double min_step = spec.min_step > 0.0 ? spec.min_step : std::min(step, max_step) / 64.0;
  const double direction = spec.to > spec.from ? 1.0 : -1.0;
  const double stick_speed = first.output.summary.stick_speed;
  r.stick_speed = stick_speed;

  // The orbit from `start` over `period` at the scene `at`, sampled into pt: the observed
  // coordinate, its extremes and amplitude, the smallest slip speed and the stick fraction.
  // Reads nothing but its arguments and the branch's constants (it may run on a worker).
  // Returns the flow's end (`flow` is the scene's: the return map's step gives its own).
  auto sampleOrbit = [&](const io::Scene& at, const shooting::Flow& flow,
                         const Eigen::VectorXd& start, double period, BranchPoint& pt) {
    const auto b = static_cast<std::size_t>(body);
    std::vector<double>& x = pt.x;
    pt.t.assign(1, 0.0);
    x.assign(1, coords.fromVector(start).bodies[b].position[axis]);
    // The slip speed as the run summary takes it: the largest over the body's contact points,
    // counted where the body touches (normal force > 0); each sample weighs its step.
    double t_prev = 0.0, dt = 0.0, stuck = 0.0, touching = 0.0, min_slip = INFINITY;
    pt.min_slip = pt.stick_fraction = NAN;
    Eigen::VectorXd end = flow(
        start, period,
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
      pt.stick_fraction = stuck / period;
    }
    // A forced orbit peaks anywhere between samples (an autonomous one starts at its peak).
    pt.x_max = r.forced ? shooting::refinedMaximum(x) : *std::max_element(x.begin(), x.end());
    pt.x_min = shooting::refinedMinimum(x);
    pt.amplitude_pp = pt.x_max - pt.x_min;
    return end;
  };

  // A converged point: its multipliers, tangent and the sampled orbit's amplitude (`sampled`:
  // the orbit at z already sampled by sampleOrbit, beside the return map's products).
  auto makePoint = [&](const BranchShooter& shooter, const Eigen::VectorXd& z, shooting::Floquet f,
                       const Eigen::VectorXd& tangent, const Eigen::VectorXd& w,
                       BranchPoint* sampled = nullptr) {
    BranchPoint pt;
    if (sampled != nullptr) pt = std::move(*sampled);
    pt.start = z.head(n);
    pt.period = z[n];
    pt.parameter = z[n + 1];
    pt.dp_ds = w[n + 1] * tangent[n + 1];
    pt.multipliers = std::move(f.multipliers);
    pt.trivial = f.trivial;
    pt.trivial_error = f.trivial_error;
    pt.stable = f.stable;
    pt.largest = f.largest;
    // As `tribo orbit`'s neutral orbits (periodic_orbit.cpp): a multiplier the flow cannot
    // tell from the unit circle leaves the stability undecided.
    pt.undecided = shooting::undecidedStability(pt.multipliers, pt.trivial, pt.trivial_error);
    if (pt.undecided) pt.stable = false;
    const io::Scene at = shooter.sceneAt(pt.parameter);
    if (sampled == nullptr)
      sampleOrbit(at, shooting::Flow(at.model, coords), pt.start, pt.period, pt);
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
  } else if (!r.forced && orbit->monodromy.size() > 0) {
    // The first orbit's own Jacobian (within its tolerance of z) and the parameter's column:
    // two flows where evaluate() takes 2 (n + 2), and the multipliers `tribo orbit` reports.
    monodromy = orbit->monodromy;
    A = Eigen::MatrixXd::Zero(n + 1, n + 2);
    A.topLeftCorner(n, n) = monodromy - Eigen::MatrixXd::Identity(n, n);
    A.col(n).head(n) = orbit->period_column;
    A.col(n + 1).head(n) = shooter.parameterColumn(z);
    A(n, shooter.phase()) = 1.0;
    first_iterations = orbit->iterations;
    along[n + 1] = direction;
  } else {
    shooter.evaluate(z, F, A, monodromy);
    first_iterations = orbit->iterations;
    along[n + 1] = direction;
  }
  Eigen::VectorXd tangent = unitTangent(A, along.cwiseQuotient(w), w);
  {
    BranchPoint pt = makePoint(shooter, z, shooting::floquet(monodromy, !r.forced), tangent, w);
    pt.iterations = first_iterations;
    pt.residual = F.size() > 0 ? F.norm() / (1.0 + z.head(n).norm()) : orbit->residual;
    r.points.push_back(std::move(pt));
    if (progress) progress(r.points.back(), 0);
  }
  const double low = std::min(spec.from, spec.to), high = std::max(spec.from, spec.to);

  // A point found off the arclength corrector (a grazing bracket's end): appended after
  // `from`, the branch's last z, with its corrector's iterations and residual (arclength in
  // the norm of w).
  auto push = [&](BranchPoint pt, const Correction& c, const Eigen::VectorXd& from,
                  const Eigen::VectorXd& w) {
    pt.iterations = c.iterations;
    pt.residual = c.residual;
    pt.fixed_parameter = true;
    pt.arclength = r.points.back().arclength + (c.z - from).cwiseQuotient(w).norm();
    r.points.push_back(std::move(pt));
    if (progress) progress(r.points.back(), r.points.size() - 1);
  };
  // The orbits on either side of a grazing point the corrector could not pass, from the last
  // point z in the direction d (branch_grazing.hpp). Each probe solves the orbit at its
  // parameter by Newton from the secant's prediction through the two nearest orbits on the
  // near side, no farther from it than the prediction lies from the nearest (near the kink
  // the differences' Jacobian can send Newton's iteration onto another cycle, the unstable
  // one beside the stable, which lies farther), in at most the corrector's iterations: the
  // 24 probes cost at most about four times the halved steps that failed before them.
  struct GrazingOrbit {
    Correction c;
    Eigen::VectorXd tangent;
    BranchPoint point;
  };
  struct GrazingPass {
    branch::GrazingBracket bracket;
    std::optional<GrazingOrbit> inside, outside;
  };
  auto passGrazing = [&](const BranchShooter& shooter, const Eigen::VectorXd& z,
                         const Eigen::VectorXd& w, const Eigen::VectorXd& d,
                         const Eigen::VectorXd& tangent) {
    GrazingPass g;
    const bool sticking = r.points.back().min_slip < stick_speed;
    const double p_last = z[n + 1];
    // The point before the last (the last itself on a branch of one point).
    const BranchPoint& previous = r.points[r.points.size() >= 2 ? r.points.size() - 2 : 0];
    const double last_step = std::max(std::abs(p_last - previous.parameter), min_step * w[n + 1]);
    Eigen::VectorXd p_row = Eigen::VectorXd::Zero(n + 2);
    p_row[n + 1] = 1.0;
    // The two nearest orbits on the near side, for the secant's prediction.
    Eigen::VectorXd near = z, before(n + 2);
    before << previous.start, previous.period, previous.parameter;
    auto probe = [&](double p) {
      // Newton from the secant's prediction at p, no farther from it than the prediction is
      // from the nearest orbit (near the kink the differences' Jacobian can send Newton's
      // iteration onto the unstable cycle beside the stable one).
      Eigen::VectorXd guess = near;
      if (before[n + 1] != near[n + 1])
        guess += (p - near[n + 1]) / (near[n + 1] - before[n + 1]) * (near - before);
      guess[n + 1] = p;
      const double reach = std::max((guess - near).cwiseQuotient(w).norm(), 1e-12);
      GrazingOrbit o;
      o.c = newtonWithRow(shooter, guess, p_row, p, reach, w, spec.max_corrector,
                          spec.orbit.tolerance);
      if (!o.c.ok) return branch::GrazingSide::kNone;
      o.tangent = unitTangent(o.c.A, tangent, w);
      o.point =
          makePoint(shooter, o.c.z, shooting::floquet(o.c.monodromy, !r.forced), o.tangent, w);
      if (!(o.point.amplitude_pp > kCollapsed * r.points.front().amplitude_pp) ||
          !std::isfinite(o.point.min_slip))
        return branch::GrazingSide::kNone;
      if ((o.point.min_slip < stick_speed) == sticking) {
        before = near;
        near = o.c.z;
        g.inside = std::move(o);
        return branch::GrazingSide::kSame;
      }
      g.outside = std::move(o);
      return branch::GrazingSide::kCrossed;
    };
    g.bracket = branch::bracketGrazing(p_last, d[n + 1] > 0.0 ? 1.0 : -1.0, last_step / 4,
                                       kGrazingWidth * last_step, kGrazingExpansions,
                                       kGrazingProbes, probe);
    // A crossed orbit from before a probe that found none nearer is not the bracket's end.
    if (g.bracket.outside_side != branch::GrazingSide::kCrossed) g.outside.reset();
    return g;
  };

  // The sticking cycles beside slipping ones at grazing, where the corrector and the orbits at
  // fixed parameters (passGrazing) found none past the last orbit, which slips within
  // kBesideSlip of the stick speed, on a branch none of whose orbits sticks (one that came
  // from the sticking cycles, across grazing and round the slipping cycles' smooth fold, would
  // find the same sticking cycles again and retrace itself). The law's kink gives Newton's
  // iteration no derivative to pass on where two shapes of branch meet: a corner, the unstable
  // slipping cycles of a subcritical Hopf point meeting the stable sticking ones at a fold at
  // grazing (the largest multiplier jumps through 1; the sticking cycles lie back in p), or a
  // stable slipping cycle just past the corner's smooth fold, the sticking cycles ahead. The
  // sticking cycle is the attractor there: the orbit Newton's iteration at a fixed p finds
  // from a settling run started outside the last orbit, at p back by the last step's change,
  // then ahead by as much, then both 4 and 16 times as far, each kept only if it is stable
  // and sticks (the other cycle, not the last one again) and lies within twice the last
  // step's arclength (times how far it is in p) of the last orbit: the two branches meet
  // there, it is not another attractor farther off. The branch goes on from it, away from
  // the last orbit in p.
  auto stickingBeside = [&](const BranchShooter& shooter, const Eigen::VectorXd& z,
                            const Eigen::VectorXd& w,
                            const Eigen::VectorXd& d) -> std::optional<GrazingOrbit> {
    if (r.forced || !(stick_speed > 0.0) || r.points.size() < 2 || d[n + 1] == 0.0)
      return std::nullopt;
    const BranchPoint& last = r.points.back();
    const BranchPoint& previous = r.points[r.points.size() - 2];
    if (!(last.min_slip >= stick_speed) || last.min_slip > (1.0 + kBesideSlip) * stick_speed)
      return std::nullopt;  // not slipping near grazing
    if (std::any_of(r.points.begin(), r.points.end(),
                    [&](const BranchPoint& q) { return !(q.min_slip >= stick_speed); }))
      return std::nullopt;  // come from the sticking cycles: those beside are the same ones
    const double p_last = z[n + 1];
    const double back = std::abs(p_last - previous.parameter);
    const double last_arc = last.arclength - previous.arclength;
    if (!(back > 0.0)) return std::nullopt;
    const double sign = d[n + 1] > 0.0 ? 1.0 : -1.0;
    Eigen::VectorXd p_row = Eigen::VectorXd::Zero(n + 2);
    p_row[n + 1] = 1.0;
    // The settling runs start outside the last orbit: its start (the observed coordinate's
    // peak) pushed out by kBesidePush of its amplitude, beyond the unstable cycle (whose inside
    // leads to steady sliding) and the sticking cycle beside it.
    Eigen::VectorXd y_out = z.head(n);
    y_out[amplitude_index] += kBesidePush * last.amplitude_pp;
    const State pushed = coords.fromVector(y_out);
    const double settle_beside =
        spec.orbit.settle > 0.0 ? spec.orbit.settle : first.model->options.duration;
    for (const double times : {1.0, 4.0, 16.0}) {
      for (const double towards : {-sign, sign}) {
        const double p = p_last + towards * times * back;
        if (p < low || p > high) continue;
        try {
          const io::Scene at = sceneAt(p);
          const shooting::Guess settled =
              shooting::settledGuess(at.model, body, axis, settle_beside, &pushed);
          Eigen::VectorXd guess(n + 2);
          guess << coords.toVector(settled.state), settled.period, p;
          GrazingOrbit o;
          o.c = newtonWithRow(shooter, guess, p_row, p, INFINITY, w, spec.max_corrector,
                              spec.orbit.tolerance);
          if (!o.c.ok || (o.c.z - z).cwiseQuotient(w).norm() > 2.0 * times * last_arc) continue;
          Eigen::VectorXd away = Eigen::VectorXd::Zero(n + 2);
          away[n + 1] = towards;
          o.tangent = unitTangent(o.c.A, away, w);
          o.point =
              makePoint(shooter, o.c.z, shooting::floquet(o.c.monodromy, !r.forced), o.tangent, w);
          if (o.point.stable && o.point.min_slip < stick_speed) return o;
        } catch (const std::exception&) {  // no orbit there (OrbitError) or not in y's terms
        }
      }
    }
    return std::nullopt;
  };

  // Where a branch from the sticking side ends at grazing with steady sliding stable there
  // too, what goes round the corner (stickingBeside comes to it from the slipping side).
  auto fromHopfHint = [&](const BranchPoint& end) -> std::string {
    if (spec.from_hopf || !(end.steady_growth < 0.0)) return "";
    return "; steady sliding is stable there too (its leading growth rate " +
           shooting::messageNumber(end.steady_growth) +
           " 1/s): an unstable cycle separates the two, and where it is born at a Hopf point "
           "of steady sliding in the range, --from-hopf follows it round this corner onto the "
           "sticking cycles";
  };

  // Follows a branch from its first point (in r.points, at z with `tangent`) on `shooter`,
  // in the norm of w: towards `to` (or, `either_way`, until p leaves [from, to]); with
  // `switch_at`, until the first such bifurcation between the last two points.
  std::unique_ptr<BranchShooter> secondary;  // a switch's: orbits twice as long, or the same
  std::optional<BranchEvent> end_event;      // a grazing point past the last point
  auto follow = [&](const BranchShooter& shooter, Eigen::VectorXd z, Eigen::VectorXd tangent,
                    const Eigen::VectorXd& w, bool either_way, BranchSwitch switch_at) {
    Eigen::VectorXd d = tangent;  // the predictor's direction: the tangent, then the secant
    double ds = std::min(step, max_step);
    double smallest = min_step;  // lowered past a grazing point
    int grazing_probes = 0;      // the last grazing pass's
    double crossed_at = NAN;     // the grazing point it crossed, if one
    bool approached = false;     // the smallest step lowered towards a grazing corner
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
      // Where the last orbit contracts strongly, the return map at the predicted parameter
      // (branch_return_map.hpp); the arclength corrector otherwise, or where it fails or lands
      // farther than the step from the prediction (another attractor at that parameter).
      Correction c;
      shooting::Floquet floquet;
      bool by_return_map = false;
      BranchPoint sampled;
      if (spec.orbit.return_map && r.points.back().largest < kReturnMapBelow) {
        const branch::ReturnMapStep q = branch::returnMapStep(
            shooter, z_pred, spec.orbit.tolerance, kReturnMapBelow,
            [&](const io::Scene& at, const shooting::Flow& flow, const Eigen::VectorXd& y,
                double T) { return sampleOrbit(at, flow, y, T, sampled); });
        if (q.ok && (q.z - z_pred).cwiseQuotient(w).norm() <= ds) {
          by_return_map = true;
          c.ok = true;
          c.z = q.z;
          c.iterations = q.iterations;
          c.residual = q.residual;
          floquet = q.floquet;
        }
      }
      if (!by_return_map) {
        c = correct(shooter, z_pred, d, ds, w, spec.max_corrector, spec.orbit.tolerance);
        if (c.ok) floquet = shooting::floquet(c.monodromy, !r.forced);
      }
      Eigen::VectorXd t;
      BranchPoint pt;
      if (c.ok) {
        // A return-map point's tangent is the secant that reached it (no Jacobian there).
        t = by_return_map ? Eigen::VectorXd((c.z - z).cwiseQuotient(w).normalized())
                          : unitTangent(c.A, tangent, w);
        pt = makePoint(shooter, c.z, floquet, t, w, by_return_map ? &sampled : nullptr);
        pt.by_return_map = by_return_map;
        // An equilibrium closes on itself for any T: a branch whose orbit shrinks to nothing
        // has left the orbits (steady sliding or sticking), not found one. (A forced orbit's
        // period is fixed: a small response is an orbit.)
        if (!r.forced && !(pt.amplitude_pp > kCollapsed * r.points.front().amplitude_pp)) {
          c.ok = false;
          c.why = "the orbit collapsed onto an equilibrium at " + spec.parameter + " = " +
                  shooting::messageNumber(pt.parameter) + " (amplitude " +
                  shooting::messageNumber(pt.amplitude_pp) + ")";
        }
        const double turn = t.dot(tangent);
        if (c.ok && !(turn >= kMaxTurnCos)) {
          c.ok = false;
          c.why = "the orbit found at " + spec.parameter + " = " +
                  shooting::messageNumber(pt.parameter) + " turns the branch's tangent by " +
                  shooting::messageNumber(std::acos(std::clamp(turn, -1.0, 1.0)) * 180.0 /
                                          std::numbers::pi) +
                  " degrees from the last point's: another branch reached, not this one";
        }
        // Slipping cycles and sticking ones of the other stability meet only where the
        // parameter turns (a fold at a grazing corner, stickingBeside): a step across grazing
        // that changes the stability with neither the parameter nor dp/ds turning has jumped
        // from one to the other (the tangent need not turn much: 38 degrees on the damped
        // belt continued in the mass).
        const BranchPoint& last = r.points.back();
        const bool across_grazing = stick_speed > 0.0 && std::isfinite(last.min_slip) &&
                                    std::isfinite(pt.min_slip) &&
                                    (last.min_slip < stick_speed) != (pt.min_slip < stick_speed);
        const bool flips = !last.undecided && !pt.undecided && last.stable != pt.stable;
        const bool no_turn =
            (pt.parameter - last.parameter) * d[n + 1] > 0.0 && pt.dp_ds * last.dp_ds > 0.0;
        if (c.ok && across_grazing && flips && no_turn) {
          c.ok = false;
          c.why = "the orbit found at " + spec.parameter + " = " +
                  shooting::messageNumber(pt.parameter) + " is " +
                  (pt.stable ? "stable" : "unstable") + " and " +
                  (pt.min_slip < stick_speed ? "sticks" : "slips") + " where the last " +
                  (last.min_slip < stick_speed ? "sticks" : "slips") +
                  ", with no turn of the parameter between: another branch reached";
        }
      }
      if (!c.ok) {
        ds /= 2;
        if (ds < smallest && !approached && stick_speed > 0.0 && r.points.size() >= 2) {
          // Slipping cycles whose smallest slip speed falls towards the stick speed approach a
          // grazing corner (stickingBeside), where the branch bends within a small fraction of
          // the step: the smallest step is lowered once, by kApproachSteps.
          const BranchPoint &last = r.points.back(), &previous = r.points[r.points.size() - 2];
          if (last.min_slip > stick_speed && previous.min_slip > last.min_slip) {
            approached = true;
            smallest /= kApproachSteps;
          }
        }
        if (ds < smallest) {
          const double slip = r.points.back().min_slip;
          if (stick_speed > 0.0 && std::isfinite(slip) &&
              std::abs(slip - stick_speed) <= kNearGrazing * stick_speed &&
              !r.points.back().fixed_parameter && d[n + 1] != 0.0) {
            // Grazing of a law with a kink: the orbits on either side at fixed parameters,
            // and on from the far one, or the branch's end located when there is none.
            const GrazingPass g = passGrazing(shooter, z, w, d, tangent);
            grazing_probes = g.bracket.evaluations;
            if (g.inside) {
              push(std::move(g.inside->point), g.inside->c, z, w);
              z = g.inside->c.z;
              if (!g.bracket.bracketed) {  // no grazing within reach: on from the last orbit
                tangent = g.inside->tangent;
                d = tangent;
                ds = std::min(step, max_step);
                continue;
              }
            }
            if (g.outside) {
              // On from the far orbit with a step a hundred times the bracket's (a fold of
              // the cycles may lie just past a grazing point), the smallest step lowered
              // with it.
              const Eigen::VectorXd z_in = z;
              crossed_at = 0.5 * (g.bracket.inside + g.bracket.outside);
              push(std::move(g.outside->point), g.outside->c, z, w);
              z = g.outside->c.z;
              tangent = g.outside->tangent;
              d = tangent;
              ds = std::min(kGrazingRestart * (z - z_in).cwiseQuotient(w).norm(), max_step);
              smallest = std::min(smallest, ds / 64.0);
              continue;
            }
            const BranchPoint& end = r.points.back();
            if (g.bracket.bracketed && end.fixed_parameter && end.stable &&
                end.min_slip < stick_speed && end.min_slip >= (1.0 - kGrazingEnd) * stick_speed) {
              // The stable sticking orbits end at grazing: no orbit on either side past it.
              r.lost = true;
              end_event =
                  BranchEvent{BranchEventKind::kGrazing, r.points.size() - 1, r.points.size() - 1,
                              0.5 * (g.bracket.inside + g.bracket.outside)};
              r.stop_reason =
                  "the stable orbits stop sticking (grazing) at " + spec.parameter + " ~ " +
                  shooting::messageNumber(end_event->parameter) + ": the last, at " +
                  shooting::messageNumber(end.parameter) + ", slips no slower than " +
                  shooting::messageNumber(end.min_slip) + " m/s (stick speed " +
                  shooting::messageNumber(stick_speed) + " m/s); no orbit was found at " +
                  shooting::messageNumber(g.bracket.outside) + " (" +
                  std::to_string(g.bracket.evaluations) + " orbits solved at fixed parameters)";
              r.stop_reason += fromHopfHint(end);
              break;
            }
          }
          // (Once: the sticking orbit it pushes keeps stickingBeside from looking again.)
          if (std::optional<GrazingOrbit> o = stickingBeside(shooter, z, w, d)) {
            push(std::move(o->point), o->c, z, w);
            z = o->c.z;
            tangent = o->tangent;
            d = tangent;
            ds = std::min(step, max_step);
            continue;
          }
          r.lost = true;
          r.stop_reason = "the branch was lost after " + spec.parameter + " = " +
                          shooting::messageNumber(z[n + 1]) +
                          ": the corrector failed with the step at its " + "smallest (" +
                          shooting::messageNumber(2 * ds) + "): " + c.why;
          const BranchPoint& last = r.points.back();
          if (std::isfinite(crossed_at)) {
            r.stop_reason += "; it had crossed grazing at " + spec.parameter + " ~ " +
                             shooting::messageNumber(crossed_at) +
                             " (orbits at fixed parameters on either side) and followed the "
                             "orbits past it to here" +
                             fromHopfHint(last);
          } else if (stick_speed > 0.0 &&
                     std::abs(last.min_slip - stick_speed) <= kNearGrazing * stick_speed) {
            r.stop_reason += "; the last orbit's smallest slip speed (" +
                             shooting::messageNumber(last.min_slip) + " m/s) is within " +
                             shooting::messageNumber(100.0 * kNearGrazing) +
                             "% of the stick speed (" + shooting::messageNumber(stick_speed) +
                             " m/s): sticking is about to " +
                             (last.min_slip < stick_speed ? "end" : "begin") +
                             " there (grazing), where a law with a kink at the stick speed "
                             "gives Newton's iteration no derivative";
            if (grazing_probes > 0)
              r.stop_reason += ", and " + std::to_string(grazing_probes) +
                               " orbits solved at fixed parameters found none across it";
          }
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
      if (by_return_map || c.iterations <= 2 || (c.iterations == 3 && off <= kStraight))
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
          BranchPoint pt =
              makePoint(*secondary, c1.z, shooting::floquet(c1.monodromy, !r.forced), t1, w2);
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
  if (end_event) r.events.push_back(*end_event);
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

}  // namespace tribo::study
