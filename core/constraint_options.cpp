#include "core/constraint_options.hpp"

#include <stdexcept>

namespace tribo {

RedundancyPolicy redundancyPolicyFromName(const std::string& name) {
  if (name == "error") return RedundancyPolicy::kError;
  if (name == "remove") return RedundancyPolicy::kRemove;
  throw std::invalid_argument("unknown redundancy policy '" + name +
                              "' (expected one of: error, remove)");
}

ConstraintSolverKind constraintSolverFromName(const std::string& name) {
  if (name == "auto") return ConstraintSolverKind::kAuto;
  if (name == "dense") return ConstraintSolverKind::kDense;
  if (name == "sparse") return ConstraintSolverKind::kSparse;
  throw std::invalid_argument("unknown constraint solver '" + name +
                              "' (expected one of: auto, dense, sparse)");
}

std::string constraintSolverName(ConstraintSolverKind kind) {
  switch (kind) {
    case ConstraintSolverKind::kDense:
      return "dense";
    case ConstraintSolverKind::kSparse:
      return "sparse";
    case ConstraintSolverKind::kAuto:
      break;
  }
  return "auto";
}

}  // namespace tribo
