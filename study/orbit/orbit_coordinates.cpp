#include "study/orbit/orbit_coordinates.hpp"

#include <stdexcept>

namespace tribo::study {

namespace {

// The rotation vector of a unit quaternion (angle times axis, angle in [0, pi]).
Vec3 rotationVector(const Quat& q) {
  const Eigen::AngleAxisd aa(q.w() < 0 ? Quat(-q.w(), -q.x(), -q.y(), -q.z()) : q);
  return aa.angle() * aa.axis();
}

Quat fromRotationVector(const Vec3& r) {
  const double angle = r.norm();
  if (angle == 0.0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(angle, r / angle));
}

}  // namespace

OrbitCoordinates::OrbitCoordinates(const Model& model, const State& reference)
    : reference_(reference), offset_(model.bodies.size(), -1) {
  static const char* kAxes[] = {"x", "y", "z"};
  Eigen::Index next = 0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].kind != BodyKind::kDynamic) continue;
    bodies_.push_back(static_cast<int>(b));
    offset_[b] = next;
    next += 12;
    const std::string& name = model.bodies[b].name;
    for (const char* prefix : {"", "r", "v", "w"})
      for (const char* axis : kAxes)
        names_.push_back(std::string(name).append(".").append(prefix).append(axis));
  }
  friction_offset_ = next;
  size_ = next + static_cast<Eigen::Index>(reference.friction_values.size());
  for (std::size_t i = 0; i < reference.friction_values.size(); ++i)
    names_.push_back(std::string("z").append(std::to_string(i)));
}

Eigen::VectorXd OrbitCoordinates::toVector(const State& state) const {
  if (state.friction_values.size() != reference_.friction_values.size())
    throw std::runtime_error(
        "the friction laws' internal states changed in number along the orbit (" +
        std::to_string(reference_.friction_values.size()) + " -> " +
        std::to_string(state.friction_values.size()) +
        "): contacts with friction memory came or went, which shooting cannot follow");
  Eigen::VectorXd y(size_);
  for (int b : bodies_) {
    const Eigen::Index o = offset_[static_cast<std::size_t>(b)];
    const BodyState& s = state.bodies[static_cast<std::size_t>(b)];
    const BodyState& r = reference_.bodies[static_cast<std::size_t>(b)];
    y.segment<3>(o) = s.position;
    y.segment<3>(o + 3) = rotationVector(r.orientation.conjugate() * s.orientation);
    y.segment<3>(o + 6) = s.velocity;
    y.segment<3>(o + 9) = s.angular_velocity;
  }
  for (std::size_t i = 0; i < state.friction_values.size(); ++i)
    y[friction_offset_ + static_cast<Eigen::Index>(i)] = state.friction_values[i];
  return y;
}

State OrbitCoordinates::fromVector(const Eigen::VectorXd& y) const {
  State s = reference_;
  for (int b : bodies_) {
    const Eigen::Index o = offset_[static_cast<std::size_t>(b)];
    BodyState& out = s.bodies[static_cast<std::size_t>(b)];
    const BodyState& r = reference_.bodies[static_cast<std::size_t>(b)];
    out.position = y.segment<3>(o);
    out.orientation = (r.orientation * fromRotationVector(y.segment<3>(o + 3))).normalized();
    out.velocity = y.segment<3>(o + 6);
    out.angular_velocity = y.segment<3>(o + 9);
  }
  for (std::size_t i = 0; i < s.friction_values.size(); ++i)
    s.friction_values[i] = y[friction_offset_ + static_cast<Eigen::Index>(i)];
  return s;
}

char OrbitCoordinates::kind(Eigen::Index i) const {
  if (i >= friction_offset_) return 'z';
  return "xrvw"[(i % 12) / 3];
}

Eigen::Index OrbitCoordinates::velocityIndex(int body, int axis) const {
  const Eigen::Index o = offset_.at(static_cast<std::size_t>(body));
  return o < 0 ? -1 : o + 6 + axis;
}

Eigen::Index OrbitCoordinates::positionIndex(int body, int axis) const {
  const Eigen::Index o = offset_.at(static_cast<std::size_t>(body));
  return o < 0 ? -1 : o + axis;
}

}  // namespace tribo::study
