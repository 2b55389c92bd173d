// The coordinates a periodic orbit is solved in: a State of the engine as a vector y and
// back, relative to a reference State. Per dynamic body (kinematic bodies and the world move
// by the scene's prescription, not by the state): position (3), the rotation from the
// reference orientation as a rotation vector (3: a quaternion's four numbers are not free),
// velocity (3), angular velocity (3); then the dynamic friction laws' internal states
// (State::friction_values: bristles, rate-and-state's theta...). The contact records, stick
// anchors and the time are the reference's: a state made from y has the reference's contacts
// with y's values in them.
// Not here: the orbit (study/orbit/periodic_orbit.hpp), joints' own coordinates (bodies
// joined by constraints are perturbed in all six directions; the constraint projection of a
// step removes what violates the joints, which shows as multipliers at zero).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"

namespace tribo::study {

class OrbitCoordinates {
 public:
  // The dynamic bodies of `model`; `reference` fixes the friction values' count.
  OrbitCoordinates(const Model& model, const State& reference);

  Eigen::Index size() const { return size_; }
  // y of `state`, whose friction values must be as many as the reference's (else throws
  // std::runtime_error naming both counts: contacts with memory came or went).
  Eigen::VectorXd toVector(const State& state) const;
  // The reference State with y's values (time and contact records the reference's).
  State fromVector(const Eigen::VectorXd& y) const;
  // Each entry's name: "box.x", "box.rx" (rotation vector), "box.vx", "box.wx", "z3".
  const std::vector<std::string>& names() const { return names_; }
  // The index in y of body `body`'s velocity component `axis` (0..2); -1 for a body that is
  // not dynamic.
  Eigen::Index velocityIndex(int body, int axis) const;
  // What entry i is: 'x' a position, 'r' a rotation, 'v' a velocity, 'w' an angular
  // velocity, 'z' a friction law's internal state.
  char kind(Eigen::Index i) const;
  Eigen::Index positionIndex(int body, int axis) const;

 private:
  State reference_;
  std::vector<int> bodies_;           // the dynamic bodies, model order
  std::vector<Eigen::Index> offset_;  // per model body: its block's start in y, -1 if none
  Eigen::Index friction_offset_ = 0, size_ = 0;
  std::vector<std::string> names_;
};

}  // namespace tribo::study
