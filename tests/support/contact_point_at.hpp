// A contact point of pair `pair` at world position p, normal +z, 0.1 mm deep, with the
// narrowphase feature `feature` (-1: none): the input of contact identity tests.
#pragma once

#include <Eigen/Core>

#include "contact/contact_point.hpp"

namespace tribo::test {

inline contact::ContactPoint contactPointAt(int pair, int feature, const Eigen::Vector3d& p) {
  contact::ContactPoint cp;
  cp.pair = pair;
  cp.feature = feature;
  cp.position = p;
  cp.normal = Eigen::Vector3d::UnitZ();
  cp.depth = 1e-4;
  return cp;
}

}  // namespace tribo::test
