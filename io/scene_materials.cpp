// Scene reader (io/scene_reader.hpp): friction laws (read with the scene, built when a
// material or a joint selects one), materials and their normal laws, listed contacts.
#include <algorithm>
#include <array>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>

#include "contact/normal_law.hpp"
#include "friction/tabulated_law.hpp"
#include "io/friction_curve.hpp"
#include "io/scene_expression.hpp"
#include "io/scene_keys.hpp"
#include "io/scene_reader.hpp"

namespace tribo::io::scene_detail {

namespace {

// The value of a law entry that is an expression over parameters, or nothing when the text
// is not one (an option's word, a file name with '/' or '-').
std::optional<double> expressionValue(const Value& value, const std::string& text) {
  if (!looksLikeExpression(text)) return std::nullopt;
  try {
    return value.number();
  } catch (const SceneError&) {
    return std::nullopt;
  }
}

}  // namespace

// The friction law an entry of friction_laws names, built on first use.
std::shared_ptr<const friction::FrictionLaw> Loader::frictionLaw(const Value& name) {
  const auto it = laws_.find(name.text());
  if (it == laws_.end()) {
    if (const auto user = user_laws_.find(name.text()); user != user_laws_.end()) {
      uses_user_law_ = true;
      return user->second;
    }
    Keys defined = law_names_;
    for (const auto& [user_name, law] : user_laws_) defined.push_back(user_name);
    name.fail("friction law '" + name.text() +
              "' is not defined in friction_laws (defined: " + joined(defined) + ")");
  }
  LawEntry& law = it->second;
  if (!law.law && law.spec.name == "tabulated") law.law = tabulatedLaw(law, name);
  if (!law.law) {
    try {
      law.law = friction::makeFrictionLaw(law.spec);
    } catch (const friction::FrictionParameterError& e) {
      law.at.fail(std::string(e.what()) + " (selected by " + name.path() + ")");
    }
  }
  return law.law;
}

// The `tabulated` law: its only key `file`, a CSV curve relative to the scene file
// (io/friction_curve.hpp); rule violations are reported at the curve's line.
std::shared_ptr<const friction::FrictionLaw> Loader::tabulatedLaw(const LawEntry& law,
                                                                  const Value& selected_by) {
  for (const auto& [key, value] : law.spec.values)
    law.at.fail("tabulated: unknown key '" + key + "' (accepted keys: file)");
  for (const auto& [key, value] : law.spec.options)
    if (key != "file") law.at.fail("tabulated: unknown key '" + key + "' (accepted keys: file)");
  const auto file = law.spec.options.find("file");
  if (file == law.spec.options.end())
    law.at.fail("tabulated: missing required key 'file' (a CSV of speed, coefficient)");
  std::filesystem::path path = file->second;
  if (path.is_relative()) path = std::filesystem::path(file_).parent_path() / path;
  const FrictionCurve curve = readFrictionCurve(path.string());
  try {
    return std::make_shared<friction::TabulatedLaw>(curve.speeds, curve.coefficients);
  } catch (const friction::TabulatedPointError& e) {
    throw SceneError({path.string(), curve.lines[e.point], 0}, "",
                     std::string(e.what()) + " (selected by " + selected_by.path() + ")");
  } catch (const friction::FrictionParameterError& e) {
    law.at.fail(std::string(e.what()) + " (selected by " + selected_by.path() + ")");
  }
}

// Reads every law entry (known law name, scalar values, resolvable references) but builds
// only the laws a material selects (readMaterial), so that values out of range for a law
// that is not used are no error: e.g. `--set a=0.5` while the materials use recurdyn.
// Key names are checked by makeFrictionLaw, and so also only for the laws in use.
// An entry is a law by its own name (`coulomb: {mu: 0.3}`), or an instance of the law its
// `law:` key names (`steel: {law: coulomb, mu: 0.3}`), so two materials can use two
// parameter sets of one law.
void Loader::readFrictionLaws(const Value& v) {
  Keys known = friction::knownFrictionLaws();
  for (const auto& name : friction::knownStatefulFrictionLaws()) known.push_back(name);
  for (const auto& name : friction::knownDynamicFrictionLaws()) known.push_back(name);
  known.push_back("tabulated");  // built here from its file (tabulatedLaw)
  const auto isLaw = [&](const std::string& name) {
    return std::find(known.begin(), known.end(), name) != known.end();
  };
  const Map laws(v, {});
  for (const auto& [name, entry] : laws.entries()) {
    const Map keys(entry, {});
    const std::optional<Value> law_key = keys.get("law");
    const std::string law = law_key ? law_key->text() : name;
    if (law_key && !isLaw(law))
      law_key->fail("unknown friction law '" + law + "' (known laws: " + joined(known) + ")");
    if (!law_key && !isLaw(name))
      entry.fail("unknown friction law '" + name + "' (known laws: " + joined(known) +
                 "; to name an instance of a law, give it: " + name + ": {law: coulomb, mu: 0.3})");
    if (law_key && isLaw(name) && name != law)
      law_key->fail("the entry '" + name + "' is named after a law but is a " + law +
                    ": give this instance another name");
    if (user_laws_.count(name))
      entry.fail("friction law '" + name +
                 "' is defined both here and by the caller (a law given in Python): rename one");
    LawEntry e{entry, {law, {}, {}}, nullptr};
    for (const auto& [key, value] : keys.entries()) {
      if (key == "law") continue;
      if (!value.node().IsScalar())
        value.fail("expected a number or a string, found " + value.found());
      const std::string text = value.text();
      if (const auto number = parseNumber(text)) {
        e.spec.values[key] = *number;
      } else if (const auto result = expressionValue(value, text)) {
        e.spec.values[key] = *result;  // e.g. theta0: $theta with theta: '$d_c / $v'
      } else {
        e.spec.options[key] = text;  // a word: an option, or a file name
      }
    }
    law_names_.push_back(name);
    laws_.emplace(name, std::move(e));
  }
}

void Loader::readMaterial(const Value& v) {
  const Map m(v, scene_keys::kMaterial);
  const Value name_value = m.required("name");
  const std::string name = name_value.text();
  if (materials_.count(name)) name_value.fail("material '" + name + "' defined twice");
  contact::Material material;
  if (auto n = m.get("normal")) material.normal = readNormalLaw(*n);
  material.friction = frictionLaw(m.required("friction"));
  if (auto a = m.get("anisotropy")) material.anisotropy = readAnisotropy(*a);
  if (auto r = m.get("rolling")) material.resistance.rolling = readAngularStick(*r, false);
  if (auto s = m.get("spinning")) material.resistance.spinning = readAngularStick(*s, true);
  const int index = guarded(v, [&] { return builder_.addMaterial(material); });
  materials_[name] = index;
  material_values_[name] = material;
  if (auto d = m.get("default"); d && d->flag()) {
    if (!default_material_.empty())
      d->fail("material '" + default_material_ + "' is already the default");
    default_material_ = name;
    builder_.setDefaultMaterial(index);
  }
  if (auto list = m.get("surfaces")) {
    for (const Value& item : list->items("surface pairs [a, b]")) {
      if (!item.node().IsSequence() || item.node().size() != 2)
        item.fail("expected a surface pair [a, b], found " + item.found());
      const auto both = item.items("surface names");
      const std::string a = both[0].text(), b = both[1].text();
      guarded(item, [&] { builder_.addSurfacePairMaterial(a, b, index); });
      surface_pairs_.insert({std::min(a, b), std::max(a, b)});
    }
  }
}

// Direction-dependent ratios of the material's law (contact/anisotropy.hpp); the axis is a
// direction, normalised.
contact::Anisotropy Loader::readAnisotropy(const Value& v) {
  const Map m(v, scene_keys::kAnisotropy);
  contact::Anisotropy an;
  an.active = true;
  if (auto f = m.get("frame")) an.frame_is_b = f->choice(scene_keys::kFrameSides) == 1;
  an.axis = m.vec3("axis", Vec3::UnitX());
  auto ratios = [](const Value& x) {
    const auto r = x.numbers({2}, "2 ratios [along the axis, across it]");
    for (double value : r)
      if (!(value > 0.0))  // NaN too
        x.fail("expected 2 ratios > 0 [along the axis, across it], found " + x.found());
    return std::array<double, 2>{r[0], r[1]};
  };
  if (auto r = m.get("ratio")) an.forward = an.backward = ratios(*r);
  if (auto b = m.get("backward")) an.backward = ratios(*b);
  guarded(v, [&] { an.validate(); });
  return an;
}

// Rolling resistance (length) or spinning friction (mu times radius) with its angular stick
// spring (contact/rolling_resistance.hpp).
std::shared_ptr<const friction::ElasticStickLaw> Loader::readAngularStick(const Value& v,
                                                                          bool spinning) {
  const Map m(v, spinning ? scene_keys::kSpinning : scene_keys::kRolling);
  contact::AngularStickParams p;
  if (spinning)
    p.limit = m.required("mu").positive() * m.required("radius").positive();
  else
    p.limit = m.required("length").positive();
  p.stiffness = m.required("stiffness").positive();
  if (auto c = m.get("damping")) p.damping = c->nonNegative();
  if (auto s = m.get("stick_speed")) p.stick_speed = s->positive();
  return guarded(v, [&] { return contact::angularStick(p, spinning ? "spinning" : "rolling"); });
}

contact::NormalLaw Loader::readNormalLaw(const Value& v) {
  const Map m(v, scene_keys::kNormal);
  contact::NormalLaw law;
  if (auto x = m.get("law"))
    law.type = guarded(*x, [&] { return contact::normalLawFromName(x->text()); });
  const std::string name = contact::normalLawName(law.type);
  auto only = [&](const char* key, std::initializer_list<contact::NormalLawType> types,
                  const std::string& which) {
    const auto x = m.get(key);
    if (x && std::find(types.begin(), types.end(), law.type) == types.end())
      x->fail(std::string(key) + " applies to law " + which + " only (this law is " + name + ")");
    return x;
  };
  using T = contact::NormalLawType;
  if (auto x = m.get("stiffness")) law.stiffness = x->number();
  if (auto x = only("damping", {T::kLinear, T::kHuntCrossley, T::kRecurDyn},
                    "linear, hunt_crossley or recurdyn"))
    law.damping = x->number();
  if (auto x = only("exponent", {T::kHuntCrossley, T::kRecurDyn}, "hunt_crossley or recurdyn"))
    law.exponent = x->number();
  if (auto x = only("max_depth", {T::kRecurDyn}, "recurdyn")) law.max_depth = x->number();
  const auto e = only("restitution", {T::kHuntCrossley}, "hunt_crossley");
  const auto speed = only("impact_speed", {T::kHuntCrossley}, "hunt_crossley");
  if (e || speed) {
    // alpha from the exact Hunt-Crossley restitution relation (contact/normal_law.hpp).
    if (!e || !speed) v.fail("restitution and impact_speed go together");
    if (m.get("damping")) v.fail("give damping or restitution, not both");
    law.damping =
        guarded(*e, [&] { return contact::huntCrossleyDamping(e->number(), speed->positive()); });
  }
  guarded(v, [&] { law.validate(); });
  return law;
}

void Loader::readContact(const Value& v) {
  const Map m(v, scene_keys::kContact);
  auto geometry = [&](const Value& g) {
    const auto index = builder_.findGeometry(g.text());
    if (!index)
      g.fail("unknown geometry '" + g.text() + "' (known geometries: " + joined(geometry_names_) +
             ")");
    return *index;
  };
  const int a = geometry(m.required("a"));
  const int b = geometry(m.required("b"));
  const Value mat = m.required("material");
  const auto it = materials_.find(mat.text());
  if (it == materials_.end()) {
    Keys known;
    for (const auto& [name, index] : materials_) known.push_back(name);
    mat.fail("unknown material '" + mat.text() + "' (known materials: " + joined(known) + ")");
  }
  guarded(v, [&] { builder_.addContactPair(a, b, it->second); });
}

}  // namespace tribo::io::scene_detail
