#include "core/constraint_options.hpp"

#include "friction/name_table.hpp"

namespace tribo {

namespace {

constexpr NameTable<RedundancyPolicy, 2> kRedundancyNames{
    "redundancy policy",
    {{{RedundancyPolicy::kError, "error"}, {RedundancyPolicy::kRemove, "remove"}}}};
constexpr NameTable<ConstraintSolverKind, 3> kSolverNames{
    "constraint solver",
    {{{ConstraintSolverKind::kAuto, "auto"},
      {ConstraintSolverKind::kDense, "dense"},
      {ConstraintSolverKind::kSparse, "sparse"}}}};

}  // namespace

RedundancyPolicy redundancyPolicyFromName(const std::string& name) {
  return kRedundancyNames.fromName(name);
}

ConstraintSolverKind constraintSolverFromName(const std::string& name) {
  return kSolverNames.fromName(name);
}

std::string constraintSolverName(ConstraintSolverKind kind) { return kSolverNames.name(kind); }

}  // namespace tribo
