#include "apps/info_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "apps/common_options.hpp"
#include "core/stability.hpp"
#include "io/output_channels.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_source.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_scene.hpp"
#include "study/material_report.hpp"

namespace tribo::app {

namespace {

// The link tree, one line per link, indented by depth; walked with a stack of its own, as a
// chain of links is as deep as it is long.
void printTree(const io::UrdfRobot& r) {
  std::map<std::string, std::vector<const io::UrdfJoint*>> children;
  for (const auto& j : r.joints) children[j.parent].push_back(&j);
  std::map<std::string, const io::UrdfLink*> links;
  for (const auto& l : r.links) links.emplace(l.name, &l);
  struct Visit {
    std::string link;
    int depth;
    const io::UrdfJoint* via;
  };
  std::vector<Visit> stack{{r.root, 0, nullptr}};
  while (!stack.empty()) {
    const Visit v = stack.back();
    stack.pop_back();
    const auto found = links.find(v.link);
    const io::UrdfLink* l = found == links.end() ? nullptr : found->second;
    // Indented by depth up to kIndentDepth; deeper links say their depth instead (a chain of
    // n links would print n^2 spaces).
    constexpr int kIndentDepth = 32;
    std::string line(static_cast<std::size_t>(2 * std::min(v.depth, kIndentDepth) + 2), ' ');
    if (v.depth > kIndentDepth) line += "[depth " + std::to_string(v.depth) + "] ";
    line += v.link;
    if (v.via) line += "  [" + v.via->type + " '" + v.via->name + "']";
    char mass[64];
    if (l && l->has_inertial)
      std::snprintf(mass, sizeof mass, "  %.6g kg", l->mass);
    else
      std::snprintf(mass, sizeof mass, "  (no inertial)");
    line += mass;
    if (l && !l->collisions.empty())
      line += "  " + std::to_string(l->collisions.size()) + " collision";
    std::printf("%s\n", line.c_str());
    const auto& below = children[v.link];
    for (auto j = below.rbegin(); j != below.rend(); ++j)
      stack.push_back({(*j)->child, v.depth + 1, *j});
  }
}

// A note's kind: its text with quoted names and numbers set aside.
std::string kindOf(const std::string& line) {
  std::string kind;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '\'') {
      quoted = !quoted;
      if (quoted) kind += "'*'";
      continue;
    }
    if (quoted) continue;
    const bool digit = (c >= '0' && c <= '9') || ((c == '-' || c == '.') && i + 1 < line.size() &&
                                                  line[i + 1] >= '0' && line[i + 1] <= '9');
    if (digit) {
      if (kind.empty() || kind.back() != '#') kind += '#';
      continue;
    }
    kind += c;
  }
  return kind;
}

}  // namespace

void printGrouped(std::FILE* out, const char* label, const std::vector<std::string>& lines,
                  bool verbose) {
  if (verbose) {
    for (const auto& l : lines) std::fprintf(out, "tribo: %s: %s\n", label, l.c_str());
    return;
  }
  std::vector<std::pair<std::string, int>> kinds;  // first line of each kind, count
  std::map<std::string, std::size_t> index;
  for (const auto& l : lines) {
    const auto [it, fresh] = index.try_emplace(kindOf(l), kinds.size());
    if (fresh)
      kinds.emplace_back(l, 1);
    else
      ++kinds[it->second].second;
  }
  for (const auto& [first, count] : kinds) {
    if (count == 1)
      std::fprintf(out, "tribo: %s: %s\n", label, first.c_str());
    else
      std::fprintf(out, "tribo: %s: %s (and %d more like it; --verbose lists them)\n", label,
                   first.c_str(), count - 1);
  }
}

namespace {

struct InfoArguments {
  std::string file;
  std::vector<std::string> overrides;  // --set, a scene file only
  std::vector<std::string> package_paths;
  io::UrdfReadOptions read;
  bool verbose = false;
};

// A scene file (.yaml, .yml, and not a <robot> document, which is read as URDF whatever its
// name, as run does: io/scene_source.hpp): what it holds and what run would do, with each
// material's laws, limit surface and rolling and spinning thresholds, and the pairs that use it.
bool isSceneFile(const std::string& file) {
  if (io::isUrdfScene(file)) return false;
  std::string ext = std::filesystem::path(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".yaml" || ext == ".yml";
}

int runSceneInfo(const InfoArguments& a) {
  io::Scene scene;
  try {
    scene = io::loadScene(a.file, a.overrides, a.package_paths);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 2;
  }
  const Model& model = *scene.model;
  std::printf("scene '%s'\n", scene.path.c_str());
  std::printf("bodies %zu (%d dynamic), joints %zu, loads %zu, contacts: ", model.bodies.size(),
              model.dynamicBodyCount(), model.joints.size(), model.loads.size());
  if (model.automatic_contacts)  // every two geometries that may touch: not listed (quadratic)
    std::printf("automatic, among %zu geometries\n", model.geometries.size());
  else
    std::printf("%zu listed pair%s\n", model.contact_pairs.size(),
                model.contact_pairs.size() == 1 ? "" : "s");
  const auto& o = model.options;
  const StabilityReport stability = estimateStableStep(model);
  std::printf("run: %s, step %g s, duration %g s\n", integratorName(o.integrator).c_str(),
              o.time_step, o.duration);
  if (std::isinf(stability.limit.max_step))
    std::printf("stable step: no explicit limit\n");
  else
    std::printf("stable step: < %.4g s (%s)\n", stability.limit.max_step,
                stability.limit.element.c_str());
  // Materials in model order, each with the listed pairs that use it (the first few by name).
  constexpr std::size_t kNamedPairs = 4;
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    std::vector<std::string> users;
    std::size_t count = 0;
    for (const ContactPair& p : model.contact_pairs)
      if (static_cast<std::size_t>(p.material) == i && count++ < kNamedPairs)
        users.push_back(io::pairName(model, p));
    std::string used;
    for (const std::string& u : users) used += (used.empty() ? "" : ", ") + u;
    if (count > users.size()) used += " (+" + std::to_string(count - users.size()) + " more)";
    if (model.automatic_contacts)
      std::printf("material %zu:\n", i);
    else
      std::printf("material %zu (%zu pair%s%s%s):\n", i, count, count == 1 ? "" : "s",
                  used.empty() ? "" : ": ", used.c_str());
    for (const std::string& line : study::describeMaterial(model.materials[i]))
      std::printf("  %s\n", line.c_str());
  }
  std::fflush(stdout);
  printGrouped(stdout, "note", scene.notes, a.verbose);
  printGrouped(stdout, "note", stability.notes, a.verbose);
  return 0;
}

int runInfo(const InfoArguments& a) {
  if (isSceneFile(a.file)) return runSceneInfo(a);
  const std::string& file = a.file;
  const std::vector<std::string>& package_paths = a.package_paths;
  const io::UrdfReadOptions& read = a.read;
  const bool verbose = a.verbose;
  io::UrdfRobot robot;
  try {
    robot = io::readUrdf(file, io::PackagePaths::withEnvironment(package_paths), read);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tribo: %s\n", e.what());
    return 2;
  }
  std::map<std::string, int> by_type;
  for (const auto& j : robot.joints) ++by_type[j.type];
  std::string types;
  for (const auto& [t, n] : by_type)
    types += (types.empty() ? "" : ", ") + std::to_string(n) + " " + t;
  std::printf("robot '%s' (%s)\n", robot.name.c_str(), robot.path.c_str());
  std::printf("links %zu, joints %zu%s%s%s, total mass %.6g kg\n", robot.links.size(),
              robot.joints.size(), types.empty() ? "" : " (", types.c_str(),
              types.empty() ? "" : ")", robot.totalMass());
  std::printf("tree:\n");
  printTree(robot);
  int errors = 0;
  for (const auto& i : robot.issues) errors += i.severity == io::UrdfIssue::Severity::kError;
  std::printf("checks: %s\n", errors ? "" : "no errors");
  for (const auto& i : robot.issues)
    if (i.severity == io::UrdfIssue::Severity::kError)
      std::printf("  error: %s: %s\n", i.where.c_str(), i.message.c_str());
  if (errors) return 2;
  // The scene `tribo run FILE` would build, with its notes (the reader's included).
  io::Scene scene;
  try {
    scene = io::sceneFromUrdf(file, package_paths, {}, read);
  } catch (const std::exception& e) {
    std::printf("run: refused: %s\n", e.what());
    return 2;
  }
  const auto& o = scene.model->options;
  const StabilityReport stability = estimateStableStep(*scene.model);
  std::string k, points;
  for (const auto& [name, value] : scene.parameters) {
    if (name == "stiffness") k = value;
    if (name == "support_points") points = value;
  }
  std::printf("run: %s, step %g s, contact stiffness %s N/m on %s support points\n",
              integratorName(o.integrator).c_str(), o.time_step, k.c_str(), points.c_str());
  if (std::isinf(stability.limit.max_step))
    std::printf("stable step: no explicit limit\n");
  else
    std::printf("stable step: < %.4g s (%s)\n", stability.limit.max_step,
                stability.limit.element.c_str());
  std::fflush(stdout);
  printGrouped(stdout, "note", scene.notes, verbose);
  printGrouped(stdout, "note", stability.notes, verbose);
  return 0;
}

}  // namespace

Command addInfoCommand(CLI::App& tribo) {
  auto a = std::make_shared<InfoArguments>();
  CLI::App* info = tribo.add_subcommand(
      "info",
      "print a URDF robot's tree, masses, joint types, model checks and what run would do; or a "
      "scene's bodies, materials (laws, limit surfaces, rolling and spinning thresholds) and "
      "stable step");
  addPathArgument(*info, "FILE", a->file, "the URDF file (FILE.urdf) or a scene (FILE.yaml)");
  addSetOption(*info, a->overrides,
               "override a value of a scene's parameters: section (repeatable; a scene only)");
  addPackagePathOption(*info, a->package_paths);
  addUrdfOptions(*info, a->read, a->verbose);
  info->footer(
      "A file that passes info does not fail tribo run at load.\n"
      "exit status: 0 the robot or scene can be simulated, 1 usage, 2 the file or a check is an "
      "error");
  return {info, [a] { return runInfo(*a); }};
}

}  // namespace tribo::app
