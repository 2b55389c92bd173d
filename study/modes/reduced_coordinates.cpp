#include "study/modes/reduced_coordinates.hpp"

#include <stdexcept>

#include "core/constraint_rows.hpp"

namespace tribo::study {

namespace {

// exp([v]x) as a quaternion.
Quat rotationVector(const Vec3& v) {
  const double angle = v.norm();
  if (angle < 1e-300) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(angle, v / angle));
}

}  // namespace

ReducedCoordinates::ReducedCoordinates(const Model& model, const State& at) : model_(model) {
  std::vector<int> slot(model.bodies.size(), -1);
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].kind == BodyKind::kDynamic) {
      slot[b] = static_cast<int>(dynamic_.size());
      dynamic_.push_back(static_cast<int>(b));
    }
  const int n = 6 * static_cast<int>(dynamic_.size());
  if (n == 0) throw std::invalid_argument("the scene has no dynamic body: nothing moves");

  std::vector<Mat3> rotation(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    rotation[b] = at.bodies[b].orientation.toRotationMatrix();

  // J over the full velocity coordinates, then N from its SVD.
  const std::vector<ConstraintRow> rows = constraintRows(model);
  if (rows.empty()) {
    basis_ = Eigen::MatrixXd::Identity(n, n);
  } else {
    std::vector<RowValue> values(rows.size());
    evaluateRows(rows, rowGroups(rows), MotionView(at, rotation), at.time, values);
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), n);
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (int k = 0; k < rows[r].body_count; ++k) {
        const int s = slot[rows[r].body[k]];
        if (s >= 0) j.block(static_cast<Eigen::Index>(r), 6 * s, 1, 6) += values[r].j[k];
      }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeFullV);
    const Eigen::VectorXd& sv = svd.singularValues();
    const double cut = 1e-10 * std::max(1.0, sv.size() > 0 ? sv(0) : 0.0);
    int rank = 0;
    while (rank < sv.size() && sv(rank) > cut) ++rank;
    basis_ = svd.matrixV().rightCols(n - rank);
  }
  if (basis_.cols() == 0)
    throw std::invalid_argument("the joints leave no degree of freedom: nothing moves");

  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const Body& body = model.bodies[dynamic_[i]];
    const Mat3& r = rotation[dynamic_[i]];
    const int o = 6 * static_cast<int>(i);
    mass.block<3, 3>(o, o) = body.mass * Mat3::Identity();
    mass.block<3, 3>(o + 3, o + 3) = r * body.inertia * r.transpose();
  }
  mass_basis_T_ = (mass * basis_).transpose();
  reduced_mass_ = mass_basis_T_ * basis_;
  reduced_mass_llt_.compute(reduced_mass_);
}

std::string ReducedCoordinates::fullName(int i) const {
  static const char* kDirection[] = {"x", "y", "z", "rx", "ry", "rz"};
  return model_.bodies[dynamic_[i / 6]].name + "." + kDirection[i % 6];
}

void ReducedCoordinates::perturb(const State& base, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& u, State& out) const {
  out = base;
  const Eigen::VectorXd dx = basis_ * q;
  const Eigen::VectorXd dv = basis_ * u;
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    BodyState& s = out.bodies[dynamic_[i]];
    const int o = 6 * static_cast<int>(i);
    s.position += dx.segment<3>(o);
    s.orientation = (rotationVector(dx.segment<3>(o + 3)) * s.orientation).normalized();
    s.velocity += dv.segment<3>(o);
    s.angular_velocity += dv.segment<3>(o + 3);
  }
}

Eigen::VectorXd ReducedCoordinates::difference(const State& from, const State& to) const {
  Eigen::VectorXd d(fullSize());
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const BodyState& a = from.bodies[dynamic_[i]];
    const BodyState& b = to.bodies[dynamic_[i]];
    const int o = 6 * static_cast<int>(i);
    d.segment<3>(o) = b.position - a.position;
    const Eigen::AngleAxisd turn(b.orientation * a.orientation.conjugate());
    d.segment<3>(o + 3) = turn.angle() * turn.axis();
  }
  return d;
}

Eigen::VectorXd ReducedCoordinates::reducedAcceleration(const Workspace& ws) const {
  Eigen::VectorXd a(fullSize());
  for (std::size_t i = 0; i < dynamic_.size(); ++i) {
    const int o = 6 * static_cast<int>(i);
    a.segment<3>(o) = ws.linear_acceleration[dynamic_[i]];
    a.segment<3>(o + 3) = ws.angular_acceleration[dynamic_[i]];
  }
  return reduced_mass_llt_.solve(mass_basis_T_ * a);
}

}  // namespace tribo::study
