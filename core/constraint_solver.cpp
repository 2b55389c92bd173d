#include "core/constraint_solver.hpp"

#include <algorithm>
#include <cmath>

namespace tribo {

namespace {

struct Motion {
  const Mat3& rotation;
  const Vec3& origin;
  const Vec3& velocity;
  const Vec3& angular_velocity;
};

Motion motionOf(const State& state, const Workspace& ws, BodyIndex b) {
  static const Mat3 kIdentity = Mat3::Identity();
  static const Vec3 kZero = Vec3::Zero();
  if (b.isWorld()) return {kIdentity, kZero, kZero, kZero};
  const BodyState& s = state.bodies[b.value];
  return {ws.rotation[b.value], s.position, s.velocity, s.angular_velocity};
}

}  // namespace

ConstraintSolver::ConstraintSolver(const Model& model) : model_(model) {
  for (const Joint& j : model.joints) {
    for (const ConstraintEquation& e : jointEquations(j.type)) {
      rows_.push_back({e.kind, j.parent, j.child, j.axes_in_parent.col(e.parent_axis),
                       j.axes_in_child.col(e.child_axis), j.anchor_in_parent, j.anchor_in_child});
    }
  }
  const int m = equationCount();
  jac_.resize(m);
  auto dynamicIndex = [&](BodyIndex b) {
    return (!b.isWorld() && model.bodies[b.value].kind == BodyKind::kDynamic) ? b.value : -1;
  };
  for (int i = 0; i < m; ++i) {
    jac_[i].body[0] = dynamicIndex(rows_[i].parent);
    jac_[i].body[1] = dynamicIndex(rows_[i].child);
  }
  for (const Body& b : model.bodies) inv_mass_.push_back(1.0 / b.mass);
  if (m <= kSmall) {
    schur_small_.setZero(m, m);
    rhs_small_.setZero(m);
  } else {
    schur_.setZero(m, m);
    rhs_.setZero(m);
  }
  lambda_.setZero(m);
}

template <typename Matrix>
void ConstraintSolver::fillSchur(Matrix& schur) const {
  const int m = equationCount();
  for (int r = 0; r < m; ++r) {
    for (int s = r; s < m; ++s) {
      double sum = 0.0;
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          if (jac_[r].body[a] >= 0 && jac_[r].body[a] == jac_[s].body[b])
            sum += jac_[r].j[a].dot(jac_[s].minv_j[b]);
      schur(r, s) = schur(s, r) = sum;
    }
  }
}

void ConstraintSolver::solve(const State& state, Workspace& ws) {
  ws.max_constraint_error = 0.0;
  ws.max_constraint_rate_error = 0.0;
  for (auto& w : ws.constraint_wrench) w.setZero();
  const int m = equationCount();
  if (m == 0) return;
  const double alpha = model_.options.baumgarte_alpha;
  const double beta = model_.options.baumgarte_beta;

  for (int i = 0; i < m; ++i) {
    const Row& row = rows_[i];
    const Motion p = motionOf(state, ws, row.parent);
    const Motion c = motionOf(state, ws, row.child);
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
    const double phi_dot = jp.head<3>().dot(p.velocity) + jp.tail<3>().dot(p.angular_velocity) +
                           jc.head<3>().dot(c.velocity) + jc.tail<3>().dot(c.angular_velocity);
    RowJacobian& rj = jac_[i];
    double ja_free = 0.0;  // J a for the unconstrained accelerations
    const Row6* blocks[2] = {&jp, &jc};
    for (int k = 0; k < 2; ++k) {
      const int b = rj.body[k];
      if (b < 0) continue;
      const Row6& jb = *blocks[k];
      rj.j[k] = jb;
      rj.minv_j[k].head<3>() = jb.head<3>() * inv_mass_[b];
      rj.minv_j[k].tail<3>() = jb.tail<3>() * ws.inv_inertia_world[b];  // symmetric
      ja_free += jb.head<3>().dot(ws.linear_acceleration[b]) +
                 jb.tail<3>().dot(ws.angular_acceleration[b]);
    }
    const double rhs = -jdot_v - 2.0 * alpha * phi_dot - beta * beta * phi - ja_free;
    (m <= kSmall ? rhs_small_(i) : rhs_(i)) = rhs;
    ws.max_constraint_error = std::max(ws.max_constraint_error, std::abs(phi));
    ws.max_constraint_rate_error = std::max(ws.max_constraint_rate_error, std::abs(phi_dot));
  }

  // Schur complement J M^-1 J^T from the sparse row blocks, then the multipliers.
  if (m <= kSmall) {
    fillSchur(schur_small_);
    llt_small_.compute(schur_small_);
    lambda_ = llt_small_.solve(rhs_small_);
  } else {
    fillSchur(schur_);
    ldlt_.compute(schur_);
    lambda_ = ldlt_.solve(rhs_);
  }

  for (int r = 0; r < m; ++r) {
    for (int a = 0; a < 2; ++a) {
      const int b = jac_[r].body[a];
      if (b < 0) continue;
      const double l = lambda_(r);
      ws.linear_acceleration[b] += l * jac_[r].minv_j[a].head<3>().transpose();
      ws.angular_acceleration[b] += l * jac_[r].minv_j[a].tail<3>().transpose();
      ws.constraint_wrench[b].force += l * jac_[r].j[a].head<3>().transpose();
      ws.constraint_wrench[b].torque += l * jac_[r].j[a].tail<3>().transpose();
    }
  }
}

}  // namespace tribo
