// Moves a state back onto the constraint manifold after a step (drift control beyond
// Baumgarte): positions by Gauss-Newton iterations on Phi(q, t) = 0 with the mass-weighted
// least change, then velocities onto J v = f'(t) (Bayo & Ledesma 1996, Nonlinear Dynamics
// 9:113-130; Blajer 2002, Multibody System Dynamics 7:265-284):
//   dq = -M^-1 J^T (J M^-1 J^T)^-1 Phi          (repeated while max |Phi| > tol)
//   dv = -M^-1 J^T (J M^-1 J^T)^-1 (J v - f')
// A body's position moves by the linear part of dq, its orientation by the rotation vector
// of the angular part. Kinematic bodies and the world are not moved.
// Not here: when to project (ConstraintOptions, the simulator), the acceleration solve.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "core/constraint_jacobian.hpp"
#include "core/constraint_rows.hpp"
#include "core/model.hpp"
#include "core/multiplier_matrix.hpp"
#include "core/state.hpp"

namespace tribo {

struct ProjectionReport {
  int position_iterations = 0;  // Gauss-Newton corrections applied
  bool velocities_projected = false;
  double max_phi_before = 0.0;  // max |Phi| found at entry
  double max_phi_after = 0.0;   // max |Phi| at the last evaluation
  bool converged = true;        // max |Phi| <= tolerance within the iterations allowed
};

class ConstraintProjection {
 public:
  explicit ConstraintProjection(const Model& model);

  bool hasConstraints() const { return !rows_.empty(); }
  // Projects positions (while max |Phi| > tolerance, at most `iterations` corrections) and
  // then velocities (when max |J v - f'| > tolerance).
  ProjectionReport project(State& state, double tolerance, int iterations);

 private:
  // Rotations, world inverse inertias and all rows at `state`; returns max |Phi|.
  double evaluate(const State& state);
  bool factorize();
  // delta_linear_, delta_angular_ = M^-1 J^T (J M^-1 J^T)^-1 (-residual): the mass-weighted
  // least change of the body motions that cancels the rows' residual (phi or phi_dot) to
  // first order. Needs factorize().
  void leastChange(double RowValue::*residual);

  const Model& model_;
  std::vector<ConstraintRow> rows_;
  std::vector<RowGroup> groups_;
  ConstraintJacobian jacobian_;
  MultiplierMatrix matrix_;
  std::vector<RowValue> values_;
  std::vector<Mat3> rotation_, inv_inertia_world_, inv_inertia_body_;
  std::vector<double> inv_mass_;
  std::vector<Vec3> delta_linear_, delta_angular_;
  Eigen::VectorXd mu_;
};

}  // namespace tribo
