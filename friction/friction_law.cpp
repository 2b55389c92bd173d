// The law factory (scene name and keys -> a validated law) and the shared tangential-force
// helper. Key handling lives here; each law's constructor checks the values.
#include "friction/friction_law.hpp"

#include <span>
#include <string>

#include "friction/adams_law.hpp"
#include "friction/coulomb_law.hpp"
#include "friction/elastic_stick_law.hpp"
#include "friction/lugre_law.hpp"
#include "friction/recurdyn_law.hpp"
#include "friction/roh_yoo_law.hpp"
#include "friction/stribeck_law.hpp"

namespace tribo::friction {
namespace {

std::string joined(std::span<const std::string_view> words) {
  std::string out;
  for (const std::string_view word : words) {
    if (!out.empty()) out += ", ";
    out += word;
  }
  return out;
}

// Reads the keys of one law's spec; rejects keys and options the law does not accept.
class SpecReader {
 public:
  SpecReader(const LawSpec& spec, std::span<const std::string_view> keys,
             std::span<const std::string_view> option_keys = {})
      : spec_(spec), keys_(keys), option_keys_(option_keys) {
    for (const auto& [key, value] : spec.values) {
      if (!contains(keys_, key)) fail("unknown key '" + key + "'");
    }
    for (const auto& [key, value] : spec.options) {
      if (!contains(option_keys_, key)) fail("unknown option '" + key + "'");
    }
  }

  double required(std::string_view key) const {
    const auto it = spec_.values.find(std::string(key));
    if (it == spec_.values.end()) fail("missing required key '" + std::string(key) + "'");
    return it->second;
  }

  double optional(std::string_view key, double fallback) const {
    const auto it = spec_.values.find(std::string(key));
    return it == spec_.values.end() ? fallback : it->second;
  }

  // The option's value, or "" when absent.
  std::string option(std::string_view key) const {
    const auto it = spec_.options.find(std::string(key));
    return it == spec_.options.end() ? std::string() : it->second;
  }

  [[noreturn]] void fail(const std::string& what) const {
    std::string message = spec_.name + ": " + what + " (accepted keys: " + joined(keys_);
    if (!option_keys_.empty()) message += "; options: " + joined(option_keys_);
    throw FrictionParameterError(message + ")");
  }

 private:
  static bool contains(std::span<const std::string_view> list, std::string_view key) {
    for (const std::string_view item : list) {
      if (item == key) return true;
    }
    return false;
  }

  const LawSpec& spec_;
  std::span<const std::string_view> keys_;
  std::span<const std::string_view> option_keys_;
};

// Accepted keys per law (static storage: SpecReader keeps views of them).
constexpr std::string_view kCoulombKeys[] = {"mu", "v_eps"};
constexpr std::string_view kCoulombOptions[] = {"regularization"};
constexpr std::string_view kStepLawKeys[] = {"mu_s", "mu_k", "v_s", "v_d"};
constexpr std::string_view kRohYooKeys[] = {"mu_s", "mu_k", "v_s", "a", "beta"};
constexpr std::string_view kStribeckKeys[] = {"mu_s", "mu_k", "v_st", "delta", "viscous", "v_eps"};
constexpr std::string_view kLuGreKeys[] = {"sigma0", "sigma1", "sigma2", "mu_c", "mu_s", "v_s"};
constexpr std::string_view kElasticStickKeys[] = {"mu_s", "mu_k", "stiffness", "damping",
                                                  "stick_speed"};

std::unique_ptr<const FrictionLaw> makeCoulomb(const LawSpec& spec) {
  const SpecReader reader(spec, kCoulombKeys, kCoulombOptions);
  CoulombParams params;
  params.mu = reader.required("mu");
  params.v_eps = reader.optional("v_eps", params.v_eps);
  const std::string regularization = reader.option("regularization");
  if (!regularization.empty()) {
    const auto r = kCoulombRegularizationNames.find(regularization);
    if (!r)
      throw FrictionParameterError("coulomb: regularization must be one of " +
                                   kCoulombRegularizationNames.names() + " (got '" +
                                   regularization + "')");
    params.regularization = *r;
  }
  return std::make_unique<CoulombLaw>(params);
}

TwoStepParams twoStepParams(const LawSpec& spec) {
  const SpecReader reader(spec, kStepLawKeys);
  return {.mu_s = reader.required("mu_s"),
          .mu_k = reader.required("mu_k"),
          .v_s = reader.required("v_s"),
          .v_d = reader.required("v_d")};
}

std::unique_ptr<const FrictionLaw> makeLuGre(const LawSpec& spec) {
  const SpecReader reader(spec, kLuGreKeys);
  LuGreParams p;
  p.sigma0 = reader.optional("sigma0", p.sigma0);
  p.sigma1 = reader.optional("sigma1", p.sigma1);
  p.sigma2 = reader.optional("sigma2", p.sigma2);
  p.mu_c = reader.optional("mu_c", p.mu_c);
  p.mu_s = reader.optional("mu_s", p.mu_s);
  p.v_s = reader.optional("v_s", p.v_s);
  return std::make_unique<LuGreLaw>(p);
}

std::unique_ptr<const FrictionLaw> makeRecurDyn(const LawSpec& spec) {
  return std::make_unique<RecurDynLaw>("recurdyn", twoStepParams(spec));
}

std::unique_ptr<const FrictionLaw> makeAdams(const LawSpec& spec) {
  return std::make_unique<AdamsLaw>("adams", twoStepParams(spec));
}

std::unique_ptr<const FrictionLaw> makeRohYoo(const LawSpec& spec) {
  const SpecReader reader(spec, kRohYooKeys);
  return std::make_unique<RohYooLaw>(RohYooParams{.mu_s = reader.required("mu_s"),
                                                  .mu_k = reader.required("mu_k"),
                                                  .v_s = reader.required("v_s"),
                                                  .a = reader.required("a"),
                                                  .beta = reader.required("beta")});
}

std::unique_ptr<const FrictionLaw> makeStribeck(const LawSpec& spec) {
  const SpecReader reader(spec, kStribeckKeys);
  const StribeckParams defaults;
  return std::make_unique<StribeckLaw>(
      StribeckParams{.mu_s = reader.required("mu_s"),
                     .mu_k = reader.required("mu_k"),
                     .v_st = reader.required("v_st"),
                     .delta = reader.optional("delta", defaults.delta),
                     .viscous = reader.optional("viscous", defaults.viscous),
                     .v_eps = reader.optional("v_eps", defaults.v_eps)});
}

std::unique_ptr<const FrictionLaw> makeElasticStick(const LawSpec& spec) {
  const SpecReader reader(spec, kElasticStickKeys);
  const ElasticStickParams defaults;
  return std::make_unique<ElasticStickLaw>(
      ElasticStickParams{.mu_s = reader.required("mu_s"),
                         .mu_k = reader.required("mu_k"),
                         .stiffness = reader.required("stiffness"),
                         .damping = reader.optional("damping", defaults.damping),
                         .stick_speed = reader.optional("stick_speed", defaults.stick_speed)});
}

}  // namespace

Eigen::Vector3d FrictionLaw::stickForce(const Eigen::Vector3d& slip, double fn, const StickView&,
                                        double* mu_out) const {
  return tangentialForce(*this, slip, fn, mu_out);
}

StickUpdate FrictionLaw::advance(const Eigen::Vector3d&, double, const StickView&) const {
  return {};
}

std::unique_ptr<const FrictionLaw> makeFrictionLaw(const LawSpec& spec) {
  if (spec.name == "coulomb") return makeCoulomb(spec);
  if (spec.name == "recurdyn") return makeRecurDyn(spec);
  if (spec.name == "adams") return makeAdams(spec);
  if (spec.name == "roh_yoo") return makeRohYoo(spec);
  if (spec.name == "stribeck") return makeStribeck(spec);
  if (spec.name == "elastic_stick") return makeElasticStick(spec);
  if (spec.name == "lugre") return makeLuGre(spec);
  std::string known;
  for (const std::string& name : knownFrictionLaws()) known += (known.empty() ? "" : ", ") + name;
  for (const std::string& name : knownStatefulFrictionLaws()) known += ", " + name;
  for (const std::string& name : knownDynamicFrictionLaws()) known += ", " + name;
  throw FrictionParameterError("unknown friction law '" + spec.name + "' (known laws: " + known +
                               ")");
}

const std::vector<std::string>& knownFrictionLaws() {
  static const std::vector<std::string> names = {"coulomb", "recurdyn", "adams", "roh_yoo",
                                                 "stribeck"};
  return names;
}

const std::vector<std::string>& knownStatefulFrictionLaws() {
  static const std::vector<std::string> names = {"elastic_stick"};
  return names;
}

const std::vector<std::string>& knownDynamicFrictionLaws() {
  static const std::vector<std::string> names = {"lugre"};
  return names;
}

Eigen::Vector3d tangentialForce(const FrictionLaw& law, const Eigen::Vector3d& slip, double fn,
                                double* mu_out) {
  const double speed = slip.norm();
  if (speed == 0.0) {  // a NaN slip is not caught here: it propagates into the force
    if (mu_out != nullptr) *mu_out = 0.0;
    return Eigen::Vector3d::Zero();
  }
  const double mu = law.coefficient(speed);
  if (mu_out != nullptr) *mu_out = mu;
  return (-mu * fn / speed) * slip;
}

}  // namespace tribo::friction
