#include "apps/common_options.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <utility>

#include "core/thread_count.hpp"
#include "io/scene_parameters.hpp"

namespace tribo::app {

CLI::Option* addCheckedOption(CLI::App& command, const std::string& name,
                              const std::string& value_name, const std::string& description,
                              std::function<void(const std::string&)> apply) {
  auto checked = [apply = std::move(apply)](const std::string& value) {
    try {
      apply(value);
    } catch (const CLI::Error&) {
      throw;
    } catch (const std::exception& e) {
      throw CLI::ValidationError(e.what());
    }
  };
  return command.add_option_function<std::string>(name, std::move(checked), description)
      ->type_name(value_name)
      ->allow_extra_args(false)
      ->trigger_on_parse();
}

CLI::Option* addPathArgument(CLI::App& command, const std::string& name, std::string& path,
                             const std::string& description) {
  return command.add_option(name, path, description)->type_name("")->required();
}

CLI::Option* addSetOption(CLI::App& command, std::vector<std::string>& overrides,
                          const std::string& description) {
  return command.add_option("--set", overrides, description)
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
}

CLI::Option* addOutOption(CLI::App& command, std::string& out, const std::string& description) {
  return command.add_option("--out", out, description)->type_name("DIR");
}

CLI::Option* addPackagePathOption(CLI::App& command, std::vector<std::string>& paths) {
  return command
      .add_option("--package-path", paths,
                  "a folder holding ROS packages, for package:// paths (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
}

CLI::Option* addThreadsOption(CLI::App& command, std::optional<int>& threads) {
  return addCheckedOption(
      command, "--threads", "N|auto",
      "threads of one force evaluation, 1 to 4096 (replaces the scene's simulation.threads;\n"
      "auto: one per core where the scene is large enough; results do not depend on it)",
      [&threads](const std::string& value) {
        const auto n = io::parseNumber(value);
        if (value == "auto")
          threads = kAutoThreads;
        else if (n && *n >= 1 && *n <= 4096 && *n == std::floor(*n))
          threads = static_cast<int>(*n);
        else
          throw std::invalid_argument(
              "--threads: expected auto or a whole number from 1 to 4096, found '" + value + "'");
      });
}

CLI::Option* addQuietOption(CLI::App& command, bool& quiet) {
  return command.add_flag("--quiet", quiet, "never show the progress line");
}

void addUrdfOptions(CLI::App& command, io::UrdfReadOptions& read, bool& verbose) {
  command.add_flag("--strict", read.strict,
                   "refuse URDF that urdfdom refuses (a joint without <limit>, an undeclared "
                   "world)");
  command.add_flag("--verbose", verbose,
                   "list every note (default: one line per kind, with a count)");
}

}  // namespace tribo::app
