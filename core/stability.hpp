// A-priori step-size limit for the explicit integrators, from the stiffest element of the
// model, so a run whose step is too large is flagged before it produces a plausible-looking
// wrong answer.
//
// Each element is reduced to the linear test system  x'' + (c/m) x' + (k/m) x = 0, with m
// the dynamic body's mass (reduced mass if both are dynamic):
//   contact pair, normal: k = n dF/dd, c = n dF/dd' of the pair's normal law at rest, n = 4
//                  points (a box resting on a face). Linear: k, c as given. Nonlinear
//                  (hertz, hunt_crossley, recurdyn): the tangent at the static depth d0
//                  where the n points share the resting load W (the dynamic body's weight,
//                  the heavier one's if both are dynamic): k d0^p = W / n, so
//                    dF/dd = p W / (n d0);  dF/dd' = 0 (hertz), alpha W / n
//                    (hunt_crossley), havsin(d0, 0, 0, d_max, c) (recurdyn).
//                  Without gravity there is no static depth: the stated depth 1e-4 m, with
//                  a note. A deeper contact (an impact, a stack's lower pairs) is stiffer:
//                  the limit falls as d^-(p-1)/2;
//   contact pair, rocking: a box resting on a face, on a half-space or on another box, turns
//                  about the face's two edges through its centre of mass on the same n
//                  points (the face's corners, at the normal law's tangent k_p, c_p): per
//                  point lever arm l_i = a . ((p_i - x_cm) x normal), k = k_p sum l_i^2,
//                  c = c_p sum l_i^2, m = a^T I a (the body's inertia about that axis);
//                  for a box of edges (a, b, c) on its a x b face about x: 4 k_p (b/2)^2
//                  against m (b^2 + c^2) / 12, 1.55 times the normal frequency for
//                  0.2 x 0.2 x 0.1 m. With both bodies turning, the larger eigenvalue of the
//                  two-body system (a stack's relative rocking). Assumed: the body rests on
//                  that face at the initial pose (on a half-space, its face against the
//                  plane; for two boxes, as for every pair taken to touch, the faces along
//                  the separating axis of least overlap, the smaller face clipped to the
//                  other being the patch, no patch when they do not overlap); it counts only
//                  for a body that can turn about that axis through its centre of mass
//                  without breaking a joint at the initial pose (free, spherical at the
//                  centre of mass, revolute about that axis; not planar_translation,
//                  prismatic, fixed). Left out: the coupling of rocking with translation
//                  (zero for a box centred on its body), rounded shapes (sphere, cylinder,
//                  capsule, cone) and meshes, a body turning about a joint away from its
//                  centre of mass, and what friction adds through the corners' depth below
//                  the centre of mass in rocking (10-25% lower limits on the belt boxes);
//   contact pair, yaw: the same body turning about the contact normal through its centre of
//                  mass (when it can, as for rocking; on a face carrying the weight, its
//                  normal within 60 degrees of gravity) on the same n points, each friction
//                  element below per point (k_p, c_p: its k, c over n) with the tangential
//                  lever arms g_i = normal x (p_i - x_cm): k = k_p sum |g_i|^2,
//                  c = c_p sum |g_i|^2, m = the inertia about the normal (both bodies turning:
//                  the larger eigenvalue, as for rocking). A box of edges (a, b) on its face:
//                  3 times the translation's k/m and c/m, for any a, b (sum |g_i|^2 = a^2 + b^2
//                  against m (a^2 + b^2) / 12), so friction's damping limits yaw at a third
//                  of the step (measured: a free box creeping on an incline under a
//                  tabulated law at 0.9 of the translational limit crept 29% too fast; held
//                  against turning, exact at 1.8 times it);
//   contact pair, stateful friction (elastic_stick): its stick spring-damper, k = n k_t,
//                  c = n c_t (read off the law's stuck force), tangential;
//   contact pair, dynamic friction (friction/dynamic_law.hpp): the bristles' presliding
//                  spring-damper under the resting load W, k = sigma0 W, c = sigma_d W
//                  (DynamicFrictionLaw::presliding, per unit normal force); the direct
//                  effect, the slip's damping with the state held, k = 0, c = mu_d(v_ref) W
//                  (DynamicFrictionLaw::directSlope: rate_state's a / v, 0 for the bristle
//                  laws) at the reference slip speed v_ref = max(v_drive, the law's stick
//                  speed), with a note: it grows without bound as the slip slows, so below
//                  v_ref explicit steps chatter, within about the speed where the limit meets
//                  the step; for a law without bristles (presliding stiffness 0: rate_state)
//                  the damping across the slip, whose direction the force follows at once,
//                  c = mu(v_ref) / v_ref W (mu0 / a = 20 times the direct effect for the
//                  defaults), for a body free to slide across the contact plane (not on a
//                  slide or planar_translation joint), and in yaw (with the larger of the two,
//                  for a body free to turn); for semi-implicit Euler, whose state update
//                  starts from the step's slip (explicit Euler on the bristle), the bristle
//                  keeps half its damping: h <= sigma_d / (2 sigma0) (explicitStateStep in
//                  core/stability.cpp; none for an undamped bristle, dahl: a note); and, except
//                  for semi-implicit Euler (whose state update is exact at frozen slip), the
//                  internal state's decay rate as a
//                  first-order mode (k = 0, c/m = lambda, DynamicFrictionLaw::stateStiffness)
//                  at slip speed 4 v_ref, v_drive the fastest kinematic body, moving surface
//                  or slider's drive (prismatic): a driven stick-slip slips at up to 3.5
//                  times its drive;
//   spring-damper: k, c as given, m as above;
//   bushing:       per axis of frame A at the initial pose, k, c as given; translation on m
//                  as above, rotation on the bodies' reduced moment of inertia about that
//                  axis (I_a I_b / (I_a + I_b), or the dynamic body's); the coupling of
//                  rotation and translation through a frame away from the centre of mass is
//                  left out;
//   torsional spring: k, c on the reduced moment of inertia about its axis, likewise;
//   friction:      c/m = g mu'(v) (the sticking slope of the law under the body's weight), at
//                  the steepest rise over the speeds where mu still rises: [0, stick speed]
//                  extended over the breakpoints to which mu rises (a table rising to its last
//                  point creeps beyond its stick speed, its first point); 16 samples on each
//                  piece between breakpoints (a table's points: 16 samples over the whole
//                  range missed a short steep segment, 0.05 to 0.40 over 0.1 mm/s), the
//                  steepest refined by golden section between its neighbours (a table's slope
//                  is quadratic on a piece); for a law whose slope is
//                  unbounded at zero slip (roh_yoo with beta < 1) the slope at the stick speed,
//                  so that at the limit the numerical chatter stays below the stick speed;
//   rolling:       friction's slip elements above (presliding, direct effect, across the
//                  slip, stick spring, sticking slope; not the state's own decay) on a round
//                  shape that rolls, alone on its body (a sphere; a capsule or cylinder on its
//                  side, rim or end), meet the slip's inverse mass 1/m + (r x t)^T I^-1 (r x t)
//                  at the contact point, not 1/m: their c/m and k/m scale by that ratio
//                  (rollingSlipFactor in core/resting_contact.hpp; 3.5 for a solid sphere, 3
//                  for a solid cylinder rolling on its side); a capsule or cylinder lying on
//                  its side also yaws on its line's two ends, each friction element as for a
//                  box's yaw (a stick spring there counts twice: conservative). Measured
//                  without them: spheres, cylinders and capsules rolling down an incline
//                  under a regularized Coulomb law left the rolling solution at 0.9 of the
//                  old estimate; with them they hold it to 1% up to 1.09-1.13 times the
//                  estimate (tests/core/stability_rolling_test.cpp); scenes/rolling_sphere
//                  at 4 ms (old limit 5.7 ms, new 1.6 ms) completed unwarned with its slip
//                  chattering at 18 times the rolling solution's;
//   joint elements (revolute, prismatic): m = the coordinate's inertia (coordinateInertia in
//                  core/joint_forces.hpp, a light link's few 1e-6 kg m^2 included), k = the
//                  spring's and the limit's stiffness, a servo's kp with its own c = kd
//                  (core/joint_actuator.hpp, not held), c = damping plus the friction's
//                  sticking slope mu'(v) N r^2 (as for contacts; N: the constant load, or the
//                  child's weight for a reaction load), c held to m / (2 h) at a fixed step as
//                  the joint forces hold it (so it never bounds the step there; for dopri5 it
//                  does); a dynamic law's friction (not held: its force is not capped) as on a
//                  contact with N r^2 for the load W, on the same m: presliding k = sigma0 N r^2,
//                  c = sigma_d N r^2, and for semi-implicit Euler h <= sigma_d / (2 sigma0);
//                  direct effect c = mu_d(v_ref) N r^2; the state's decay c/m = lambda at
//                  4 v_ref (not for semi-implicit Euler). On a heavy disc, I_q / (N r^2) =
//                  10 s^2/m, the bristle mode is underdamped and the explicit state update
//                  sets semi-implicit Euler's limit (measured: lugre off at 1.08 times it).
// A user law (Python) is bounded by what it states: its curve's sampled slope, its presliding,
// state_stiffness and direct_slope (0 when left out: the direct effect is the slope with the
// state held, which the steady curve mu(v) does not show). Measured in the class
// (tests/core/stability_laws_test.cpp, docs/speed-accuracy.md): at 0.9 of the estimate each
// law agrees with a tenth of the step, and it stops agreeing within 1-4 times it (RK4 on a
// lugre slider or light disc: 0.93-0.95); dahl, whose undamped presliding ratchets a body
// along by the method's numerical damping, is checked for boundedness instead: with RK4 its
// reference converges and the run at 0.9 is stable and creeps no further; with semi-implicit
// Euler its creep converges at first order only (the state update feeds its ring).
// The limit is the largest h for which the integrator's one-step matrix for that system has
// spectral radius <= 1 (undamped: RK4 h w < 2 sqrt(2), semi-implicit Euler h w < 2; real
// axis: RK4 2.785, Dormand-Prince 5(4) 3.307). For dopri5 it bounds the internal steps the
// error control will settle on (a cost estimate, not a warning); bdf has no explicit limit.
// Not here: rocking other than a box's on its face, yaw other than a box's on its face or a
// capsule's or cylinder's on its side, a body rolling on several round geometries (an axle's
// two wheels: taken to be held), shapes resting on more
// or fewer than 4 points (linear law: a disc on 8 rim points has sqrt(2) times the
// frequency, a sphere on one point half), nonlinear instability, contact chatter, accuracy
// (see the README's measurements).
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"

namespace tribo {

struct StabilityLimit {
  double max_step = 0.0;  // [s], +infinity when nothing limits it
  std::string element;    // e.g. "contact pair (belt_surface, box_shape)"
};

// A joint whose damping plus steepest friction slope c exceeds the fixed step's budget
// c_max = I_q / (2 h) (core/joint_forces.hpp): its torques are held within c_max |q'| where
// the law is steeper, and a step of at most `rule_step` = I_q / (2 c) gives the law as written.
struct HeldJoint {
  int joint = -1;
  double slope = 0.0;      // c [N m s/rad or N s/m]
  double max_slope = 0.0;  // c_max at the model's step
  double rule_step = 0.0;  // [s]
};

struct StabilityReport {
  StabilityLimit limit;                // the most restrictive element
  std::vector<std::string> notes;      // elements that could not be bounded, and why
  std::vector<HeldJoint> held_joints;  // fixed steps only
};

// Largest stable step of `integrator` on x'' + c_over_m x' + k_over_m x = 0.
double stableStep(IntegratorType integrator, double k_over_m, double c_over_m);

StabilityReport estimateStableStep(const Model& model);

}  // namespace tribo
