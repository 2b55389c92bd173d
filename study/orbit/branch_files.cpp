// A branch's files (orbit_branch.hpp): branch.csv and primary_branch.csv (one row a point),
// branch_orbits.csv (each point's sampled orbit), branch.json (the spec, events, switch and
// stop reason).
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "study/csv_text.hpp"
#include "study/orbit/hopf_start.hpp"
#include "study/orbit/orbit_branch.hpp"

namespace tribo::study {

namespace {

std::string stabilityWord(const BranchPoint& p) {
  return p.undecided ? "undecided" : p.stable ? "stable" : "unstable";
}

std::string pointsCsvText(const std::vector<BranchPoint>& points,
                          const std::vector<BranchEvent>& branch_events) {
  std::string csv =
      "index,parameter,period,amplitude_pp,largest_multiplier,stable,stick_fraction,min_slip,"
      "x_min,x_max,dp_ds,arclength,iterations,residual,trivial_error,steady_growth_rate,"
      "stability,event\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const BranchPoint& p = points[i];
    std::string events;
    for (const BranchEvent& e : branch_events)
      if (e.after == i) {
        if (!events.empty()) events += ';';
        events += branchEventName(e.kind);
      }
    csv += std::to_string(i) + "," + csvNumber(p.parameter, 17) + "," + csvNumber(p.period, 17) +
           "," + csvNumber(p.amplitude_pp, 17) + "," + csvNumber(p.largest, 17) + "," +
           (p.stable ? "1" : "0") + "," + csvNumber(p.stick_fraction, 6) + "," +
           csvNumber(p.min_slip, 6) + "," + csvNumber(p.x_min, 17) + "," + csvNumber(p.x_max, 17) +
           "," + csvNumber(p.dp_ds, 17) + "," + csvNumber(p.arclength, 17) + "," +
           std::to_string(p.iterations) + "," + csvNumber(p.residual, 6) + "," +
           csvNumber(p.trivial_error, 6) + "," + csvNumber(p.steady_growth, 17) + "," +
           stabilityWord(p) + "," + events + "\n";
  }
  return csv;
}

}  // namespace

std::string branchCsvText(const BranchResult& r) { return pointsCsvText(r.points, r.events); }

std::string primaryBranchCsvText(const BranchResult& r) {
  return pointsCsvText(r.primary, r.primary_events);
}

std::string branchOrbitsCsvText(const BranchResult& r) {
  std::string csv = "point,t," + r.observed + "\n";
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.points[i];
    for (std::size_t k = 0; k < p.t.size(); ++k)
      csv += std::to_string(i) + "," + csvNumber(p.t[k], 17) + "," + csvNumber(p.x[k], 17) + "\n";
  }
  return csv;
}

std::string branchJsonText(const std::string& scene_path, const BranchSpec& spec,
                           const BranchResult& r) {
  nlohmann::ordered_json j;
  j["scene"] = scene_path;
  j["parameter"] = spec.parameter;
  j["from"] = spec.from;
  j["to"] = spec.to;
  j["observed"] = r.observed;
  j["status"] = r.reached_end   ? "reached_end"
                : r.lost        ? "lost"
                : r.interrupted ? "interrupted"
                                : "stopped";
  j["stop_reason"] = r.stop_reason;
  j["stick_speed"] = r.stick_speed;
  j["forced"] = r.forced;
  if (r.forced) j["periods"] = r.periods;
  if (spec.from_hopf) {  // where the branch started, located by the modes analysis
    j["start"] = "hopf";
    j["hopf"] = {
        {"parameter", r.hopf_parameter},
        {"omega", r.hopf_omega},
        {"period", 2.0 * std::numbers::pi / r.hopf_omega},
        {"amplitude", spec.hopf_amplitude > 0.0 ? spec.hopf_amplitude : kDefaultHopfAmplitude},
        {"analyses", r.hopf_analyses}};
  } else {
    j["start"] = "orbit";
  }
  if (spec.switch_at != BranchSwitch::kNone) {
    // Where the secondary branch (this one) left the primary (primary_branch.csv).
    j["switch"] = {{"at", branchSwitchName(spec.switch_at)},
                   {"found", r.switched.found},
                   {"primary_points", r.switched.found ? r.primary.size() : r.points.size()}};
    if (r.switched.after > 0) {
      j["switch"]["between"] = {r.switched.before, r.switched.after};
      j["switch"]["evaluations"] = r.switched.evaluations;
    }
    if (r.switched.found) {
      j["switch"]["parameter"] = r.switched.parameter;
      j["switch"]["multiplier"] = {{"re", r.switched.multiplier.real()},
                                   {"im", r.switched.multiplier.imag()}};
      j["switch"]["residual"] = r.switched.residual;
      j["switch"]["primary_period"] = r.switched.period;
      j["switch"]["amplitude"] = r.switched.amplitude;
      nlohmann::ordered_json primary_events = nlohmann::ordered_json::array();
      for (const BranchEvent& e : r.primary_events)
        primary_events.push_back({{"kind", branchEventName(e.kind)},
                                  {"parameter", e.parameter},
                                  {"between", {e.before, e.after}}});
      j["switch"]["primary_events"] = primary_events;
    }
  }
  j["points"] = r.points.size();
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const BranchEvent& e : r.events)
    events.push_back(
        {{"kind", branchEventName(e.kind)},
         {"parameter", e.parameter},
         {"between", {e.before, e.after}},
         {"located", e.before == e.after ? "bracketed past the last point by orbits at fixed "
                                           "parameters"
                                         : "interpolated between the two points"}});
  j["events"] = events;
  nlohmann::ordered_json pts = nlohmann::ordered_json::array();
  for (const BranchPoint& p : r.points) {
    nlohmann::ordered_json mu = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < p.multipliers.size(); ++i)
      if (static_cast<int>(i) != p.trivial)
        mu.push_back({{"re", p.multipliers[i].real()}, {"im", p.multipliers[i].imag()}});
    pts.push_back({{"parameter", p.parameter},
                   {"period", p.period},
                   {"amplitude_pp", p.amplitude_pp},
                   {"stable", p.stable},
                   {"stability", stabilityWord(p)},
                   {"stick_fraction", std::isfinite(p.stick_fraction)
                                          ? nlohmann::ordered_json(p.stick_fraction)
                                          : nlohmann::ordered_json()},
                   {"min_slip", std::isfinite(p.min_slip) ? nlohmann::ordered_json(p.min_slip)
                                                          : nlohmann::ordered_json()},
                   {"trivial_multiplier_error", p.trivial_error},
                   // "return_map": the multipliers are the leading two, estimated
                   // (branch_return_map.hpp); "newton": all, from the monodromy matrix;
                   // "fixed_parameter": the same, at a grazing point's bracket's end
                   // (branch_grazing.hpp).
                   {"method", p.by_return_map     ? "return_map"
                              : p.fixed_parameter ? "fixed_parameter"
                                                  : "newton"},
                   {"steady_growth_rate", std::isfinite(p.steady_growth)
                                              ? nlohmann::ordered_json(p.steady_growth)
                                              : nlohmann::ordered_json()},
                   {"multipliers", mu}});
  }
  j["branch"] = pts;
  j["settings"] = {{"max_points", spec.max_points},
                   {"step", spec.step},
                   {"min_step", spec.min_step},
                   {"max_step", spec.max_step},
                   {"tolerance", spec.orbit.tolerance},
                   {"fd_step", spec.orbit.fd_step},
                   {"arclength_norm", arclengthNormName(spec.norm)},
                   {"return_map", spec.orbit.return_map},
                   {"switch_amplitude", spec.switch_amplitude}};
  // The scaled norm's weights of the period and the parameter (the state's are per entry).
  if (spec.norm == ArclengthNorm::kScaled && r.weights.size() >= 2)
    j["settings"]["weights"] = {{"period", r.weights[r.weights.size() - 2]},
                                {"parameter", r.weights[r.weights.size() - 1]}};
  j["seconds"] = r.seconds;
  return j.dump(2);
}

}  // namespace tribo::study
