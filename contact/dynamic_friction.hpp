// One contact point under a dynamic friction law (friction/dynamic_law.hpp): its internal
// state carried from the frame it is stored in to the contact's current frame, and the
// force and state rate there.
//
// Each contact point under a dynamic law has a FrictionStateRecord: which contact it is
// (contact/contact_identity.hpp), where its state z lies in State::friction_values, and the
// normal its tangent vectors are stored against.
// Tangent-vector states are stored against the normal n0 of the record
// and turned with the contact frame by the smallest rotation taking n0 to the current normal
// n (Rodrigues, with c = n0 x n, d = n0 . n):
//   R v = v + c x v + c x (c x v) / (1 + d)
// exactly the identity when n == n0; the rate is turned back by R^T so that it adds to the
// stored numbers. A normal that flipped (d <= -1 + 1e-12) projects instead of rotating.
// Under an anisotropic material (contact/anisotropy.hpp) the state lives in the scaled plane
// of the frame geometry's axes, so it is stored against that frame as well: the record keeps
// t1 (the material's first axis in the tangent plane) beside n0, and each tangent vector
// keeps its components along t1, t2 = n x t1 and n: with T = [t1 t2 n],
//   v -> T T0^T v,
// so a contact spinning about its normal turns its bristles with the grain, as bristles fixed
// to the grained surface turn.
// Not here: when records are made and states advanced (core/friction_states.hpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "contact/contact_point.hpp"
#include "friction/dynamic_law.hpp"

namespace tribo::contact {

// The record of one contact point's internal state.
struct FrictionStateRecord {
  std::uint64_t key = 0;                               // contact identity: (pair << 32) | slot
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world contact point when set [m]
  int state = 0;                                       // where z starts in State::friction_values
  int state_size = 0;  // how many numbers z has (the law's stateSize())
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // the frame of z's tangent vectors
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();    // anisotropic: t1 of that frame

  bool operator==(const FrictionStateRecord&) const = default;
};

// Largest number of internal-state values a law may declare (scratch sizes).
constexpr int kMaxFrictionState = 96;

// Copies the state z (law.stateSize() values) from the frame of normal `from` into `out`,
// in the frame of normal `to`; `inverse` turns from `to` back to `from`.
void transportState(const friction::DynamicFrictionLaw& law, const double* z,
                    const Eigen::Vector3d& from, const Eigen::Vector3d& to, double* out,
                    bool inverse = false);

// The same for an anisotropic material: from the frame (from, from_axis) into (to, to_axis)
// (unit normals, unit tangent axes), T T0^T v; `inverse` turns back.
void transportStateWithAxis(const friction::DynamicFrictionLaw& law, const double* z,
                            const Eigen::Vector3d& from, const Eigen::Vector3d& from_axis,
                            const Eigen::Vector3d& to, const Eigen::Vector3d& to_axis, double* out,
                            bool inverse = false);

// Fills out.friction_force (tangential, on B) and out.mu from the law at state z given in
// the contact's current frame, and writes dz/dt (current frame) into zdot.
void dynamicFrictionForce(const friction::DynamicFrictionLaw& law, const double* z,
                          ContactRecord& out, double* zdot);

}  // namespace tribo::contact
