#include "study/modes/modes_report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "study/csv_text.hpp"
#include "study/file_commit.hpp"

namespace tribo::study {

namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

nlohmann::json modeJson(const Mode& m, bool shape) {
  nlohmann::json j = {{"eigenvalue", {number(m.eigenvalue.real()), number(m.eigenvalue.imag())}},
                      {"frequency_hz", number(m.frequency)},
                      {"growth_rate", number(m.growth_rate)},
                      {"damping_ratio", number(m.damping_ratio)},
                      {"unstable", m.unstable},
                      {"dominant", m.dominant}};
  if (shape) {
    nlohmann::json s = nlohmann::json::array();
    for (const ShapeEntry& e : m.shape)
      s.push_back({{"coordinate", e.coordinate},
                   {"magnitude", number(e.magnitude)},
                   {"phase_deg", number(e.phase_deg)}});
    j["shape"] = s;
  }
  return j;
}

}  // namespace

std::string modesJsonText(const io::Scene& scene, const ModesResult& r) {
  const Model& model = *scene.model;
  nlohmann::json j;
  j["scene"] = scene.path;
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [name, value] : scene.parameters) params[name] = value;
  j["parameters"] = params;
  j["stable"] = r.unstable_count == 0;
  j["unstable_count"] = r.unstable_count;
  j["leading"] = modeJson(r.leading(), false);
  nlohmann::json bodies = nlohmann::json::array();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].kind != BodyKind::kDynamic) continue;
    const BodyState& s = r.steady.state.bodies[b];
    bodies.push_back(
        {{"name", model.bodies[b].name},
         {"position", {s.position.x(), s.position.y(), s.position.z()}},
         {"orientation_wxyz",
          {s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z()}}});
  }
  j["steady_state"] = {{"bodies", bodies},
                       {"newton_iterations", r.steady.iterations},
                       {"residual", r.steady.residual},
                       {"settled_for", r.steady.settled_for}};
  j["linearization"] = {{"coordinates", r.coordinates},
                        {"states", 2 * r.coordinates},
                        {"position_step", r.steps.position},
                        {"velocity_step", r.steps.velocity},
                        {"step_check_disagreement", r.worst_disagreement}};
  j["eigensolver"] = {{"method", r.solver.method},
                      {"modes_requested", r.solver.requested},
                      {"shifts", r.solver.shifts},
                      {"eigenvalues_found", r.solver.found},
                      {"band_top", r.solver.band_top},
                      {"strip", r.solver.strip},
                      {"worst_residual", r.solver.worst_residual},
                      {"sparse_factorization", r.solver.sparse_factorization},
                      {"operations", r.solver.operations}};
  j["warnings"] = r.warnings;
  j["notes"] = scene.notes;
  j["timing"] = {{"steady_state_s", r.steady_seconds},
                 {"linearization_and_eigenvalues_s", r.linearize_seconds},
                 {"evaluations", r.evaluations}};
  nlohmann::json modes = nlohmann::json::array();
  for (const Mode& m : r.modes) modes.push_back(modeJson(m, true));
  j["modes"] = modes;
  return j.dump(2);
}

void writeModesJson(const std::filesystem::path& file, const io::Scene& scene,
                    const ModesResult& result) {
  writeFileWhole(file, modesJsonText(scene, result) + "\n");
}

void writeModesCsv(const std::filesystem::path& file, const ModesResult& r) {
  std::vector<std::string> header = {"mode",     "frequency_hz", "growth_rate", "damping_ratio",
                                     "eigen_re", "eigen_im",     "unstable",    "dominant"};
  for (const ShapeEntry& e : r.leading().shape) header.push_back(e.coordinate);
  std::string text = csvLine(header);
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const Mode& m = r.modes[i];
    std::vector<std::string> row = {std::to_string(i + 1),          csvNumber(m.frequency),
                                    csvNumber(m.growth_rate),       csvNumber(m.damping_ratio),
                                    csvNumber(m.eigenvalue.real()), csvNumber(m.eigenvalue.imag()),
                                    m.unstable ? "1" : "0",         m.dominant};
    for (const ShapeEntry& e : m.shape) row.push_back(csvNumber(e.magnitude, 6));
    text += csvLine(row);
  }
  writeFileWhole(file, text);
}

void writeBoundaryJson(const std::filesystem::path& file, const BoundarySpec& spec,
                       const BoundaryResult& r) {
  nlohmann::json j = {{"scene", spec.scene_path},
                      {"overrides", spec.overrides},
                      {"parameter", spec.parameter},
                      {"search", {spec.lo, spec.hi}},
                      {"critical", r.critical},
                      {"bracket", {r.lo, r.hi}},
                      {"unstable_side", r.unstable_above ? "above" : "below"},
                      {"growth_at_search_ends", {r.growth_lo, r.growth_hi}},
                      {"frequency_at_onset_hz", r.frequency_unstable},
                      {"growth_tolerance", spec.modes.growth_tolerance},
                      {"analyses", r.analyses}};
  writeFileWhole(file, j.dump(2) + "\n");
}

}  // namespace tribo::study
