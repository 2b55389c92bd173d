// Energy bookkeeping for the divergence guard: "energy rising without a source".
//
//   E     = sum over dynamic bodies (1/2 m v.v + 1/2 w.I_W w - m g.p)
//         + sum over springs 1/2 k (L - L0)^2
//         + sum over bushings 1/2 d^T K_t d + 1/2 phi^T K_r phi  (core/bushing.hpp)
//         + sum over torsional springs 1/2 k delta^2             (core/torsional_spring.hpp)
//         + sum over contact points U(d):  1/2 k d^2 (linear),  k d^(p+1) / (p+1) (Hunt-Crossley)
//   P_in  = power delivered by sources:
//           - (F_X . v_X + T_X . w_X)  over kinematic bodies X, F_X, T_X the contact and force
//                                      element wrenches on X (moving walls, rotating drums)
//           - F_X . s_X                over each contact side X with a surface velocity s_X
//                                      (belts; F_X the contact force on that side)
//           + (F_c . v + T_c . w)       over dynamic bodies, F_c, T_c the joint constraint
//                                      wrench (zero for ideal joints to fixed parents;
//                                      Baumgarte correction and moving parents do work) and
//                                      the joint elements' wrench (limits, springs, dampers,
//                                      friction, drives: their energy is not in E)
//           + (F_L . v + T_L . w)       over dynamic bodies, F_L, T_L the applied loads' wrench
//                                      about the origin (core/applied_load.hpp: work done
//                                      from outside, so a pushed body does not read as a
//                                      divergence and a diverging one is not excused)
// Along an exact solution dE/dt = P_in - D with D >= 0 (contact and force element damping, friction
// slip, the clipped tension of a separating penalty contact), so E_net = E - integral(P_in dt)
// never rises. The guard integrates P_in with the trapezoidal rule between checks and
// compares E_net with its running minimum (at time s):
//   E_net(t) - E_net(s) > (T + V_elastic)(s) + (V_gravity(s) - min V_gravity on [s, t])
//                         + integral over [s, t] of |P_in| dt + E_0
// (the integral by the trapezoid; for semi-implicit Euler by each step's larger end, since it
// applies the step's starting force over the whole step: core/energy.cpp)
// For semi-implicit Euler E is replaced by its modified energy E + (h/2) sum (m a.v + w.I_W alpha)
// (on a linear oscillator v^2 + w^2 x^2 - h w^2 x v is exactly conserved), because near its
// stability limit the plain energy of a stable step swings by a factor (2 + hw)/(2 - hw).
// The guard stops the run when E_net has risen by more than the energy available since s,
// i.e. more than doubling what the system had and received, plus a floor on the scale of the
// scene and of the energy its sources move through it,
//   E_0 = sum over dynamic bodies [m (|g| L + V_b^2 / 2) + I_max W^2 / 2] + 1e-9 J
// (L: the smallest size of the body's geometries; V_b: the fastest kinematic body, surface
// or prismatic drive, plus the fastest turning kinematic body's spin times its distance to
// the body; W: the fastest spin of a kinematic body or revolute drive; I_max: the body's
// largest moment about its own axes). A body with no geometry and a driver that turns it (a
// flywheel driven through a spring) thus has a floor on the scale of what the driver gives it. A
// divergence grows exponentially past any such bound within a few steps, while
// the energy error of a stable step (semi-implicit Euler near its limit, a coarse step
// across the first touch of a contact) stays below it. The body named is the one whose
// kinetic plus gravitational energy rose most since s.
// Not here: other divergence checks (core/simulator.hpp); the energy of kinematic bodies
// (sources); the elastic energy of stateful friction laws' tangential springs (F^2 / 2k, small
// against the floor), which the account reads as dissipated while stuck and as a rise when
// released.
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"

namespace tribo {

struct EnergyAccount {
  double kinetic = 0.0;      // [J]
  double gravity = 0.0;      // [J], zero at the world origin
  double elastic = 0.0;      // springs and contact points [J]
  double input_power = 0.0;  // P_in [W]
  double total() const { return kinetic + gravity + elastic; }
};

// Each body's and each contact point's share of an account: computed per item, split across
// `threads` when the items pay for them (core/stage_threads.hpp), then summed in index order,
// the additions of the one-thread loop in its order, so the account is the same bit for bit
// for any number of threads (on one thread each term is summed as it is formed). Scratch kept
// between calls so that a step does not allocate.
struct EnergyTerms {
  struct Body {
    double kinetic = 0.0, gravity = 0.0;
    double power[3] = {0.0, 0.0, 0.0};  // kinematic: [0] its sources' power; dynamic: the
                                        // joint constraint's, the joint elements', the loads'
    double kinetic_rate = 0.0;          // m a.v + w.I_W alpha, for the modified energy
  };
  struct Point {
    double elastic = 0.0;
    double power_b = 0.0, power_a = 0.0;  // sign f.s per side, zero without a surface speed
  };
  std::vector<Body> bodies;   // filled only when the bodies split across threads
  std::vector<Point> points;  // likewise the points
  // Each body's isotropicMoment (core/math.hpp: I for inertia I 1, else 0), read from the
  // model once (listBodies) rather than compared again on every account.
  std::vector<double> isotropic;
  // Each body's Body::dynamicMass (0: kinematic): an account reads it rather than the model's
  // body record (288 bytes, a cache miss a body on the 32 000-sphere chute).
  std::vector<double> mass;
  void listBodies(const Model& model);
};

// The account at `state`; `ws` must be its evaluation. If `body_energy` is given it receives
// each body's kinetic plus gravitational energy (zero for kinematic bodies). `threads` > 1
// splits the per-body and per-point terms (the same result).
EnergyAccount measureEnergy(const Model& model, const State& state, const Workspace& ws,
                            std::vector<double>* body_energy = nullptr, int threads = 1);

struct EnergyVerdict {
  bool ok = true;
  std::string body;        // when !ok: the body whose energy rose most
  double rise = 0.0;       // E_net(t) - E_net(s) [J]
  double available = 0.0;  // the bound it exceeded [J]
  double since = 0.0;      // s [s]
};

class EnergyGuard {
 public:
  // `modified_step` h > 0 selects the modified energy of semi-implicit Euler at step h;
  // `threads` splits the account's terms as measureEnergy does (the verdicts do not change).
  explicit EnergyGuard(const Model& model, double modified_step = 0.0, int threads = 1);
  // Starts watching at `state` (evaluated in `ws`).
  void reset(const State& state, const Workspace& ws);
  bool started() const { return started_; }
  // From the next account on, its terms split over `threads` (the verdicts do not change).
  void setThreads(int threads) { threads_ = threads; }
  // Takes the next checked state (evaluated in `ws`).
  EnergyVerdict update(const State& state, const Workspace& ws);

 private:
  void markMinimum(double t, double net, const EnergyAccount& a);
  // The account at `state`, its kinetic energy the modified one for semi-implicit Euler.
  EnergyAccount measure(const State& state, const Workspace& ws);

  const Model* model_;
  double floor_ = 0.0;  // E_0 [J]
  double modified_step_ = 0.0;
  int threads_ = 1;
  EnergyTerms terms_;
  bool started_ = false;
  double t_ = 0.0, power_ = 0.0;        // at the last update
  double work_ = 0.0, abs_work_ = 0.0;  // integral of P_in and |P_in| since reset
  // At the running minimum of E_net:
  double min_time_ = 0.0, min_net_ = 0.0, min_kinetic_elastic_ = 0.0, min_gravity_ = 0.0;
  double min_abs_work_ = 0.0, lowest_gravity_ = 0.0;
  std::vector<double> min_body_energy_, body_energy_;
};

}  // namespace tribo
