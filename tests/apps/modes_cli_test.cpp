// `tribo modes` end to end: the exit status scripts branch on (8 unstable, 0 stable, 9 no
// steady state, 2 bad scene, 1 usage), the files it writes (modes.json whole and parseable,
// modes.csv one row per mode), and --boundary's boundary.json. The figures themselves are
// checked at library level (tests/study/modes_test.cpp, mode_coupling_test.cpp).
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/chain_on_belt.hpp"
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

// --solver sparse and --solver dense on a chain of 10 boxes (40 states): the same leading mode
// (the dense solver is the reference; 1e-8 relative: both solvers' backward errors are ~1e-13
// of ||A|| ~ 1e6 and the leading pair is well separated), and the solver named in modes.json.
TEST_F(ModesCli, SparseAndDenseSolversGiveTheSameLeadingMode) {
  fs::create_directories(dir_);
  const fs::path scene = dir_ / "chain.yaml";
  std::ofstream(scene) << chainOnBelt(10, "roh_yoo", 0.5);
  const Result dense =
      runTribo("modes " + scene.string() + " --solver dense --out " + (dir_ / "dense").string());
  const Result sparse = runTribo("modes " + scene.string() + " --solver sparse --modes 4 --out " +
                                 (dir_ / "sparse").string());
  EXPECT_EQ(dense.status, 8) << dense.output;  // the in-phase modes grow
  EXPECT_EQ(sparse.status, 8) << sparse.output;
  const auto d = nlohmann::json::parse(slurp(dir_ / "dense" / "modes.json"));
  const auto s = nlohmann::json::parse(slurp(dir_ / "sparse" / "modes.json"));
  EXPECT_EQ(d["eigensolver"]["method"], "dense");
  EXPECT_EQ(s["eigensolver"]["method"], "sparse");
  EXPECT_EQ(s["modes"].size(), 4u);
  const double dr = d["leading"]["eigenvalue"][0].get<double>();
  const double di = d["leading"]["eigenvalue"][1].get<double>();
  const double sr = s["leading"]["eigenvalue"][0].get<double>();
  const double si = s["leading"]["eigenvalue"][1].get<double>();
  EXPECT_LE(std::hypot(dr - sr, di - si), 1e-8 * std::hypot(dr, di));
}

TEST_F(ModesCli, BadSolverAndZeroModesAreUsageErrors) {
  const Result bad = runTribo("modes " + kBelt + " --solver fast --out " + dir_.string());
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find("--solver: expected auto, dense or sparse"), std::string::npos)
      << bad.output;
  const Result zero = runTribo("modes " + kBelt + " --modes 0 --out " + dir_.string());
  EXPECT_EQ(zero.status, 1);
  EXPECT_NE(zero.output.find("--modes"), std::string::npos) << zero.output;
  EXPECT_EQ(runTribo("modes " + kBelt + " --modes 2.5 --out " + dir_.string()).status, 1);
  // The belt's 4 states are too few for the sparse solver: refused, not guessed.
  EXPECT_EQ(runTribo("modes " + kBelt + " --solver sparse --out " + dir_.string()).status, 2);
}

}  // namespace
}  // namespace tribo::test
