// The law factory (scene name and keys -> a validated law) and the shared tangential-force
// helper. One table (kLaws) lists every law once: its name, kind, keys, options and factory;
// the factory, frictionLawKeys and the name lists read it. Key handling lives here; each
// law's constructor checks the values.
#include "friction/friction_law.hpp"

#include <cmath>
#include <span>
#include <string>

#include "friction/adams_law.hpp"
#include "friction/coulomb_law.hpp"
#include "friction/dahl_law.hpp"
#include "friction/elastic_stick_law.hpp"
#include "friction/elasto_plastic_law.hpp"
#include "friction/gms_law.hpp"
#include "friction/law_keys.hpp"
#include "friction/lugre_law.hpp"
#include "friction/parameter_check.hpp"
#include "friction/rate_state_law.hpp"
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
constexpr std::string_view kDahlKeys[] = {"sigma0", "mu_c", "alpha"};
constexpr std::string_view kElastoPlasticKeys[] = {"sigma0", "sigma1", "sigma2",       "mu_c",
                                                   "mu_s",   "v_s",    "z_ba_fraction"};
constexpr std::string_view kGmsKeys[] = {
    "elements", "stiffness",  "k_1",     "k_2",     "k_3",     "k_4",     "k_5",
    "k_6",      "k_7",        "k_8",     "alpha_1", "alpha_2", "alpha_3", "alpha_4",
    "alpha_5",  "alpha_6",    "alpha_7", "alpha_8", "mu_c",    "mu_s",    "v_s",
    "delta",    "attraction", "sigma1",  "sigma2"};
constexpr std::string_view kRateStateKeys[] = {"mu0", "a", "b", "d_c", "v0", "theta0"};
constexpr std::string_view kRateStateOptions[] = {"evolution"};
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

std::unique_ptr<const FrictionLaw> makeDahl(const LawSpec& spec) {
  const SpecReader reader(spec, kDahlKeys);
  DahlParams p;
  p.sigma0 = reader.optional("sigma0", p.sigma0);
  p.mu_c = reader.optional("mu_c", p.mu_c);
  p.alpha = reader.optional("alpha", p.alpha);
  return std::make_unique<DahlLaw>(p);
}

std::unique_ptr<const FrictionLaw> makeElastoPlastic(const LawSpec& spec) {
  const SpecReader reader(spec, kElastoPlasticKeys);
  ElastoPlasticParams p;
  p.sigma0 = reader.optional("sigma0", p.sigma0);
  p.sigma1 = reader.optional("sigma1", p.sigma1);
  p.sigma2 = reader.optional("sigma2", p.sigma2);
  p.mu_c = reader.optional("mu_c", p.mu_c);
  p.mu_s = reader.optional("mu_s", p.mu_s);
  p.v_s = reader.optional("v_s", p.v_s);
  p.z_ba_fraction = reader.optional("z_ba_fraction", p.z_ba_fraction);
  return std::make_unique<ElastoPlasticLaw>(p);
}

// Per-element values NAME_1..NAME_N of gms: all N or none, none beyond N.
std::vector<double> gmsElementValues(const LawSpec& spec, const std::string& name, int n) {
  std::vector<double> values;
  int given = 0;
  for (int i = 1; i <= GmsParams::kMaxElements; ++i) {
    const auto it = spec.values.find(name + "_" + std::to_string(i));
    if (it == spec.values.end()) continue;
    ++given;
    if (i > n)
      ParameterCheck("gms").fail(name + "_" + std::to_string(i) + " given for " +
                                 std::to_string(n) + " elements (set elements)");
  }
  if (given == 0) return values;
  for (int i = 1; i <= n; ++i) {
    const auto it = spec.values.find(name + "_" + std::to_string(i));
    if (it == spec.values.end())
      ParameterCheck("gms").fail("missing " + name + "_" + std::to_string(i) + ": give " + name +
                                 "_1.." + name + "_N for all N = " + std::to_string(n) +
                                 " elements or none");
    values.push_back(it->second);
  }
  return values;
}

std::unique_ptr<const FrictionLaw> makeGms(const LawSpec& spec) {
  const SpecReader reader(spec, kGmsKeys);
  const ParameterCheck check("gms");
  GmsParams p;
  const double elements = reader.optional("elements", p.elements);
  check.require(std::isfinite(elements) && elements == std::floor(elements) && elements >= 1 &&
                    elements <= GmsParams::kMaxElements,
                "elements must be an integer in 1.." + std::to_string(GmsParams::kMaxElements),
                elements);
  p.elements = static_cast<int>(elements);
  p.stiffness = reader.optional("stiffness", p.stiffness);
  p.k = gmsElementValues(spec, "k", p.elements);
  if (!p.k.empty() && spec.values.count("stiffness") != 0)
    check.fail("give stiffness or k_1..k_N, not both");
  p.alpha = gmsElementValues(spec, "alpha", p.elements);
  p.mu_c = reader.optional("mu_c", p.mu_c);
  p.mu_s = reader.optional("mu_s", p.mu_s);
  p.v_s = reader.optional("v_s", p.v_s);
  p.delta = reader.optional("delta", p.delta);
  p.attraction = reader.optional("attraction", p.attraction);
  p.sigma1 = reader.optional("sigma1", p.sigma1);
  p.sigma2 = reader.optional("sigma2", p.sigma2);
  return std::make_unique<GmsLaw>(p);
}

std::unique_ptr<const FrictionLaw> makeRateState(const LawSpec& spec) {
  const SpecReader reader(spec, kRateStateKeys, kRateStateOptions);
  const ParameterCheck check("rate_state");
  RateStateParams p;
  p.mu0 = reader.optional("mu0", p.mu0);
  p.a = reader.optional("a", p.a);
  p.b = reader.optional("b", p.b);
  p.d_c = reader.optional("d_c", p.d_c);
  p.v0 = reader.optional("v0", p.v0);
  if (spec.values.count("theta0") != 0) {
    p.theta0 = reader.required("theta0");
    check.require(p.theta0 > 0.0 || std::isnan(p.theta0), "theta0 must be > 0 [s]", p.theta0);
  }
  const std::string evolution = reader.option("evolution");
  if (evolution == "slip") {
    p.evolution = RateStateEvolution::kSlip;
  } else if (!evolution.empty() && evolution != "aging") {
    throw FrictionParameterError("rate_state: evolution must be one of aging, slip (got '" +
                                 evolution + "')");
  }
  return std::make_unique<RateStateLaw>(p);
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

// The words of coulomb's `regularization` option.
std::vector<std::string> coulombRegularizations() {
  std::vector<std::string> words;
  const std::string all = kCoulombRegularizationNames.names();  // "a, b, c"
  for (std::size_t at = 0; at != std::string::npos;) {
    const std::size_t comma = all.find(", ", at);
    words.push_back(all.substr(at, comma == std::string::npos ? comma : comma - at));
    at = comma == std::string::npos ? comma : comma + 2;
  }
  return words;
}

std::vector<std::string> rateStateEvolutions() { return {"aging", "slip"}; }

enum class LawKind { kMemoryless, kStateful, kDynamic };

// One row per law: its scene name, kind, accepted keys and options, the words its options
// take, and its factory. The factory, the key lists and the name lists all read this table.
struct LawEntry {
  std::string_view name;
  LawKind kind;
  std::span<const std::string_view> keys;
  std::span<const std::string_view> options;
  std::vector<std::string> (*option_words)();  // nullptr: none
  std::unique_ptr<const FrictionLaw> (*make)(const LawSpec&);
};

constexpr LawEntry kLaws[] = {
    {"coulomb", LawKind::kMemoryless, kCoulombKeys, kCoulombOptions, coulombRegularizations,
     makeCoulomb},
    {"recurdyn", LawKind::kMemoryless, kStepLawKeys, {}, nullptr, makeRecurDyn},
    {"adams", LawKind::kMemoryless, kStepLawKeys, {}, nullptr, makeAdams},
    {"roh_yoo", LawKind::kMemoryless, kRohYooKeys, {}, nullptr, makeRohYoo},
    {"stribeck", LawKind::kMemoryless, kStribeckKeys, {}, nullptr, makeStribeck},
    {"elastic_stick", LawKind::kStateful, kElasticStickKeys, {}, nullptr, makeElasticStick},
    {"lugre", LawKind::kDynamic, kLuGreKeys, {}, nullptr, makeLuGre},
    {"dahl", LawKind::kDynamic, kDahlKeys, {}, nullptr, makeDahl},
    {"elasto_plastic", LawKind::kDynamic, kElastoPlasticKeys, {}, nullptr, makeElastoPlastic},
    {"gms", LawKind::kDynamic, kGmsKeys, {}, nullptr, makeGms},
    {"rate_state", LawKind::kDynamic, kRateStateKeys, kRateStateOptions, rateStateEvolutions,
     makeRateState},
};

const LawEntry* findLaw(const std::string& name) {
  for (const LawEntry& entry : kLaws)
    if (entry.name == name) return &entry;
  return nullptr;
}

std::vector<std::string> lawNames(LawKind kind) {
  std::vector<std::string> names;
  for (const LawEntry& entry : kLaws)
    if (entry.kind == kind) names.emplace_back(entry.name);
  return names;
}

}  // namespace

Eigen::Vector3d FrictionLaw::stickForce(const Eigen::Vector3d& slip, double fn, const StickView&,
                                        double* mu_out) const {
  return tangentialForce(*this, slip, fn, mu_out);
}

void FrictionLaw::coefficientsAt(std::span<const double> v, std::span<double> mu) const {
  for (std::size_t i = 0; i < v.size(); ++i) mu[i] = v[i] != 0.0 ? coefficient(v[i]) : 0.0;
}

StickUpdate FrictionLaw::advance(const Eigen::Vector3d&, double, const StickView&) const {
  return {};
}

std::unique_ptr<const FrictionLaw> makeFrictionLaw(const LawSpec& spec) {
  if (const LawEntry* entry = findLaw(spec.name)) return entry->make(spec);
  std::string known;
  for (const LawEntry& entry : kLaws)
    known += (known.empty() ? "" : ", ") + std::string(entry.name);
  throw FrictionParameterError("unknown friction law '" + spec.name + "' (known laws: " + known +
                               ")");
}

LawKeys frictionLawKeys(const std::string& name) {
  const LawEntry* entry = findLaw(name);
  if (entry == nullptr) throw FrictionParameterError("unknown friction law '" + name + "'");
  const auto words = [](std::span<const std::string_view> v) {
    return std::vector<std::string>(v.begin(), v.end());
  };
  return {words(entry->keys), words(entry->options),
          entry->option_words != nullptr ? entry->option_words() : std::vector<std::string>{}};
}

const std::vector<std::string>& knownFrictionLaws() {
  static const std::vector<std::string> names = lawNames(LawKind::kMemoryless);
  return names;
}

const std::vector<std::string>& knownStatefulFrictionLaws() {
  static const std::vector<std::string> names = lawNames(LawKind::kStateful);
  return names;
}

const std::vector<std::string>& knownDynamicFrictionLaws() {
  static const std::vector<std::string> names = lawNames(LawKind::kDynamic);
  return names;
}

Eigen::Vector3d tangentialForce(const FrictionLaw& law, const Eigen::Vector3d& slip, double fn,
                                double* mu_out) {
  const double speed = slipSpeed(slip);
  const double mu = speed == 0.0 ? 0.0 : law.coefficient(speed);  // a NaN slip propagates
  if (mu_out != nullptr) *mu_out = mu;
  return tangentialForceAt(slip, speed, fn, mu);
}

}  // namespace tribo::friction
