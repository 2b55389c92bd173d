#include "study/sweep/sweep_manifest.hpp"

#include <nlohmann/json.hpp>
#include <optional>

#include "study/sweep/sweep_results.hpp"

namespace tribo::study {

namespace {

using Json = nlohmann::ordered_json;

std::optional<Json> parse(const std::string& text) {
  Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  return j;
}

}  // namespace

ManifestGrid readManifestGrid(const std::string& manifest, const std::string& path) {
  const auto bad = [&](const std::string& why) {
    return SweepOutputError(SweepOutputError::Reason::kOtherSweep,
                            "'" + path + "' is not a sweep description tribo wrote: " + why);
  };
  const auto j = parse(manifest);
  if (!j) throw bad("not a JSON object");
  if (!j->contains("tribo_sweep")) throw bad("no \"tribo_sweep\" entry");
  const auto axes = j->find("axes");
  if (axes == j->end() || !axes->is_array()) throw bad("no \"axes\" list");
  std::vector<SweepAxis> list;
  try {
    for (const auto& a : *axes)
      list.push_back(
          {a.at("name").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
  } catch (const Json::exception&) {
    throw bad("an axis without a name or its values as text");
  }
  SweepAnalysis analysis = SweepAnalysis::kRun;
  if (const auto a = j->find("analysis"); a != j->end()) {
    const auto found = a->is_string() ? kSweepAnalysisNames.find(a->get<std::string>())
                                      : std::optional<SweepAnalysis>();
    if (!found) throw bad("an unknown \"analysis\"");
    analysis = *found;
  }
  try {
    return {SweepGrid(std::move(list)), analysis};
  } catch (const SweepSpecError& e) {
    throw bad(e.what());
  }
}

std::string manifestDifferences(const std::string& a, const std::string& b) {
  const auto ja = parse(a), jb = parse(b);
  if (!ja || !jb) return "the whole file";
  std::string out;
  const auto add = [&](const std::string& key) { out += (out.empty() ? "" : ", ") + key; };
  for (const auto& [key, value] : ja->items())
    if (!jb->contains(key) || (*jb)[key] != value) add(key);
  for (const auto& [key, value] : jb->items())
    if (!ja->contains(key)) add(key);
  return out;
}

}  // namespace tribo::study
