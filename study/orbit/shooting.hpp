// The pieces a shooting method for periodic orbits is made of, shared by the single orbit
// (study/orbit/periodic_orbit.hpp) and its continuation in a parameter
// (study/orbit/orbit_branch.hpp); internal to study/orbit/. The flow phi_T(y) of the scene's
// own integrator (a fixed step's last step shortened, an adaptive one's last interval, so that
// it ends at T exactly), the checks that a scene can be shot (an observed body coordinate,
// autonomous), the finite-difference step an integrator wants, the
// first guess from a settled run, the finite-difference steps of the Jacobian's columns and
// their spread over threads, and the Floquet multipliers of a monodromy matrix (Seydel,
// "Practical Bifurcation and Stability Analysis", 3rd ed., Springer 2010, sec. 7.3-7.4).
// Not here: Newton's iteration, which each caller sets up on its own unknowns.
#pragma once

#include <Eigen/Dense>
#include <atomic>
#include <complex>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"
#include "io/scene_loader.hpp"
#include "study/orbit/orbit_coordinates.hpp"

namespace tribo::study::shooting {

// The observed body's index in the model after checking that its summary observes a
// dynamic body's coordinate. Throws OrbitError naming what is missing.
int observedBody(const io::Scene& scene);
// observedBody after checking that the scene is autonomous (study/orbit/forcing.hpp).
int shootableBody(const io::Scene& scene);

// The finite-difference step shooting uses on `model`'s integrator: `fd_step` for the
// fixed-step ones (their flow is smooth in y0 to rounding), at least rtol^(1/3) for the
// adaptive ones (dopri5, bdf): their error control chooses other internal steps for a
// perturbed start, so the flow is smooth only to about rtol, and a central difference over d
// errs by rtol / d plus d^2, least near d = rtol^(1/3) (Dennis & Schnabel, "Numerical
// Methods for Unconstrained Optimization and Nonlinear Equations", SIAM 1996, sec. 5.4).
double fdStepFor(const Model& model, double fd_step);

// The state T after `start` on the scene's integrator (the last step shortened so that it
// ends at T exactly); `sample(t - start.time, state)` after each step if given, then
// `contacts(workspace)` with the forces and contacts at that state if given. Throws
// OrbitError for a failed step.
State advance(const std::shared_ptr<const Model>& model, const State& start, double T,
              const std::function<void(double, const State&)>& sample = {},
              const std::function<void(const Workspace&)>& contacts = {});

// The flow of the scene's integrator: from y over T, with the last step shortened.
class Flow {
 public:
  Flow(std::shared_ptr<const Model> model, const OrbitCoordinates& coords);
  // y at T; `sample(t, state)` after each step if given, then `contacts(workspace)` with the
  // forces and contacts evaluated at that state if given. Throws OrbitError for a failed step.
  Eigen::VectorXd operator()(const Eigen::VectorXd& y, double T,
                             const std::function<void(double, const State&)>& sample = {},
                             const std::function<void(const Workspace&)>& contacts = {}) const;
  // Flows computed so far (on any thread), and the time they integrated [s].
  long count() const { return count_.load(); }
  double integrated() const { return integrated_.load(); }

 private:
  std::shared_ptr<const Model> model_;
  const OrbitCoordinates& coords_;
  mutable std::atomic<long> count_{0};
  mutable std::atomic<double> integrated_{0.0};
};

// The guess from a run of at most `seconds`: the state at the observed coordinate's last
// maximum and the cycle's period, the time back to the maximum m before it (each time linear
// in the velocity's zero crossing), m the maxima a cycle: 1, or up to kMostPeaksPerCycle where
// the coordinate peaks more than once a cycle (a pendulum swinging past the horizontal, a
// doubled period). The run stops early once the cycle repeats: kSettledCycles successive
// cycles whose last peak (the parabola through the velocity's last step before its zero
// crossing) and period each differ from the cycle's before by at most kSettledTolerance of the
// cycle's amplitude and period (a stick-slip cycle after three or four cycles; a growing or
// decaying one never). A run that ends unsettled takes the smallest m whose peak repeats to
// 1e-3 of the amplitude, else 1. The run starts at the model's initial state, or at `start`
// where given (a state of the model's bodies and contacts).
inline constexpr int kSettledCycles = 3;
inline constexpr double kSettledTolerance = 1e-6;
inline constexpr std::size_t kMostPeaksPerCycle = 4;
struct Guess {
  State state;
  double period = 0, amplitude_pp = 0;
  int peaks_per_cycle = 1;  // m
  double seconds = 0;       // how long the run went on
};
Guess settledGuess(const std::shared_ptr<const Model>& model, int body, int axis, double seconds,
                   const State* start = nullptr);

// The floor of each unknown's finite-difference scale: 1 cm, 1 cm/s and 10 mrad for bodies;
// the largest friction state (of y) for the `friction_count` last entries.
Eigen::VectorXd fdFloor(const Eigen::VectorXd& y, std::size_t friction_count);

// Calls column(j) for j = 0..count-1, spread over `threads` threads (each one core); rethrows
// the first exception a column threw.
void parallelColumns(Eigen::Index count, unsigned threads,
                     const std::function<void(Eigen::Index)>& column);

// The multipliers of a monodromy matrix by decreasing modulus, the trivial one (nearest 1)
// and its distance from 1, and stability (every other one inside the unit circle). A forced
// orbit's monodromy (`autonomous` false) has no trivial multiplier: trivial stays -1 and
// every multiplier must be inside the unit circle.
struct Floquet {
  std::vector<std::complex<double>> multipliers;
  int trivial = -1;
  double trivial_error = 0;
  bool stable = false;
  double largest = 0;  // the largest modulus of the others (the trivial one aside)
};
Floquet floquet(const Eigen::MatrixXd& monodromy, bool autonomous = true);
// The same from multipliers already computed (all of them, or the leading ones: the trivial
// one and stability are decided among those given).
Floquet classify(std::vector<std::complex<double>> multipliers, bool autonomous);

// Whether a multiplier other than the trivial one lies closer to the unit circle than the
// flow can tell (ten times the trivial one's error, at least 1e-6): the orbit's stability is
// then not decided (`tribo orbit` reports it neutral; a branch point, undecided).
bool undecidedStability(const std::vector<std::complex<double>>& multipliers, int trivial,
                        double trivial_error);

// v to 6 significant digits (printf's %.6g), for messages.
std::string messageNumber(double v);

// The smallest value of x by a parabola through the smallest sample and its neighbours.
double refinedMinimum(const std::vector<double>& x);
// The largest value of x, refined the same way (a forced orbit peaks anywhere between
// samples).
double refinedMaximum(const std::vector<double>& x);

// The observed coordinate (body `body`'s position component `axis`) over one period from y:
// the samples at t = 0 and after each step, and its extremes (the maximum the start's for an
// autonomous orbit, which starts at its peak; refined between samples for a forced one, and
// the minimum refined always).
struct SampledPeriod {
  std::vector<double> t, x;
  double x_max = 0, x_min = 0;
};
SampledPeriod samplePeriod(const Flow& flow, const OrbitCoordinates& coords,
                           const Eigen::VectorXd& y, double T, int body, int axis, bool forced);

// Newton's matrix of the closing rows at an orbit: the monodromy less I and, for an
// autonomous orbit (period_column given), d phi / d T as a last column and the phase row
// (a 1 at `phase`). Square: n, or n + 1.
Eigen::MatrixXd closingJacobian(const Eigen::MatrixXd& monodromy,
                                const Eigen::VectorXd* period_column, Eigen::Index phase);

}  // namespace tribo::study::shooting
