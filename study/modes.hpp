// Will it squeal? The linear stability of a scene's steady state (complex eigenvalue
// analysis). The steady state comes from study/steady_state.hpp, the linearized system
// y' = A y from study/linearization.hpp; the eigenvalues lambda = sigma + i omega of A
// (Eigen::EigenSolver, dense: fine up to some 2000 states) give per mode
//   frequency f = |omega| / (2 pi) [Hz],  growth rate sigma [1/s],
//   damping ratio zeta = -sigma / |lambda|  (1 for a real, decaying lambda; -1 growing),
// and the mode shape: the configuration part N z of the eigenvector (z its first half),
// per full coordinate (body, x y z rx ry rz) a magnitude scaled so the largest is 1 and a
// phase [deg] relative to it. A mode is unstable when sigma > growth_tolerance. A complex
// pair is reported once (omega >= 0). Modes are sorted by decreasing growth rate.
// For one body of mass m on a belt at speed v_b held by a spring (k, c), the in-plane pair
// is sigma = -(c + N mu'(v_b)) / (2 m), f = sqrt(k/m - sigma^2) / (2 pi) (docs/stability.md).
// Errors: ModesError for what cannot be analysed (stateful friction, no dynamic body, a
// non-finite linearization, an eigenproblem that fails); NoSteadyState from the steady-state
// search. Never a table of NaN.
// Not here: the internal states of stateful friction laws, sparse shift-invert solvers for
// large systems, nonlinear (limit-cycle) amplitudes, files (apps/modes_command.cpp).
#pragma once

#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/linearization.hpp"
#include "study/steady_state.hpp"

namespace tribo::study {

class ModesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// The numbers failed: a non-finite linearization or an eigenproblem that did not converge.
class LinearizationFailure : public ModesError {
 public:
  using ModesError::ModesError;
};

struct ModesSpec {
  SteadyStateOptions steady;
  double check_tolerance = 1e-4;   // finite-difference step check (study/linearization.hpp)
  double growth_tolerance = 1e-6;  // sigma above this is unstable [1/s]
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
  double steady_seconds = 0.0;     // wall time of the steady-state search
  double linearize_seconds = 0.0;  // wall time of the linearization and eigenvalues
  int evaluations = 0;             // of Dynamics::evaluate, in all

  // The mode with the largest growth rate (modes is never empty).
  const Mode& leading() const { return modes.front(); }
};

// Steady state, linearization and modes of a loaded scene.
ModesResult analyzeModes(const io::Scene& scene, const ModesSpec& spec = {});

// Modes of A = [[0, I], [K, C]] in `coords` (exposed for tests and benches).
std::vector<Mode> modesOf(const Eigen::MatrixXd& a, const ReducedCoordinates& coords,
                          double growth_tolerance);

}  // namespace tribo::study
