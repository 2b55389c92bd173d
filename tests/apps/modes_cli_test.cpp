// `tribo modes` end to end: the exit status scripts branch on (8 unstable, 0 stable, 9 no
// steady state, 2 bad scene, 1 usage), the files it writes (modes.json whole and parseable,
// modes.csv one row per mode), and --boundary's boundary.json. The figures themselves are
// checked at library level (tests/study/modes_test.cpp, mode_coupling_test.cpp).
#include <nlohmann/json.hpp>

#include "support/cli_support.hpp"

namespace tribo::test {
namespace {

class ModesCli : public CliTest {
 protected:
  ModesCli() : CliTest("tribo_modes_cli_") {}
};

const std::string kCoupling = std::string(TRIBO_SOURCE_DIR) + "/scenes/mode_coupling.yaml";

TEST_F(ModesCli, UnstableBeltExitsEightAndWritesBothFiles) {
  const Result r = runTribo("modes " + kBelt + " --out " + dir_.string());
  EXPECT_EQ(r.status, 8) << r.output;
  EXPECT_NE(r.output.find("UNSTABLE"), std::string::npos) << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "modes.json"));
  EXPECT_FALSE(j["stable"].get<bool>());
  EXPECT_EQ(j["unstable_count"].get<int>(), 1);
  EXPECT_EQ(j["modes"].size(), 2u);  // x pair and z pair of the planar box
  EXPECT_EQ(lines(dir_ / "modes.csv"), 3);
  EXPECT_FALSE(fs::exists(dir_ / "modes.json.partial"));
}

TEST_F(ModesCli, StableExitsZeroNoSteadyStateNineBadSceneTwoUsageOne) {
  // coulomb on the belt with no friction slope and no damping is neutral (growth 0): stable.
  EXPECT_EQ(runTribo("modes " + kBelt + " --set friction=coulomb --out " + dir_.string()).status,
            0);
  const Result none = runTribo("modes " + kBelt + " --set k=0 --out " + dir_.string());
  EXPECT_EQ(none.status, 9) << none.output;
  EXPECT_NE(none.output.find("box.x"), std::string::npos) << none.output;
  EXPECT_EQ(runTribo("modes " + kBelt + " --set nosuch=1 --out " + dir_.string()).status, 2);
  EXPECT_EQ(runTribo("modes " + kBelt).status, 1);
  EXPECT_EQ(runTribo("modes " + kBelt + " --out " + dir_.string() + " --boundary mu").status, 1);
}

TEST_F(ModesCli, BoundaryWritesTheCriticalValue) {
  const Result r =
      runTribo("modes " + kCoupling + " --out " + dir_.string() + " --boundary mu=0.4:0.8");
  EXPECT_EQ(r.status, 0) << r.output;  // mu = 0.5 is below the boundary
  const auto j = nlohmann::json::parse(slurp(dir_ / "boundary.json"));
  EXPECT_EQ(j["parameter"], "mu");
  EXPECT_EQ(j["unstable_side"], "above");
  const double c = j["critical"].get<double>();
  EXPECT_GT(c, 0.5);
  EXPECT_LT(c, 0.7);
  // A bracket without a crossing is a bad parameter.
  EXPECT_EQ(
      runTribo("modes " + kCoupling + " --out " + dir_.string() + " --boundary mu=0.1:0.3").status,
      2);
}

}  // namespace
}  // namespace tribo::test
