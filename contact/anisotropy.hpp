// Direction-dependent friction: any friction law (memoryless, stateful or dynamic) made
// anisotropic, with a forward and a backward coefficient along each of two principal axes
// fixed in the frame of one geometry of the contact.
//
// With n the contact normal, t1 the material's axis turned with the frame geometry and
// projected on the tangent plane, t2 = n x t1, and ratios r_i (r_i+ when the frame geometry
// moves along +t_i relative to the other geometry, r_i- when against it), the law is
// evaluated in a scaled tangent plane and its force scaled back:
//   s' = R s,   F = R F'(s'),   R = r_1 t1 t1^T + r_2 t2 t2^T
// For a memoryless law F' = -mu(|s'|) F_n s' / |s'|, so
//   F = -mu(|R s|) F_n R^2 s / |R s|:
// the limit surface is the ellipse (F_1 / r_1)^2 + (F_2 / r_2)^2 = (mu F_n)^2 (a half-ellipse
// per sense when r_i+ != r_i-), and the force is the point of it where its outward normal is
// parallel to the slip, i.e. the force that dissipates most among all on the limit surface
// (the maximum-dissipation rule of the limit-surface description, Goyal, Ruina & Papadopoulos,
// Wear 143 (1991) 307-330; for anisotropic dry friction, Walker & Leine, Nonlinear Dyn. 96
// (2019) 885-920). It is chosen because it keeps F . s <= 0 for every slip (no law can
// gain energy from it) and because it is a linear map of the tangent plane, so a stuck
// contact's spring (elastic_stick) and a dynamic law's bristle state live in the scaled plane
// unchanged: their stiffness along t_i is r_i^2 times the law's.
// Consequence to know: along t_i the law sees the speed r_i v, so its curve there is
// r_i mu(r_i v) (a Stribeck or stick speed is divided by r_i along that axis).
// Not here: which geometry is the frame for a given pair and when the functions are called
// (core/friction_states.cpp), how a dynamic law's state is kept against the axes so that it
// turns with the frame geometry (contact/dynamic_friction.hpp).
#pragma once

#include <Eigen/Core>
#include <array>

#include "contact/contact_point.hpp"

namespace tribo::contact {

// A material's anisotropy, as the scene gives it.
struct Anisotropy {
  bool active = false;
  bool frame_is_b = true;  // the axes are fixed in geometry b's frame (else in a's)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // first principal axis, frame geometry
  std::array<double, 2> forward{1.0, 1.0};          // ratio r_i+ along +axis_i
  std::array<double, 2> backward{1.0, 1.0};         // ratio r_i- along -axis_i
  // Throws std::invalid_argument for a ratio that is not finite and > 0 or an axis that is
  // not finite or zero; normalises the axis (its length carries no meaning).
  void validate();
};

// The principal directions at one contact point, world frame, in the tangent plane.
struct SlipAxes {
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();
  double sense = 1.0;  // +1: slip of b relative to a is the frame's motion; -1: its opposite
};

// t1, t2 for normal n, with the frame geometry turned by frame_rotation. When the axis lies
// along the normal (|projection| < 1e-9) t1 is the projection of the frame's next axis.
SlipAxes slipAxes(const Anisotropy& an, const Eigen::Matrix3d& frame_rotation,
                  const Eigen::Vector3d& n);

// R v for a tangential vector v of the slip's kind (a slip or a spring's elongation):
// the ratio of each axis chosen by the sense of v along it.
Eigen::Vector3d toLawPlane(const Anisotropy& an, const SlipAxes& axes, const Eigen::Vector3d& v);
// R^-1 v' for such a vector of the scaled plane (an elongation a stateful law decided).
Eigen::Vector3d fromLawPlane(const Anisotropy& an, const SlipAxes& axes, const Eigen::Vector3d& v);
// R F' for a force of the scaled plane: the ratio of each axis chosen by the sense of the
// slip the force opposes.
Eigen::Vector3d forceFromLawPlane(const Anisotropy& an, const SlipAxes& axes,
                                  const Eigen::Vector3d& f);

// Before a friction stage: out.slip replaced by R s; returns the world slip s.
Eigen::Vector3d enterLawPlane(const Anisotropy& an, const SlipAxes& axes, ContactRecord& out);
// After it: out.friction_force = R F', out.slip = s again, out.mu = |F| / F_n (the effective
// coefficient in the slip's direction; the law's own when F_n = 0).
void leaveLawPlane(const Anisotropy& an, const SlipAxes& axes, const Eigen::Vector3d& slip,
                   ContactRecord& out);

}  // namespace tribo::contact
