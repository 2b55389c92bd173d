// The tangential forces of many contact points under one law, in three passes:
//
//   speeds  s_i = |slip_i|                          (add: the caller's loop over its points)
//   law     mu_i = mu(s_i), all i in one call        (evaluate: FrictionLaw::coefficientsAt)
//   forces  F_i = -(mu_i fn_i / s_i) slip_i          (force: F_i = 0, mu_i = 0 at s_i = 0)
//
// Point by point this is tangentialForce (friction/friction_law.hpp), written with the same
// two pieces (slipSpeed, tangentialForceAt), so the same bits. What it saves: the law is asked
// once for the batch, through a loop over its own coefficient() (coefficientsOf), instead of
// once a point through a virtual call; the speeds and coefficients are plain arrays.
// Not here: which points go together (core/friction_states.cpp batches the runs of points of a
// material without memory, direction or rolling terms); stateful and dynamic laws' forces.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <span>

#include "friction/friction_law.hpp"

namespace tribo::friction {

struct TangentialBatch {
  static constexpr std::size_t kCapacity = 256;
  std::size_t size = 0;  // points added, at most kCapacity
  std::array<double, kCapacity> speed, mu;

  void clear() { size = 0; }
  bool full() const { return size == kCapacity; }
  // Adds a point by its slip (B relative to A, tangential) [m/s].
  void add(const Eigen::Vector3d& slip) { speed[size++] = slipSpeed(slip); }
  // The coefficient at every speed added: one call of the law.
  void evaluate(const FrictionLaw& law) {
    law.coefficientsAt(std::span<const double>(speed.data(), size),
                       std::span<double>(mu.data(), size));
  }
  // Point k's force on B for its slip and load fn >= 0 [N], after evaluate; optionally its
  // coefficient (0 without slip: coefficientsAt gives 0 at speed 0).
  Eigen::Vector3d force(std::size_t k, const Eigen::Vector3d& slip, double fn,
                        double* mu_out) const {
    if (mu_out != nullptr) *mu_out = mu[k];
    return tangentialForceAt(slip, speed[k], fn, mu[k]);
  }
};

}  // namespace tribo::friction
