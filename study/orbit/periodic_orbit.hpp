// Periodic orbits of a scene (the limit cycle of stick-slip, its period, amplitude and
// stability) by shooting on the engine's own step, as circuit simulators find a periodic
// steady state on their transient integrator (Telichevesky, Kundert & White, "Efficient
// steady-state analysis based on matrix-free Krylov-subspace methods", DAC 1995; the
// formulation and the phase condition as in Seydel, "Practical Bifurcation and Stability
// Analysis", 3rd ed., Springer 2010, sec. 7.3). Unknowns: the state y0 on the orbit
// (study/orbit/orbit_coordinates.hpp: the dynamic bodies and the friction laws' internal
// states) and the period T:
//   phi_T(y0) - y0 = 0    phi: the scene's integrator at its step, the last step shortened
//                         so that the flow ends at T exactly
//   v_obs(y0)      = 0    phase: the orbit starts where the observed coordinate (the scene's
//                         summary body and coordinate) turns from rising to falling
// solved by return-map iterations while they contract fast (study/orbit/picard.hpp: a
// stick-slip orbit converges in two of them), then Newton's method with the Jacobian from
// finite differences of the flow (one column
// per unknown, the columns shared over the cores) and least squares (QR with column
// pivoting: directions the joints' constraints remove make it singular). The Floquet
// multipliers are the eigenvalues of the monodromy matrix d phi_T / d y0 at the orbit; one is
// 1 (the direction along the orbit) and its distance from 1 is reported as a quality check.
// On a stick-slip orbit the stick phase collapses phase space: the other multipliers come out
// near zero. The first guess is the settled tail of a run of the scene: its last two maxima.
// A forced scene (an input that varies in time, study/orbit/forcing.hpp) has orbits of the
// forcing's period P (or K P, a subharmonic): the period is known and the phase is the
// forcing's, so the unknowns are y0 alone, taken at a whole number of periods, and
//   phi_KP(y0) - y0 = 0
// is solved the same way; there is no trivial multiplier (every one inside the unit circle
// for a stable orbit). The first guess is the state after the settling run's whole periods.
// Any integrator: a fixed-step one (rk4, semi_implicit_euler) flows to T with its last step
// shortened; an adaptive one (dopri5, bdf) ends its last communication interval on T, and
// its finite differences span at least rtol^(1/3) (shooting::fdStepFor): its flow is smooth
// in y0 only to about rtol, so Newton's tolerance must lie above rtol (the error says so).
// Limits: friction memory on contacts that
// stay the same along the orbit; forced scenes whose inputs repeat (sines, sine drives, or a
// period the user gives and every input is checked against).
// Continuation in a parameter and the bifurcations along a branch: study/orbit/orbit_branch.hpp.
// Large states: with OrbitSolver::kKrylov (auto from 40 unknowns) Newton's step is GMRES on
// products of the Jacobian with a vector, each one flow, and only the leading multipliers are
// computed, by Arnoldi (study/orbit/krylov.hpp).
// Not here: a start from a Hopf point of `tribo modes` (hopf_start.hpp); continuation
// (orbit_branch.hpp), whose linear systems stay dense.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/state.hpp"
#include "io/scene_loader.hpp"
#include "study/orbit/step_check.hpp"

namespace tribo::study {

// A scene that has no orbit to shoot for (not autonomous, no oscillation, a failed step,
// Newton not converging): what() says which and what to change.
class OrbitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How Newton's linear systems and the multipliers are solved: dense (a Jacobian column of two
// flows per unknown, on the cores; every multiplier) or Krylov (matrix-free: GMRES for Newton's
// step, one flow per product, and Arnoldi for the leading multipliers;
// study/orbit/krylov.hpp); auto takes Krylov from kKrylovFromUnknowns unknowns on (measured,
// bench/scenes/orbit_bench.cpp BM_OrbitLanes, with the return-map iterations before Newton's:
// Krylov takes 1.17 of dense shooting's time at 12 unknowns, 0.87 at 48, 0.47 at 120 and 0.49
// at 300).
enum class OrbitSolver { kAuto, kDense, kKrylov };
inline constexpr long kKrylovFromUnknowns = 40;

struct OrbitSpec {
  double settle = 0.0;      // [s] the run that gives the first guess; 0: the scene's duration
  int max_iterations = 12;  // Newton iterations at most
  bool return_map = true;   // return-map iterations before Newton's (study/orbit/picard.hpp)
  double tolerance = 1e-9;  // converged when |F| <= tolerance (1 + |y0|)
  double fd_step = 1e-7;    // finite-difference step, relative to each unknown's scale
  unsigned threads = 0;     // for the Jacobian's columns; 0: one per core
  double period = 0.0;      // [s] forced scenes: the forcing's period; 0: read from the inputs
  int periods = 1;          // forced scenes: the orbit spans this many forcing periods
  OrbitSolver solver = OrbitSolver::kAuto;
  long leading_multipliers = 8;  // Krylov: the multipliers of largest modulus computed
};

struct OrbitResult {
  std::string observed;                             // "box.x": the summary body's coordinate
  double period = 0;                                // [s]
  double x_max = 0, x_min = 0, amplitude_pp = 0;    // of the observed coordinate on the orbit
  double guess_period = 0, guess_amplitude_pp = 0;  // from the settled run
  double guess_seconds = 0;   // how long the settling run went on (it stops once cycles repeat)
  int iterations = 0;         // Newton's
  int picard_iterations = 0;  // return-map iterations before Newton's (study/orbit/picard.hpp)
  double residual = 0;        // |F| at the end, relative to 1 + |y0|
  std::vector<std::complex<double>> multipliers;  // by decreasing modulus
  int trivial = -1;  // which one is the trivial multiplier (nearest 1); -1 for a forced orbit
  double trivial_error = 0;  // |mu_trivial - 1|
  bool stable = false;       // every other multiplier inside the unit circle
  // A multiplier other than the trivial one on the unit circle within the flow's error (ten
  // times the trivial one's, at least 1e-6): the orbit is one of a family and its stability is
  // not decided (stable is then false).
  bool neutral = false;
  double largest_multiplier = 0;   // the largest modulus of the others
  bool forced = false;             // the scene has inputs that vary in time: the period is theirs
  std::string forcing;             // forced: the first input that varies, and how many more
  double forcing_period = 0;       // [s] forced: the inputs' common period
  int periods = 1;                 // forced: the orbit's period over the forcing's
  std::string solver;              // "dense" or "krylov"
  long flows = 0;                  // flows computed (the settling run aside): of one period,
                                   // and one step a return-map iteration
  long flows_to_converge = 0;      // of those, the flows until the residual was met (the rest
                                   // are the multipliers' and the sampled period's)
  double periods_to_converge = 0;  // the time those flows integrated, in periods
  long krylov_products = 0;        // Krylov: GMRES and Arnoldi products
  std::vector<std::string> coordinates;  // names of y0's entries
  Eigen::VectorXd start;                 // y0
  State reference;  // the state y0's coordinates are taken against (its contacts and time)
  // The dense solver's Jacobian at the last Newton iterate (the polishing step, where kept,
  // moved y0 from it by less than the tolerance): the monodromy, from which the multipliers
  // above come, and d phi / d T (autonomous). Empty with the Krylov solver. A branch takes its
  // first tangent from them (orbit_branch.hpp), the step check its chord steps.
  Eigen::MatrixXd monodromy;
  Eigen::VectorXd period_column;
  // The orbit against a finer integrator setting, where the caller checked it
  // (study/orbit/step_check.hpp); orbit.json's "step_check".
  std::optional<StepCheck> step_check;
  std::vector<double> t, x;  // the observed coordinate over one period, per step
  double seconds = 0;        // wall time
};

// Throws OrbitError (and SceneError never: the scene is loaded).
OrbitResult findPeriodicOrbit(const io::Scene& scene, const OrbitSpec& spec = {});

// orbit.json's text: the scene, the figures, the multipliers and the start state.
std::string orbitJsonText(const io::Scene& scene, const OrbitSpec& spec, const OrbitResult& r);

}  // namespace tribo::study
