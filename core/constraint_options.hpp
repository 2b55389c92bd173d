// Settings of the joint-constraint formulation that trade speed for accuracy or decide how
// a model's constraints are treated; part of SimulationOptions (core/model.hpp).
//   projection: after each step, positions are moved back onto Phi(q, t) = 0 by a few
//     Gauss-Newton iterations of the mass-weighted least change
//       dq = -M^-1 J^T (J M^-1 J^T)^-1 Phi,
//     then velocities onto J v = target rate by the same projection (Bayo & Ledesma 1996,
//     Nonlinear Dynamics 9:113-130, mass-orthogonal projection). Off by default: Baumgarte
//     alone keeps the validating scenes' drift small (measured in docs/joints.md).
//   redundancy: equations that depend on others at the initial configuration (e.g. the
//     out-of-plane equations of a planar loop of revolute joints) are an error naming them,
//     or, with kRemove, are dropped from the solve (and listed in the run summary).
//   solver: the multiplier system J M^-1 J^T is factorized dense (Cholesky) or sparse
//     (block-sparse Cholesky in an approximate-minimum-degree order, core/block_cholesky.hpp);
//     kAuto picks sparse from `sparse_threshold` equations on (the crossover measured by
//     bench/core/chain_bench.cpp), and solves in closed form when every row belongs to a
//     joint holding one body to the world with its rotations locked
//     (core/locked_rotation_solve.hpp).
//   drift: the largest |Phi| at a step's end (m for a distance, rad or - for an angle or a
//     perpendicularity) above `drift_warning` is a warning after the run naming the joint,
//     above `drift_stop` a stop naming the joint's child body (quantity "constraint_drift"):
//     a joint that has come apart by a tenth of a metre is not the mechanism any more, however
//     the energy looks. 1 cm is where a joint's gap is seen in the replay; the validating
//     scenes drift 1e-9 (rk4) to 4e-3 (semi-implicit Euler), docs/joints.md.
// Not here: the Baumgarte gains (SimulationOptions), the solve itself.
#pragma once

#include <string>

namespace tribo {

enum class RedundancyPolicy { kError, kRemove };
enum class ConstraintSolverKind { kAuto, kDense, kSparse };

struct ConstraintOptions {
  bool projection = false;
  double projection_tolerance = 1e-10;  // target max |Phi| [m or rad]
  int projection_iterations = 3;        // Gauss-Newton iterations at most, per step
  // Project the initial state too (poses and velocities that violate the joints by more
  // than the tolerance, e.g. a driven crank started from rest), whether or not `projection`.
  bool project_initial = true;
  RedundancyPolicy redundant = RedundancyPolicy::kError;
  ConstraintSolverKind solver = ConstraintSolverKind::kAuto;
  // Equations from which kAuto factorizes sparse. Measured (bench/core/chain_bench.cpp,
  // docs/joints.md): dense and sparse tie at one joint (5 equations); sparse is 8% faster at
  // 10, 26% at 20 and 2.4 times at Andrews' 41 equations in closed loops.
  int sparse_threshold = 8;
  double drift_warning = 1e-2;  // [m or rad]
  double drift_stop = 0.1;      // [m or rad]
};

// Scene names: "error" / "remove"; "auto" / "dense" / "sparse". Throw std::invalid_argument.
RedundancyPolicy redundancyPolicyFromName(const std::string& name);
ConstraintSolverKind constraintSolverFromName(const std::string& name);
std::string constraintSolverName(ConstraintSolverKind kind);

}  // namespace tribo
