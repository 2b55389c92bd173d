#include "core/constraint_rows.hpp"

#include <cmath>
#include <numbers>

namespace tribo {

namespace {

bool isDynamic(const Model& model, BodyIndex b) {
  return !b.isWorld() && model.bodies[b.value].kind == BodyKind::kDynamic;
}

void addBody(const Model& model, BodyIndex b, ConstraintRow& row) {
  if (!isDynamic(model, b)) return;
  for (int k = 0; k < row.body_count; ++k)
    if (row.body[k] == b.value) return;
  row.body[row.body_count++] = b.value;
}

// Blocks of a row that touches a parent and a child (bodies listed parent first).
void setBlocks(const ConstraintRow& row, BodyIndex parent, const Row6& jp, BodyIndex child,
               const Row6& jc, RowValue& out) {
  int k = 0;
  if (k < row.body_count && row.body[k] == parent.value) out.j[k++] = jp;
  if (k < row.body_count && row.body[k] == child.value) out.j[k] = jc;
}

void addBlock(const ConstraintRow& row, BodyIndex b, const Row6& block, RowValue& out) {
  for (int k = 0; k < row.body_count; ++k)
    if (row.body[k] == b.value) out.j[k] += block;
}

// Distance equation u . (p_C - p_P) with u fixed in the parent; Phi, Phi' (without any
// target), J' v and the two Jacobian blocks.
struct DistanceValue {
  double phi, phi_dot, jdot_v;
  Row6 jp, jc;
};
DistanceValue distance(const Vec3& u_parent, const Vec3& anchor_parent, const Vec3& anchor_child,
                       const BodyMotion& p, const BodyMotion& c) {
  DistanceValue out;
  const Vec3 u = p.rotation * u_parent;
  const Vec3 wp_u = p.angular_velocity.cross(u);
  const Vec3 rp = p.rotation * anchor_parent;
  const Vec3 rc = c.rotation * anchor_child;
  const Vec3 d = (c.origin + rc) - (p.origin + rp);
  const Vec3 d_dot =
      c.velocity + c.angular_velocity.cross(rc) - p.velocity - p.angular_velocity.cross(rp);
  out.phi = u.dot(d);
  out.phi_dot = wp_u.dot(d) + u.dot(d_dot);
  out.jp << -u.transpose(), u.cross(c.origin + rc - p.origin).transpose();
  out.jc << u.transpose(), rc.cross(u).transpose();
  out.jdot_v = p.angular_velocity.cross(wp_u).dot(d) + 2.0 * wp_u.dot(d_dot) +
               u.dot(c.angular_velocity.cross(c.angular_velocity.cross(rc)) -
                     p.angular_velocity.cross(p.angular_velocity.cross(rp)));
  return out;
}

}  // namespace

BodyMotion MotionView::operator()(BodyIndex b) const {
  static const Mat3 kIdentity = Mat3::Identity();
  static const Vec3 kZero = Vec3::Zero();
  if (b.isWorld()) return {kIdentity, kZero, kZero, kZero};
  const BodyState& s = state_.bodies[b.value];
  return {rotations_[b.value], s.position, s.velocity, s.angular_velocity};
}

double wrapAngle(double a) {
  constexpr double kPi = std::numbers::pi;
  if (a > -kPi && a <= kPi) return a;
  a = std::remainder(a, 2.0 * kPi);
  return a <= -kPi ? a + 2.0 * kPi : a;
}

JointCoordinate jointCoordinate(const Joint& joint) {
  JointCoordinate c;
  c.angular = isAngular(joint.type);
  c.parent = joint.parent;
  c.child = joint.child;
  c.z_parent = joint.axes_in_parent.col(2);
  c.x_parent = joint.axes_in_parent.col(0);
  c.x_child = joint.axes_in_child.col(0);
  c.anchor_parent = joint.anchor_in_parent;
  c.anchor_child = joint.anchor_in_child;
  return c;
}

void evaluateCoordinate(const JointCoordinate& c, const BodyMotion& p, const BodyMotion& ch,
                        CoordinateValue& out) {
  if (!c.angular) {
    const DistanceValue d = distance(c.z_parent, c.anchor_parent, c.anchor_child, p, ch);
    out.q = d.phi;
    out.rate = d.phi_dot;
    out.jdot_v = d.jdot_v;
    out.j_parent = d.jp;
    out.j_child = d.jc;
    return;
  }
  const Vec3 z = p.rotation * c.z_parent;
  const Vec3 xp = p.rotation * c.x_parent;
  const Vec3 xc = ch.rotation * c.x_child;
  const Vec3 relative = ch.angular_velocity - p.angular_velocity;
  out.q = std::atan2(z.dot(xp.cross(xc)), xp.dot(xc));
  out.rate = z.dot(relative);
  out.jdot_v = p.angular_velocity.cross(z).dot(relative);
  out.j_parent << 0.0, 0.0, 0.0, -z.transpose();
  out.j_child << 0.0, 0.0, 0.0, z.transpose();
}

std::vector<ConstraintRow> constraintRows(const Model& model, bool include_dropped) {
  std::vector<ConstraintRow> rows;
  for (int ji = 0; ji < static_cast<int>(model.joints.size()); ++ji) {
    const Joint& j = model.joints[ji];
    const auto& equations = jointEquations(j.type);
    for (int e = 0; e < static_cast<int>(equations.size()); ++e) {
      if (!include_dropped && (j.dropped_equations >> e) & 1u) continue;
      ConstraintRow row;
      row.kind = equations[e].kind == ConstraintEquation::Kind::kDistance
                     ? ConstraintRow::Kind::kDistance
                     : ConstraintRow::Kind::kPerpendicular;
      row.joint = ji;
      row.equation = e;
      row.parent = j.parent;
      row.child = j.child;
      row.u_parent = j.axes_in_parent.col(equations[e].parent_axis);
      row.w_child = j.axes_in_child.col(equations[e].child_axis);
      row.anchor_parent = j.anchor_in_parent;
      row.anchor_child = j.anchor_in_child;
      addBody(model, j.parent, row);
      addBody(model, j.child, row);
      rows.push_back(row);
    }
  }
  for (int ji = 0; ji < static_cast<int>(model.joints.size()); ++ji) {
    const Joint& j = model.joints[ji];
    if (!j.elements.drive) continue;
    ConstraintRow row;
    row.kind = ConstraintRow::Kind::kCoordinate;
    row.joint = ji;
    row.equation = ConstraintRow::kDriveEquation;
    row.coordinate = jointCoordinate(j);
    row.drive = &*j.elements.drive;
    addBody(model, j.parent, row);
    addBody(model, j.child, row);
    rows.push_back(row);
  }
  for (int ci = 0; ci < static_cast<int>(model.couplings.size()); ++ci) {
    const JointCoupling& c = model.couplings[ci];
    const Joint& follower = model.joints[c.follower];
    const Joint& leader = model.joints[c.leader];
    ConstraintRow row;
    row.kind = ConstraintRow::Kind::kCoupling;
    row.joint = c.follower;
    row.equation = ConstraintRow::kCouplingEquation;
    row.coupling = ci;
    row.coordinate = jointCoordinate(follower);
    row.leader = jointCoordinate(leader);
    row.multiplier = c.multiplier;
    row.offset = c.offset;
    for (BodyIndex b : {follower.parent, follower.child, leader.parent, leader.child})
      addBody(model, b, row);
    rows.push_back(row);
  }
  return rows;
}

namespace {

// The equations of one joint: distance rows u . d and perpendicular rows u . w with the
// joint's frames, sharing d, its rate and the velocity-product terms:
//   distance:      Phi' = u . (d x w_P + d'),
//                  J' v = (w_P . u)(w_P . d) - |w_P|^2 Phi + u . (2 d' x w_P + h),
//                  h = w_C x (w_C x r_C) - w_P x (w_P x r_P)
//   perpendicular: Phi' = u . ((w_C - w_P) x w),
//                  J' v = (w_P x (w_P x u)) . w + 2 (w_P x u) . (w_C x w) + u . (w_C x (w_C x w))
// The same equations for a joint whose parent is the world (identity frame, at rest): u is
// u_parent, r_P the parent anchor, and every term with w_P or the parent's motion drops out
// (their values are exact zeros in the general form, so the results are the same).
void evaluateWorldJointEquations(const std::vector<ConstraintRow>& rows, const RowGroup& g,
                                 const MotionView& motion, RowValue* out) {
  const ConstraintRow& first = rows[g.begin];
  const BodyMotion c = motion(first.child);
  const Vec3& wc = c.angular_velocity;
  const Vec3 rc = c.rotation * first.anchor_child;
  const Vec3 e = c.origin + rc;
  const Vec3 d = e - first.anchor_parent;
  const Vec3 d_dot = c.velocity + wc.cross(rc);
  const Vec3 k_bias = wc.cross(wc.cross(rc));
  const Row6 none = Row6::Zero();  // the world's block: not stored
  for (int r = g.begin; r < g.end; ++r) {
    const ConstraintRow& row = rows[r];
    RowValue& v = out[r - g.begin];
    const Vec3& u = row.u_parent;
    Row6 jc;
    if (row.kind == ConstraintRow::Kind::kDistance) {
      v.phi = u.dot(d);
      v.phi_dot = u.dot(d_dot);
      v.bias = u.dot(k_bias);
      jc << u.transpose(), rc.cross(u).transpose();
    } else {
      const Vec3 w = c.rotation * row.w_child;
      const Vec3 wc_w = wc.cross(w);
      v.phi = u.dot(w);
      v.phi_dot = u.dot(wc_w);
      v.bias = u.dot(wc.cross(wc_w));
      const Vec3 uw = u.cross(w);
      jc << 0.0, 0.0, 0.0, -uw.transpose();
    }
    setBlocks(row, row.parent, none, row.child, jc, v);
  }
}

void evaluateJointEquations(const std::vector<ConstraintRow>& rows, const RowGroup& g,
                            const MotionView& motion, RowValue* out) {
  const ConstraintRow& first = rows[g.begin];
  if (first.parent.isWorld()) {
    evaluateWorldJointEquations(rows, g, motion, out);
    return;
  }
  const BodyMotion p = motion(first.parent);
  const BodyMotion c = motion(first.child);
  const Vec3& wp = p.angular_velocity;
  const Vec3& wc = c.angular_velocity;
  const Vec3 rp = p.rotation * first.anchor_parent;
  const Vec3 rc = c.rotation * first.anchor_child;
  const Vec3 e = c.origin + rc - p.origin;  // child anchor from the parent origin
  const Vec3 d = e - rp;
  const Vec3 d_dot = c.velocity + wc.cross(rc) - p.velocity - wp.cross(rp);
  const Vec3 g_rate = d.cross(wp) + d_dot;
  const Vec3 k_bias = 2.0 * d_dot.cross(wp) + wc.cross(wc.cross(rc)) - wp.cross(wp.cross(rp));
  const double wp_d = wp.dot(d);
  const double wp2 = wp.squaredNorm();
  for (int r = g.begin; r < g.end; ++r) {
    const ConstraintRow& row = rows[r];
    RowValue& v = out[r - g.begin];
    const Vec3 u = p.rotation * row.u_parent;
    Row6 jp, jc;
    if (row.kind == ConstraintRow::Kind::kDistance) {
      v.phi = u.dot(d);
      v.phi_dot = u.dot(g_rate);
      v.bias = wp_d * wp.dot(u) - wp2 * v.phi + u.dot(k_bias);
      jp << -u.transpose(), u.cross(e).transpose();
      jc << u.transpose(), rc.cross(u).transpose();
    } else {
      const Vec3 w = c.rotation * row.w_child;
      const Vec3 wp_u = wp.cross(u);
      const Vec3 wc_w = wc.cross(w);
      v.phi = u.dot(w);
      v.phi_dot = u.dot((wc - wp).cross(w));
      v.bias = wp.cross(wp_u).dot(w) + 2.0 * wp_u.dot(wc_w) + u.dot(wc.cross(wc_w));
      const Vec3 uw = u.cross(w);
      jp << 0.0, 0.0, 0.0, uw.transpose();
      jc << 0.0, 0.0, 0.0, -uw.transpose();
    }
    setBlocks(row, row.parent, jp, row.child, jc, v);
  }
}

void evaluateSingle(const ConstraintRow& row, const MotionView& motion, double time,
                    RowValue& out) {
  if (row.kind == ConstraintRow::Kind::kCoordinate) {
    const JointCoordinate& jc = row.coordinate;
    CoordinateValue v;
    evaluateCoordinate(jc, motion(jc.parent), motion(jc.child), v);
    const double error = v.q - row.drive->position(time);
    out.phi = jc.angular ? wrapAngle(error) : error;
    out.phi_dot = v.rate - row.drive->velocity(time);
    out.bias = v.jdot_v - row.drive->acceleration(time);
    setBlocks(row, jc.parent, v.j_parent, jc.child, v.j_child, out);
    return;
  }
  CoordinateValue f, l;
  evaluateCoordinate(row.coordinate, motion(row.coordinate.parent), motion(row.coordinate.child),
                     f);
  evaluateCoordinate(row.leader, motion(row.leader.parent), motion(row.leader.child), l);
  const double r = row.multiplier;
  const double error = f.q - r * l.q - row.offset;
  out.phi = row.coordinate.angular ? wrapAngle(error) : error;
  out.phi_dot = f.rate - r * l.rate;
  out.bias = f.jdot_v - r * l.jdot_v;
  for (int k = 0; k < row.body_count; ++k) out.j[k].setZero();
  addBlock(row, row.coordinate.parent, f.j_parent, out);
  addBlock(row, row.coordinate.child, f.j_child, out);
  addBlock(row, row.leader.parent, -r * l.j_parent, out);
  addBlock(row, row.leader.child, -r * l.j_child, out);
}

bool isPrimitive(const ConstraintRow& row) {
  return row.kind == ConstraintRow::Kind::kDistance ||
         row.kind == ConstraintRow::Kind::kPerpendicular;
}

}  // namespace

std::vector<RowGroup> rowGroups(const std::vector<ConstraintRow>& rows) {
  std::vector<RowGroup> groups;
  const int n = static_cast<int>(rows.size());
  for (int r = 0; r < n;) {
    int end = r + 1;
    if (isPrimitive(rows[r]))
      while (end < n && isPrimitive(rows[end]) && rows[end].joint == rows[r].joint) ++end;
    groups.push_back({r, end});
    r = end;
  }
  return groups;
}

std::vector<int> groupBegins(const std::vector<RowGroup>& groups, int rows) {
  std::vector<int> begins;
  for (const RowGroup& g : groups) begins.push_back(g.begin);
  begins.push_back(rows);
  return begins;
}

void evaluateRowGroup(const std::vector<ConstraintRow>& rows, const RowGroup& g,
                      const MotionView& motion, double time, RowValue* out) {
  if (isPrimitive(rows[g.begin])) {
    evaluateJointEquations(rows, g, motion, out);
    return;
  }
  for (int r = g.begin; r < g.end; ++r) evaluateSingle(rows[r], motion, time, out[r - g.begin]);
}

void evaluateRows(const std::vector<ConstraintRow>& rows, const std::vector<RowGroup>& groups,
                  const MotionView& motion, double time, std::vector<RowValue>& out) {
  for (const RowGroup& g : groups) evaluateRowGroup(rows, g, motion, time, &out[g.begin]);
}

}  // namespace tribo
