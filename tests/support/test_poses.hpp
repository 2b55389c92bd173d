// A pose from a position and an orientation, for the contact tests.
#pragma once

#include <Eigen/Geometry>

namespace tribo::contact::test {

inline Eigen::Isometry3d pose(const Eigen::Vector3d& p,
                              const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  t.translation() = p;
  return t;
}

}  // namespace tribo::contact::test
