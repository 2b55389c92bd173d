#include "io/output_channels.hpp"

#include <algorithm>

#include "friction/dynamic_law.hpp"

namespace tribo::io {

namespace {

struct Group {
  const char* name;
  std::vector<const char*> suffixes;  // per body; empty for the joint and energy groups
};

const std::vector<Group>& bodyGroups() {
  static const std::vector<Group> groups = {
      {"position", {".x", ".y", ".z"}},
      {"orientation", {".qw", ".qx", ".qy", ".qz"}},
      {"rpy", {".roll", ".pitch", ".yaw"}},
      {"velocity", {".vx", ".vy", ".vz"}},
      {"angular_velocity", {".wx", ".wy", ".wz"}},
      {"contact", {".slip", ".normal_force"}},
      {"friction", {".friction_force"}},
      {"resistance", {".resisting_moment"}},  // rolling and spinning (|sum of moments|)
  };
  return groups;
}

}  // namespace

const std::vector<std::string>& knownChannelGroups() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Group& g : bodyGroups()) n.emplace_back(g.name);
    n.emplace_back("pairs");
    n.emplace_back("pair_resistance");
    n.emplace_back("joints");
    n.emplace_back("friction_states");
    n.emplace_back("energy");
    n.emplace_back("loads");
    n.emplace_back("actuators");
    return n;
  }();
  return names;
}

const std::vector<std::string>& defaultChannelGroups() {
  static const std::vector<std::string> names = {"position", "velocity", "contact"};
  return names;
}

std::string pairName(const Model& model, const ContactPair& p) {
  return model.geometries[static_cast<std::size_t>(p.geometry_a)].name + "/" +
         model.geometries[static_cast<std::size_t>(p.geometry_b)].name;
}

bool hasGroup(const std::vector<std::string>& groups, std::string_view group) {
  return std::find(groups.begin(), groups.end(), group) != groups.end();
}

std::vector<std::string> channelColumns(const Model& model,
                                        const std::vector<std::string>& groups) {
  std::vector<std::string> names = {"t"};
  for (const Body& b : model.bodies)
    for (const Group& g : bodyGroups())
      if (hasGroup(groups, g.name))
        for (const char* suffix : g.suffixes) names.push_back(b.name + suffix);
  const PairSlots slots = hasGroup(groups, "pairs") || hasGroup(groups, "pair_resistance") ||
                                  hasGroup(groups, "friction_states")
                              ? PairSlots(model)
                              : PairSlots();
  if (hasGroup(groups, "pairs"))
    for (const ContactPair& p : slots.pairs())
      for (const char* suffix : {".normal_force", ".friction_force", ".slip"})
        names.push_back(pairName(model, p) + suffix);
  if (hasGroup(groups, "pair_resistance"))
    for (const ContactPair& p : slots.pairs())
      for (const char* suffix : {".mu_slip", ".resisting_moment"})
        names.push_back(pairName(model, p) + suffix);
  if (hasGroup(groups, "joints"))
    for (const Joint& j : model.joints)
      if (hasScalarCoordinate(j.type))
        for (const char* suffix : {".q", ".rate", ".friction"}) names.push_back(j.name + suffix);
  if (hasGroup(groups, "friction_states")) {
    auto add = [&](const std::string& owner, const friction::FrictionLaw& law) {
      if (const friction::DynamicFrictionLaw* d = law.dynamic())
        for (int i = 0; i < d->stateSize(); ++i) names.push_back(owner + "." + d->stateName(i));
    };
    for (const Joint& j : model.joints)
      if (hasScalarCoordinate(j.type) && j.elements.friction)
        add(j.name, *j.elements.friction->law);
    for (const ContactPair& p : slots.pairs())
      add(pairName(model, p), *model.materials[static_cast<std::size_t>(p.material)].friction);
  }
  if (hasGroup(groups, "energy"))
    for (const char* e :
         {"energy.kinetic", "energy.gravity", "energy.elastic", "energy.input_power"})
      names.emplace_back(e);
  if (hasGroup(groups, "loads"))
    for (const AppliedLoad& l : model.loads)
      for (const char* suffix : {".fx", ".fy", ".fz"}) names.push_back(l.name + suffix);
  if (hasGroup(groups, "actuators"))
    for (const Joint& j : model.joints)
      if (const auto& a = j.elements.actuator)
        for (const char* suffix : {".target", ".effort", ".saturated"})
          names.push_back(a->name + suffix);
  return names;
}

std::string channelUnit(const Model& model, std::string_view column) {
  if (column == "t") return "s";
  const std::size_t dot = column.rfind('.');
  if (dot == std::string_view::npos) return "";
  const std::string_view owner = column.substr(0, dot), part = column.substr(dot + 1);
  if (owner == "energy") return part == "input_power" ? "W" : "J";
  for (const Joint& j : model.joints) {
    const auto& a = j.elements.actuator;
    if (!a || a->name != owner) continue;
    const bool turns = j.type == JointType::kRevolute;
    if (part == "effort" || (part == "target" && a->kind == ActuatorKind::kMotor))
      return turns ? "N m" : "N";
    if (part == "target" && a->kind == ActuatorKind::kPositionServo) return turns ? "rad" : "m";
    if (part == "target") return turns ? "rad/s" : "m/s";
    return "";  // saturated: 0 or 1
  }
  for (const Joint& j : model.joints) {
    if (j.name != owner || (j.type != JointType::kRevolute && j.type != JointType::kPrismatic))
      continue;
    const bool turns = j.type == JointType::kRevolute;
    if (part == "q") return turns ? "rad" : "m";
    if (part == "rate") return turns ? "rad/s" : "m/s";
    if (part == "friction") return turns ? "N m" : "N";
    return "";  // a friction state
  }
  static const std::pair<std::string_view, const char*> kParts[] = {{"x", "m"},
                                                                    {"y", "m"},
                                                                    {"z", "m"},
                                                                    {"roll", "rad"},
                                                                    {"pitch", "rad"},
                                                                    {"yaw", "rad"},
                                                                    {"vx", "m/s"},
                                                                    {"vy", "m/s"},
                                                                    {"vz", "m/s"},
                                                                    {"wx", "rad/s"},
                                                                    {"wy", "rad/s"},
                                                                    {"wz", "rad/s"},
                                                                    {"slip", "m/s"},
                                                                    {"normal_force", "N"},
                                                                    {"friction_force", "N"},
                                                                    {"resisting_moment", "N m"},
                                                                    {"fx", "N"},
                                                                    {"fy", "N"},
                                                                    {"fz", "N"}};
  // A pair's state names (A/B.z.x) hold a dot of their own: only body and pair columns here.
  if (owner.find('.') != std::string_view::npos) return "";
  for (const auto& [name, unit] : kParts)
    if (part == name) return unit;
  return "";
}

}  // namespace tribo::io
