// The `tribo` command: reads the command line with CLI11 (each command adds its options and
// help, apps/*_command.hpp) and hands over to the command named. Exit status: the command's
// (each header says which), 1 for a usage error, 0 for --help.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <vector>

#include "apps/command.hpp"
#include "apps/info_command.hpp"
#include "apps/modes_command.hpp"
#include "apps/orbit_command.hpp"
#include "apps/run_command.hpp"
#include "apps/sweep_command.hpp"
#include "apps/tradeoff_command.hpp"
#include "apps/usage_error.hpp"
#include "apps/view_command.hpp"

int main(int argc, char** argv) {
  namespace app = tribo::app;
  CLI::App tribo("Tribo: rigid multibody dynamics with swappable friction laws", "tribo");
  // An option given twice: the last one counts (lists such as --set take every one).
  tribo.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  tribo.require_subcommand(1);
  tribo.footer("Run 'tribo COMMAND --help' for a command's options.");
  const std::vector<app::Command> commands = {
      app::addRunCommand(tribo),      app::addInfoCommand(tribo),  app::addSweepCommand(tribo),
      app::addTradeoffCommand(tribo), app::addModesCommand(tribo), app::addOrbitCommand(tribo),
      app::addViewCommand(tribo)};
  // `tribo help`: the same as `tribo --help` (not listed).
  CLI::App* help = tribo.add_subcommand("help", "")->group("");
  try {
    tribo.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app::reportParseError(tribo, e);
  }
  for (const app::Command& c : commands)
    if (c.app->parsed()) return c.run();
  if (help->parsed()) {
    std::printf(
        "%s",
        tribo.get_formatter()->make_help(&tribo, "tribo", CLI::AppFormatMode::Normal).c_str());
    return 0;
  }
  return app::usageError(tribo, "no command given");
}
