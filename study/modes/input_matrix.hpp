// The linear model with inputs, for control and squeal engineers' own tools: about the
// steady state of study/modes/modes.hpp,
//   y' = A y + B w,   y = (q, u, z),  w = the scene's inputs,
// A from study/modes/linearization.hpp, and B by central differences of the reduced
// accelerations (and dynamic friction states' rates) in each input:
//   column j of B = (g(w0 + h e_j) - g(w0 - h e_j)) / (2 h),  rows for q zero.
// Inputs, in this order: each applied load's six components in its own frame (LOAD.fx,
// LOAD.fy, LOAD.fz [N], LOAD.tx, LOAD.ty, LOAD.tz [N m]; core/applied_load.hpp) and each
// joint actuator's target (ACT: a motor's effort, a position servo's target, a velocity
// servo's target rate; core/joint_actuator.hpp), w0 their values at the state's time. The
// loads enter linearly, so h (1 in the input's unit) only sets the rounding; a saturated
// actuator's column is zero (the saturation holds its effort).
// The files (writeLinearModel): A.mtx, B.mtx, K.mtx (dq''/dq), C.mtx (dq''/du) in Matrix
// Market coordinate format (NIST; scipy.io.mmread, MATLAB's mmread), dense entries written
// where nonzero, N.mtx (the basis below), and linear_model.json naming the states (q:NAME,
// u:NAME, z:JOINT.STATE for a joint's friction state, z:contact[k] for the contacts' k-th
// state value), the inputs, the full coordinates and the files. The names of reduced coordinates
// are their full coordinates' (a joint-free scene) or "c<j>~NAME" for the full coordinate that
// independent coordinate j moves most. Not here: the mass matrix in its own block (K and C are
// already divided by it), outputs (a C/D pair for measured quantities), input rates (a servo's
// target rate is held).
#pragma once

#include <Eigen/Dense>
#include <filesystem>
#include <string>
#include <vector>

#include "core/dynamics.hpp"
#include "study/modes/linearization.hpp"
#include "study/modes/reduced_coordinates.hpp"

namespace tribo::study {

struct LinearModel {
  Eigen::MatrixXd a, b, k, c;
  // N: the full coordinates (6 per dynamic body, `coordinates`) of a unit step of each
  // independent one: full = N q (the identity for a scene without joints).
  Eigen::MatrixXd basis;
  std::vector<std::string> coordinates;
  std::vector<std::string> states;  // rows of A and B
  std::vector<std::string> inputs;  // columns of B
};

// A, K, C from `lin`; B at `at` (restores the loads and actuators afterwards).
LinearModel linearModel(Dynamics& dynamics, const ReducedCoordinates& coords, const State& at,
                        const Linearization& lin);

// The files above into `folder` (which exists). Throws std::runtime_error when one cannot be
// written.
void writeLinearModel(const std::filesystem::path& folder, const LinearModel& model);

}  // namespace tribo::study
