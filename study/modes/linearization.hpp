// The linearized equations of motion about a state, by central finite differences of
// Dynamics::evaluate in independent coordinates (study/modes/reduced_coordinates.hpp):
//   q'' = g(q, u),   K = dg/dq,   C = dg/du  at q = u = 0,
//   column j of K ~ (g(h e_j, 0) - g(-h e_j, 0)) / (2 h)   (error O(h^2), rounding O(eps/h))
// and the first-order system  y' = A y,  y = (q, u),  A = [[0, I], [K, C]].
// Everything the evaluation contains is differentiated at once: springs, penalty contact
// normal forces and their damping, the friction law's slope at the steady slip, gyroscopic
// terms, joint elements and the constraint forces' geometric stiffness.
// Steps (chooseSteps): positions and rotations h_q = min(1e-7, depth / 100) [m or rad] with
// `depth` the shallowest contact at the state (the step stays inside the penalty regime);
// velocities h_u = min(1e-6, v_stick / 100) [m/s or rad/s] with v_stick the smallest stick
// speed of the laws in contact (the step stays on one branch of a regularized law). Each
// column is computed again with 4 h: for a smooth function the two differ by about 15 times
// the error of the first; a relative difference above `check_tolerance` is a warning that
// names the coordinate (a kink, a contact opening or closing within the step).
// Internal states of dynamic friction laws (friction/dynamic_law.hpp) enter as a third
// block y = (q, u, z): the columns for q and u also give dz'/dq and dz'/du, and each state
// value z_i is stepped by h_z = 1e-4 |z_i| + 1e-12 (the states' own scale) for dq''/dz and
// dz'/dz; the records stay those of `at` (study/modes/modes.cpp settles them first).
// Not here: elastic_stick's anchors (study/modes/modes.cpp refuses them), analytic derivatives,
// choosing the state (study/modes/steady_state.hpp).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "core/dynamics.hpp"
#include "study/modes/reduced_coordinates.hpp"

namespace tribo::study {

struct DifferenceSteps {
  double position = 1e-7;  // [m or rad]
  double velocity = 1e-6;  // [m/s or rad/s]
};

// The reduced accelerations at `x`, followed by the internal states' rates when
// `with_states` (what the columns of K, C and the state blocks difference).
Eigen::VectorXd reducedResponse(Dynamics& dynamics, const ReducedCoordinates& coords,
                                const State& x, bool with_states);

// Steps for the state `at` (see the header comment); evaluates it once.
DifferenceSteps chooseSteps(Dynamics& dynamics, const State& at);

struct Linearization {
  Eigen::MatrixXd stiffness;        // K = dq''/dq
  Eigen::MatrixXd damping;          // C = dq''/du (empty when not asked for)
  double worst_disagreement = 0.0;  // largest relative difference of a column between h and 4 h
  std::vector<std::string> warnings;
  int evaluations = 0;
  // Dynamic friction's internal states z (State::friction_values, when `at` has them and
  // velocities are asked for): D = dq''/dz (n x nz), and z' = E q + F u + G z.
  Eigen::MatrixXd state_force, state_from_position, state_from_velocity, state_rate;
};

// K (and C when `velocities`) at `at`. With check_tolerance > 0 every column is checked
// against the step 4 h.
Linearization linearize(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at,
                        const DifferenceSteps& steps, bool velocities, double check_tolerance);

// A = [[0, I], [K, C]], or with internal states y = (q, u, z):
//   A = [[0, I, 0], [K, C, D], [E, F, G]].
Eigen::MatrixXd firstOrderMatrix(const Linearization& lin);

}  // namespace tribo::study
