// How `tribo` reports a usage error (exit status 1): "tribo COMMAND: PROBLEM" and a pointer to
// the command's --help on stderr; and how what the CLI11 parser throws becomes either that or,
// for --help, the generated help on stdout (exit status 0). Not here: the options themselves
// (apps/common_options.hpp and each command's file).
#pragma once

#include <string>

namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace tribo::app {

// Prints the usage error `problem` of `command` (the top-level app or one of its commands)
// and returns 1.
int usageError(const CLI::App& command, const std::string& problem);

// Reports `error`, thrown by `tribo.parse`: the help asked for (returns 0) or a usage error
// (returns 1), naming an unknown option or command, or the option that lacks its value.
int reportParseError(const CLI::App& tribo, const CLI::ParseError& error);

}  // namespace tribo::app
