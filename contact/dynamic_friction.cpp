#include "contact/dynamic_friction.hpp"

namespace tribo::contact {

void transportState(const friction::DynamicFrictionLaw& law, const double* z,
                    const Eigen::Vector3d& from, const Eigen::Vector3d& to, double* out,
                    bool inverse) {
  const int n = law.stateSize();
  for (int i = 0; i < n; ++i) out[i] = z[i];
  if (from == to) return;
  const Eigen::Vector3d c = inverse ? Eigen::Vector3d(to.cross(from)) : from.cross(to);
  const double d = from.dot(to);
  const Eigen::Vector3d& target = inverse ? from : to;
  for (int k = 0; k < law.tangentVectors(); ++k) {
    const Eigen::Vector3d v(z[3 * k], z[3 * k + 1], z[3 * k + 2]);
    Eigen::Vector3d w;
    if (d > -1.0 + 1e-12) {
      const Eigen::Vector3d cv = c.cross(v);
      w = v + cv + c.cross(cv) / (1.0 + d);
    } else {
      w = v - target.dot(v) * target;
    }
    for (int i = 0; i < 3; ++i) out[3 * k + i] = w[i];
  }
}

void transportStateWithAxis(const friction::DynamicFrictionLaw& law, const double* z,
                            const Eigen::Vector3d& from, const Eigen::Vector3d& from_axis,
                            const Eigen::Vector3d& to, const Eigen::Vector3d& to_axis, double* out,
                            bool inverse) {
  const int n = law.stateSize();
  for (int i = 0; i < n; ++i) out[i] = z[i];
  if (from == to && from_axis == to_axis) return;
  auto frame = [](const Eigen::Vector3d& normal, const Eigen::Vector3d& t1) {
    Eigen::Matrix3d t;
    t.col(0) = t1;
    t.col(1) = normal.cross(t1);
    t.col(2) = normal;
    return t;
  };
  const Eigen::Matrix3d f = frame(from, from_axis), g = frame(to, to_axis);
  const Eigen::Matrix3d map =
      inverse ? Eigen::Matrix3d(f * g.transpose()) : Eigen::Matrix3d(g * f.transpose());
  for (int k = 0; k < law.tangentVectors(); ++k) {
    const Eigen::Vector3d w = map * Eigen::Vector3d(z[3 * k], z[3 * k + 1], z[3 * k + 2]);
    for (int i = 0; i < 3; ++i) out[3 * k + i] = w[i];
  }
}

void dynamicFrictionForce(const friction::DynamicFrictionLaw& law, const double* z,
                          ContactRecord& out, double* zdot) {
  law.rate(z, out.slip, out.normal_force, zdot);
  double mu = 0.0;
  Eigen::Vector3d f = law.force(z, zdot, out.slip, out.normal_force, &mu);
  const Eigen::Vector3d& n = out.point.normal;
  f -= n.dot(f) * n;  // a stored vector slightly off the plane must not push along n
  out.friction_force = f;
  out.mu = mu;
}

}  // namespace tribo::contact
