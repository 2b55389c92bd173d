#include "core/locked_rotation_solve.hpp"

#include <map>

namespace tribo {

namespace {

// Whether a 3 x 3 matrix is invertible with room to spare: |det| against the product of its
// rows' lengths (1 for orthonormal rows, 0 for dependent ones), both squared (no roots taken:
// this runs at every evaluation). Rows so long or so short that the squares leave the double
// range read as not well conditioned, and the caller factorizes instead.
bool wellConditioned(const Mat3& m) {
  const double scale_squared =
      m.row(0).squaredNorm() * m.row(1).squaredNorm() * m.row(2).squaredNorm();
  const double det = m.determinant();
  return scale_squared > 0.0 && det * det > 1e-18 * scale_squared;
}

}  // namespace

std::optional<LockedRotationSolve> LockedRotationSolve::plan(
    const Model& model, const std::vector<ConstraintRow>& rows) {
  if (rows.empty()) return std::nullopt;
  std::map<int, HeldBody> by_body;
  std::map<int, int> joint_of_body;
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
    const ConstraintRow& row = rows[r];
    const bool primitive = row.kind == ConstraintRow::Kind::kDistance ||
                           row.kind == ConstraintRow::Kind::kPerpendicular;
    if (!primitive || !row.parent.isWorld() || row.body_count != 1 ||
        row.body[0] != row.child.value)
      return std::nullopt;
    const int b = row.child.value;
    const auto [it, fresh] = joint_of_body.emplace(b, row.joint);
    if (!fresh && it->second != row.joint) return std::nullopt;  // two joints on one body
    HeldBody& held = by_body[b];
    held.body = b;
    if (row.kind == ConstraintRow::Kind::kPerpendicular) {
      int k = 0;
      while (k < 3 && held.rotation_rows[k] >= 0) ++k;
      if (k == 3) return std::nullopt;
      held.rotation_rows[k] = r;
    } else {
      if (held.translations == 3) return std::nullopt;
      held.translation_rows[held.translations++] = r;
    }
  }
  LockedRotationSolve solve;
  for (auto& [b, held] : by_body) {
    if (held.rotation_rows[2] < 0) return std::nullopt;  // a rotation left free
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    held.mass = body.mass;
    held.inertia_body = body.inertia;
    // U^T U from the rows' world directions (fixed: the parent is the world).
    const int n = held.translations;
    Mat3 gram = Mat3::Identity();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        gram(i, j) =
            rows[held.translation_rows[i]].u_parent.dot(rows[held.translation_rows[j]].u_parent);
    if (!wellConditioned(gram)) return std::nullopt;
    held.gram_inverse = gram.inverse();
    solve.bodies_.push_back(held);
  }
  solve.rotation_blocks_.resize(solve.bodies_.size());
  return solve;
}

bool LockedRotationSolve::project(const std::vector<RowValue>& values, const Eigen::VectorXd& rhs,
                                  Workspace& ws, Eigen::VectorXd& lambda) {
  // Check every body first, so that a refusal leaves ws and lambda as they were.
  std::vector<Mat3>& gt = rotation_blocks_;
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    for (int i = 0; i < 3; ++i) gt[k].row(i) = values[bodies_[k].rotation_rows[i]].j[0].tail<3>();
    if (!wellConditioned(gt[k])) return false;
  }
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const HeldBody& held = bodies_[k];
    const auto b = static_cast<std::size_t>(held.body);
    const Mat3 gt_inverse = gt[k].inverse();
    const Vec3 b_r(rhs(held.rotation_rows[0]), rhs(held.rotation_rows[1]),
                   rhs(held.rotation_rows[2]));
    const Vec3 alpha = gt_inverse * b_r;
    const Vec3 a0 = ws.linear_acceleration[b];
    const Vec3 alpha0 = ws.angular_acceleration[b];
    Vec3 t = Vec3::Zero();
    for (int i = 0; i < held.translations; ++i) {
      const Row6& j = values[held.translation_rows[i]].j[0];
      t(i) = rhs(held.translation_rows[i]) - j.tail<3>().dot(alpha) - j.head<3>().dot(a0);
    }
    const Vec3 s = held.gram_inverse * t;  // (U^T U)^-1 t; rows past `translations` are 0
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();  // sum_i lambda_t,i c_i
    for (int i = 0; i < held.translations; ++i) {
      const Row6& j = values[held.translation_rows[i]].j[0];
      const double l = held.mass * s(i);
      lambda(held.translation_rows[i]) += l;
      force += l * j.head<3>().transpose();
      moment += l * j.tail<3>().transpose();
    }
    const Mat3& r = ws.rotation[b];
    const Vec3 torque = r * (held.inertia_body * (r.transpose() * (alpha - alpha0)));
    const Vec3 lambda_r = gt_inverse.transpose() * (torque - moment);
    for (int i = 0; i < 3; ++i) lambda(held.rotation_rows[i]) += lambda_r(i);
    ws.linear_acceleration[b] = a0 + force / held.mass;
    ws.angular_acceleration[b] = alpha;
    ws.constraint_wrench[b].force += force;
    ws.constraint_wrench[b].torque += torque;
  }
  return true;
}

}  // namespace tribo
