// A branch of periodic orbits followed in one scene parameter (a `parameters:` entry): how
// the stick-slip cycle's period, amplitude and stability change with, say, the belt speed,
// and where along the branch it folds, doubles its period or loses stability. Pseudo-
// arclength continuation (Keller 1977; Seydel, "Practical Bifurcation and Stability
// Analysis", 3rd ed., Springer 2010, ch. 4; Allgower & Georg, "Introduction to Numerical
// Continuation Methods", SIAM 2003, ch. 2) on the unknowns z = (y0, T, p), y0 the state on
// the orbit (study/orbit/orbit_coordinates.hpp), T the period, p the parameter:
//   phi_T(y0; p) - y0           = 0   the orbit closes (the scene's own integrator, reloaded
//                                     at p)
//   v_obs(y0)                   = 0   phase: it starts where the observed coordinate peaks
//   d_k . (z - z_k - ds d_k)    = 0   arclength: the correction is normal to the prediction
// Predictor: z_k + ds d_k, d_k the unit secant (z_k - z_{k-1}) / |z_k - z_{k-1}| (at the first
// point the unit tangent, the null vector of the Jacobian of the first two rows). Corrector:
// Newton's method on the three rows with the Jacobian from central differences of the flow:
// the y0 and T columns as in periodic_orbit.cpp, the p column from the scene reloaded at
// p +- dp (io::SceneDocument re-reads the overrides without parsing the YAML again). After a
// point whose non-trivial multipliers are all below 0.05 (stick-slip), a step is first tried
// by the return map at the predicted parameter (study/orbit/branch_return_map.hpp: no
// Jacobian, the leading multipliers estimated; OrbitSpec::return_map false never tries one),
// the corrector taking over where it fails. Step
// control: ds grows by 1.5 after a return-map step or a corrector that converged in at most 2
// iterations (or in 3 that moved the prediction by at most 0.02 ds: a nearly straight stretch),
// halves after one that failed (no convergence, a failed step, a correction longer than ds, an
// orbit collapsed onto an equilibrium: amplitude below 1e-6 of the first point's, which closes on
// itself for any T, a tangent turned by more than 45.6 degrees from the last point's, or a
// step across grazing that changes the stability with neither p nor dp/ds turning: an orbit
// of another branch at the same parameter, reached by a step too long for the bend); the
// branch stops below the smallest step, naming why. Where the law has a kink at the stick
// speed, grazing is passed by orbits at fixed parameters (study/orbit/branch_grazing.hpp), the
// smallest step is lowered once (by 64) where slipping cycles approach the stick speed, and
// where none of that passes, the sticking cycle beside the last slipping one is the attractor
// a settling run finds (started outside the last orbit) a little back or ahead in p, near
// the last orbit (a grazing corner: docs/orbits.md, "Grazing corners").
// The arclength's norm (BranchSpec::norm): `si`, the unknowns in their own SI units
// (|dz|^2 = |dy0|^2 + dT^2 + dp^2, a parameter in N/m weighs a million times one in MN/m), or
// `scaled`, each unknown over its own scale (|dz|^2 = sum (dz_i / w_i)^2): a state entry over
// its range along the first orbit (at least 1e-3 of the largest range among the positions,
// rotations, velocities or friction states it is one of, and 10 um, um/s or urad; from a Hopf
// point, whose first orbit is tiny, the finite differences' 1 cm, 1 cm/s, 10 mrad), the
// period over the
// first period, the parameter over |to - from|. Scaled, the branch does not depend on the
// parameter's units: p -> c p gives the same points (p times c) and events, and a step is a
// fraction of that balance (default 0.1). Every step, tangent and secant is formed in the
// scaled unknowns z_i / w_i (the Newton rows A diag(w) and the arclength row d / w); the
// columns' finite differences stay in SI (`fd_step`).
// Keller's arclength with such weights: Allgower & Georg 2003, sec. 2.3; AUTO's scaled norm
// (Doedel et al., AUTO-07P manual, "NPR, THETA").
// (`arclength` and `step` of each point, and dp_ds, are in the norm's units.)
// At each point: the period, the observed coordinate's peak-to-peak amplitude, the Floquet
// multipliers (study/orbit/shooting.hpp), the unit tangent's parameter component dp/ds, and
// the observed body's smallest slip speed on the orbit and the fraction of the period it
// spends below the summary's stick speed. Between consecutive points (detectBranchEvents):
// - fold: dp/ds changes sign where the points' parameters turn too (the secants on either
//   side point opposite ways; a sign change without that is the tangent's noise, as near a
//   joint stop's kink); located where the linear interpolation of dp/ds in s vanishes, the
//   vertex of the parabola p(s) it integrates to; a turn of the parameters without a sign
//   change of dp/ds is a fold at the vertex of the parabola through its three points;
// - Hopf point: such a turn where the amplitude has a minimum below 0.2 of the branch's
//   largest (the orbit shrinks onto the steady state, and the phase condition meets it again
//   from its minimum: p - p_H ~ eps^2 turns there too); the branch stops there;
// - period doubling: the number of real multipliers below -1 changes;
// - torus (Neimark-Sacker): the number of complex multipliers outside the unit circle changes;
// - stability change otherwise (a real multiplier through +1, as at a fold);
// - grazing: the smallest slip speed crosses the stick speed (sticking begins or ends).
// Period doubling, torus and stability change are looked for between consecutive decided
// points (points whose stability is undecided, BranchPoint::undecided, are passed over) and
// located by linear interpolation in p of the crossing multipliers' modulus to 1, grazing of
// the smallest slip speed to the stick speed.
// Located values are interpolations between two points, not solved for.
// Beside each point, steady sliding at the same parameter as `tribo modes` analyses it (its
// leading growth rate): where the two branches coexist, both stable, is hysteresis.
// The branch may also start at a Hopf point of steady sliding (BranchSpec::from_hopf,
// study/orbit/hopf_start.hpp): the first orbit is solved with its amplitude fixed (a row
// y_obs - y_obs,steady = eps in place of the arclength row), the unknowns z as above, from
// the guess steady state + eps (mode's real part), T = 2 pi / omega, p = p_H; the branch then
// leaves along the tangent on which the amplitude grows, and stops when p leaves the range.
// A forced scene (an input that varies in time, study/orbit/forcing.hpp) has a branch of forced
// orbits: the same unknowns, the phase row replaced by T - K P(p) = 0 (P the forcing's period
// at p, K = OrbitSpec::periods; its p column by central differences), the orbit's start taken
// at t = 0 so that the forcing's phase stays whatever P becomes (a branch in the forcing
// frequency: the frequency response, its folds and the unstable response between them), no
// trivial multiplier, no Hopf start, no collapse check (a small response is an orbit).
// Branch switching (BranchSpec::switch_at): the branch above (the primary) is followed until
// the first period doubling (or branch point: a real multiplier through +1 that is not a
// fold's) between two of its points; the point is then located by the Illinois variant of
// regula falsi on g(p) = |mu(p)| - 1, mu the multiplier nearest -1 (+1, the trivial one set
// aside by its eigenvector, the flow's direction, the T column of the Jacobian), each g from
// the orbit corrected at fixed p (the parameter's row in place of the arclength's), to
// |g| <= 1e-9 or 12 evaluations. The secondary branch leaves the located orbit z* = (y*, T*,
// p*) along the critical multiplier's eigenvector v (Seydel 2010, sec. 7.6-7.7; Kuznetsov,
// "Elements of Applied Bifurcation Theory", 3rd ed., Springer 2004, sec. 10.3): at a period
// doubling the orbit of twice the period (T* -> 2 T*; a forced orbit spans 2 K forcing
// periods), at a branch point the same period. Its first orbit is solved with the row
// r . (z - z1) = 0, z1 = (y* + a v, T', p*), r = (v, 0, 0) less its part along the primary's
// tangent (so the primary, traversed once or twice, does not satisfy it), v scaled so that its
// largest position or rotation entry is 1 and a = switch_amplitude [m or rad]; the secondary
// branch then runs either way from it, within [from, to], like a Hopf start's.
// Not here: matrix-free solves for large states; a torus's branch (quasi-periodic, no orbit).
// Where: the loop and the switch in orbit_branch.cpp, the rows and corrector in
// branch_shooter.hpp, the events in branch_events.cpp, the files in branch_files.cpp.
#pragma once

#include <Eigen/Dense>
#include <atomic>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "study/orbit/periodic_orbit.hpp"

namespace tribo::study {

// Which bifurcation of the primary branch the secondary leaves from (above).
enum class BranchSwitch { kNone, kPeriodDoubling, kBranchPoint };
// "none", "period_doubling", "branch_point".
std::string branchSwitchName(BranchSwitch kind);
inline constexpr double kDefaultSwitchAmplitude = 1e-3;

// The arclength's norm (above): the unknowns in SI units, or each over its own scale.
enum class ArclengthNorm { kSi, kScaled };
// "si", "scaled".
std::string arclengthNormName(ArclengthNorm norm);

struct BranchSpec {
  std::string parameter;    // a name in the scene's parameters: section
  double from = 0, to = 0;  // the branch starts at `from` and runs towards `to`
  int max_points = 20;      // points at most, the start included
  ArclengthNorm norm = ArclengthNorm::kSi;
  double step = 0;  // first arclength step; 0: |to - from| / 10 (si), 0.1 (scaled)
  // The branch stops below this step (lowered past a grazing point it crossed, to 1/64 of
  // the step it goes on with there); 0: min(step, max_step) / 64.
  double min_step = 0;
  double max_step = 0;      // 0: 4 step
  int max_corrector = 6;    // Newton iterations per point at most
  double fd_parameter = 0;  // dp of the p column; 0: orbit.fd_step max(|p|, |to - from|)
  OrbitSpec orbit;          // the first orbit (settle), tolerance, fd_step, threads
  // Start at the Hopf point of steady sliding between `from` and `to`
  // (study/orbit/hopf_start.hpp) instead of at the orbit a settling run finds at `from`: the
  // first orbit has the observed coordinate peaking `hopf_amplitude` [m or rad] above steady
  // sliding's value (0: 1e-3), and the branch runs whichever way the orbits go, within the
  // range.
  bool from_hopf = false;
  double hopf_amplitude = 0;
  // Switch at the primary branch's first period doubling or branch point to the branch that
  // leaves it there; the first secondary orbit is `switch_amplitude` [m or rad] off the
  // primary's along the critical mode (0: kDefaultSwitchAmplitude).
  BranchSwitch switch_at = BranchSwitch::kNone;
  double switch_amplitude = 0;
  // Set from outside (a signal handler): the branch ends after the point in hand, with the
  // points so far (BranchResult::interrupted).
  const std::atomic<bool>* stop = nullptr;
};

struct BranchPoint {
  double parameter = 0, period = 0;
  double amplitude_pp = 0, x_min = 0, x_max = 0;  // of the observed coordinate
  std::vector<std::complex<double>> multipliers;  // by decreasing modulus
  int trivial = -1;                               // the one nearest 1
  double trivial_error = 0;
  double largest = 0;  // modulus of the largest non-trivial multiplier
  bool stable = false;
  // Stability not decided (and `stable` false): a non-trivial multiplier within what the flow
  // can tell of the unit circle, ten times the trivial one's error and at least 1e-6 (the
  // rule by which `tribo orbit` reports an orbit `neutral`). Period doublings, tori and
  // stability changes are looked for between decided points only.
  bool undecided = false;
  // The observed body's slip speed over the orbit where it touches (the largest over its
  // contact points, as the run summary takes it): its minimum, and the fraction of the period
  // spent below the summary's stick speed; NaN when it never touches.
  double min_slip = NAN, stick_fraction = NAN;
  // The leading growth rate [1/s] of steady sliding at this parameter (`tribo modes`,
  // study/modes/modes.hpp): the steady branch beside the orbits, stable where it is < 0;
  // NaN where the scene has no steady state.
  double steady_growth = NAN;
  double dp_ds = 0;      // the unit tangent's parameter component (dp per unit of s)
  double arclength = 0;  // s from the branch's start
  int iterations = 0;    // the corrector's (the return map's where by_return_map)
  // Reached by the return map at the predicted parameter (branch_return_map.hpp): its
  // multipliers are then the trivial one and the two leading others, estimated.
  bool by_return_map = false;
  // Solved at a fixed parameter: one of the two orbits that bracket a grazing point the
  // arclength corrector could not pass (branch_grazing.hpp), or the sticking cycle beside the
  // last slipping one at a grazing corner; its multipliers are every one.
  bool fixed_parameter = false;
  double residual = 0;  // |F| / (1 + |y0|) of the closing and phase rows
  double step = 0;  // the step ds that reached this point (0 for the first, and fixed_parameter)
  Eigen::VectorXd start;     // y0
  std::vector<double> t, x;  // the observed coordinate over one period, per step, from y0
};

enum class BranchEventKind { kFold, kPeriodDoubling, kTorus, kStabilityChange, kGrazing, kHopf };
std::string branchEventName(BranchEventKind kind);  // "fold", "period_doubling", ...

struct BranchEvent {
  BranchEventKind kind{};
  std::size_t before = 0, after = 0;  // the points it lies between
  double parameter = 0;               // where, interpolated
};

// Where a secondary branch left the primary (BranchSpec::switch_at).
struct BranchSwitchPoint {
  bool found = false;                 // the bifurcation was on the primary branch and located
  BranchEventKind kind{};             // kPeriodDoubling or kStabilityChange (a branch point)
  std::size_t before = 0, after = 0;  // the primary's points it lies between
  double parameter = NAN;             // located
  std::complex<double> multiplier;    // the critical one at the located orbit
  double residual = NAN;              // |g| = ||mu| - 1| there
  int evaluations = 0;                // orbits corrected at fixed p to locate it
  double period = NAN;                // the primary orbit's there
  double amplitude = 0;               // a, the first secondary orbit's offset
};

struct BranchResult {
  std::string observed;                  // "box.x"
  std::vector<std::string> coordinates;  // the names of each point's `start` entries
  // The branch; with a switch, the secondary one (the primary's in `primary`).
  std::vector<BranchPoint> points;
  // The events between the points (detectBranchEvents), and last a grazing point located
  // past the last point (before = after = its index): where the stable orbits stop sticking
  // and no orbit was found beyond at fixed parameters (orbit_branch.cpp).
  std::vector<BranchEvent> events;
  // With BranchSpec::switch_at: the primary branch up to the bifurcation, its events and where
  // the secondary left it (switched.found false: the primary ended without one; `points` then
  // holds the primary).
  std::vector<BranchPoint> primary;
  std::vector<BranchEvent> primary_events;
  BranchSwitchPoint switched;
  double stick_speed = 0;    // the scene's output.summary.stick_speed, for grazing
  bool reached_end = false;  // a point at or past `to`
  bool lost = false;         // stopped by the corrector failing at the smallest step
  bool interrupted = false;  // stopped by BranchSpec::stop
  // With BranchSpec::from_hopf: the Hopf point the branch started from (NaN otherwise), the
  // angular frequency of its mode [rad/s] and the modes analyses its location took.
  double hopf_parameter = NAN, hopf_omega = NAN;
  int hopf_analyses = 0;
  std::string stop_reason;
  double seconds = 0;
  ArclengthNorm norm = ArclengthNorm::kSi;
  Eigen::VectorXd weights;  // the norm's w per unknown (y0, T, p): ones for si
  bool forced = false;      // the scene's inputs vary in time: a branch of forced orbits
  int periods = 1;          // forced: each orbit spans this many forcing periods
};

// The branch from the orbit findPeriodicOrbit finds at `from` (scene `path` loaded with
// `overrides` and then parameter=value), or from the Hopf point in [from, to] (from_hopf).
// `progress(point, index)` after each point if given. Throws io::SceneError for an unreadable scene
// or an unknown or non-numeric parameter (before any work), OrbitError when there is no orbit at
// `from` (or only the equilibrium a damped settling run decays to) or, with from_hopf, no Hopf
// point in the range or no first orbit at it; a branch lost later returns the points found so far
// with stop_reason saying why.
BranchResult continueOrbit(
    const std::string& path, const std::vector<std::string>& overrides, const BranchSpec& spec,
    const std::function<void(const BranchPoint&, std::size_t)>& progress = {});
// The same from the scene's YAML text; `name_for_errors` stands for the file name in
// messages and relative paths (as io::loadSceneFromString).
BranchResult continueOrbitFromText(
    const std::string& yaml, const std::string& name_for_errors,
    const std::vector<std::string>& overrides, const BranchSpec& spec,
    const std::function<void(const BranchPoint&, std::size_t)>& progress = {});

// The events between consecutive points (points need parameter, arclength, dp_ds,
// multipliers, trivial, stable, undecided and, for grazing, min_slip; stick_speed 0: no
// grazing). A period doubling, torus or stability change lies between two decided points,
// with undecided ones between them, if any. A branch of forced orbits (`autonomous` false)
// has no Hopf point: every turn is a fold.
std::vector<BranchEvent> detectBranchEvents(const std::vector<BranchPoint>& points,
                                            double stick_speed = 0, bool autonomous = true);

// branch.csv: one row per point (columns in docs/orbits.md); branch.json: the spec, the
// events, the stop reason; branch_orbits.csv: each point's sampled orbit (point, t and the
// observed coordinate), for replay and plots.
std::string branchCsvText(const BranchResult& r);
// primary_branch.csv (with a switch): the primary branch's rows, in branch.csv's columns.
std::string primaryBranchCsvText(const BranchResult& r);
std::string branchOrbitsCsvText(const BranchResult& r);
std::string branchJsonText(const std::string& scene_path, const BranchSpec& spec,
                           const BranchResult& r);

}  // namespace tribo::study
