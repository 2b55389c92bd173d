#include "apps/usage_error.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <vector>

namespace tribo::app {
namespace {

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// The problem to report for `error`, in the words tribo uses: an argument nobody takes is an
// unknown option (or command), and an option given without its value (CLI11: "NAME: N
// required TYPE missing") needs a value.
std::string problemOf(const CLI::App& tribo, const CLI::App* command,
                      const CLI::ParseError& error) {
  const std::vector<std::string> extra = tribo.remaining(true);
  if (!extra.empty() && (!command || dynamic_cast<const CLI::ExtrasError*>(&error))) {
    const std::string& first = extra.front();
    if (first.rfind('-', 0) == 0) return "unknown option '" + first + "'";
    return command ? "unexpected argument '" + first + "'" : "unknown command '" + first + "'";
  }
  if (!command && dynamic_cast<const CLI::RequiredError*>(&error)) return "no command given";
  const std::string what = error.what();
  const auto colon = what.find(": ");
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) && colon != std::string::npos &&
      endsWith(what, " missing"))
    return what.substr(0, colon) + " needs a value";
  return what;
}

}  // namespace

int usageError(const CLI::App& command, const std::string& problem) {
  const bool top = command.get_parent() == nullptr;
  const std::string name = top ? command.get_name() : "tribo " + command.get_name();
  std::fprintf(stderr, "%s: %s\nRun '%s --help' for %s.\n", name.c_str(), problem.c_str(),
               name.c_str(), top ? "the commands" : "its usage and options");
  return 1;
}

int reportParseError(const CLI::App& tribo, const CLI::ParseError& error) {
  if (error.get_exit_code() == 0) {  // --help
    std::printf("%s", tribo.help().c_str());
    return 0;
  }
  const std::vector<CLI::App*> chosen = tribo.get_subcommands();
  const CLI::App* command = chosen.empty() ? nullptr : chosen.front();
  return usageError(command ? *command : tribo, problemOf(tribo, command, error));
}

}  // namespace tribo::app
