// One contact point under a dynamic friction law (friction/dynamic_law.hpp): its internal
// state carried from the frame it is stored in to the contact's current frame, and the
// force and state rate there.
//
// Tangent-vector states are stored against the normal n0 of the record (StickAnchor::normal)
// and turned with the contact frame by the smallest rotation taking n0 to the current normal
// n (Rodrigues, with c = n0 x n, d = n0 . n):
//   R v = v + c x v + c x (c x v) / (1 + d)
// exactly the identity when n == n0; the rate is turned back by R^T so that it adds to the
// stored numbers. A normal that flipped (d <= -1 + 1e-12) projects instead of rotating.
// Not here: which record a contact continues (contact/stick_anchor.hpp), the step (core/).
#pragma once

#include <Eigen/Core>

#include "contact/contact_point.hpp"
#include "friction/dynamic_law.hpp"

namespace tribo::contact {

// Largest number of internal-state values a law may declare (scratch sizes).
constexpr int kMaxFrictionState = 96;

// Copies the state z (law.stateSize() values) from the frame of normal `from` into `out`,
// in the frame of normal `to`; `inverse` turns from `to` back to `from`.
void transportState(const friction::DynamicFrictionLaw& law, const double* z,
                    const Eigen::Vector3d& from, const Eigen::Vector3d& to, double* out,
                    bool inverse = false);

// Fills out.friction_force (tangential, on B) and out.mu from the law at state z given in
// the contact's current frame, and writes dz/dt (current frame) into zdot.
void dynamicFrictionForce(const friction::DynamicFrictionLaw& law, const double* z,
                          ContactRecord& out, double* zdot);

}  // namespace tribo::contact
