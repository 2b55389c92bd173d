// `tribo orbit` end to end: the exit status scripts branch on (0 a stable orbit, 11 no orbit,
// 2 bad scene, 1 usage), the files it writes (orbit.json whole, its period and amplitude
// those orbit.csv shows: the samples span one period and return to the start). The figures
// themselves are checked at library level (tests/study/periodic_orbit_test.cpp).
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_support.hpp"

namespace tribo::test {
namespace {

class OrbitCli : public CliTest {
 protected:
  OrbitCli() : CliTest("tribo_orbit_cli_") {}
};

TEST_F(OrbitCli, TheBeltsStableOrbitExitsZeroAndWritesBothFiles) {
  const Result r = runTribo("orbit " + kBelt + " --set duration=30 --out " + dir_.string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("stable"), std::string::npos) << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "orbit.json"));
  EXPECT_TRUE(j["stable"].get<bool>());
  EXPECT_EQ(j["observed"].get<std::string>(), "box.x");
  const double period = j["period"].get<double>();
  EXPECT_EQ(j["multipliers"].size(), 12u);
  // orbit.csv: t from 0 to the period, x back where it started, its range the amplitude's.
  std::ifstream csv(dir_ / "orbit.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "t,box.x");
  double t = 0, x = 0, x0 = NAN, lo = 1e9, hi = -1e9;
  char comma = 0;
  while (std::getline(csv, line)) {
    std::istringstream(line) >> t >> comma >> x;
    if (std::isnan(x0)) x0 = x;
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  EXPECT_NEAR(t, period, 1e-12);
  EXPECT_NEAR(x, x0, 1e-7);
  EXPECT_NEAR(hi - lo, j["amplitude_pp"].get<double>(), 1e-5);  // the minimum is refined
  EXPECT_FALSE(fs::exists(dir_ / "orbit.json.partial"));
}

TEST_F(OrbitCli, NoOrbitElevenBadSceneTwoUsageOne) {
  const Result none =
      runTribo("orbit " + kBelt + " --set v_b=0 --set duration=3 --out " + dir_.string());
  EXPECT_EQ(none.status, 11) << none.output;
  EXPECT_NE(none.output.find("no oscillation"), std::string::npos) << none.output;
  EXPECT_EQ(runTribo("orbit " + kBelt + " --set nosuch=1 --out " + dir_.string()).status, 2);
  EXPECT_EQ(runTribo("orbit " + kBelt).status, 1);
  EXPECT_EQ(runTribo("orbit " + kBelt + " --out " + dir_.string() + " --settle -1").status, 1);
}

}  // namespace
}  // namespace tribo::test
