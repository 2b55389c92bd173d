// The `tribo` command: parse arguments, load the scene (io), run it (core via io), write
// results, print a short summary. Exit status: 0 success, 1 usage error, 2 bad scene or
// parameters, 3 the run diverged (partial results written and marked so), 4 output error.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/info_command.hpp"
#include "apps/sweep_command.hpp"
#include "apps/tradeoff_command.hpp"
#include "core/constraint_rows.hpp"
#include "io/scene_loader.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "study/result_writer.hpp"
#include "study/scene_run.hpp"

namespace {

constexpr const char* kUsage =
    "usage: tribo run SCENE.yaml --out DIR [--package-path DIR ...] [--set NAME=VALUE ...]\n"
    "       tribo run ROBOT.urdf --out DIR [--package-path DIR ...] [--set NAME=VALUE ...]\n"
    "                [--strict] [--verbose]\n"
    "       tribo info FILE.urdf [--package-path DIR ...] [--strict] [--verbose]\n"
    "       tribo sweep SCENE.yaml --out DIR --grid NAME=START:STOP:COUNT | --list NAME=V1,... "
    "(see tribo sweep --help)\n"
    "       tribo tradeoff SCENE.yaml [--out DIR] (integrators vs a converged reference; "
    "see tribo tradeoff --help)\n"
    "\n"
    "  run     simulate the scene; write DIR/trajectory.csv and DIR/summary.json\n"
    "  --out   output folder (created if missing)\n"
    "  --set   override a value of the scene's parameters: section (repeatable)\n"
    "  info    print a URDF robot's tree, masses, joint types, model checks and what run "
    "would do\n"
    "  --strict   refuse URDF that urdfdom refuses (a joint without <limit>, an undeclared "
    "world)\n"
    "  --verbose  list every note (default: one line per kind, with a count)\n";

int usage(const std::string& problem) {
  std::fprintf(stderr, "tribo: %s\n\n%s", problem.c_str(), kUsage);
  return 1;
}

void printSummary(const tribo::io::Scene& scene, const tribo::study::RunResult& r,
                  const std::filesystem::path& out) {
  const auto& s = r.summary;
  const auto& o = scene.model->options;
  std::printf("scene            %s\n", scene.path.c_str());
  std::printf("integrator       %s, step %g s, %ld steps\n",
              tribo::integratorName(o.integrator).c_str(), o.time_step, r.stats.steps);
  std::printf("status           %s\n",
              r.complete ? "complete" : ("DIVERGED: " + r.message).c_str());
  static const char* kAxis[] = {"x", "y", "z"};
  if (scene.output.summary.body.empty()) {
    std::printf("observed         nothing (the scene's output.summary names no body)\n");
  } else {
    std::printf("observed         %s.%s\n", scene.output.summary.body.c_str(),
                kAxis[scene.output.summary.coordinate]);
    std::printf("oscillating      %s (%zu cycles)\n", s.oscillating ? "yes" : "no",
                s.cycles.size());
    std::printf("amplitude (p-p)  %.6g m\n", s.amplitude_pp);
    std::printf("period           %.6g s\n", s.period);
    std::printf("time to 98%%      %.6g s\n", s.time_to_98);
    std::printf("stuck fraction   %.4g\n", s.stuck_fraction);
  }
  std::printf("max penetration  %.3g m\n", r.stats.max_penetration);
  const auto& limit = r.stability.limit;
  const std::string method = tribo::integratorName(o.integrator);
  if (o.integrator == tribo::IntegratorType::kBdf)
    std::printf("stable step      n/a (%s is implicit: no explicit step limit)\n", method.c_str());
  else if (std::isinf(limit.max_step))
    std::printf(
        "stable step      not estimated (no contact, spring or friction slope bounds it)\n");
  else
    std::printf("stable step     < %.4g s (%s%s)\n", limit.max_step, limit.element.c_str(),
                tribo::isAdaptive(o.integrator) ? "; bounds the internal steps" : "");
  // Joint drift of the Baumgarte-stabilized constraints: position level |Phi| [m or -],
  // velocity level |J v| [m/s or rad/s], the largest over the run.
  if (!tribo::constraintRows(*scene.model).empty())
    std::printf("constraint drift max |Phi| %.2g, max |J v| %.2g\n", r.stats.max_constraint_error,
                r.stats.max_constraint_rate_error);
  std::printf("speed            %.4g simulated s per wall s (%.3g s wall)\n",
              r.simulated_seconds / r.wall_seconds, r.wall_seconds);
  std::printf("results          %s\n", out.string().c_str());
}

int run(const std::vector<std::string>& args) {
  std::string scene_path;
  std::string out_dir;
  std::vector<std::string> overrides;
  std::vector<std::string> package_paths;
  tribo::io::UrdfReadOptions read;
  bool verbose = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--strict" || a == "--verbose") {
      (a == "--strict" ? read.strict : verbose) = true;
    } else if (a == "--out" || a == "--set" || a == "--package-path") {
      if (i + 1 >= args.size()) return usage(a + " needs a value");
      if (a == "--out")
        out_dir = args[++i];
      else if (a == "--set")
        overrides.push_back(args[++i]);
      else
        package_paths.push_back(args[++i]);
    } else if (a.rfind("--", 0) == 0) {
      return usage("unknown option '" + a + "'");
    } else if (scene_path.empty()) {
      scene_path = a;
    } else {
      return usage("more than one scene given ('" + scene_path + "', '" + a + "')");
    }
  }
  if (scene_path.empty()) return usage("no scene file given");
  if (out_dir.empty()) return usage("no output folder given (--out DIR)");

  tribo::io::Scene scene;
  try {
    // A URDF by its content (an XML <robot> root), whatever the extension (.URDF, .xml), or
    // by its name when its content is not even XML (the reader then says what it is).
    std::string ext = std::filesystem::path(scene_path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    scene = tribo::io::looksLikeUrdf(scene_path) || ext == ".urdf"
                ? tribo::io::sceneFromUrdf(scene_path, package_paths, overrides, read)
                : tribo::io::loadScene(scene_path, overrides, package_paths);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 2;
  }
  tribo::app::printGrouped(stderr, "note", scene.notes, verbose);  // before the run: why
  const tribo::study::RunResult result = tribo::study::runScene(scene);
  tribo::app::printGrouped(stderr, "warning", result.warnings, verbose);
  try {
    tribo::study::writeResults(out_dir, scene, result);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 4;
  }
  printSummary(scene, result, out_dir);
  if (!result.complete) {
    std::fprintf(stderr, "tribo: run stopped early: %s\n", result.message.c_str());
    return 3;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage("no command given");
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::printf("%s", kUsage);
    return 0;
  }
  if (args[0] == "run") return run({args.begin() + 1, args.end()});
  if (args[0] == "info") return tribo::app::runInfo({args.begin() + 1, args.end()});
  if (args[0] == "sweep") return tribo::app::sweepCommand({args.begin() + 1, args.end()});
  if (args[0] == "tradeoff") return tribo::app::tradeoffCommand({args.begin() + 1, args.end()});
  return usage("unknown command '" + args[0] + "'");
}
