// What each `tribo` command hands main: its subcommand of the CLI11 app (its options and
// generated --help) and the work to do once the command line is parsed, which returns the
// exit status. Not here: parsing, usage errors or any command's work.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace tribo::app {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

}  // namespace tribo::app
