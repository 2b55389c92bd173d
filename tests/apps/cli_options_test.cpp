// The `tribo` command line as read by CLI11 (apps/common_options.hpp, apps/usage_error.hpp):
// every command's --help goes to stdout, exits 0 and lists each of its options; an unknown
// option, an unknown command, an option without its value and a bad --threads are usage
// errors (exit 1) naming what is wrong and pointing to --help; --grid and --list given in
// any mix keep their command-line order as the sweep's axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "support/cli_support.hpp"

namespace {

using namespace tribo::test;

class CliOptions : public CliTest {
 protected:
  CliOptions() : CliTest("tribo_cli_options_") {}
  // " --out DIR" for a command that takes --out, else "".
  std::string outFor(const std::string& command) const {
    return command == "info" || command == "view" ? "" : " --out " + (dir_ / "out").string();
  }
};

// Runs `tribo ARGS` with its stderr thrown away: what it prints on stdout only.
Result stdoutOf(const std::string& args) {
  return runCommand("(" + kTribo + " " + args + " 2>/dev/null)");
}

const std::map<std::string, std::vector<std::string>> kOptions = {
    {"run",
     {"SCENE", "--out", "--set", "--package-path", "--quiet", "--progress", "--profile", "--view",
      "--threads", "--strict", "--verbose"}},
    {"info", {"FILE", "--set", "--package-path", "--strict", "--verbose"}},
    {"sweep",
     {"SCENE", "--out", "--grid", "--list", "--set", "--settle", "--settle-every", "--jobs",
      "--keep-trajectories", "--quiet", "--analysis", "--slice", "--merge"}},
    {"tradeoff", {"SCENE", "--set", "--out", "--window", "--repeat", "--integrators"}},
    {"modes",
     {"SCENE", "--out", "--set", "--settle", "--boundary", "--growth-tolerance",
      "--steady-tolerance", "--solver", "--modes"}},
    {"view", {"RUN_DIR", "--frames", "--three", "--package-path"}},
};

TEST_F(CliOptions, EveryCommandsHelpExitsZeroAndListsEachOfItsOptions) {
  for (const auto& [command, options] : kOptions) {
    for (const std::string help : {"--help", "-h"}) {
      const Result r = stdoutOf(command + " " + help);
      EXPECT_EQ(r.status, 0) << command << "\n" << r.output;
      EXPECT_NE(r.output.find("Usage: tribo " + command + " [OPTIONS] " + options.front()),
                std::string::npos)
          << command << "\n"
          << r.output;
      for (const auto& option : options)
        EXPECT_NE(r.output.find("\n  " + option + " "), std::string::npos)
            << command << " " << help << " does not list " << option << "\n"
            << r.output;
      EXPECT_NE(r.output.find("exit status: 0 "), std::string::npos) << command << "\n" << r.output;
    }
  }
  // --help wins over the rest of the line, even a line that would be refused.
  EXPECT_EQ(stdoutOf("sweep " + kBelt + " --help").status, 0);
  EXPECT_EQ(stdoutOf("run --help --frobnicate").status, 0);
}

TEST_F(CliOptions, TopLevelHelpListsTheSixCommandsOneLineEach) {
  for (const std::string help : {"--help", "-h", "help"}) {
    const Result r = stdoutOf(help);
    EXPECT_EQ(r.status, 0) << help << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage: tribo [OPTIONS] SUBCOMMAND"), std::string::npos) << r.output;
    for (const auto& [command, options] : kOptions)
      EXPECT_NE(r.output.find("\n  " + command + " "), std::string::npos)
          << help << " does not list " << command << "\n"
          << r.output;
    EXPECT_EQ(r.output.find("\n  help "), std::string::npos) << r.output;
  }
}

TEST_F(CliOptions, UnknownOptionsAndCommandsAreUsageErrorsNamingThem) {
  const std::string out = outFor("run");
  for (const auto& [command, options] : kOptions) {
    const Result r = runTribo(command + " " + kBelt + outFor(command) + " --frobnicate 3");
    EXPECT_EQ(r.status, 1) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("tribo " + command + ": unknown option '--frobnicate'"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("Run 'tribo " + command + " --help'"), std::string::npos) << r.output;
  }
  struct Case {
    std::string args, expected;
  };
  for (const Case& c :
       {Case{"", "tribo: no command given"}, Case{"fly", "tribo: unknown command 'fly'"},
        Case{"--frobnicate", "tribo: unknown option '--frobnicate'"},
        Case{"run " + kBelt + " " + kBelt + out, "tribo run: unexpected argument '" + kBelt + "'"},
        Case{"sweep" + out + " --grid v_b=1:2:2", "tribo sweep: SCENE is required"},
        Case{"modes " + kBelt, "tribo modes: --out is required"}}) {
    const Result r = runTribo(c.args);
    EXPECT_EQ(r.status, 1) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(CliOptions, AnOptionWithoutItsValueIsAUsageErrorNamingIt) {
  const std::vector<std::string> flags = {"--quiet",  "--progress", "--profile",          "--view",
                                          "--strict", "--verbose",  "--keep-trajectories"};
  for (const auto& [command, options] : kOptions)
    for (const auto& option : options) {
      const bool flag = std::find(flags.begin(), flags.end(), option) != flags.end() ||
                        (command == "modes" && option == "--settle");
      if (option.rfind("--", 0) != 0 || flag) continue;
      const Result r = runTribo(command + " " + kBelt + outFor(command) + " " + option);
      EXPECT_EQ(r.status, 1) << command << " " << option << "\n" << r.output;
      EXPECT_NE(r.output.find("tribo " + command + ": " + option + " needs a value"),
                std::string::npos)
          << command << " " << option << "\n"
          << r.output;
    }
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(CliOptions, BadThreadsAreRefused) {
  for (const std::string bad : {"0", "x", "4097", "1.5", "-2"}) {
    const Result r =
        runTribo("run " + kBelt + " --out " + (dir_ / "out").string() + " --threads " + bad);
    EXPECT_EQ(r.status, 1) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("tribo run: --threads: expected auto or a whole number from 1 to "
                            "4096, found '" +
                            bad + "'"),
              std::string::npos)
        << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_));
}

// The axes of results.csv (after its "point" column) in the order --grid and --list were
// given, however they are mixed; a short run of the belt per point.
TEST_F(CliOptions, GridAndListKeepTheirCommandLineOrder) {
  const std::string quick =
      " --set duration=0.05 --set dt=0.005 --set output_interval=0.01 --jobs 1 --quiet";
  struct Case {
    std::string axes, columns;
  };
  for (const Case& c :
       {Case{"--grid v_b=1:2:2 --list mu_s=0.33,0.4 --grid k=300:310:2", "point,v_b,mu_s,k,"},
        Case{"--list mu_s=0.33,0.4 --grid k=300:310:2 --grid v_b=1:2:2", "point,mu_s,k,v_b,"},
        Case{"--grid k=300:310:2 --list v_b=1,2 --list mu_s=0.33,0.4", "point,k,v_b,mu_s,"}}) {
    const fs::path out = dir_ / std::to_string(std::hash<std::string>{}(c.axes));
    const Result r = runTribo("sweep " + kBelt + " " + c.axes + " --out " + out.string() + quick);
    ASSERT_EQ(r.status, 0) << c.axes << "\n" << r.output;
    const std::string csv = slurp(out / "results.csv");
    EXPECT_EQ(csv.rfind(c.columns, 0), 0u) << c.axes << "\n" << csv.substr(0, csv.find('\n'));
    EXPECT_EQ(lines(out / "results.csv"), 1 + 8) << c.axes;
  }
}

}  // namespace
