// The joint-force stage: generalized forces tau on the scalar coordinates of revolute and
// prismatic joints (limits, springs, dampers, efforts, actuators, friction;
// core/joint_elements.hpp),
// applied to the two bodies as J_q^T tau with J_q the coordinate's Jacobian, so the power
// they deliver is exactly tau q'. Results go to Workspace::joint_wrench.
//
// Friction uses the friction-law strategy (friction/friction_law.hpp) on a one-dimensional
// slip: tau = -mu(v) N r sign(v), v = r q' (revolute; r = pin radius) or q' (prismatic,
// r = 1). With a constant load N it is an ordinary force. With the reaction load N depends
// on the multipliers, which depend on the friction: the stage iterates
//   N_k = |reaction(lambda_k)|,  tau_k = friction(N_k),  lambda_k+1 = solve with tau_k
// re-using the factorization of J M^-1 J^T (ConstraintSolver::addForcesAndResolve) until
// the torques change by less than 1e-12 relative, at most 20 times (a step whose state
// hit the cap is counted in StepStats and warned about after the run). Measured: 1 iteration when
// the load does not depend on the friction (a slider pushed through its centre), 4-6 for a
// pendulum's pin with mu r <= 0.015 m, 13 at mu r = 0.06 m; the map contracts by about mu r m d /
// I_pivot. Reaction load: revolute |F| (radial and axial; moments are not turned into load);
// prismatic |F - (F.z) z| (the part normal to the slide).
// Dissipative elements at small speeds (fixed-step integrators): the damper's torque and the
// friction's together are held within c_max |q'| (the damper first, the friction within what
// it leaves), c_max = I_q / (2 h) (I_q: the coordinate's
// inertia, coordinateInertia below; h: the time step; the 1/2 for a chain of light links,
// whose coupled dampers reach twice one joint's rate). The friction's regularized sign then
// widens from v_eps to the speed 2 N r h / I_q where that is larger; the torque never exceeds
// the law's, always opposes the motion, and its slope keeps h c / I_q <= 1 for the chain,
// where RK4 and semi-implicit Euler damp the motion without overshoot (RK4 is stable to
// 2.785): a damper or friction can never add energy, however light the link (friction of 5 N m on a
// finger of 1e-6 kg m^2 would otherwise need h < 6e-10 s at v_eps 1e-3). That is the implicit
// (backward Euler) answer's scale: within one step a fully damped coordinate stops. bdf and dopri5
// get the elements as written (they choose their own steps). Not here: the drive constraints
// (core/constraint_rows.hpp), contact friction.
// A dynamic law (LuGre and the others with internal state) gets the same slip and load with
// its state; its force is not capped (its bristle force does not vanish with q': the
// a-priori step limit and semi-implicit Euler's exact state update handle its stiffness).
#pragma once

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

#include "core/constraint_rows.hpp"
#include "core/constraint_solver.hpp"
#include "core/model.hpp"
#include "core/signal_memo.hpp"
#include "core/state.hpp"
#include "core/workspace.hpp"
#include "friction/dynamic_law.hpp"

namespace tribo {

// Inertia of joint `joint`'s coordinate at the model's initial pose [kg m^2 or kg]: revolute,
// the child's moment about the joint axis (I_com about the axis plus m d^2, d the centre of
// mass's distance from the axis); prismatic, the child's mass. The parent counts as held
// (bodies beyond the child only add inertia) unless it gives way about the same axis: a
// free parent, or one on a joint of the same type along a parallel axis (a chain of light
// fingers), or can come to (the last of three revolute joints whose first and last axes
// make the same angle with the middle one: at gimbal lock they line up), makes it the
// pair's reduced inertia I_p I_c / (I_p + I_c).
double coordinateInertia(const Model& model, int joint, std::span<const int> joint_of_child);
// The angle q (wrapped to (-pi, pi]) as `limit` reads it: the turn nearest the middle of its
// range, so a range across +-pi (a shoulder's [-1.3, 4.45] rad) is continuous where the
// body turns through pi, and its discontinuity lies opposite the range's middle, outside
// any range narrower than a full turn. Prismatic coordinates are returned as they are.
double limitCoordinate(const JointLimit& limit, double q, bool angular);
// Per body: the last joint whose child it is (-1: none), the table coordinateInertia reads
// (made once, so that all joints' inertias cost O(joints), not O(joints^2)).
std::vector<int> jointOfChild(const Model& model);

// c_max = kDissipativeSlopeShare I_q / h (see above).
constexpr double kDissipativeSlopeShare = 0.5;

// Per model joint, the offset of its dynamic friction law's slice in
// State::friction_values, or -1 when its friction (if any) has no internal state; the
// slices' layout that JointForces uses.
std::vector<int> jointFrictionStateOffsets(const Model& model);

class JointForces {
 public:
  explicit JointForces(const Model& model);

  bool empty() const { return entries_.empty(); }
  // Limits, springs, dampers, efforts and constant-load friction at `state` (whose rotations
  // are in ws.rotation) into ws.joint_wrench, which it zeroes first (a model without joint
  // forces never writes it).
  void accumulate(const State& state, Workspace& ws);
  // Reaction-load friction, after solver.solve(state, ws): adds it to ws.joint_wrench and
  // updates the constrained accelerations. Returns the iterations used (0: none needed).
  int applyReactionFriction(ConstraintSolver& solver, Workspace& ws);
  // A command for joint `joint`'s actuator in place of its target signal's value from now on
  // (its rate taken as 0: held until the next command), NaN to return to the signal. False
  // when the joint has no actuator.
  bool setActuatorCommand(int joint, double command);

  // Dynamic friction laws on joints (friction/dynamic_law.hpp): each such joint owns a
  // fixed slice of State::friction_values, all of them first, in joint order; the state sees
  // the one-dimensional slip (r q', 0, 0) and the joint's load. accumulate() writes their
  // dz/dt into ws.friction_state_rate (sized by the caller). jointStateSize(): the slices'
  // total; initialJointStates fills them with the laws' initial states; stepStates is
  // semi-implicit Euler's update at the last evaluation's slip and load.
  int jointStateSize() const { return joint_state_size_; }
  void initialJointStates(double* z) const;
  void stepStates(State& state, double h) const;

 private:
  struct Entry {
    int joint = -1;
    JointCoordinate coordinate;
    const JointElements* elements = nullptr;
    CoordinateValue value;         // at the last accumulate()
    Vec3 axis = Vec3::UnitZ();     // world joint axis at the last accumulate()
    double reaction_torque = 0.0;  // friction with the reaction load, last applied
    double max_slope = std::numeric_limits<double>::infinity();  // c_max [N m s/rad or N s/m]
    const friction::DynamicFrictionLaw* dynamic = nullptr;       // the friction's, if dynamic
    int state = -1;             // its slice in State::friction_values
    const double* z = nullptr;  // that slice at the last accumulate()
    double* z_rate = nullptr;   // and its rate in the workspace
    double load = 0.0;          // the friction's load at the last evaluation [N]
    double command = std::numeric_limits<double>::quiet_NaN();  // the actuator's, if set
    SignalMemo target;  // the actuator's target (and a position servo's its rate), if any
  };
  // Holds a dissipative torque within c_max |q'| (see the header comment).
  static double capped(double tau, double rate, double max_slope) {
    const double bound = max_slope * std::abs(rate);
    return std::clamp(tau, -bound, bound);
  }
  // `held` within c_max |q'| in place of the law's `tau`: the change noted in `ws`.
  static void noteHeld(const Entry& e, double tau, double held, Workspace& ws);
  void addGeneralized(const Entry& e, double tau, std::vector<Wrench>& out) const;
  double frictionTorque(const Entry& e, double load, Workspace& ws) const;

  std::vector<Entry> entries_;
  std::vector<int> reaction_;  // entries with reaction-load friction
  std::vector<Wrench> delta_;  // per body
  int joint_state_size_ = 0;
};

}  // namespace tribo
