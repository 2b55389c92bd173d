// Redundant-constraint detection at the initial configuration. A row is redundant when its
// Jacobian is a linear combination of the rows before it; then J M^-1 J^T is singular and
// the multipliers are not unique. Found by a pivot-threshold Cholesky of J M^-1 J^T in row
// order: row i is redundant when its pivot
//   d_i = A_ii - sum_k L_ik^2   (over the rows kept so far)
// is below `relative_tolerance` A_ii, i.e. when the sine of the angle between row i and the
// span of the kept rows (in the M^-1 metric) is below sqrt(relative_tolerance).
// Typical case: a planar closed loop of revolute joints in 3D, whose out-of-plane equations
// repeat each other. Open chains and trees without drives or couplings cannot be redundant
// with the joint types of core/joint.hpp; needsRankCheck() skips them (the check is O(n^3)).
// Not here: deciding what to do about it (ModelBuilder::build, ConstraintOptions).
#pragma once

#include <string>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/model.hpp"

namespace tribo {

// True when the model has a closed loop of joints (through the world and kinematic bodies
// too), a drive or a coupling.
bool needsRankCheck(const Model& model);

// One line per joint whose equations the builder dropped as redundant, naming them (for the
// run summary's warnings).
std::vector<std::string> droppedEquationNotes(const Model& model);

// Indices into `rows` of the redundant rows, at the model's initial configuration.
std::vector<int> findRedundantRows(const Model& model, const std::vector<ConstraintRow>& rows,
                                   double relative_tolerance = 1e-10);

}  // namespace tribo
