// Independent coordinates about a configuration, for linearizing and for finding a steady
// state. Every dynamic body b has six full coordinates about the configuration x0: a
// translation dp_b (world, [m]) and a rotation vector dth_b (world, [rad]), its pose being
//   p_b = p0_b + dp_b,   R_b = exp([dth_b]x) R0_b
// and six velocity coordinates (v_b, w_b) (world), so that d(dth)/dt = w at first order
// about a body at rest. Joint constraints J(x) (v, w) = 0 (core/constraint_rows.hpp) leave
// the independent coordinates q with  (dp, dth) = N q,  (v, w) = v0 + N u,  where the
// columns of N are an orthonormal basis of the null space of J(x0) (from the SVD of J;
// redundant rows drop out by rank). The reduced accelerations are the mass-weighted
// projection of the accelerations a = (a_b, alpha_b) that Dynamics::evaluate returns:
//   q'' = (N^T M N)^-1 N^T M a,    M = diag(m_b I, R_b I_b R_b^T)
// Since J N = 0 and M a = f + J^T lambda, N^T M a = N^T f: the Lagrange multipliers (and
// Baumgarte's terms, second order off the constraint manifold) drop out, while the change
// of J along the manifold keeps its first-order share, the constraint forces' geometric
// stiffness (Blajer 2002, Multibody System Dynamics 7:265-284, projective formulation).
// Not here: rheonomic constraints (drives are treated as frozen at t), time stepping,
// deciding which state to linearize about (study/modes/steady_state.hpp).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo::study {

class ReducedCoordinates {
 public:
  // The basis at configuration `at` (its velocities do not matter).
  ReducedCoordinates(const Model& model, const State& at);

  int size() const { return static_cast<int>(basis_.cols()); }      // independent ones
  int fullSize() const { return static_cast<int>(basis_.rows()); }  // 6 per dynamic body
  const Eigen::MatrixXd& basis() const { return basis_; }           // N
  const Eigen::MatrixXd& reducedMass() const { return reduced_mass_; }
  // Model body index of each dynamic body, in coordinate order.
  const std::vector<int>& dynamicBodies() const { return dynamic_; }
  // Name of full coordinate i, e.g. "box.x", "box.rz".
  std::string fullName(int i) const;

  // `out` = `base` moved by N q in configuration and N u in velocity.
  void perturb(const State& base, const Eigen::VectorXd& q, const Eigen::VectorXd& u,
               State& out) const;
  // Full coordinates (6 per dynamic body) of a configuration change: translation and
  // rotation vector of each dynamic body of `to` relative to `from`.
  Eigen::VectorXd difference(const State& from, const State& to) const;
  // q'' = (N^T M N)^-1 N^T M a for the accelerations in an evaluated workspace.
  Eigen::VectorXd reducedAcceleration(const Workspace& ws) const;

 private:
  const Model& model_;
  std::vector<int> dynamic_;
  Eigen::MatrixXd basis_;         // N: fullSize x size
  Eigen::MatrixXd mass_basis_T_;  // (M N)^T = N^T M: size x fullSize
  Eigen::MatrixXd reduced_mass_;  // N^T M N
  Eigen::LLT<Eigen::MatrixXd> reduced_mass_llt_;
};

}  // namespace tribo::study
