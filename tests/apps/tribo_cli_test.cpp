// The `tribo` command end to end: exit status, what lands in the output folder, and the
// error text a user sees for bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_support.hpp"
#include "support/urdf_corpus.hpp"

namespace {

using namespace tribo::test;

// The rest of the line that follows `start` in `text` ("" when `start` is not there).
std::string lineAfter(const std::string& text, const std::string& start) {
  const auto at = text.find(start);
  if (at == std::string::npos) return "";
  const auto from = at + start.size();
  return text.substr(from, text.find('\n', from) - from);
}

class TriboCli : public CliTest {
 protected:
  TriboCli() : CliTest("tribo_cli_") {}
};

TEST_F(TriboCli, RunWritesTrajectoryAndSummary) {
  const Result r = runTribo("run " + kBelt + " --out " + dir_.string() + " --set duration=3");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("amplitude (p-p)"), std::string::npos) << r.output;
  const std::string csv = slurp(dir_ / "trajectory.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* col : {"t", "box.x", "box.y", "box.z", "box.vx", "box.vy", "box.vz"})
    EXPECT_NE(("," + header + ",").find(std::string(",") + col + ","), std::string::npos) << col;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3001);  // header + t = 0..3 s at 1 ms
  const std::string summary = slurp(dir_ / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"complete\""), std::string::npos);
  for (const char* key : {"amplitude_pp", "time_to_98", "period", "stuck_fraction"})
    EXPECT_NE(summary.find(std::string("\"") + key + "\""), std::string::npos) << key;
  EXPECT_FALSE(fs::exists(dir_ / "trajectory.csv.partial"));
}

TEST_F(TriboCli, ProfilePrintsEveryStageAndItsShareOfTheStep) {
  const Result r =
      runTribo("run " + kBelt + " --out " + dir_.string() + " --set duration=1 --profile --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  // RK4 evaluates the forces four times a step.
  EXPECT_NE(r.output.find("us a step, 4 evaluations a step"), std::string::npos) << r.output;
  double shares = 0.0;
  for (const char* stage :
       {"poses", "detect", "contact_kinematics", "normal_force", "friction", "assemble",
        "accelerations", "constraints", "friction_states", "integrator, checks"}) {
    const auto at = r.output.find("  " + std::string(stage) + " ");
    ASSERT_NE(at, std::string::npos) << stage << "\n" << r.output;
    const auto line = r.output.substr(at, r.output.find('\n', at) - at);
    const double share = std::stod(line.substr(line.rfind(' ', line.size() - 2) + 1));
    EXPECT_GE(share, 0.0) << line;
    shares += share;
  }
  EXPECT_NEAR(shares, 100.0, 0.6) << r.output;  // ten shares rounded to 0.1%
  // Without --profile nothing is timed or printed.
  const Result plain = runTribo("run " + kBelt + " --out " + (dir_ / "plain").string() +
                                " --set duration=1 --quiet");
  EXPECT_EQ(plain.output.find("stage profile"), std::string::npos) << plain.output;
}

TEST_F(TriboCli, SummaryNamesEveryNormalLawWithItsExponent) {
  // The ball-drop scene with its Hunt-Crossley material swapped for each other law: the
  // summary's materials carry the law's own name (not "linear" or "hunt_crossley" for all).
  const std::string base = slurp(std::string(TRIBO_SOURCE_DIR) + "/scenes/ball_drop.yaml");
  const std::string hc =
      "{law: hunt_crossley, stiffness: $k, exponent: 1.5, restitution: $e,\n"
      "             impact_speed: $v_impact}";
  ASSERT_NE(base.find(hc), std::string::npos) << "scenes/ball_drop.yaml changed its material";
  struct Case {
    std::string law, yaml, expected;
  };
  for (const Case& c :
       {Case{"hertz", "{law: hertz, stiffness: $k}", "\"exponent\": 1.5"},
        Case{"recurdyn",
             "{law: recurdyn, stiffness: $k, exponent: 1.3, damping: 50, max_depth: 1e-4}",
             "\"max_depth\": 0.0001"},
        Case{"hunt_crossley", hc, "\"exponent\": 1.5"},
        Case{"linear", "{law: linear, stiffness: 1e5, damping: 100}", "\"damping\": 100.0"}}) {
    std::string text = base;
    text.replace(text.find(hc), hc.size(), c.yaml);
    fs::create_directories(dir_);
    const fs::path scene = dir_ / (c.law + ".yaml");
    std::ofstream(scene) << text;
    const fs::path out = dir_ / c.law;
    const Result r =
        runTribo("run " + scene.string() + " --out " + out.string() + " --set duration=0.01");
    ASSERT_EQ(r.status, 0) << c.law << "\n" << r.output;
    const std::string summary = slurp(out / "summary.json");
    EXPECT_NE(summary.find("\"normal_law\": \"" + c.law + "\""), std::string::npos) << c.law << "\n"
                                                                                    << summary;
    EXPECT_NE(summary.find(c.expected), std::string::npos) << c.law << "\n" << summary;
  }
}

// The summary's stable-step line: the a-priori limit of an explicit method and what sets it
// (the box's contact, 316 rad/s, not the 5.5 rad/s spring), none for an implicit one; and the
// joint's drift, which stays at roundoff: the planar joint's box neither leaves its plane nor
// turns. A scene without joints prints no drift.
TEST_F(TriboCli, SummaryPrintsTheStepLimitOrItsAbsenceAndTheJointDrift) {
  const Result rk4 = runTribo("run " + kBelt + " --out " + dir_.string() + " --set duration=3");
  ASSERT_EQ(rk4.status, 0) << rk4.output;
  const auto summary = nlohmann::json::parse(slurp(dir_ / "summary.json"));
  // "stable step     < LIMIT s (contact pair (belt_surface, box_shape) normal)"
  const std::string step = lineAfter(rk4.output, "\nstable step     < ");
  ASSERT_NE(step.find(" s (contact pair (belt_surface, box_shape) normal)"), std::string::npos)
      << rk4.output;
  const double limit = summary["stability"]["estimated_max_step"].get<double>();
  EXPECT_NEAR(std::stod(step), limit, 5e-4 * limit);
  // "constraint drift max |Phi| PHI, max |J v| RATE"
  const std::string drift = lineAfter(rk4.output, "\nconstraint drift max |Phi| ");
  const auto comma = drift.find(", max |J v| ");
  ASSERT_NE(comma, std::string::npos) << rk4.output;
  const double phi = summary["run"]["max_constraint_error"].get<double>();
  const double rate = summary["run"]["max_constraint_rate_error"].get<double>();
  EXPECT_NEAR(std::stod(drift.substr(0, comma)), phi, 0.05 * phi);
  EXPECT_NEAR(std::stod(drift.substr(comma + 12)), rate, 0.05 * rate);
  EXPECT_LT(phi, 1e-12);
  EXPECT_LT(rate, 1e-12);

  const Result bdf = runTribo("run " + kBelt + " --out " + (dir_ / "bdf").string() +
                              " --set duration=1 --set integrator=bdf");
  ASSERT_EQ(bdf.status, 0) << bdf.output;
  EXPECT_NE(bdf.output.find("\nstable step      n/a (bdf is implicit: no explicit step limit)\n"),
            std::string::npos)
      << bdf.output;
  EXPECT_EQ(bdf.output.find("< inf"), std::string::npos) << bdf.output;
  EXPECT_NE(bdf.output.find("\nconstraint drift max |Phi| "), std::string::npos) << bdf.output;

  const Result free_box =
      runTribo("run " + std::string(TRIBO_SOURCE_DIR) +
               "/scenes/belt_free_box.yaml --set duration=0.5 --out " + (dir_ / "free").string());
  ASSERT_EQ(free_box.status, 0) << free_box.output;
  EXPECT_NE(free_box.output.find("\nstable step     < "), std::string::npos) << free_box.output;
  EXPECT_EQ(free_box.output.find("constraint drift"), std::string::npos) << free_box.output;
}

// Pin friction whose reaction-load iteration cannot settle (mu r m d / I_O = 1.7) is warned
// about and counted in summary.json; the same pendulum with a small pin is not.
TEST_F(TriboCli, UnsettledJointFrictionIsWarnedAndCounted) {
  fs::create_directories(dir_);
  auto scene = [&](const std::string& name, double mu, double radius) {
    const fs::path path = dir_ / (name + ".yaml");
    std::ofstream(path)
        << "simulation: {duration: 0.5, time_step: 0.001}\n"
           "bodies: [{name: bob, mass: 1, inertia: [0.01, 0.01, 0.01], "
           "position: [0.5, 0, 0]}]\n"
           "friction_laws: {coulomb: {mu: "
        << mu
        << ", v_eps: 0.01}}\n"
           "joints: [{name: pin, type: revolute, parent: world, child: bob, anchor: [0, 0, 0], "
           "axis: [0, 1, 0], friction: {law: coulomb, load: reaction, radius: "
        << radius << "}}]\n";
    return path.string();
  };
  const Result hard =
      runTribo("run " + scene("hard", 0.9, 0.5) + " --out " + (dir_ / "hard").string());
  ASSERT_EQ(hard.status, 0) << hard.output;
  EXPECT_NE(hard.output.find("tribo: warning: joint friction under reaction load did not settle"),
            std::string::npos)
      << hard.output;
  const auto summary = nlohmann::json::parse(slurp(dir_ / "hard" / "summary.json"));
  EXPECT_GT(summary["run"]["joint_friction_unconverged_steps"].get<long>(), 0);
  EXPECT_FALSE(summary["warnings"].empty());

  const Result easy =
      runTribo("run " + scene("easy", 0.3, 0.05) + " --out " + (dir_ / "easy").string());
  ASSERT_EQ(easy.status, 0) << easy.output;
  EXPECT_EQ(easy.output.find("did not settle"), std::string::npos) << easy.output;
  EXPECT_EQ(nlohmann::json::parse(
                slurp(dir_ / "easy" / "summary.json"))["run"]["joint_friction_unconverged_steps"]
                .get<long>(),
            0);
}

TEST_F(TriboCli, SceneWithoutASummaryBodySaysSoInsteadOfFigures) {
  fs::create_directories(dir_);
  const fs::path scene = dir_ / "fall.yaml";
  std::ofstream(scene) << "simulation: {duration: 0.1}\n"
                          "bodies: [{name: ball, mass: 1, inertia: [1, 1, 1]}]\n";
  const Result r = runTribo("run " + scene.string() + " --out " + (dir_ / "out").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(
      r.output.find("\nobserved         nothing (the scene's output.summary names no body)\n"),
      std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("amplitude (p-p)"), std::string::npos) << r.output;
}

TEST_F(TriboCli, BadParametersFailWithFileAndKeyAndWriteNothing) {
  struct Case {
    std::string set;
    std::string expected;
  };
  for (const Case& c :
       {Case{"--set nope=1", "nope"}, Case{"--set friction=magic", "magic"},
        Case{"--set a=0.9", "a must be > 1"}, Case{"--set mu_k=0.4", "mu_s must exceed mu_k"},
        Case{"--set k=abc", "expected a number"}}) {
    const Result r = runTribo("run " + kBelt + " --out " + dir_.string() + " " + c.set);
    EXPECT_EQ(r.status, 2) << c.set << "\n" << r.output;
    EXPECT_NE(r.output.find("belt.yaml"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_)) << c.set;
  }
}

TEST_F(TriboCli, AStepLongerThanTheRunIsAnErrorNamingBothValues) {
  const Result r = runTribo("run " + kBelt + " --out " + dir_.string() + " --set dt=1e300");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("time_step (1e+300 s) is larger than the duration (60 s)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(TriboCli, DivergedRunExitsNonZeroAndMarksTheSummary) {
  const Result r =
      runTribo("run " + kBelt + " --out " + dir_.string() + " --set dt=0.02 --set duration=5");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("warning: time step 0.02 s exceeds"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("diverged at step"), std::string::npos) << r.output;
  const std::string summary = slurp(dir_ / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"diverged\""), std::string::npos) << summary;
  EXPECT_EQ(slurp(dir_ / "trajectory.csv").find("nan"), std::string::npos);
}

TEST_F(TriboCli, UsageErrors) {
  EXPECT_EQ(runTribo("").status, 1);
  EXPECT_EQ(runTribo("fly").status, 1);
  EXPECT_EQ(runTribo("run " + kBelt).status, 1);  // no --out
  const Result missing = runTribo("run /nonexistent/scene.yaml --out " + dir_.string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("/nonexistent/scene.yaml"), std::string::npos);
  EXPECT_EQ(runTribo("--help").status, 0);
}

TEST_F(TriboCli, InfoPrintsTheUrdfTreeAndRefusesAnInvalidOne) {
  TRIBO_REQUIRE_URDF_CORPUS(corpus);
  const Result ok = runTribo("info " + (corpus / "bullet3" / "r2d2.urdf").string());
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_NE(ok.output.find("links 16, joints 15 (5 continuous, 7 fixed, 1 prismatic, 2 revolute), "
                           "total mass 65.25 kg"),
            std::string::npos)
      << ok.output;
  EXPECT_NE(ok.output.find("left_gripper  [revolute 'left_gripper_joint']"), std::string::npos);
  const Result loop =
      runTribo("info " + (corpus / "ros_urdf/urdf/test/fail_pr2_desc_loop.urdf").string());
  EXPECT_EQ(loop.status, 2) << loop.output;
  EXPECT_NE(loop.output.find("no root link: joint"), std::string::npos) << loop.output;
}

// info on a scene: its materials' limit surface (the anisotropic slider's ratios per sense)
// and rolling and spinning thresholds, as the scene sets them and after --set; a bad value is
// refused naming its key; the stable step is the one run would print.
TEST_F(TriboCli, InfoOnASceneShowsTheLimitSurfaceAndTheResistanceThresholds) {
  const std::string experiments = std::string(TRIBO_SOURCE_DIR) + "/scenes/experiments/";
  const Result slider = runTribo("info " + experiments + "anisotropic_slider.yaml");
  EXPECT_EQ(slider.status, 0) << slider.output;
  EXPECT_NE(slider.output.find("material 0 (1 pair: floor/sole):"), std::string::npos)
      << slider.output;
  EXPECT_NE(slider.output.find("axis (1, 0, 0) fixed in geometry b; limit surface: along the "
                               "axis 0.5 mu forward, 3 mu backward; across it 1.5 mu forward, "
                               "1.5 mu backward"),
            std::string::npos)
      << slider.output;
  EXPECT_NE(slider.output.find("stable step: < 0.0001052 s"), std::string::npos) << slider.output;
  const Result turned =
      runTribo("info " + experiments + "anisotropic_slider.yaml --set forward=0.25 --set across=2");
  EXPECT_NE(turned.output.find("along the axis 0.25 mu forward, 3 mu backward; across it 2 mu "
                               "forward, 2 mu backward"),
            std::string::npos)
      << turned.output;
  const Result ball =
      runTribo("info " + experiments + "ball_on_slope.yaml --set rolling_length=0.004");
  EXPECT_EQ(ball.status, 0) << ball.output;
  EXPECT_NE(ball.output.find("rolling: holds up to 0.004 m times the normal load (mu_r)"),
            std::string::npos)
      << ball.output;
  const Result top = runTribo("info " + experiments + "spinning_top.yaml");
  // mu_spin r_c = 0.3 x 5 mm.
  EXPECT_NE(top.output.find("spinning: holds up to 0.0015 m times the normal load (mu_spin r_c)"),
            std::string::npos)
      << top.output;
  const Result bad = runTribo("info " + experiments + "ball_on_slope.yaml --set rolling_length=-1");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("materials[0].rolling.length: expected a number > 0, found '-1'"),
            std::string::npos)
      << bad.output;
}

// Issue #11 from the command line: an upper-case .URDF runs as a robot, a zero-radius foot
// is a contact point that info and run agree on, and many notes of one kind are one line
// (--verbose lists them) before the run's summary.
TEST_F(TriboCli, UrdfByContentWithGroupedNotesAndInfoSayingWhatRunDoes) {
  fs::create_directories(dir_);
  std::string chain =
      "<robot name=\"chain\"><link name=\"base\"><inertial><mass value=\"2\"/>"
      "<inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" ixz=\"0\" "
      "iyz=\"0\"/></inertial><collision><geometry><sphere radius=\"0\"/>"
      "</geometry></collision><collision><origin xyz=\"0.1 0 0\"/><geometry>"
      "<box size=\"0.05 0.05 0.05\"/></geometry></collision></link>";
  const int kMimics = 66;
  for (int i = 0; i < kMimics; ++i) {
    const std::string n = std::to_string(i);
    chain += "<link name=\"l" + n +
             "\"><inertial><mass value=\"0.1\"/><inertia ixx=\"1e-4\" iyy=\"1e-4\" izz=\"1e-4\" "
             "ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link><joint name=\"j" +
             n + "\" type=\"continuous\"><parent link=\"base\"/><child link=\"l" + n +
             "\"/><axis xyz=\"0 0 1\"/><mimic joint=\"ghost" + n + "\"/></joint>";
  }
  chain += "</robot>";
  const fs::path file = dir_ / "CHAIN.URDF";
  std::ofstream(file) << chain;
  const Result info = runTribo("info " + file.string());
  EXPECT_EQ(info.status, 0) << info.output;
  EXPECT_NE(info.output.find("a contact point"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("run: rk4, step"), std::string::npos) << info.output;
  // A short run: the notes are printed before the first step, and 67 bodies on 66 joints
  // cost about 11 ms a step in Release (ten times that under the sanitizers).
  const std::string shortRun = " --set duration=0.02";
  const Result run =
      runTribo("run " + file.string() + shortRun + " --out " + (dir_ / "out").string());
  EXPECT_EQ(run.status, 0) << run.output;
  long mimic_lines = 0;
  std::istringstream lines(run.output);
  std::string line, last;
  while (std::getline(lines, line)) {
    mimic_lines += line.find("mimic ignored") != std::string::npos;
    if (!line.empty()) last = line;
  }
  EXPECT_EQ(mimic_lines, 1) << run.output;
  EXPECT_NE(run.output.find("(and " + std::to_string(kMimics - 1) + " more like it"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(last.rfind("results", 0), 0u) << run.output;  // the summary ends the output
  const Result verbose =
      runTribo("run " + file.string() + shortRun + " --verbose --out " + (dir_ / "out").string());
  EXPECT_EQ(verbose.status, 0) << verbose.output;
  long listed = 0;
  std::istringstream all(verbose.output);
  while (std::getline(all, line)) listed += line.find("mimic ignored") != std::string::npos;
  EXPECT_EQ(listed, kMimics);
  // A .urdf that is not XML is refused by the URDF reader's words, not the scene loader's.
  const fs::path text = dir_ / "ROBOT.URDF";
  std::ofstream(text) << "links: [a, b]\n";
  const Result refused = runTribo("run " + text.string() + " --out " + (dir_ / "out2").string());
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(
      refused.output.find("ROBOT.URDF:1: not an XML document: it starts with 'links: [a, b]'"),
      std::string::npos)
      << refused.output;
}

// The printed summary says what it measured, in the observed quantity's units, and says
// "none" rather than 0 where there is no cycle.
TEST_F(TriboCli, SummaryNamesUnitsAndSaysWhenThereIsNoCycle) {
  const std::string source = TRIBO_SOURCE_DIR;
  struct Case {
    std::string args, amplitude_line;
  };
  const std::vector<Case> cases = {
      {kBelt + " --set duration=6", "amplitude (p-p)  "},  // box.x
      {kBelt + " --set duration=6 --set 'output.summary={channel: box.vx}'", " m/s\n"},
      {source + "/scenes/pendulum.yaml --set 'output.channels=[position, velocity, joints]' "
                "--set 'output.summary={channel: pivot.q}'",
       " rad\n"},
  };
  for (const Case& c : cases) {
    const Result r = runTribo("run " + c.args + " --out " + (dir_ / "units").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string amplitude = lineAfter(r.output, "amplitude (p-p)  ");
    EXPECT_NE(("amplitude (p-p)  " + amplitude + "\n").find(c.amplitude_line), std::string::npos)
        << r.output;
  }
  // A box that slides to a stop: no cycle, so no period and no time to 98%.
  const Result still =
      runTribo("run " + std::string(TRIBO_SOURCE_DIR) +
               "/scenes/sliding_box.yaml --set 'output.summary={body: box, coordinate: x}' --out " +
               (dir_ / "still").string());
  ASSERT_EQ(still.status, 0) << still.output;
  EXPECT_NE(still.output.find("period           none (no cycle)"), std::string::npos)
      << still.output;
  EXPECT_NE(still.output.find("time to 98%      none (no cycle)"), std::string::npos)
      << still.output;
  EXPECT_EQ(still.output.find("period           0 s"), std::string::npos) << still.output;
  // A channel without a body: no stuck fraction to give.
  const Result channel = runTribo(
      "run " + kBelt + " --set duration=3 --set 'output.summary={channel: box.vx}' --out " +
      (dir_ / "channel").string());
  EXPECT_NE(channel.output.find("stuck fraction   n/a"), std::string::npos) << channel.output;
}

}  // namespace
