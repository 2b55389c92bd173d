#include "apps/info_command.hpp"

#include <cstdio>
#include <functional>
#include <map>

#include "io/urdf_reader.hpp"

namespace tribo::app {

namespace {

void printTree(const io::UrdfRobot& r) {
  std::map<std::string, std::vector<const io::UrdfJoint*>> children;
  for (const auto& j : r.joints) children[j.parent].push_back(&j);
  std::function<void(const std::string&, int, const io::UrdfJoint*)> visit =
      [&](const std::string& link, int depth, const io::UrdfJoint* via) {
        const io::UrdfLink* l = r.findLink(link);
        std::string line(static_cast<std::size_t>(2 * depth + 2), ' ');
        line += link;
        if (via) line += "  [" + via->type + " '" + via->name + "']";
        char mass[64];
        if (l && l->has_inertial)
          std::snprintf(mass, sizeof mass, "  %.6g kg", l->mass);
        else
          std::snprintf(mass, sizeof mass, "  (no inertial)");
        line += mass;
        if (l && !l->collisions.empty())
          line += "  " + std::to_string(l->collisions.size()) + " collision";
        std::printf("%s\n", line.c_str());
        for (const auto* j : children[link]) visit(j->child, depth + 1, j);
      };
  visit(r.root, 0, nullptr);
}

}  // namespace

int runInfo(const std::vector<std::string>& args) {
  std::string file;
  std::vector<std::string> package_paths;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--package-path") {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "tribo: --package-path needs a folder\n");
        return 1;
      }
      package_paths.push_back(args[++i]);
    } else if (file.empty()) {
      file = args[i];
    } else {
      std::fprintf(stderr, "tribo: info takes one URDF file\n");
      return 1;
    }
  }
  if (file.empty()) {
    std::fprintf(stderr, "usage: tribo info FILE.urdf [--package-path DIR ...]\n");
    return 1;
  }
  io::UrdfRobot robot;
  try {
    robot = io::readUrdf(file, io::PackagePaths::withEnvironment(package_paths));
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
  std::printf("checks: %s\n", robot.issues.empty() ? "no findings" : "");
  for (const auto& i : robot.issues)
    std::printf("  %s: %s: %s\n",
                i.severity == io::UrdfIssue::Severity::kError ? "error" : "warning",
                i.where.c_str(), i.message.c_str());
  return robot.hasErrors() ? 2 : 0;
}

}  // namespace tribo::app
