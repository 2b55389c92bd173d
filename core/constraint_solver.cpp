#include "core/constraint_solver.hpp"

#include <algorithm>
#include <cmath>

namespace tribo {

namespace {

struct Motion {
  Mat3 rotation = Mat3::Identity();
  Vec3 origin = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
};

Motion motionOf(const State& state, BodyIndex b) {
  if (b.isWorld()) return {};
  const BodyState& s = state.bodies[b.value];
  return {s.orientation.toRotationMatrix(), s.position, s.velocity, s.angular_velocity};
}

}  // namespace

ConstraintSolver::ConstraintSolver(const Model& model) : model_(model) {
  dof_.assign(model.bodies.size(), -1);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].kind == BodyKind::kDynamic) {
      dof_[b] = n_dof_;
      n_dof_ += 6;
    }
  }
  for (const Joint& j : model.joints) {
    for (const ConstraintEquation& e : jointEquations(j.type)) {
      rows_.push_back({e.kind, j.parent, j.child, j.axes_in_parent.col(e.parent_axis),
                       j.axes_in_child.col(e.child_axis), j.anchor_in_parent, j.anchor_in_child});
    }
  }
  const int m = equationCount();
  jac_.setZero(m, n_dof_);
  minv_jt_.setZero(n_dof_, m);
  schur_.setZero(m, m);
  rhs_.setZero(m);
  lambda_.setZero(m);
  ldlt_ = Eigen::LDLT<Eigen::MatrixXd>(m);
  inv_inertia_world_.assign(model.bodies.size(), Mat3::Zero());
}

void ConstraintSolver::solve(const State& state, Workspace& ws) {
  ws.max_constraint_error = 0.0;
  ws.max_constraint_rate_error = 0.0;
  for (auto& w : ws.constraint_wrench) w.setZero();
  const int m = equationCount();
  if (m == 0) return;
  const double alpha = model_.options.baumgarte_alpha;
  const double beta = model_.options.baumgarte_beta;

  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    if (dof_[b] < 0) continue;
    const Mat3 r = state.bodies[b].orientation.toRotationMatrix();
    inv_inertia_world_[b] = r * model_.bodies[b].inertia.inverse() * r.transpose();
  }

  jac_.setZero();
  for (int i = 0; i < m; ++i) {
    const Row& row = rows_[i];
    const Motion p = motionOf(state, row.parent);
    const Motion c = motionOf(state, row.child);
    const Vec3 u = p.rotation * row.u_parent;
    const Vec3 wp_u = p.angular_velocity.cross(u);
    Row6 jp, jc;
    double phi = 0.0, jdot_v = 0.0;
    if (row.kind == ConstraintEquation::Kind::kDistance) {
      const Vec3 rp = p.rotation * row.anchor_parent;
      const Vec3 rc = c.rotation * row.anchor_child;
      const Vec3 d = (c.origin + rc) - (p.origin + rp);
      const Vec3 d_dot = c.velocity + c.angular_velocity.cross(rc) - p.velocity -
                         p.angular_velocity.cross(rp);
      phi = u.dot(d);
      jp << -u.transpose(), u.cross(c.origin + rc - p.origin).transpose();
      jc << u.transpose(), rc.cross(u).transpose();
      jdot_v = p.angular_velocity.cross(wp_u).dot(d) + 2.0 * wp_u.dot(d_dot) +
               u.dot(c.angular_velocity.cross(c.angular_velocity.cross(rc)) -
                     p.angular_velocity.cross(p.angular_velocity.cross(rp)));
    } else {
      const Vec3 w = c.rotation * row.w_child;
      phi = u.dot(w);
      jp << Vec3::Zero().transpose(), u.cross(w).transpose();
      jc << Vec3::Zero().transpose(), w.cross(u).transpose();
      const Vec3 wc_w = c.angular_velocity.cross(w);
      jdot_v = p.angular_velocity.cross(wp_u).dot(w) + 2.0 * wp_u.dot(wc_w) +
               u.dot(c.angular_velocity.cross(wc_w));
    }
    Eigen::Matrix<double, 6, 1> vp, vc;
    vp << p.velocity, p.angular_velocity;
    vc << c.velocity, c.angular_velocity;
    const double phi_dot = jp.dot(vp) + jc.dot(vc);
    double ja_free = 0.0;  // J a for the unconstrained accelerations
    auto place = [&](BodyIndex b, const Row6& jb) {
      if (b.isWorld() || dof_[b.value] < 0) return;
      jac_.block<1, 6>(i, dof_[b.value]) += jb;
      ja_free += jb.head<3>().dot(ws.linear_acceleration[b.value]) +
                 jb.tail<3>().dot(ws.angular_acceleration[b.value]);
    };
    place(row.parent, jp);
    place(row.child, jc);
    rhs_(i) = -jdot_v - 2.0 * alpha * phi_dot - beta * beta * phi - ja_free;
    ws.max_constraint_error = std::max(ws.max_constraint_error, std::abs(phi));
    ws.max_constraint_rate_error = std::max(ws.max_constraint_rate_error, std::abs(phi_dot));
  }

  // M^-1 J^T, body block by body block.
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const int o = dof_[b];
    if (o < 0) continue;
    const double inv_m = 1.0 / model_.bodies[b].mass;
    minv_jt_.middleRows<3>(o).noalias() = inv_m * jac_.middleCols<3>(o).transpose();
    minv_jt_.middleRows<3>(o + 3).noalias() =
        inv_inertia_world_[b] * jac_.middleCols<3>(o + 3).transpose();
  }
  schur_.noalias() = jac_ * minv_jt_;
  ldlt_.compute(schur_);
  lambda_ = ldlt_.solve(rhs_);

  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const int o = dof_[b];
    if (o < 0) continue;
    ws.linear_acceleration[b] += minv_jt_.middleRows<3>(o) * lambda_;
    ws.angular_acceleration[b] += minv_jt_.middleRows<3>(o + 3) * lambda_;
    ws.constraint_wrench[b].force = jac_.middleCols<3>(o).transpose() * lambda_;
    ws.constraint_wrench[b].torque = jac_.middleCols<3>(o + 3).transpose() * lambda_;
  }
}

}  // namespace tribo
