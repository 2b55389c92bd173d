// The options several `tribo` commands share, each named and explained once: the scene
// argument, --set, --out, --package-path, --threads, --quiet, --strict and --verbose, and
// the way an option whose value is checked as it is read is added. Not here: any command's
// own options, what a command does with the values, or how usage errors are reported
// (apps/usage_error.hpp).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/urdf_reader.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace tribo::app {

// An option that takes one value each time it is given; `apply` gets the value as the
// command line is read, so options that add to one list keep their command-line order.
// What `apply` throws is a usage error with its message (which names the option).
CLI::Option* addCheckedOption(CLI::App& command, const std::string& name,
                              const std::string& value_name, const std::string& description,
                              std::function<void(const std::string&)> apply);

// The file or folder the command works on (required), shown as `name`.
CLI::Option* addPathArgument(CLI::App& command, const std::string& name, std::string& path,
                             const std::string& description);

// --set NAME=VALUE (repeatable): overrides of the scene's parameters: section.
CLI::Option* addSetOption(CLI::App& command, std::vector<std::string>& overrides,
                          const std::string& description =
                              "override a value of the scene's parameters: section (repeatable)");

// --out DIR: the output folder.
CLI::Option* addOutOption(CLI::App& command, std::string& out, const std::string& description);

// --package-path DIR (repeatable): folders holding ROS packages (package:// URIs).
CLI::Option* addPackagePathOption(CLI::App& command, std::vector<std::string>& paths);

// --threads N|auto: threads of one force evaluation, a whole number from 1 to 4096 or auto
// (kAutoThreads).
CLI::Option* addThreadsOption(CLI::App& command, std::optional<int>& threads);

// --quiet: no progress line.
CLI::Option* addQuietOption(CLI::App& command, bool& quiet);

// --strict (URDF read as urdfdom would) and --verbose (every note, not one line per kind).
void addUrdfOptions(CLI::App& command, io::UrdfReadOptions& read, bool& verbose);

}  // namespace tribo::app
