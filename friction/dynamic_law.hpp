// Friction laws with internal state integrated with the motion (dynamic friction): bristle
// deflection (LuGre, Dahl, elasto-plastic), Maxwell-slip elements (GMS), the state variable of
// rate-and-state friction. Per contact point the law owns stateSize() numbers z, and
//
//   dz/dt = rate(z, s, F_n)            F_t = force(z, dz/dt, s, F_n)
//
// with s the slip velocity of body B relative to A in the tangent plane (world frame [m/s])
// and F_n >= 0 the normal force [N]; F_t is the tangential force on B [N]. Contact laws are
// written per unit normal force (coefficients, bristle stiffness in 1/m), so F_t scales with
// F_n and vanishes at zero load; the state itself evolves with the slip alone.
//
// Layout of z: the first 3 * tangentVectors() numbers are that many vectors in the tangent
// plane (world frame, x y z each): the engine projects them onto the new tangent plane and
// turns them with the contact frame between steps; the rest are scalars (e.g. theta [s]).
//
// The memoryless view of the law (FrictionLaw::coefficient and friends) is its steady-state
// curve: the coefficient at constant slip speed once z has settled. Events, the a-priori
// stability estimate and `tribo modes` read that curve.
//
// The engine (core/dynamics.hpp) keeps z per contact in State, keyed like the stick anchors
// (contact/stick_anchor.hpp); a new contact starts from initialState(); a contact that ends
// forgets its state (touching again starts afresh). RK4, dopri5 and bdf integrate z with the
// bodies; semi-implicit Euler calls stableStep(), an update at frozen slip and load that
// stays bounded for stiff bristles (for LuGre the exact exponential solution over h).
// Not here: anchors of elastic_stick (a spring between material points, re-set after each
// step: friction/elastic_stick_law.hpp), joints' friction (core/joint_forces.hpp).
#pragma once

#include <Eigen/Core>
#include <string>

#include "friction/friction_law.hpp"

namespace tribo::friction {

class DynamicFrictionLaw : public FrictionLaw {
 public:
  const DynamicFrictionLaw* dynamic() const final { return this; }

  // Numbers of internal state per contact, and how many of the leading ones form tangent
  // vectors (3 numbers each).
  virtual int stateSize() const = 0;
  virtual int tangentVectors() const = 0;
  // Names of the state's numbers for output, e.g. "z.x" or "theta" (stateSize() entries).
  virtual std::string stateName(int i) const = 0;
  // The state of a contact first seen (z has stateSize() entries).
  virtual void initialState(double* z) const = 0;
  // dz/dt at state z, slip s, load fn.
  virtual void rate(const double* z, const Eigen::Vector3d& slip, double fn,
                    double* zdot) const = 0;
  // Tangential force on B, given z and its rate (laws with bristle damping use it);
  // optionally the effective coefficient |F_t| / fn (0 at zero load).
  virtual Eigen::Vector3d force(const double* z, const double* zdot, const Eigen::Vector3d& slip,
                                double fn, double* mu_out) const = 0;
  // z over a step h at frozen slip and load, for semi-implicit Euler: bounded however stiff
  // the state equation (an exact or implicit update, not explicit Euler).
  virtual void stableStep(double* z, const Eigen::Vector3d& slip, double fn, double h) const = 0;
  // Small-motion stiffness [1/m] and damping [s/m] per unit normal force about a stuck
  // contact: the bristle spring that sets the fast presliding mode sqrt(stiffness F_n / m)
  // which the a-priori stable step must resolve (stiffness 0 when the law has none).
  struct Presliding {
    double stiffness = 0.0;
    double damping = 0.0;
  };
  virtual Presliding presliding() const = 0;
  // d|F_t|/d|s| per unit normal force [s/m] in steady sliding at slip speed v > 0 with the
  // state held, where it is stiffer than the steady curve's slope: the damping the slip
  // meets before the state responds (rate-and-state's direct effect, about a / v), for the
  // a-priori stable step. 0 by default: a bristle law's damping is in presliding() (in
  // steady sliding its sigma1 dz/dt term has no slope, leaving sigma2, the steady slope's).
  virtual double directSlope(double /*v*/) const { return 0.0; }
  // Largest |d(dz/dt)/dz| over the states a slip speed up to v_max can reach [1/s]: the
  // state equation's stiffness, for the a-priori stable step (0: not stiff).
  virtual double stateStiffness(double v_max) const = 0;
};

}  // namespace tribo::friction
