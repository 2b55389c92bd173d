// The friction-law strategy: a memoryless friction coefficient mu(v) of the signed slip
// speed v [m/s], odd in v, and the one shared helper that turns it into a tangential force.
//
//   F_t = -mu(|s|) * F_n * s / |s|      (s: slip velocity of body B relative to A, F_n >= 0)
//
// What it is not: a contact model. A law never sees geometry, bodies or time; stateful laws
// (bristle/LuGre, elastic stick anchors) will extend this interface with per-contact state.
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
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

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  // Coefficient at signed slip speed v [m/s]. Odd: coefficient(-v) == -coefficient(v).
  virtual double coefficient(double v) const = 0;
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

// Names accepted by makeFrictionLaw, in a stable order.
const std::vector<std::string>& knownFrictionLaws();

// Tangential force on body B (slip s = velocity of B's material point relative to A's, in
// the tangent plane) for normal force fn >= 0. Zero at zero slip. Optionally returns mu.
Eigen::Vector3d tangentialForce(const FrictionLaw& law, const Eigen::Vector3d& slip, double fn,
                                double* mu_out = nullptr);

}  // namespace tribo::friction
