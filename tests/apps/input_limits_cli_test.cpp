// `tribo run`, `tribo info` and `tribo view` on hostile input: geometry past the 1e6 m limit
// (which once crashed FCL's broadphase with exit 139 and left a .partial file), devices and
// FIFOs where a file is expected, a run folder whose trajectory never ends. Each is refused
// with its exit status and a message naming the file and what was found, and nothing is
// written for a refused run.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "support/cli_support.hpp"

namespace tribo::test {
namespace {

class InputLimits : public CliTest {
 protected:
  InputLimits() : CliTest("tribo_input_limits_") {}
  fs::path write(const std::string& name, const std::string& text) {
    fs::create_directories(dir_);
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
};

bool has(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

std::string sceneWithBox(const std::string& size) {
  return "simulation: {duration: 0.01, time_step: 0.001, integrator: rk4}\n"
         "bodies:\n"
         "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n"
         "  - {name: b, mass: 1, inertia: [1, 1, 1], position: [0, 0, 1],\n"
         "     geometry: [{name: big, shape: box, size: [" +
         size +
         ", 1, 1]}]}\n"
         "  - {name: c, mass: 1, inertia: [1, 1, 1], position: [0, 0, 3],\n"
         "     geometry: [{name: small, shape: box, size: [1, 1, 1]}]}\n"
         "friction_laws: {coulomb: {mu: 0.3, regularization: tanh, v_eps: 0.05}}\n"
         "materials:\n"
         "  - {name: m, normal: {law: linear, stiffness: 1e4, damping: 10}, friction: coulomb,\n"
         "     default: true}\n";
}

std::string urdfWithBox(const std::string& size) {
  return "<robot name=\"r\"><link name=\"base\"><inertial><mass value=\"1\"/>"
         "<inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>"
         "<collision><geometry><box size=\"" +
         size + " 1 1\"/></geometry></collision></link></robot>\n";
}

TEST_F(InputLimits, HugeGeometryIsRefusedBeforeTheRunAndNothingIsWritten) {
  for (const std::string& size : std::vector<std::string>{"2e154", "1e308", "1000000.001"}) {
    const fs::path scene = write("huge.yaml", sceneWithBox(size));
    const fs::path out = dir_ / "out";
    const Result r = runTribo("run " + scene.string() + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_TRUE(has(r.output, scene.string()) && has(r.output, "geometry 'big'") &&
                has(r.output, "box size") && has(r.output, "expected at most 1000000 m"))
        << r.output;
    EXPECT_FALSE(fs::exists(out)) << "a refused run wrote " << out;

    const fs::path urdf = write("huge.urdf", urdfWithBox(size));
    const Result u = runTribo("run " + urdf.string() + " --out " + out.string());
    EXPECT_EQ(u.status, 2) << u.output;
    EXPECT_TRUE(has(u.output, "link 'base'") && has(u.output, "1000000 m")) << u.output;
    EXPECT_FALSE(fs::exists(out));

    const Result i = runTribo("info " + urdf.string());
    EXPECT_EQ(i.status, 2) << i.output;
    EXPECT_FALSE(has(i.output, "no errors")) << i.output;
    EXPECT_TRUE(has(i.output, "error: link 'base'") && has(i.output, "1000000 m")) << i.output;
  }
}

TEST_F(InputLimits, AtTheLimitTheDefaultPathRunsToTheEnd) {
  const fs::path scene = write("at_limit.yaml", sceneWithBox("1000000"));
  const Result r = runTribo("run " + scene.string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(r.status, 0) << r.output;
  for (const auto& e : fs::recursive_directory_iterator(dir_))
    EXPECT_NE(e.path().extension(), ".partial") << e.path();
}

TEST_F(InputLimits, DevicesAndFifosAreRefusedWithoutReadingThem) {
  fs::create_directories(dir_);
  const fs::path fifo = dir_ / "pipe.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& file : {std::string("/dev/zero"), fifo.string()}) {
    const Result i = runTribo("info " + file);
    EXPECT_EQ(i.status, 2) << i.output;
    EXPECT_TRUE(has(i.output, file) && has(i.output, "expected a regular file")) << i.output;
    const Result r = runTribo("run " + file + " --out " + (dir_ / "out").string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_TRUE(has(r.output, file) && has(r.output, "expected a regular file")) << r.output;
    std::string text = sceneWithBox("1");
    text.insert(text.find("friction_laws:"), "robots: [{file: " + file + "}]\n");
    const fs::path scene = write("robots.yaml", text);
    const Result s = runTribo("run " + scene.string() + " --out " + (dir_ / "out").string());
    EXPECT_EQ(s.status, 2) << s.output;
    EXPECT_TRUE(has(s.output, file) && has(s.output, "expected a regular file")) << s.output;
  }
}

TEST_F(InputLimits, ViewRefusesATrajectoryThatNeverEnds) {
  const fs::path scene = write("small.yaml", sceneWithBox("1"));
  const fs::path out = dir_ / "out";
  ASSERT_EQ(runTribo("run " + scene.string() + " --out " + out.string()).status, 0);
  fs::remove(out / "trajectory.csv");
  fs::create_symlink("/dev/zero", out / "trajectory.csv");
  const Result v = runTribo("view " + out.string());
  EXPECT_EQ(v.status, 2) << v.output;
  EXPECT_TRUE(has(v.output, "trajectory.csv") && has(v.output, "a character device")) << v.output;
}

}  // namespace
}  // namespace tribo::test
