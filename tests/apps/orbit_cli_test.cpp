// `tribo orbit` end to end: the exit status scripts branch on (0 a stable orbit, 11 no orbit,
// 2 bad scene, 1 usage), the files it writes (orbit.json whole, its period and amplitude
// those orbit.csv shows: the samples span one period and return to the start). The figures
// themselves are checked at library level (tests/study/periodic_orbit_test.cpp). With
// --continue: branch.csv's columns and rows, branch.json's events, the usage errors, and a
// SIGINT that ends the branch with its points written.
#include <signal.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <vector>

#include "support/cli_support.hpp"
#include "support/process_support.hpp"

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
  // The orbit at half the step (study/orbit/step_check.hpp; its figures are checked in
  // tests/study/step_check_test.cpp): printed and in orbit.json, its change the step's.
  const auto& check = j["step_check"];
  EXPECT_EQ(check["setting"].get<std::string>(), "time_step");
  EXPECT_EQ(check["value"].get<double>(), 0.0005);
  EXPECT_TRUE(check["converged"].get<bool>());
  EXPECT_NEAR(check["period"].get<double>() - period, check["period_change"].get<double>(), 1e-15);
  EXPECT_GT(std::abs(check["period_change"].get<double>()), 1e-9);
  EXPECT_NE(r.output.find("step check       at time_step 0.0005: period "), std::string::npos)
      << r.output;
  const Result unchecked =
      runTribo("orbit " + kBelt + " --set duration=30 --no-step-check --out " + dir_.string());
  EXPECT_EQ(unchecked.status, 0) << unchecked.output;
  EXPECT_FALSE(nlohmann::json::parse(slurp(dir_ / "orbit.json")).contains("step_check"));
  EXPECT_EQ(unchecked.output.find("step check"), std::string::npos) << unchecked.output;
}

TEST_F(OrbitCli, AForcedSceneGivesTheForcingsPeriodAndRefusesContinuation) {
  const std::string forced = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
  const Result r = runTribo("orbit " + forced + " --out " + dir_.string() + " --periods 2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 x the forcing's 0.8333333333 s (load 'shaker' force x varies"),
            std::string::npos)
      << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "orbit.json"));
  EXPECT_TRUE(j["forced"].get<bool>());
  EXPECT_EQ(j["periods"].get<int>(), 2);
  EXPECT_NEAR(j["period"].get<double>(), 2 / 1.2, 1e-12);  // f = 1.2 Hz in the scene
  EXPECT_FALSE(j.contains("trivial_multiplier_error"));
  for (const auto& mu : j["multipliers"]) EXPECT_FALSE(mu["trivial"].get<bool>());
  // A forced scene continues in the forcing frequency (tests/study/forced_branch_test.cpp);
  // --periods 2 with it makes every orbit two forcing periods long; a period the inputs do
  // not repeat with is no orbit (exit 11).
  const Result branch = runTribo("orbit " + forced + " --out " + dir_.string() +
                                 " --continue f=1:1.1 --periods 2 --max-points 3");
  EXPECT_EQ(branch.status, 0) << branch.output;
  const auto b = nlohmann::json::parse(slurp(dir_ / "branch.json"));
  EXPECT_TRUE(b["forced"].get<bool>());
  EXPECT_EQ(b["periods"].get<int>(), 2);
  for (const auto& p : b["branch"])
    EXPECT_NEAR(p["period"].get<double>() * p["parameter"].get<double>(), 2.0, 1e-9);
  EXPECT_EQ(
      runTribo("orbit " + forced + " --out " + dir_.string() + " --continue f=1:2 --period 0.7")
          .status,
      11);
  EXPECT_EQ(runTribo("orbit " + forced + " --out " + dir_.string() + " --periods 0").status, 1);
  const Result krylov =
      runTribo("orbit " + forced + " --out " + dir_.string() + " --solver krylov");
  EXPECT_EQ(krylov.status, 0) << krylov.output;
  EXPECT_NE(krylov.output.find("(krylov: "), std::string::npos) << krylov.output;
  EXPECT_NE(krylov.output.find("8 leading"), std::string::npos) << krylov.output;
  const Result bad = runTribo("orbit " + forced + " --out " + dir_.string() + " --solver lu");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find("expected dense, krylov or auto, found 'lu'"), std::string::npos)
      << bad.output;
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

TEST_F(OrbitCli, ContinueWritesTheBranchsCsvAndEventsAndReportsEachPoint) {
  const Result r = runTribo("orbit " + kBelt + " --set duration=30 --out " + dir_.string() +
                            " --continue v_b=1.4:1.5 --step 0.1 --max-points 4");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("point 0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("point 1"), std::string::npos) << r.output;
  std::ifstream csv(dir_ / "branch.csv");
  std::string line;
  std::getline(csv, line);
  for (const char* column : {"parameter", "period", "amplitude_pp", "largest_multiplier", "stable",
                             "stick_fraction", "event"})
    EXPECT_NE(line.find(column), std::string::npos) << column << " in " << line;
  EXPECT_EQ(line.rfind("index,parameter,period,amplitude_pp,largest_multiplier,stable,", 0), 0u)
      << line;
  int rows = 0;
  double v_b = 0;
  while (std::getline(csv, line)) {
    std::istringstream fields(line);
    std::string index, value;
    std::getline(fields, index, ',');
    std::getline(fields, value, ',');
    v_b = std::stod(value);
    if (rows == 0) {
      EXPECT_EQ(v_b, 1.4) << line;
    }
    ++rows;
  }
  EXPECT_GE(rows, 2);
  EXPECT_LE(rows, 4);
  EXPECT_GE(v_b, 1.5);  // the last point reached TO
  const auto j = nlohmann::json::parse(slurp(dir_ / "branch.json"));
  EXPECT_EQ(j["parameter"].get<std::string>(), "v_b");
  EXPECT_EQ(j["status"].get<std::string>(), "reached_end");
  EXPECT_TRUE(j["events"].is_array());
  EXPECT_TRUE(j["events"].empty());  // stick-slip all the way: nothing crosses
  EXPECT_EQ(j["branch"].size(), static_cast<std::size_t>(rows));
  // branch_orbits.csv: each point's orbit sampled from t = 0 to its period, back where it
  // started.
  std::ifstream orbits(dir_ / "branch_orbits.csv");
  std::getline(orbits, line);
  EXPECT_EQ(line, "point,t,box.x");
  std::vector<double> t_end(static_cast<std::size_t>(rows), -1), x0(t_end), x_end(t_end);
  while (std::getline(orbits, line)) {
    std::istringstream fields(line);
    std::size_t point = 0;
    double t = 0, x = 0;
    char comma = 0;
    fields >> point >> comma >> t >> comma >> x;
    ASSERT_LT(point, t_end.size()) << line;
    if (t == 0.0) x0[point] = x;
    t_end[point] = t, x_end[point] = x;
  }
  for (std::size_t i = 0; i < t_end.size(); ++i) {
    EXPECT_NEAR(t_end[i], j["branch"][i]["period"].get<double>(), 1e-12) << i;
    EXPECT_NEAR(x_end[i], x0[i], 1e-6) << i;
  }
}

TEST_F(OrbitCli, ALostBranchExitsTwelveWithThePointsFoundSoFar) {
  // A viscous damper beside the wall spring (1.5 N s/m): stick-slip ends as the belt speeds
  // up, when the orbit's smallest slip speed reaches the stick speed (0.01 m/s) and the
  // sticking phase vanishes (grazing). At the law's kink there Newton's iteration stops
  // converging (measured: after v_b = 0.7303, smallest slip 0.0099 m/s); orbits solved at
  // fixed parameters past it bracket where the stable orbits stop sticking (measured 0.732042;
  // tests/study/orbit_grazing_test.cpp holds it to the one-dof model), and the branch goes
  // on from the orbit just past it, if Newton finds one there, until it is lost within
  // 1e-5 m/s of belt speed past it (docs/orbits.md): it ends before TO, with what it found.
  const Result r =
      runTribo("orbit " + kBelt + " --set 'springs[wall_spring].damping=1.5'" + " --out " +
               dir_.string() + " --continue v_b=0.5:2 --step 0.1 --max-points 25");
  EXPECT_EQ(r.status, 12) << r.output;
  EXPECT_NE(r.output.find("event            grazing"), std::string::npos) << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "branch.json"));
  EXPECT_EQ(j["status"].get<std::string>(), "lost");
  EXPECT_NE(j["stop_reason"].get<std::string>().find("grazing"), std::string::npos)
      << j["stop_reason"];
  // Steady sliding is stable there (the damper outweighs the law's slope above the Hopf
  // point, 0.7057 m/s): the reason says how to go round the corner.
  EXPECT_NE(j["stop_reason"].get<std::string>().find("--from-hopf"), std::string::npos)
      << j["stop_reason"];
  ASSERT_GE(j["branch"].size(), 2u);
  EXPECT_LT(j["branch"].back()["parameter"].get<double>(), 2.0);
  // The grazing event; the point before it still sticks, just (its smallest slip speed
  // under the stick speed, its stick fraction far below the first point's), and was solved
  // at a fixed parameter.
  ASSERT_EQ(j["events"].size(), 1u) << j["events"];
  const auto& e = j["events"][0];
  EXPECT_EQ(e["kind"].get<std::string>(), "grazing");
  const auto& before = j["branch"][e["between"][0].get<std::size_t>()];
  EXPECT_EQ(before["method"].get<std::string>(), "fixed_parameter");
  EXPECT_GT(before["min_slip"].get<double>(), 0.01 * (1 - 1e-3));
  EXPECT_LT(before["min_slip"].get<double>(), 0.01);
  EXPECT_LT(before["stick_fraction"].get<double>(),
            0.5 * j["branch"][0]["stick_fraction"].get<double>());
  EXPECT_GE(e["parameter"].get<double>(), before["parameter"].get<double>());
  EXPECT_LT(e["parameter"].get<double>(), before["parameter"].get<double>() + 1e-4);
  EXPECT_TRUE(fs::exists(dir_ / "branch.csv"));
}

// SIGINT while the branch runs: it ends after the point in hand, exits 5 and writes the
// points found so far, the same bytes as a branch asked for that many points.
TEST_F(OrbitCli, SigintEndsTheBranchWithItsPointsWritten) {
  using namespace std::chrono_literals;
  fs::create_directories(dir_);
  const fs::path out = dir_ / "interrupted";
  const Child child = spawnChild(kTribo,
                                 {"orbit", kBelt, "--out", out.string(), "--continue", "v_b=1.5:8",
                                  "--step", "0.5", "--max-points", "40"},
                                 dir_ / "io");
  ASSERT_GT(child.pid, 0);
  ASSERT_TRUE(
      waitUntil([&] { return slurp(child.err).find("point 1 ") != std::string::npos; }, 300s))
      << slurp(child.err);
  ::kill(child.pid, SIGINT);
  const Exit e = waitChild(child);
  const std::string err = slurp(child.err), said = slurp(child.out);
  EXPECT_EQ(e.status, 5) << err << said;
  const auto j = nlohmann::json::parse(slurp(out / "branch.json"));
  EXPECT_EQ(j["status"].get<std::string>(), "interrupted");
  const std::size_t points = j["points"].get<std::size_t>();
  EXPECT_GE(points, 2u);
  EXPECT_LT(points, 40u);
  EXPECT_NE(j["stop_reason"].get<std::string>().find("interrupted after " + std::to_string(points) +
                                                     " points"),
            std::string::npos);
  const Result whole =
      runTribo("orbit " + kBelt + " --out " + (dir_ / "whole").string() +
               " --continue v_b=1.5:8 --step 0.5 --max-points " + std::to_string(points));
  ASSERT_EQ(whole.status, 0) << whole.output;
  EXPECT_EQ(slurp(out / "branch.csv"), slurp(dir_ / "whole" / "branch.csv"));
}

TEST_F(OrbitCli, ContinueRefusesToStartFromAnEquilibrium) {
  // A damper of 5.5 N s/m (5 % of critical): at 1.5 m/s the settling run's oscillation
  // decays onto steady sliding, which Newton then finds: an equilibrium, no orbit.
  const Result r = runTribo("orbit " + kBelt + " --set 'springs[wall_spring].damping=5.5'" +
                            " --out " + dir_.string() + " --continue v_b=1.5:2");
  EXPECT_EQ(r.status, 11) << r.output;
  EXPECT_NE(r.output.find("equilibrium"), std::string::npos) << r.output;
}

// --step S --max-step S: evenly spaced points (the step would grow by 1.5 after each easy
// point otherwise), each about S of arclength after the one before; branch.json records the
// bound.
TEST_F(OrbitCli, MaxStepKeepsTheStepFromGrowing) {
  const double step = 0.05;
  const Result r = runTribo("orbit " + kBelt + " --set duration=30 --out " + dir_.string() +
                            " --continue v_b=1.4:1.6 --step 0.05 --max-step 0.05 --max-points 8");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "branch.json"));
  EXPECT_EQ(j["settings"]["max_step"].get<double>(), step);
  std::ifstream csv(dir_ / "branch.csv");
  std::string line;
  std::getline(csv, line);
  const std::size_t arclength_column = [&] {
    std::istringstream names(line);
    std::string name;
    for (std::size_t i = 0; std::getline(names, name, ','); ++i)
      if (name == "arclength") return i;
    return std::string::npos;
  }();
  ASSERT_NE(arclength_column, std::string::npos) << line;
  int rows = 0;
  while (std::getline(csv, line)) {
    std::istringstream fields(line);
    std::string value;
    for (std::size_t i = 0; i <= arclength_column; ++i) std::getline(fields, value, ',');
    // A return-map point lies at the predicted parameter, off the arclength's plane by the
    // prediction's error in the state (measured 2e-7 of the step); unbounded, the second step
    // would be 1.5 S.
    EXPECT_NEAR(std::stod(value), rows * step, 1e-3 * step) << line;
    ++rows;
  }
  // 0.2 m/s of belt speed, the branch nearly straight in v_b (dp/ds about 0.98): 5 or 6 points.
  EXPECT_GE(rows, 5);
  EXPECT_LE(rows, 6);
}

TEST_F(OrbitCli, ContinueRefusesMalformedRangesNamingWhatWasExpected) {
  auto refused = [&](const std::string& spec, const std::string& words) {
    const Result r = runTribo("orbit " + kBelt + " --out " + dir_.string() + " --continue " + spec);
    EXPECT_EQ(r.status, 1) << spec << ": " << r.output;
    EXPECT_NE(r.output.find(words), std::string::npos) << spec << ": " << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "branch.csv")) << spec;
  };
  refused("nosuch=1:2", "'nosuch'");
  refused("nosuch=1:2", "v_b");  // the names it expected
  refused("friction=1:2", "expected a numeric parameter");
  refused("v_b=1:1", "expected FROM and TO to differ");
  refused("v_b=one:2", "expected a number for FROM");
  refused("v_b=1:2x", "expected a number for TO");
  refused("v_b1:2", "expected NAME=FROM:TO");
  refused("v_b=1", "expected NAME=FROM:TO");
  const Result points =
      runTribo("orbit " + kBelt + " --out " + dir_.string() + " --continue v_b=1:2 --max-points 1");
  EXPECT_EQ(points.status, 1) << points.output;
  EXPECT_NE(points.output.find("--max-points"), std::string::npos) << points.output;
  const Result alone = runTribo("orbit " + kBelt + " --out " + dir_.string() + " --step 0.1");
  EXPECT_EQ(alone.status, 1) << alone.output;
  EXPECT_NE(alone.output.find("with --continue"), std::string::npos) << alone.output;
  for (const std::string hopf :
       {" --from-hopf", " --hopf-amplitude 1e-3", " --arclength scaled", " --max-step 0.1"}) {
    const Result r = runTribo("orbit " + kBelt + " --out " + dir_.string() + hopf);
    EXPECT_EQ(r.status, 1) << hopf << ": " << r.output;
    EXPECT_NE(r.output.find("with --continue"), std::string::npos) << r.output;
  }
  const Result amplitude = runTribo("orbit " + kBelt + " --out " + dir_.string() +
                                    " --continue v_b=0.15:0.5 --from-hopf --hopf-amplitude -1");
  EXPECT_EQ(amplitude.status, 1) << amplitude.output;
  EXPECT_NE(amplitude.output.find("--hopf-amplitude: expected a number > 0, found '-1'"),
            std::string::npos)
      << amplitude.output;
  const Result bound =
      runTribo("orbit " + kBelt + " --out " + dir_.string() + " --continue v_b=1:2 --max-step 0");
  EXPECT_EQ(bound.status, 1) << bound.output;
  EXPECT_NE(bound.output.find("--max-step: expected a number > 0, found '0'"), std::string::npos)
      << bound.output;
  const Result norm =
      runTribo("orbit " + kBelt + " --out " + dir_.string() + " --continue v_b=1:2 --arclength l2");
  EXPECT_EQ(norm.status, 1) << norm.output;
  EXPECT_NE(norm.output.find("--arclength: expected si or scaled, found 'l2'"), std::string::npos)
      << norm.output;
}

// --from-hopf: the branch starts at the damped Stribeck belt's Hopf point, where the damper
// cancels the law's falling slope (0.2271 m/s, tests/study/stribeck_hopf.hpp), with the
// undamped period 2 pi sqrt(m / k) there; branch.json says where; a range without a Hopf
// point exits 11 saying so.
TEST_F(OrbitCli, FromHopfStartsAtTheHopfPointAndSaysWhere) {
  const std::string damped =
      " --set friction=stribeck --set 'springs[wall_spring].damping=10' --out " + dir_.string();
  const Result r = runTribo("orbit " + kBelt + damped +
                            " --continue v_b=0.15:0.5 --from-hopf --step 0.004 --max-points 2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("start            Hopf point at v_b ~ 0.2271"), std::string::npos)
      << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "branch.json"));
  EXPECT_EQ(j["start"].get<std::string>(), "hopf");
  EXPECT_NEAR(j["hopf"]["parameter"].get<double>(), 0.227131, 2e-6);
  EXPECT_NEAR(j["hopf"]["period"].get<double>(), 2 * std::numbers::pi * std::sqrt(10.0 / 300.0),
              1e-6);
  EXPECT_EQ(j["points"].get<int>(), 2);
  const Result none = runTribo("orbit " + kBelt + damped + " --continue v_b=0.3:0.6 --from-hopf");
  EXPECT_EQ(none.status, 11) << none.output;
  EXPECT_NE(none.output.find("no Hopf point between 0.3 and 0.6"), std::string::npos)
      << none.output;
}

TEST_F(OrbitCli, SwitchWritesBothBranchesAndExitsThirteenWithoutTheBifurcation) {
  // The parametric pendulum loses its hanging orbit by a period doubling (located and checked
  // against the Mathieu equation in tests/study/branch_switch_test.cpp).
  const std::string pendulum = std::string(TRIBO_SOURCE_DIR) + "/scenes/parametric_pendulum.yaml";
  const Result r =
      runTribo("orbit " + pendulum + " --out " + dir_.string() +
               " --continue f=1.2:0.85 --switch period_doubling --step 0.1 --max-points 3");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("switched at the located period_doubling"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("switch           period_doubling located at f = 1.0794"),
            std::string::npos)
      << r.output;
  const auto j = nlohmann::json::parse(slurp(dir_ / "branch.json"));
  EXPECT_TRUE(j["switch"]["found"].get<bool>());
  EXPECT_NEAR(j["switch"]["parameter"].get<double>(), 1.0794813, 1e-6);
  EXPECT_EQ(j["points"].get<int>(), 3);
  // The primary's rows in primary_branch.csv, branch.csv's columns; the secondary's periods
  // twice the shaking's.
  const std::string primary = slurp(dir_ / "primary_branch.csv");
  EXPECT_EQ(primary.rfind("index,parameter,period,", 0), 0u) << primary;
  EXPECT_NE(primary.find("period_doubling"), std::string::npos) << primary;
  for (const auto& p : j["branch"])
    EXPECT_NEAR(p["period"].get<double>() * p["parameter"].get<double>(), 2.0, 1e-9);

  // The forced linear oscillator has no period doubling: the branch is written, exit 13, and
  // no primary_branch.csv is left from the run before.
  const std::string oscillator = std::string(TRIBO_SOURCE_DIR) + "/scenes/forced_oscillator.yaml";
  const Result none = runTribo("orbit " + oscillator + " --out " + dir_.string() +
                               " --continue f=0.8:1.2 --step 0.2 --switch period_doubling");
  EXPECT_EQ(none.status, 13) << none.output;
  EXPECT_NE(none.output.find("no period doubling on it to switch at"), std::string::npos)
      << none.output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "primary_branch.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "branch.csv"));
  // Usage: a kind it does not know, an amplitude without --switch.
  const Result bad = runTribo("orbit " + pendulum + " --continue f=1.2:0.85 --switch torus");
  EXPECT_EQ(bad.status, 1) << bad.output;
  EXPECT_NE(bad.output.find("expected period_doubling or branch_point, found 'torus'"),
            std::string::npos)
      << bad.output;
  const Result lone = runTribo("orbit " + pendulum + " --out " + dir_.string() +
                               " --continue f=1.2:0.85 --switch-amplitude 0.01");
  EXPECT_EQ(lone.status, 1) << lone.output;
  EXPECT_NE(lone.output.find("--switch-amplitude applies with --switch only"), std::string::npos)
      << lone.output;
}

}  // namespace
}  // namespace tribo::test
