#include "apps/tradeoff_command.hpp"

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

#include "io/scene_parameters.hpp"
#include "study/tradeoff.hpp"

namespace tribo::app {
namespace {

constexpr const char* kUsage =
    "usage: tribo tradeoff SCENE.yaml [--set NAME=VALUE ...] [--out DIR] [--window S]\n"
    "                      [--repeat N] [--integrators A,B,...]\n"
    "  runs every integrator over a ladder of steps or tolerances against a converged\n"
    "  reference; writes DIR/tradeoff.csv (default DIR: out/tradeoff) and prints a table\n";

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

}  // namespace

int tradeoffCommand(const std::vector<std::string>& args) {
  std::string scene_path, out_dir = "out/tradeoff";
  std::vector<std::string> overrides;
  double window = 10.0;
  int repeat = 1;
  std::vector<IntegratorType> wanted = {IntegratorType::kSemiImplicitEuler, IntegratorType::kRk4,
                                        IntegratorType::kDopri5, IntegratorType::kBdf};
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a == "--help" || a == "-h") {
        std::printf("%s", kUsage);
        return 0;
      }
      const bool takes_value = a == "--set" || a == "--out" || a == "--window" || a == "--repeat" ||
                               a == "--integrators";
      if (takes_value && i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      if (a == "--set")
        overrides.push_back(args[++i]);
      else if (a == "--out")
        out_dir = args[++i];
      else if (a == "--window")
        window = positiveNumber(a, args[++i], false);
      else if (a == "--repeat")
        repeat = static_cast<int>(positiveNumber(a, args[++i], true));
      else if (a == "--integrators")
        wanted = parseIntegrators(args[++i]);
      else if (a.rfind("--", 0) == 0)
        throw std::invalid_argument("unknown option '" + a + "'");
      else if (scene_path.empty())
        scene_path = a;
      else
        throw std::invalid_argument("more than one scene given");
    }
    if (scene_path.empty()) throw std::invalid_argument("no scene file given");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo tradeoff: %s\n\n%s", e.what(), kUsage);
    return 1;
  }
  study::TradeoffSpec spec;
  spec.scene_path = scene_path;
  spec.overrides = overrides;
  spec.integrators = wanted;
  spec.window = window;
  spec.repeat = repeat;
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

}  // namespace tribo::app
