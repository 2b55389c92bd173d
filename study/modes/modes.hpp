// Will it squeal? The linear stability of a scene's steady state (complex eigenvalue
// analysis). The steady state comes from study/modes/steady_state.hpp, the linearized system
// y' = A y from study/modes/linearization.hpp; the eigenvalues lambda = sigma + i omega of A give
// per mode
//   frequency f = |omega| / (2 pi) [Hz],  growth rate sigma [1/s],
//   damping ratio zeta = -sigma / |lambda|  (1 for a real, decaying lambda; -1 growing),
// and the mode shape: the configuration part N z of the eigenvector (z its first half),
// per full coordinate (body, x y z rx ry rz) a magnitude scaled so the largest is 1 and a
// phase [deg] relative to it. A mode is unstable when sigma > growth_tolerance. A complex
// pair is reported once (omega >= 0). Modes are sorted by decreasing growth rate.
// Two eigensolvers (ModesSpec::solver): dense, every eigenpair (Eigen::EigenSolver, cubic in
// the states), and sparse, the `sparse_modes` modes of largest growth rate among those near
// the imaginary axis (shift-and-invert Arnoldi scanning the frequency band,
// study/modes/sparse_modes.hpp; residual-checked). auto takes
// the dense one up to kSparseAboveStates states and the sparse one above, falling back to
// the dense one with a warning when the sparse one fails (docs/stability.md has the timings
// the threshold comes from). The sparse solver's unstable_count counts the modes it returned.
// For one body of mass m on a belt at speed v_b held by a spring (k, c), the in-plane pair
// is sigma = -(c + N mu'(v_b)) / (2 m), f = sqrt(k/m - sigma^2) / (2 pi) (docs/stability.md).
// Rolling and spinning resistance: the angular springs are anchored at the steady state and
// held while it is perturbed (a stuck part adds k and c to K and C about its axes); the
// steady-state search itself runs without them, so they hold no preload there (a ball held
// on a slope by rolling resistance alone has no steady state here).
// Errors: ModesError for what cannot be analysed (stateful friction, no dynamic body, a
// non-finite linearization, an eigenproblem that fails); NoSteadyState from the steady-state
// search. Never a table of NaN.
// Not here: the internal states of stateful friction laws, nonlinear (limit-cycle)
// amplitudes, modes outside the sparse solver's scanned discs (study/modes/sparse_modes.hpp says
// what its scan certifies), files (apps/modes_command.cpp).
#pragma once

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/modes/input_matrix.hpp"
#include "study/modes/linearization.hpp"
#include "study/modes/modes_error.hpp"
#include "study/modes/sparse_modes.hpp"
#include "study/modes/steady_state.hpp"

namespace tribo::study {

enum class EigenSolverChoice { kAuto, kDense, kSparse };

// auto: dense up to this many states (2 x coordinates, plus friction states), sparse above.
inline constexpr int kSparseAboveStates = 200;

struct ModesSpec {
  SteadyStateOptions steady;
  double check_tolerance = 1e-4;   // finite-difference step check (study/modes/linearization.hpp)
  double growth_tolerance = 1e-6;  // sigma above this is unstable [1/s]
  EigenSolverChoice solver = EigenSolverChoice::kAuto;
  int sparse_modes = 12;      // modes the sparse solver returns (a complex pair once)
  bool linear_model = false;  // also the matrices A, B, K, C (study/modes/input_matrix.hpp)
};

// Which solver gave the modes, and the sparse one's figures (zero for the dense one).
struct SolverReport {
  std::string method = "dense";       // "dense" or "sparse"
  int requested = 0;                  // sparse: modes asked for
  int shifts = 0;                     // sparse: shifts i w of the band scan
  int found = 0;                      // sparse: distinct eigenvalues found (a pair once)
  double band_top = 0.0;              // sparse: the scan covers i [0, band_top] [1/s]
  double strip = 0.0;                 // sparse: ... and |Re lambda| < strip along it [1/s]
  double worst_residual = 0.0;        // sparse: largest ||A v - lambda v|| / (||A||_F ||v||)
  bool sparse_factorization = false;  // sparse: A - i w I by SparseLU (else dense LU)
  int operations = 0;                 // sparse: applications of a shifted inverse
};

struct ShapeEntry {
  std::string coordinate;  // e.g. "box.x"
  double magnitude = 0.0;  // largest entry 1
  double phase_deg = 0.0;  // relative to the largest entry
};

struct Mode {
  std::complex<double> eigenvalue;
  double frequency = 0.0;      // [Hz]
  double growth_rate = 0.0;    // [1/s]
  double damping_ratio = 0.0;  // [-]
  bool unstable = false;
  std::vector<ShapeEntry> shape;  // every full coordinate, in coordinate order
  std::string dominant;           // the coordinates with magnitude >= 0.1, largest first
                                  // (the first 6 by name, then "(+N)" for the others)
};

struct ModesResult {
  SteadyState steady;
  std::vector<Mode> modes;  // decreasing growth rate
  int unstable_count = 0;
  int coordinates = 0;  // independent coordinates (the system has twice as many states)
  DifferenceSteps steps;
  double worst_disagreement = 0.0;
  std::vector<std::string> warnings;
  SolverReport solver;
  double steady_seconds = 0.0;        // wall time of the steady-state search
  double linearize_seconds = 0.0;     // wall time of the linearization and eigenvalues
  int evaluations = 0;                // of Dynamics::evaluate, in all
  std::optional<LinearModel> linear;  // with ModesSpec::linear_model

  // The mode with the largest growth rate (modes is never empty).
  const Mode& leading() const { return modes.front(); }
};

// Steady state, linearization and modes of a loaded scene.
ModesResult analyzeModes(const io::Scene& scene, const ModesSpec& spec = {});

// Modes of A = [[0, I], [K, C]] in `coords` (exposed for tests and benches): every one, by
// the dense solver.
std::vector<Mode> modesOf(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                          double growth_tolerance);
// The `options.count` modes of largest growth rate by the sparse solver; its figures in
// `report` when given.
std::vector<Mode> sparseModesOf(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                                double growth_tolerance, const SparseEigenOptions& options,
                                SolverReport* report = nullptr);

struct SolvedModes {
  std::vector<Mode> modes;  // decreasing growth rate
  SolverReport solver;
  std::vector<std::string> warnings;  // auto's fallback, growing modes beyond those returned
};
// The solver `spec` chooses (auto by size, with the fallback) applied to A.
SolvedModes solveModes(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                       const ModesSpec& spec);

}  // namespace tribo::study
