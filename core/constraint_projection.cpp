#include "core/constraint_projection.hpp"

#include <algorithm>
#include <cmath>

#include "core/constraint_solver.hpp"

namespace tribo {

ConstraintProjection::ConstraintProjection(const Model& model)
    : model_(model), rows_(constraintRows(model)), groups_(rowGroups(rows_)) {
  const int m = static_cast<int>(rows_.size());
  const std::size_t nb = model.bodies.size();
  jacobian_.init(rows_, static_cast<int>(nb));
  matrix_.init(m, jacobian_.pattern(), useSparseFactorization(model.options.constraints, m),
               groupBegins(groups_, m));
  jacobian_.bindSlots(matrix_);
  values_.resize(m);
  if (m == 0) return;  // nothing to project: no per-body arrays (project returns at once)
  rotation_.assign(nb, Mat3::Identity());
  inv_inertia_world_.assign(nb, Mat3::Zero());
  inv_mass_.reserve(nb);
  inv_inertia_body_.reserve(nb);
  for (const Body& b : model.bodies) {
    const bool dynamic = b.kind == BodyKind::kDynamic;
    inv_mass_.push_back(dynamic ? 1.0 / b.mass : 0.0);
    inv_inertia_body_.push_back(dynamic ? Mat3(b.inertia.inverse()) : Mat3::Zero());
  }
  delta_linear_.assign(nb, Vec3::Zero());
  delta_angular_.assign(nb, Vec3::Zero());
  mu_.setZero(m);
}

void ConstraintProjection::leastChange(double RowValue::*residual) {
  for (std::size_t r = 0; r < values_.size(); ++r)
    mu_(static_cast<int>(r)) = -(values_[r].*residual);
  matrix_.solveInPlace(mu_);
  std::fill(delta_linear_.begin(), delta_linear_.end(), Vec3::Zero());
  std::fill(delta_angular_.begin(), delta_angular_.end(), Vec3::Zero());
  jacobian_.applyMultipliers(mu_, delta_linear_, delta_angular_, nullptr);
}

double ConstraintProjection::evaluate(const State& state) {
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    rotation_[b] = state.bodies[b].orientation.toRotationMatrix();
    inv_inertia_world_[b] = rotatedTensor(rotation_[b], inv_inertia_body_[b]);
  }
  evaluateRows(rows_, groups_, MotionView(state, rotation_), state.time, values_);
  double max_phi = 0.0;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    jacobian_.setRow(static_cast<int>(r), values_[r]);
    max_phi = std::max(max_phi, std::abs(values_[r].phi));
  }
  return max_phi;
}

bool ConstraintProjection::factorize() {
  jacobian_.computeMassWeighted(inv_mass_, inv_inertia_world_);
  matrix_.setZero();
  jacobian_.assemble(matrix_);
  return matrix_.factorize();
}

ProjectionReport ConstraintProjection::project(State& state, double tolerance, int iterations) {
  ProjectionReport report;
  if (rows_.empty()) return report;
  const int m = static_cast<int>(rows_.size());
  double max_phi = evaluate(state);
  report.max_phi_before = max_phi;
  while (max_phi > tolerance && report.position_iterations < iterations) {
    if (!factorize()) break;
    leastChange(&RowValue::phi);
    for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
      if (model_.bodies[b].kind != BodyKind::kDynamic) continue;
      BodyState& s = state.bodies[b];
      s.position += delta_linear_[b];
      s.orientation = rotateBy(delta_angular_[b], 1.0, s.orientation);
    }
    ++report.position_iterations;
    max_phi = evaluate(state);
  }
  report.max_phi_after = max_phi;
  report.converged = max_phi <= tolerance;

  double max_rate = 0.0;
  for (int r = 0; r < m; ++r) max_rate = std::max(max_rate, std::abs(values_[r].phi_dot));
  if (max_rate <= tolerance) return report;
  if (!factorize()) return report;
  leastChange(&RowValue::phi_dot);
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    if (model_.bodies[b].kind != BodyKind::kDynamic) continue;
    state.bodies[b].velocity += delta_linear_[b];
    state.bodies[b].angular_velocity += delta_angular_[b];
  }
  report.velocities_projected = true;
  return report;
}

}  // namespace tribo
