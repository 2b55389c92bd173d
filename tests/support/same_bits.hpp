// Bit-for-bit equality of doubles and 3-vectors, for tests that check that two ways of
// computing something (threads, merged passes, batches) give the same bits, not merely close
// values: +0 and -0 differ here, and a NaN equals a NaN with the same payload.
// Not here: tolerances; a test that allows rounding states its own bound.
#pragma once

#include <Eigen/Core>
#include <cstring>

namespace tribo::test {

inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()) && sameBits(a.z(), b.z());
}

}  // namespace tribo::test
