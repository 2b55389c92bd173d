// The friction-law strategy: a memoryless friction coefficient mu(v) of the signed slip
// speed v [m/s], odd in v, and the one shared helper that turns it into a tangential force.
//
//   F_t = -mu(|s|) * F_n * s / |s|      (s: slip velocity of body B relative to A, F_n >= 0)
//
// Laws with internal state integrated with the motion (LuGre, rate-and-state...) derive from
// DynamicFrictionLaw (friction/dynamic_law.hpp); this interface is then their steady-state
// curve. Stateful laws (stateful() == true, e.g. elastic_stick_law.hpp) also see a view of their
// contact's state: the elongation of a tangential spring anchored where the contact stuck,
// and whether it was sliding. The contact stage keeps that state between steps (keyed by a
// persistent contact key) and calls advance() once after each step; memoryless laws ignore
// both and pay nothing for them.
// What it is not: a contact model. A law never sees geometry, bodies or time.
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tribo::friction {

// Thrown while building a law from bad parameters; the message names the law and the key.
class FrictionParameterError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A stateful law's view of one contact's state during a force evaluation.
struct StickView {
  bool anchored = false;  // false for a contact first seen in this step (no anchor yet)
  bool sliding = false;   // the contact's mode at the start of the step
  // Elongation u of the tangential spring between the two anchored material points, in the
  // tangent plane, world frame [m]; F = -k u - c s while stuck.
  Eigen::Vector3d elongation = Eigen::Vector3d::Zero();
};

// A stateful law's decision after a step: the new mode, and the elongation the anchor is
// re-set to hold (the contact stage moves the anchored points accordingly).
struct StickUpdate {
  bool sliding = false;
  Eigen::Vector3d elongation = Eigen::Vector3d::Zero();
};

class DynamicFrictionLaw;  // friction/dynamic_law.hpp

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  // Laws with internal state integrated with the motion (friction/dynamic_law.hpp) return
  // themselves; memoryless laws and elastic_stick nullptr. For a dynamic law the functions
  // below describe its steady-state curve.
  virtual const DynamicFrictionLaw* dynamic() const { return nullptr; }

  // Coefficient at signed slip speed v [m/s]. Odd: coefficient(-v) == -coefficient(v).
  virtual double coefficient(double v) const = 0;
  // Coefficients at many speeds at once (friction/tangential_batch.hpp): mu[i] =
  // coefficient(v[i]), the same bits, except 0 where v[i] == 0 (no slip: no force, and the
  // law is not asked there). The laws of this folder loop over their own coefficient() (no
  // virtual call per speed, and once for a run of equal speeds: coefficientsOf below); the
  // default calls the virtual one.
  virtual void coefficientsAt(std::span<const double> v, std::span<double> mu) const;
  // d mu / dv at v [s/m] (one-sided where the law has a kink, e.g. coulomb without
  // regularization at 0).
  virtual double slope(double v) const = 0;
  // Largest |mu| over |v| <= v_max (bounds the force: |F_t| <= bound * F_n).
  virtual double maxCoefficient(double v_max) const = 0;
  // Speed [m/s] below which a contact counts as stuck (the law's stick/slip transition).
  virtual double stickSpeed() const = 0;
  // Positive slip speeds where the piecewise definition changes (for continuity checks).
  virtual std::vector<double> breakpoints() const = 0;
  // Scene name of the law, e.g. "roh_yoo".
  virtual std::string_view name() const = 0;

  // Stateful laws only (the defaults are the memoryless behaviour). Tangential force on B
  // at slip s and load fn given the contact's state view; optionally the effective
  // coefficient |F_t| / fn.
  virtual bool stateful() const { return false; }
  virtual Eigen::Vector3d stickForce(const Eigen::Vector3d& slip, double fn, const StickView& view,
                                     double* mu_out) const;
  // The state after a step, from the slip, load and view at the step's end.
  virtual StickUpdate advance(const Eigen::Vector3d& slip, double fn, const StickView& view) const;
};

// The parameters of one law as read from a scene: numbers by key plus string options
// (e.g. coulomb's "regularization").
struct LawSpec {
  std::string name;
  std::map<std::string, double> values;
  std::map<std::string, std::string> options;
};

// Builds a law from its spec. Throws FrictionParameterError for an unknown law, an unknown
// or missing key, or a value out of range ("roh_yoo: a must be > 1 (got 0.9)").
std::unique_ptr<const FrictionLaw> makeFrictionLaw(const LawSpec& spec);

// Names of the memoryless laws accepted by makeFrictionLaw, in a stable order.
const std::vector<std::string>& knownFrictionLaws();
// Names of the stateful laws accepted by makeFrictionLaw ("elastic_stick").
const std::vector<std::string>& knownStatefulFrictionLaws();
// Names of the laws with internal state integrated with the motion (friction/dynamic_law.hpp)
// accepted by makeFrictionLaw, in a stable order.
const std::vector<std::string>& knownDynamicFrictionLaws();

// FrictionLaw::coefficientsAt for a law class `Law` whose coefficient() the compiler sees (a
// final class, called from the .cpp that defines coefficient()): one loop, no virtual call.
// A speed equal to the one before it takes that one's coefficient without asking the law
// again (a memoryless law's coefficient is a function of the speed alone, so the same bits):
// the points of a body that translates without turning, a box's four corners on a belt,
// slip alike, and the law was most of their friction stage.
// askedAt(v, i): whether speed i must go to the law under this rule (neither zero nor equal to
// the one before it); a batch that forms its coefficients otherwise (coulomb's tanh, several
// at once) follows the same rule through it.
inline bool askedAt(std::span<const double> v, std::size_t i) {
  return v[i] != 0.0 && !(i > 0 && v[i] == v[i - 1]);
}
template <class Law>
void coefficientsOf(const Law& law, std::span<const double> v, std::span<double> mu) {
  for (std::size_t i = 0; i < v.size(); ++i)
    mu[i] = askedAt(v, i) ? law.Law::coefficient(v[i]) : v[i] == 0.0 ? 0.0 : mu[i - 1];
}

// Tangential force on body B (slip s = velocity of B's material point relative to A's, in
// the tangent plane) for normal force fn >= 0. Zero at zero slip. Optionally returns mu.
Eigen::Vector3d tangentialForce(const FrictionLaw& law, const Eigen::Vector3d& slip, double fn,
                                double* mu_out = nullptr);

// The two pieces of tangentialForce around the law's call, shared with the batch
// (friction/tangential_batch.hpp) so both give the same bits: the slip speed |s|, and the
// force -(mu fn / |s|) s from it and mu = mu(|s|) (zero at |s| = 0; a NaN slip propagates).
inline double slipSpeed(const Eigen::Vector3d& slip) { return slip.norm(); }
inline Eigen::Vector3d tangentialForceAt(const Eigen::Vector3d& slip, double speed, double fn,
                                         double mu) {
  if (speed == 0.0) return Eigen::Vector3d::Zero();
  return (-mu * fn / speed) * slip;
}

}  // namespace tribo::friction
