#include "study/result_writer.hpp"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "core/constraint_solver.hpp"
#include "study/csv_text.hpp"
#include "study/early_growth.hpp"
#include "study/file_commit.hpp"
#include "study/material_report.hpp"
#include "study/orbit_shape.hpp"
#include "study/output_stride.hpp"

namespace tribo::study {

namespace {

// JSON has no NaN or infinity: a non-finite figure is written as null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

nlohmann::json stepStatsJson(const StepStats& stats) {
  return {{"steps", stats.steps},
          {"max_penetration", stats.max_penetration},
          {"max_constraint_error", stats.max_constraint_error},
          {"max_constraint_rate_error", stats.max_constraint_rate_error},
          {"integrator_steps", stats.integrator_steps},
          {"rejected_steps", stats.rejected_steps},
          {"force_evaluations", stats.evaluations},
          {"most_threads", stats.most_threads},
          {"threaded_steps", stats.threaded_steps},
          {"events", stats.events},
          {"joint_friction_unconverged_steps", stats.joint_friction_unconverged},
          {"joint_held_steps", stats.joint_held},
          {"joint_held_largest_change", stats.joint_held_change}};
}

}  // namespace

TrajectoryCsvFile::TrajectoryCsvFile(const std::filesystem::path& file,
                                     const std::vector<std::string>& columns, int digits)
    : file_(file), digits_(digits) {
  const auto tmp = partialPath(file);
  f_ = std::fopen(tmp.c_str(), "w");
  if (!f_) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
  std::setvbuf(f_, nullptr, _IOFBF, std::size_t{1} << 16);
  for (std::size_t c = 0; c < columns.size(); ++c)
    std::fprintf(f_, "%s%s", c ? "," : "", columns[c].c_str());
  std::fputc('\n', f_);
}

TrajectoryCsvFile::~TrajectoryCsvFile() {
  if (f_) std::fclose(f_);
}

void TrajectoryCsvFile::row(std::span<const double> values) {
  // The row's text first, then one write: a stdio call a number and one a comma took 18 % of a
  // 1600-box run's samples on one thread, and 28 % on `threads: auto`, where stdio also locks
  // the file at every call (the work team's helpers are a second thread; docs/performance.md).
  constexpr std::size_t kField = 64;  // a number's text, with room to spare
  line_.resize(values.size() * (kField + 1) + 1);
  char* p = line_.data();
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (c) *p++ = ',';
    p = csvNumberTo(p, p + kField, values[c], digits_);
  }
  *p++ = '\n';
  std::fwrite(line_.data(), 1, static_cast<std::size_t>(p - line_.data()), f_);
}

void TrajectoryCsvFile::commit() {
  const auto tmp = partialPath(file_);
  const bool ok = std::ferror(f_) == 0;
  const bool closed = std::fclose(f_) == 0;
  f_ = nullptr;
  if (!closed || !ok) throw std::runtime_error("error writing '" + tmp.string() + "'");
  commitFile(file_);
}

void writeTrajectoryCsv(const std::filesystem::path& file, const TrajectoryRecorder& trajectory,
                        int digits) {
  if (!trajectory.keepsRows())
    throw std::logic_error("writeTrajectoryCsv: the recorder kept no rows (they were streamed)");
  TrajectoryCsvFile csv(file, trajectory.columns(), digits);
  std::vector<double> row(trajectory.columns().size());
  for (std::size_t r = 0; r < trajectory.rows(); ++r) {
    for (std::size_t c = 0; c < row.size(); ++c) row[c] = trajectory.column(c)[r];
    csv.row(row);
  }
  csv.commit();
}

std::string summaryJsonText(const io::Scene& scene, const RunResult& result) {
  const Model& model = *scene.model;
  const SimulationOptions& o = model.options;
  nlohmann::json j;
  j["status"] = runStatusName(result);
  if (!result.complete && !result.interrupted) {
    j["error"] = result.message;
    // Where the run stopped: the trajectory ends at the last good state before this time.
    j["stopped_at"] = {
        {"time", result.stop.time}, {"body", result.stop.body}, {"quantity", result.stop.quantity}};
  }
  j["warnings"] = result.warnings;
  j["scene"] = scene.path;
  j["notes"] = scene.notes;
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [name, value] : scene.parameters) params[name] = value;
  j["parameters"] = params;
  j["settings"] = {{"integrator", integratorName(o.integrator)},
                   {"time_step", o.time_step},
                   {"duration", o.duration},
                   {"baumgarte_alpha", o.baumgarte_alpha},
                   {"baumgarte_beta", o.baumgarte_beta},
                   {"output_interval", outputInterval(scene.output.interval, o.time_step)}};
  nlohmann::json materials = nlohmann::json::array();
  for (const auto& m : model.materials) materials.push_back(materialJson(m));
  j["settings"]["materials"] = materials;
  if (isAdaptive(o.integrator)) {
    j["settings"]["relative_tolerance"] = o.relative_tolerance;
    j["settings"]["absolute_tolerance"] = o.absolute_tolerance;
    j["settings"]["max_internal_step"] = o.max_internal_step;
    j["settings"]["event_location"] = o.event_location;
  }
  {
    const ConstraintOptions& c = o.constraints;
    const int equations = model.constraint_equations;
    j["settings"]["constraints"] = {
        {"equations", equations},
        {"factorization", useSparseFactorization(c, equations) ? "sparse" : "dense"},
        {"projection", c.projection},
        {"projection_tolerance", c.projection_tolerance},
        {"projection_iterations", c.projection_iterations},
        {"redundant", c.redundant == RedundancyPolicy::kRemove ? "remove" : "error"}};
  }
  j["stability"] = {{"estimated_max_step", number(result.stability.limit.max_step)},
                    {"limiting_element", result.stability.limit.element},
                    {"notes", result.stability.notes}};
  const auto& s = result.summary;
  static const char* kAxis[] = {"x", "y", "z"};
  const auto& spec = scene.output.summary;
  j["observed"] = {
      {"body", spec.body},
      {"channel", spec.channel.empty() ? spec.body + "." + kAxis[spec.coordinate] : spec.channel},
      {"coordinate", kAxis[spec.coordinate]},
      {"stick_speed", spec.stick_speed}};
  j["channels"] = scene.output.channels;
  j["oscillating"] = s.oscillating;
  j["amplitude_pp"] = number(s.amplitude_pp);
  j["period"] = number(s.period);
  j["time_to_98"] = number(s.time_to_98);
  j["stuck_fraction"] = number(s.stuck_fraction);
  j["mean"] = number(s.x_mean);
  j["cycles_found"] = s.cycles.size();
  j["cycles_used"] = s.cycles_used;
  if (const EarlyGrowth g = earlyGrowth(s.cycles); g.measured)
    j["early_growth"] = {{"rate", g.rate},
                         {"first_cycle", g.first_cycle + 1},
                         {"cycles", g.cycles},
                         {"t_start", g.t_start},
                         {"t_end", g.t_end},
                         {"scatter", g.scatter},
                         {"period_spread", g.period_spread},
                         {"trustworthy", g.trustworthy},
                         {"doubt", g.doubt}};
  const OrbitShape orbit = classifyOrbit(s.cycles);
  j["orbit"] = {{"kind", orbitKindName(orbit.kind)},
                {"cycles_examined", orbit.examined},
                {"peak_to_peak", {number(orbit.peak_to_peak_a), number(orbit.peak_to_peak_b)}},
                {"period", {number(orbit.duration_a), number(orbit.duration_b)}},
                {"spread", number(orbit.spread)}};
  // Each cycle's figures, the last kListedCycles of them (a long run makes thousands).
  constexpr std::size_t kListedCycles = 100;
  nlohmann::json listed = nlohmann::json::array();
  for (std::size_t i = s.cycles.size() > kListedCycles ? s.cycles.size() - kListedCycles : 0;
       i < s.cycles.size(); ++i) {
    const Cycle& c = s.cycles[i];
    listed.push_back({{"index", i + 1},
                      {"t_start", number(c.t_start)},
                      {"period", number(c.t_end - c.t_start)},
                      {"peak_to_peak", number(c.peak_to_peak)},
                      {"mean", number(c.mean)}});
  }
  j["cycles"] = listed;
  j["run"] = stepStatsJson(result.stats);
  j["run"]["simulated_seconds"] = result.simulated_seconds;
  j["run"]["wall_seconds"] = result.wall_seconds;
  j["run"]["simulated_seconds_per_wall_second"] =
      number(result.simulated_seconds / result.wall_seconds);
  return j.dump(2);
}

std::string stepStatsJsonText(const StepStats& stats) { return stepStatsJson(stats).dump(); }

void writeSummaryJson(const std::filesystem::path& file, const io::Scene& scene,
                      const RunResult& result) {
  const std::string text = summaryJsonText(scene, result);
  const auto tmp = partialPath(file);
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
    out << text << '\n';
    if (!out) throw std::runtime_error("error writing '" + tmp.string() + "'");
  }
  commitFile(file);
}

void writeResults(const std::filesystem::path& dir, const io::Scene& scene,
                  const RunResult& result) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw std::runtime_error("cannot create output folder '" + dir.string() + "': " + ec.message());
  writeTrajectoryCsv(dir / "trajectory.csv", result.trajectory, scene.output.digits);
  writeSummaryJson(dir / "summary.json", scene, result);
}

}  // namespace tribo::study
