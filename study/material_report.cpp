#include "study/material_report.hpp"

#include <cstdio>
#include <utility>

#include "contact/normal_law.hpp"

namespace tribo::study {

namespace {

std::string format(const char* pattern, auto... values) {
  char buf[512];
  std::snprintf(buf, sizeof buf, pattern, values...);
  return buf;
}

// Rolling and spinning (contact/rolling_resistance.hpp), each null when absent.
std::pair<const friction::ElasticStickLaw*, const char*> parts(const contact::Material& m, int i) {
  return i == 0 ? std::pair{m.resistance.rolling.get(), "rolling"}
                : std::pair{m.resistance.spinning.get(), "spinning"};
}

}  // namespace

nlohmann::json materialJson(const contact::Material& m) {
  nlohmann::json material = {{"normal_law", contact::normalLawName(m.normal.type)},
                             {"stiffness", m.normal.stiffness},
                             {"damping", m.normal.damping},
                             {"friction_law", std::string(m.friction->name())}};
  // The depth exponent of the nonlinear laws (hertz: always 3/2), and where recurdyn's
  // damping is full.
  if (m.normal.type == contact::NormalLawType::kHertz) material["exponent"] = 1.5;
  if (m.normal.type == contact::NormalLawType::kHuntCrossley ||
      m.normal.type == contact::NormalLawType::kRecurDyn)
    material["exponent"] = m.normal.exponent;
  if (m.normal.type == contact::NormalLawType::kRecurDyn)
    material["max_depth"] = m.normal.max_depth;
  // The limit surface: its principal axis (unit) in the frame geometry and the ratios along
  // and across it, per sense.
  if (const contact::Anisotropy& an = m.anisotropy; an.active)
    material["anisotropy"] = {{"frame", an.frame_is_b ? "b" : "a"},
                              {"axis", {an.axis.x(), an.axis.y(), an.axis.z()}},
                              {"forward", {an.forward[0], an.forward[1]}},
                              {"backward", {an.backward[0], an.backward[1]}}};
  // The moment per newton of load [m] (mu_r; mu_spin r_c) and the angular stick spring.
  for (int i = 0; i < 2; ++i) {
    const auto [part, key] = parts(m, i);
    if (part == nullptr) continue;
    const friction::ElasticStickParams& p = part->params();
    material[key] = {{"limit", p.mu_s},
                     {"stiffness", p.stiffness},
                     {"damping", p.damping},
                     {"stick_speed", p.stick_speed}};
  }
  return material;
}

std::vector<std::string> describeMaterial(const contact::Material& m) {
  std::vector<std::string> lines;
  lines.push_back(format("normal %s, stiffness %g, damping %g; friction %s",
                         contact::normalLawName(m.normal.type).c_str(), m.normal.stiffness,
                         m.normal.damping, std::string(m.friction->name()).c_str()));
  if (const contact::Anisotropy& an = m.anisotropy; an.active)
    lines.push_back(format(
        "anisotropy: axis (%g, %g, %g) fixed in geometry %s; limit surface: along the axis %g mu "
        "forward, %g mu backward; across it %g mu forward, %g mu backward (the law sees the "
        "slip scaled by these ratios)",
        an.axis.x(), an.axis.y(), an.axis.z(), an.frame_is_b ? "b" : "a", an.forward[0],
        an.backward[0], an.forward[1], an.backward[1]));
  for (int i = 0; i < 2; ++i) {
    const auto [part, key] = parts(m, i);
    if (part == nullptr) continue;
    const friction::ElasticStickParams& p = part->params();
    lines.push_back(format(
        "%s: holds up to %g m times the normal load (%s), angular spring "
        "%g N m/rad, damping %g N m s/rad, re-sticks below %g rad/s",
        key, p.mu_s, i == 0 ? "mu_r" : "mu_spin r_c", p.stiffness, p.damping, p.stick_speed));
  }
  return lines;
}

}  // namespace tribo::study
