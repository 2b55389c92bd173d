#include "core/resting_contact.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tribo::stability_detail {
namespace {

Eigen::Isometry3d geometryPose(const Model& model, const Geometry& geometry) {
  if (geometry.body.isWorld()) return geometry.local_pose;
  const Body& body = model.bodies[geometry.body.value];
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = body.orientation.normalized().toRotationMatrix();
  pose.translation() = body.position;
  return pose * geometry.local_pose;
}

// The face of a box (pose, half extents h) whose outward normal is nearest to `towards`.
RestingFace boxFace(int box, const Eigen::Isometry3d& pose, const Vec3& h, const Vec3& towards) {
  const Mat3 r = pose.linear();
  int j = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(r.col(i).dot(towards)) > std::abs(r.col(j).dot(towards))) j = i;
  const int k = (j + 1) % 3, l = (j + 2) % 3;
  const int first = std::min(k, l), second = std::max(k, l);
  const double side = r.col(j).dot(towards) < 0.0 ? -1.0 : 1.0;
  const Vec3 centre = pose.translation() + side * h[j] * r.col(j);
  RestingFace face;
  face.box = box;
  face.normal = towards.normalized();
  face.centre = centre;
  face.edges = {r.col(first), r.col(second)};
  face.half = {h[first], h[second]};
  int c = 0;
  for (const double s1 : {-1.0, 1.0})
    for (const double s2 : {-1.0, 1.0})
      face.corners[c++] = centre + s1 * h[first] * r.col(first) + s2 * h[second] * r.col(second);
  face.axis_index = {first, second};
  for (int i = 0; i < 2; ++i) {
    const Vec3 e = r.col(face.axis_index[i]);
    face.axes[i] = (e - e.dot(face.normal) * face.normal).normalized();
  }
  return face;
}

// Support distance of a box along unit u: max over the box of u . (x - centre).
double boxSupport(const Mat3& r, const Vec3& h, const Vec3& u) {
  return h.x() * std::abs(u.dot(r.col(0))) + h.y() * std::abs(u.dot(r.col(1))) +
         h.z() * std::abs(u.dot(r.col(2)));
}

// Where a round geometry (pose, shape) touches a surface lying along the unit direction d
// (world): the contact point (world), and for a capsule or cylinder lying on its side (its
// axis within 1e-3 of the contact plane) that it touches along a line, its axis. None for the
// shapes that do not roll here (a cylinder standing on a face, boxes, cones, meshes).
struct RollingTouch {
  Vec3 point;
  bool line = false;
  Vec3 axis;
  std::array<Vec3, 2> ends;  // a line's end points (world)
};

std::optional<RollingTouch> rollingTouch(const Eigen::Isometry3d& pose, const contact::Shape& shape,
                                         const Vec3& d) {
  constexpr double kLying = 1e-3;  // |axis . d| below which a capsule or cylinder lies
  const Vec3 dl = pose.linear().transpose() * d;
  RollingTouch touch;
  touch.axis = pose.linear().col(2);
  Vec3 local;
  switch (shape.type) {
    case contact::ShapeType::kSphere:
      local = shape.radius * dl;
      break;
    case contact::ShapeType::kCapsule:
      touch.line = std::abs(dl.z()) < kLying;
      local = shape.radius * dl;
      if (!touch.line) local.z() += std::copysign(shape.half_length, dl.z());
      break;
    case contact::ShapeType::kCylinder: {
      const double radial = std::hypot(dl.x(), dl.y());
      if (radial < kLying) return std::nullopt;  // standing on a face
      touch.line = std::abs(dl.z()) < kLying;
      local = shape.radius * Vec3(dl.x(), dl.y(), 0.0) / radial;
      if (!touch.line) local.z() = std::copysign(shape.half_length, dl.z());
      break;
    }
    default:
      return std::nullopt;
  }
  touch.point = pose * local;
  for (int i = 0; i < 2; ++i)
    touch.ends[i] = touch.point + (i == 0 ? -shape.half_length : shape.half_length) * touch.axis;
  return touch;
}

}  // namespace

std::optional<RestingFace> restingFace(const Model& model, const ContactPair& pair) {
  using contact::ShapeType;
  const Geometry& ga = model.geometries[pair.geometry_a];
  const Geometry& gb = model.geometries[pair.geometry_b];
  const ShapeType ta = ga.shape.type, tb = gb.shape.type;
  const Eigen::Isometry3d pa = geometryPose(model, ga), pb = geometryPose(model, gb);
  if (ta == ShapeType::kBox && tb == ShapeType::kHalfSpace)
    return boxFace(pair.geometry_a, pa, ga.shape.half_extents, -pb.linear().col(2));
  if (ta == ShapeType::kHalfSpace && tb == ShapeType::kBox)
    return boxFace(pair.geometry_b, pb, gb.shape.half_extents, -pa.linear().col(2));
  if (ta != ShapeType::kBox || tb != ShapeType::kBox) return std::nullopt;
  const Vec3 d = pb.translation() - pa.translation();
  const Vec3 &ha = ga.shape.half_extents, &hb = gb.shape.half_extents;
  Vec3 n = Vec3::UnitZ();
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 6; ++i) {
    const Vec3 u = (i < 3 ? pa : pb).linear().col(i % 3);
    const double gap =
        std::abs(u.dot(d)) - boxSupport(pa.linear(), ha, u) - boxSupport(pb.linear(), hb, u);
    if (gap > best) {
      best = gap;
      n = u.dot(d) < 0.0 ? -u : u;  // from a towards b
    }
  }
  const RestingFace fa = boxFace(pair.geometry_a, pa, ha, n);
  const RestingFace fb = boxFace(pair.geometry_b, pb, hb, -n);
  const bool b_smaller = fb.half[0] * fb.half[1] <= fa.half[0] * fa.half[1];
  RestingFace patch = b_smaller ? fb : fa;
  const RestingFace& other = b_smaller ? fa : fb;
  for (Vec3& corner : patch.corners) {
    for (int j = 0; j < 2; ++j) {
      const double s = (corner - other.centre).dot(other.edges[j]);
      corner += (std::clamp(s, -other.half[j], other.half[j]) - s) * other.edges[j];
    }
  }
  const double overlap = (patch.corners[3] - patch.corners[0])
                             .cross(patch.corners[2] - patch.corners[1])
                             .dot(patch.normal);  // twice the clamped patch's area
  if (!(std::abs(overlap) > 1e-9 * patch.half[0] * patch.half[1])) return std::nullopt;
  return patch;
}

// Rocking about `axis` (unit, in the patch) of the bodies on either side that can turn:
// the largest eigenvalue of the corners' rotational stiffness sum_i g_i g_i^T per unit point
// stiffness (g_i: the normal displacement of corner i per unit turn of each body about the
// axis through its centre of mass) against the bodies' inertias about those axes. Zero when
// neither can turn. The contact's normal stiffness and damping per point then give
// k/m = k_point * it and c/m = c_point * it (the corners' dampers act on the same lever arms,
// so the rotational damping is proportional to the stiffness).
double rockingPerPointStiffness(const Model& model, const TurnCheck& turns, BodyIndex a,
                                BodyIndex b, const RestingFace& face, const Vec3& axis) {
  double diag[2] = {0.0, 0.0}, cross = 0.0;
  int count = 0;
  const BodyIndex sides[2] = {a, b};
  std::array<double, 4> lever[2] = {};
  double inertia[2] = {0.0, 0.0};
  bool turns_side[2] = {false, false};
  for (int s = 0; s < 2; ++s) {
    turns_side[s] = turns.canTurn(model, sides[s], axis);
    if (!turns_side[s]) continue;
    const Body& body = model.bodies[sides[s].value];
    const Mat3 r = body.orientation.normalized().toRotationMatrix();
    inertia[s] = axis.dot(r * body.inertia * r.transpose() * axis);
    if (!(inertia[s] > 0.0)) {
      turns_side[s] = false;
      continue;
    }
    for (int i = 0; i < 4; ++i)
      lever[s][i] = axis.dot((face.corners[i] - body.position).cross(face.normal));
    ++count;
  }
  if (count == 0) return 0.0;
  for (int s = 0; s < 2; ++s) {
    if (!turns_side[s]) continue;
    for (int i = 0; i < 4; ++i) diag[s] += lever[s][i] * lever[s][i] / inertia[s];
  }
  if (count == 2) {
    for (int i = 0; i < 4; ++i) cross += lever[0][i] * lever[1][i];
    cross /= std::sqrt(inertia[0] * inertia[1]);
  }
  const double mean = 0.5 * (diag[0] + diag[1]), half = 0.5 * (diag[0] - diag[1]);
  return mean + std::sqrt(half * half + cross * cross);
}

// Yaw about the contact normal of the bodies on either side that can turn about it, per unit
// tangential stiffness (or damping) of each point: the largest eigenvalue of
// sum_i g_i g_i^T against the inertias about the normal through each centre of mass, g_i the
// points' tangential displacement per unit turn of each body, n x (p_i - x_cm). A box on a
// square face: 3 times the translation's 4 / m (sum r_i^2 = (a^2 + b^2) against
// I_n = m (a^2 + b^2) / 12). Zero when neither can turn.
double yawPerPointStiffness(const Model& model, const TurnCheck& turns, BodyIndex a, BodyIndex b,
                            const RestingFace& face) {
  const BodyIndex sides[2] = {a, b};
  std::array<Vec3, 4> lever[2] = {};
  double inertia[2] = {0.0, 0.0}, diag[2] = {0.0, 0.0}, cross = 0.0;
  bool turning[2] = {false, false};
  for (int s = 0; s < 2; ++s) {
    if (!turns.canTurn(model, sides[s], face.normal)) continue;
    const Body& body = model.bodies[sides[s].value];
    const Mat3 r = body.orientation.normalized().toRotationMatrix();
    inertia[s] = face.normal.dot(r * body.inertia * r.transpose() * face.normal);
    if (!(inertia[s] > 0.0)) continue;
    turning[s] = true;
    for (int i = 0; i < 4; ++i) {
      lever[s][i] = face.normal.cross(face.corners[i] - body.position);
      diag[s] += lever[s][i].squaredNorm() / inertia[s];
    }
  }
  if (turning[0] && turning[1]) {
    for (int i = 0; i < 4; ++i) cross += lever[0][i].dot(lever[1][i]);
    cross /= std::sqrt(inertia[0] * inertia[1]);
  }
  const double mean = 0.5 * (diag[0] + diag[1]), half = 0.5 * (diag[0] - diag[1]);
  return mean + std::sqrt(half * half + cross * cross);
}

RoundContact roundContact(const Model& model, const TurnCheck& turns, const ContactPair& pair,
                          const Vec3& normal, const std::vector<int>& geometry_count) {
  RoundContact out;
  const Geometry* geometry[2] = {&model.geometries[pair.geometry_a],
                                 &model.geometries[pair.geometry_b]};
  const Eigen::Isometry3d pose[2] = {geometryPose(model, *geometry[0]),
                                     geometryPose(model, *geometry[1])};
  const Vec3 n = normal.normalized();
  const Vec3 t[2] = {n.unitOrthogonal(), n.cross(n.unitOrthogonal()).normalized()};
  Eigen::Matrix2d w = Eigen::Matrix2d::Zero();  // the bodies' turning share of w(t)
  double inverse_mass = 0.0;                    // sum of 1/m
  std::optional<Vec3> line_axis;
  bool rolls = false;
  for (int s = 0; s < 2; ++s) {
    const BodyIndex b = geometry[s]->body;
    if (b.isWorld() || model.bodies[b.value].kind != BodyKind::kDynamic) continue;
    const Body& body = model.bodies[b.value];
    inverse_mass += 1.0 / body.mass;
    // A body touching with several geometries (a foot's corner spheres) is held like a face.
    if (geometry_count[b.value] != 1) continue;
    const double towards = (pose[1 - s].translation() - pose[s].translation()).dot(n);
    if (towards == 0.0 || !std::isfinite(towards)) continue;
    const std::optional<RollingTouch> touch =
        rollingTouch(pose[s], geometry[s]->shape, towards > 0.0 ? n : Vec3(-n));
    if (!touch) continue;
    const Mat3 r = body.orientation.normalized().toRotationMatrix();
    const Eigen::LLT<Mat3> inertia(r * body.inertia * r.transpose());
    if (inertia.info() != Eigen::Success) continue;
    const Vec3 arm = touch->point - body.position;
    Eigen::Matrix<double, 3, 2> turn = Eigen::Matrix<double, 3, 2>::Zero();
    for (int i = 0; i < 2; ++i) {
      const Vec3 axis = arm.cross(t[i]);
      if (axis.norm() > 0.0 && turns.canTurn(model, b, axis.normalized())) turn.col(i) = axis;
    }
    w += turn.transpose() * inertia.solve(turn);
    rolls = true;
    if (!touch->line) continue;
    line_axis = touch->axis;
    // Yaw on the line's two end points, as yawPerPointStiffness on a face's corners.
    const double i_n = n.dot(r * body.inertia * r.transpose() * n);
    if (!(i_n > 0.0) || !turns.canTurn(model, b, n)) continue;
    out.points = 2;
    for (const Vec3& end : touch->ends) out.yaw += n.cross(end - body.position).squaredNorm() / i_n;
  }
  if (!rolls || !(inverse_mass > 0.0)) return out;
  w.diagonal().array() += inverse_mass;
  double largest = 0.0;
  if (line_axis) {  // rolling about the axis: the slip across it
    const Vec3 across = line_axis->cross(n);
    if (!(across.norm() > 0.0)) return out;
    const Eigen::Vector2d c(across.dot(t[0]), across.dot(t[1]));
    largest = c.dot(w * c) / c.squaredNorm();
  } else {
    largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(w, Eigen::EigenvaluesOnly)
                  .eigenvalues()
                  .maxCoeff();
  }
  out.slip_factor = std::max(1.0, largest / inverse_mass);
  return out;
}

}  // namespace tribo::stability_detail
