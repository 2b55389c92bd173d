// The joint multipliers in closed form for bodies each held to the world by one joint that
// locks all three rotations (planar_translation, prismatic, fixed): the belt's box and any
// scene of single bodies sliding on the world. There J M^-1 J^T is block diagonal, one block
// per body, and each block's solve splits in two small ones instead of a Cholesky of up to
// 6 x 6 (core/multiplier_matrix.hpp).
//
// One body, mass m, world inertia I; its rows' blocks are rotation rows (0, g_r) (three, the
// perpendicular equations) and translation rows (u_i, c_i) (the distance equations, u_i
// fixed in the world); the rows' right-hand sides b (core/constraint_solver.hpp). With the
// unconstrained accelerations (a0, alpha0), M a = M a0 + J^T lambda and J (a, alpha) = b give
//   alpha = G^-T b_r                          (G = [g_1 g_2 g_3], invertible off a lock-up)
//   t_i = b_i - c_i . alpha - u_i . a0,   a = a0 + U (U^T U)^-1 t,   lambda_t = m (U^T U)^-1 t
//   tau = I (alpha - alpha0),   lambda_r = G^-1 (tau - sum_i lambda_t,i c_i)
// and the constraint wrench (U lambda_t, tau): the same solution as the factorization, in
// other rounding. Applying it to accelerations that already satisfy J a = b changes nothing,
// so the resolve after a change of forces (joint friction) is the same projection.
// Not here: any row that is not such a joint's (drives, couplings, joints between bodies,
// two joints on one body; the solver then factorizes), evaluating the rows.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/model.hpp"
#include "core/workspace.hpp"

namespace tribo {

class LockedRotationSolve {
 public:
  // The plan for `rows` of `model`, or nothing when some row is not of the form above.
  static std::optional<LockedRotationSolve> plan(const Model& model,
                                                 const std::vector<ConstraintRow>& rows);

  // Moves the accelerations in ws onto the rows' equations (values at this state, right-hand
  // sides rhs), adds the multipliers to lambda and the constraint wrenches to
  // ws.constraint_wrench. False, with nothing changed, when a body's rotation rows are
  // (numerically) dependent: the caller factorizes instead.
  bool project(const std::vector<RowValue>& values, const Eigen::VectorXd& rhs, Workspace& ws,
               Eigen::VectorXd& lambda);

 private:
  struct HeldBody {
    int body = -1;
    double mass = 0.0;
    Mat3 inertia_body = Mat3::Zero();
    int rotation_rows[3] = {-1, -1, -1};
    int translation_rows[3] = {-1, -1, -1};
    int translations = 0;
    Mat3 gram_inverse = Mat3::Zero();  // (U^T U)^-1 in its leading translations^2 block
  };
  std::vector<HeldBody> bodies_;
  std::vector<Mat3> rotation_blocks_;  // per body, its rotation rows' g_r as rows (scratch)
};

}  // namespace tribo
