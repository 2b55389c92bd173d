#include "apps/tradeoff_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/common_options.hpp"
#include "io/scene_parameters.hpp"
#include "study/tradeoff.hpp"

namespace tribo::app {
namespace {

// The cheapest complete, unwarned run per target: by amplitude error alone, and by both
// errors (an amplitude that lands close while the trajectory is off is a fluke).
void printRecommendation(const std::vector<study::TradeoffRow>& rows) {
  for (const bool both : {false, true}) {
    std::printf("\ncheapest complete run without a stability warning, by %s:\n",
                both ? "amplitude and trajectory error" : "amplitude error");
    for (double target : {1e-2, 1e-3, 1e-4}) {
      const study::TradeoffRow* best = study::cheapestRow(rows, target, both);
      if (!best) {
        std::printf("  %-6g none reaches it\n", target);
        continue;
      }
      std::printf(
          "  %-6g %s %s=%g: amplitude error %.2g, trajectory error %.2g, %.3g s cpu "
          "(%.0f simulated s per cpu s)\n",
          target, best->setting.label().c_str(), best->setting.valueName(), best->setting.value(),
          best->amplitude_error, best->trajectory_error, best->cpu, best->simulated / best->cpu);
    }
  }
}

std::vector<IntegratorType> parseIntegrators(const std::string& list) {
  std::vector<IntegratorType> out;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) out.push_back(integratorFromName(name));
  if (out.empty()) throw std::invalid_argument("--integrators: no integrator named");
  return out;
}

// The value of `option`: a number > 0, and a whole one when `whole`.
double positiveNumber(const std::string& option, const std::string& text, bool whole) {
  const auto v = io::parseNumber(text);
  if (!v || !(*v > 0) || (whole && (*v != std::floor(*v) || *v > 1e6)))
    throw std::invalid_argument(option + ": expected a " +
                                (whole ? "whole number from 1 to 1e6" : "positive number") +
                                ", found '" + text + "'");
  return *v;
}

struct TradeoffArguments {
  std::string scene_path, out_dir = "out/tradeoff";
  std::vector<std::string> overrides;
  double window = 10.0;
  int repeat = 1;
  std::vector<IntegratorType> wanted = {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4,
                                        IntegratorType::kDopri5, IntegratorType::kBdf};
};

int runTradeoff(const TradeoffArguments& a) {
  const std::string& scene_path = a.scene_path;
  const std::string& out_dir = a.out_dir;
  study::TradeoffSpec spec;
  spec.scene_path = scene_path;
  spec.overrides = a.overrides;
  spec.integrators = a.wanted;
  spec.window = a.window;
  spec.repeat = a.repeat;
  study::TradeoffResult result;
  bool header = false;
  try {
    result = study::measureTradeoff(
        spec,
        [](const study::TradeoffSetting& ref) {
          std::printf("reference: rk4, dt = %g s\n", ref.step);
          std::fflush(stdout);
        },
        [&](const study::TradeoffRow& o) {
          if (o.status == "reference") {
            std::printf(
                "reference check (dt/2): amplitude %.9g, difference %.2g, trajectory %.2g\n",
                o.amplitude, o.amplitude_error, o.trajectory_error);
            return;
          }
          if (!header) {
            std::printf("%-20s %-9s %-9s %-10s %-10s %-10s %-10s %-11s %s\n", "integrator",
                        "setting", "status", "ampl.err", "traj.err", "wall [s]", "cpu [s]",
                        "sim s/cpu s", "evaluations");
            header = true;
          }
          std::printf("%-20s %-9.3g %-9s %-10.2g %-10.2g %-10.3g %-10.3g %-11.4g %ld\n",
                      o.setting.label().c_str(), o.setting.value(), o.status.c_str(),
                      o.amplitude_error, o.trajectory_error, o.wall, o.cpu, o.simulated / o.cpu,
                      o.evaluations);
          std::fflush(stdout);
        });
  } catch (const study::TradeoffReferenceError& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n", e.what());
    return 2;
  }
  printRecommendation(result.rows);
  const std::filesystem::path file = std::filesystem::path(out_dir) / "tradeoff.csv";
  try {
    study::writeTradeoffCsv(file, std::filesystem::path(scene_path).stem().string(), result.rows);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n", e.what());
    return 4;
  }
  std::printf("results          %s\n", file.string().c_str());
  return 0;
}

}  // namespace

Command addTradeoffCommand(CLI::App& tribo) {
  auto a = std::make_shared<TradeoffArguments>();
  CLI::App* tradeoff = tribo.add_subcommand(
      "tradeoff", "measure each integrator's speed and accuracy against a converged reference");
  addPathArgument(*tradeoff, "SCENE", a->scene_path, "the YAML scene");
  addSetOption(*tradeoff, a->overrides);
  addOutOption(*tradeoff, a->out_dir, "output folder of tradeoff.csv")->capture_default_str();
  addCheckedOption(*tradeoff, "--window", "S",
                   "simulated seconds over which the trajectory error is taken (10)",
                   [a](const std::string& v) { a->window = positiveNumber("--window", v, false); });
  addCheckedOption(*tradeoff, "--repeat", "N",
                   "runs per setting, the least time counts; 1 to 1e6 (1)",
                   [a](const std::string& v) {
                     a->repeat = static_cast<int>(positiveNumber("--repeat", v, true));
                   });
  addCheckedOption(*tradeoff, "--integrators", "A,B,...",
                   "the integrators to measure (semi_implicit_euler,rk4,dopri5,bdf)",
                   [a](const std::string& v) { a->wanted = parseIntegrators(v); });
  tradeoff->footer(
      "Runs every integrator over a ladder of steps or tolerances against a converged reference;\n"
      "writes DIR/tradeoff.csv and prints a table, then the cheapest run reaching each error.\n"
      "exit status: 0 done, 1 usage, 2 bad scene, 3 the reference did not complete, 4 output "
      "error");
  return {tradeoff, [a] { return runTradeoff(*a); }};
}

}  // namespace tribo::app
