// Reading URDF: malformed inputs give their clear error (file, line, what was expected),
// the model checks flag dubious inertias, Gazebo contact tags are read, and mesh URIs
// resolve (relative, file://, package:// through search paths and ROS_PACKAGE_PATH).
#include "io/urdf_reader.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace tribo::io {
namespace {

namespace fs = std::filesystem;

class UrdfReader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tribo_urdf_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  std::string errorOf(const std::string& path, const PackagePaths& packages = {}) {
    try {
      readUrdf(path, packages);
    } catch (const UrdfError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

const char* kPendulum = R"(<?xml version="1.0"?>
<robot name="pendulum">
  <link name="base"/>
  <link name="arm">
    <inertial>
      <origin xyz="0 0 -0.5" rpy="0 0 0"/>
      <mass value="2.0"/>
      <inertia ixx="0.2" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.01"/>
    </inertial>
    <collision><origin xyz="0 0 -0.5"/><geometry><box size="0.05 0.05 1.0"/></geometry></collision>
  </link>
  <joint name="hinge" type="revolute">
    <parent link="base"/><child link="arm"/>
    <origin xyz="0 0 2" rpy="0 0 1.5707963267948966"/>
    <axis xyz="0 2 0"/>
    <limit lower="-1" upper="1" effort="10" velocity="3"/>
    <dynamics damping="0.1" friction="0.05"/>
  </joint>
  <gazebo reference="arm"><mu1>0.7</mu1><mu2>0.6</mu2><kp>100000</kp><kd>10</kd></gazebo>
</robot>
)";

TEST_F(UrdfReader, ReadsLinksJointsInertialsLimitsAndGazeboTags) {
  const UrdfRobot r = readUrdf(write("p.urdf", kPendulum));
  ASSERT_EQ(r.links.size(), 2u);
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_EQ(r.root, "base");
  const UrdfLink& arm = *r.findLink("arm");
  EXPECT_EQ(arm.line, 4);
  EXPECT_DOUBLE_EQ(arm.mass, 2.0);
  EXPECT_TRUE(arm.inertial_origin.translation().isApprox(Eigen::Vector3d(0, 0, -0.5)));
  EXPECT_DOUBLE_EQ(arm.inertia(2, 2), 0.01);
  ASSERT_EQ(arm.collisions.size(), 1u);
  EXPECT_TRUE(arm.collisions[0].size.isApprox(Eigen::Vector3d(0.05, 0.05, 1.0)));
  EXPECT_EQ(*arm.contact.mu1, 0.7);
  EXPECT_EQ(*arm.contact.kp, 100000.0);
  const UrdfJoint& j = r.joints[0];
  EXPECT_EQ(j.type, "revolute");
  EXPECT_TRUE(j.axis.isApprox(Eigen::Vector3d::UnitY()));  // normalized
  EXPECT_TRUE(j.origin.translation().isApprox(Eigen::Vector3d(0, 0, 2)));
  // rpy yaw = pi/2 turns the child x axis onto the parent y axis.
  EXPECT_TRUE((j.origin.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(j.has_limits);
  EXPECT_DOUBLE_EQ(j.upper, 1.0);
  EXPECT_DOUBLE_EQ(j.damping, 0.1);
  EXPECT_DOUBLE_EQ(j.friction, 0.05);
  EXPECT_TRUE(r.issues.empty());
  EXPECT_DOUBLE_EQ(r.totalMass(), 2.0);
}

TEST_F(UrdfReader, TextReadsAsTheFileDoesAndErrorsNameTheGivenName) {
  const UrdfRobot r = readUrdfFromString(kPendulum, "mem/p.urdf");
  EXPECT_EQ(r.path, "mem/p.urdf");
  ASSERT_EQ(r.links.size(), 2u);
  EXPECT_EQ(r.findLink("arm")->line, 4);
  EXPECT_EQ(*r.findLink("arm")->contact.mu1, 0.7);
  try {
    readUrdfFromString("<robot name='x'><link name='a'>", "mem/cut.urdf");
    ADD_FAILURE() << "truncated XML was read";
  } catch (const UrdfError& e) {
    EXPECT_NE(std::string(e.what()).find("mem/cut.urdf:"), std::string::npos) << e.what();
  }
}

// fuzz/regressions/urdf_fuzzer/crash-utf8-lead-byte-at-end: TinyXML read past the text after
// a UTF-8 lead byte at its end (AddressSanitizer: heap-buffer-overflow).
TEST_F(UrdfReader, TextThatIsNotUtf8IsRefusedWithItsLine) {
  for (const std::string& text :
       {std::string("<robot name=\"a\xdf"),
        std::string("<robot name=\"a\">\n<link name=\"\x95\"/>"),
        std::string("<robot name=\"a\">\n\n<link name=\"b") + '\0' + "\"/>",
        // The shared check (io/utf8_check.hpp) is strict: overlong forms, surrogates and
        // code points past U+10FFFF, which the URDF reader's own check once let through.
        std::string("<robot name=\"a\xc0\x80\"/>"), std::string("<robot name=\"\xed\xa0\x80\"/>"),
        std::string("<robot name=\"\xf4\x90\x80\x80\"/>")}) {
    try {
      readUrdfFromString(text, "mem.urdf");
      ADD_FAILURE() << "read: " << text;
    } catch (const UrdfError& e) {
      EXPECT_NE(std::string(e.what()).find("expected UTF-8 text"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(readUrdfFromString("<robot name=\"\xc3\xa9t\xc3\xa9\"><link name=\"a\"/></robot>",
                                     "utf8.urdf"));
}

TEST_F(UrdfReader, TruncatedXmlNamesFileAndLine) {
  const std::string text(kPendulum);
  const std::string path = write("cut.urdf", text.substr(0, text.find("<joint")));
  const std::string e = errorOf(path);
  EXPECT_NE(e.find(path + ":"), std::string::npos) << e;
  EXPECT_NE(e.find("malformed XML"), std::string::npos) << e;
}

TEST_F(UrdfReader, EmptyAndNonXmlFilesSayWhatTheyAre) {
  const std::string empty = write("empty.urdf", "  \n\n");
  EXPECT_NE(errorOf(empty).find(empty + ": the file is empty"), std::string::npos)
      << errorOf(empty);
  for (const std::string text : {"links: [a, b]\n<robot/>", "ROBOT arm\n", "\x01\x02garbage"}) {
    const std::string path = write("text.urdf", text);
    const std::string e = errorOf(path);
    EXPECT_NE(e.find(path + ":1: not an XML document: it starts with '"), std::string::npos) << e;
    EXPECT_EQ(e.find("document empty"), std::string::npos) << e;
  }
  const std::string sdf = write("w.urdf", "<?xml version=\"1.0\"?>\n<sdf version=\"1.6\"/>");
  EXPECT_NE(errorOf(sdf).find(":2: expected a <robot> root element, found <sdf>"),
            std::string::npos)
      << errorOf(sdf);
}

TEST_F(UrdfReader, UrdfIsRecognisedByItsRootElement) {
  const std::string robot = "<robot name=\"r\"><link name=\"l\"/></robot>";
  EXPECT_TRUE(looksLikeUrdf(write("A.URDF", robot)));
  EXPECT_TRUE(looksLikeUrdf(write("a.xml",
                                  "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!-- <sdf> -->\n"
                                  "<!DOCTYPE robot>\n" +
                                      robot)));
  EXPECT_FALSE(looksLikeUrdf(write("s.yaml", "robots:\n  - file: a.urdf\n")));
  EXPECT_FALSE(looksLikeUrdf(write("r.urdf", "<robots/>")));
  EXPECT_FALSE(looksLikeUrdf((dir_ / "missing.urdf").string()));
}

// Drake, Gazebo and PyBullet load these; urdfdom refuses them (kept with --strict).
TEST_F(UrdfReader, LenientJointsWithoutLimitsAndAnUndeclaredWorld) {
  for (const std::string type : {"revolute", "prismatic"}) {
    std::string text(kPendulum);
    text.replace(text.find("type=\"revolute\""), 15, "type=\"" + type + "\"");
    text.erase(text.find("<limit"), text.find("/>", text.find("<limit")) + 2 - text.find("<limit"));
    text.replace(text.find("<link name=\"base\"/>"), 19, "");
    text.replace(text.find("<parent link=\"base\"/>"), 21, "<parent link=\"world\"/>");
    const std::string path = write("lenient.urdf", text);
    const UrdfRobot r = readUrdf(path);
    EXPECT_EQ(r.root, "world");
    ASSERT_EQ(r.joints.size(), 1u);
    EXPECT_EQ(r.joints[0].type, type);
    EXPECT_FALSE(r.joints[0].has_limits);
    int notes = 0;
    for (const auto& i : r.issues) {
      notes += i.severity == UrdfIssue::Severity::kNote;
      if (i.where == "joint 'hinge'") {
        EXPECT_NE(
            i.message.find("line 12: " + type + " joint without <limit>: loaded as unlimited"),
            std::string::npos)
            << i.message;
      }
      if (i.where == "link 'world'") {
        EXPECT_NE(i.message.find("parent 'world' is not declared: taken as the world frame"),
                  std::string::npos)
            << i.message;
      }
    }
    EXPECT_EQ(notes, 2);
    EXPECT_EQ(r.findLink("arm")->line, 4);  // lines are the file's
    try {
      readUrdf(path, {}, {true});
      ADD_FAILURE() << "--strict must refuse what urdfdom refuses";
    } catch (const UrdfError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

TEST_F(UrdfReader, ZeroRadiusSphereIsAContactPointAndANegativeOneIsRefused) {
  std::string text(kPendulum);
  text.replace(text.find("<box size=\"0.05 0.05 1.0\"/>"), 27, "<sphere radius=\"0\"/>");
  const UrdfRobot point = readUrdf(write("point.urdf", text));
  EXPECT_FALSE(point.hasErrors());
  bool noted = false;
  for (const auto& i : point.issues)
    noted |= i.severity == UrdfIssue::Severity::kNote &&
             i.message.find("collision sphere of radius 0 at (0, 0, -0.5): a contact point") !=
                 std::string::npos;
  EXPECT_TRUE(noted);
  // A negative radius is refused at once (tests/io/urdf_values_test.cpp has every attribute).
  text.replace(text.find("radius=\"0\""), 10, "radius=\"-0.1\"");
  const std::string bad = errorOf(write("bad.urdf", text));
  EXPECT_NE(bad.find("bad.urdf:10: link 'arm'/collision/geometry/sphere: attribute 'radius': "
                     "expected finite numbers >= 0, found '-0.1'"),
            std::string::npos)
      << bad;
}

TEST_F(UrdfReader, UnknownJointTypeNamesJointLineAndTheKnownTypes) {
  std::string text(kPendulum);
  text.replace(text.find("type=\"revolute\""), 15, "type=\"hinge\"");
  const std::string path = write("t.urdf", text);
  const std::string e = errorOf(path);
  EXPECT_NE(e.find(path + ":12: joint 'hinge': unknown type 'hinge'"), std::string::npos) << e;
  EXPECT_NE(e.find("continuous"), std::string::npos) << e;
}

TEST_F(UrdfReader, MissingParentLinkIsNamed) {
  std::string text(kPendulum);
  text.replace(text.find("<parent link=\"base\"/>"), 21, "<parent link=\"bsae\"/>");
  const std::string e = errorOf(write("m.urdf", text));
  EXPECT_NE(e.find(":13: joint 'hinge': parent link 'bsae' is not defined"), std::string::npos)
      << e;
}

TEST_F(UrdfReader, CyclicTreeIsRefusedNamingTheJointThatClosesTheLoop) {
  const std::string e = errorOf(write("loop.urdf", R"(<robot name="loop">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="bc" type="fixed"><parent link="b"/><child link="c"/></joint>
  <joint name="ca" type="fixed"><parent link="c"/><child link="a"/></joint>
</robot>)"));
  EXPECT_NE(e.find("loop.urdf:"), std::string::npos) << e;
  EXPECT_NE(e.find("no root link"), std::string::npos) << e;
  // Following parents from 'a' (the first link by name) comes back to it through 'ab'.
  EXPECT_NE(
      e.find("loop.urdf:3: no root link: joint 'ab' closes the kinematic loop a -> b -> c -> a"),
      std::string::npos)
      << e;
}

TEST_F(UrdfReader, LinkWithTwoParentJointsIsRefused) {
  const std::string e = errorOf(write("two.urdf", R"(<robot name="two">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="ac" type="fixed"><parent link="a"/><child link="c"/></joint>
  <joint name="bc" type="fixed"><parent link="b"/><child link="c"/></joint>
</robot>)"));
  EXPECT_NE(e.find("two.urdf:4: joint 'bc': link 'c' is already the child of joint 'ac' (line 3)"),
            std::string::npos)
      << e;
}

TEST_F(UrdfReader, NegativeMassIsRefusedAndDubiousInertiasAreFound) {
  std::string text(kPendulum);
  text.replace(text.find("<mass value=\"2.0\"/>"), 19, "<mass value=\"-2.0\"/>");
  const std::string neg = errorOf(write("neg.urdf", text));
  EXPECT_NE(neg.find("neg.urdf:7: link 'arm'/inertial/mass: attribute 'value': expected finite "
                     "numbers >= 0, found '-2.0'"),
            std::string::npos)
      << neg;

  std::string tri(kPendulum);
  tri.replace(tri.find("izz=\"0.01\""), 10, "izz=\"0.5\" ");
  const UrdfRobot t = readUrdf(write("tri.urdf", tri));
  ASSERT_EQ(t.issues.size(), 1u);
  EXPECT_NE(t.issues[0].message.find("triangle inequality"), std::string::npos);
  EXPECT_FALSE(t.hasErrors());
}

TEST_F(UrdfReader, MissingMeshNamesLinkAndEveryPathTried) {
  std::string text(kPendulum);
  text.replace(text.find("<box size=\"0.05 0.05 1.0\"/>"), 27,
               "<mesh filename=\"package://arms/meshes/arm.stl\"/>");
  const std::string path = write("mesh.urdf", text);
  const UrdfRobot r = readUrdf(path, PackagePaths({(dir_ / "pkgs").string()}));
  ASSERT_TRUE(r.hasErrors());
  const UrdfIssue& i = r.issues[0];
  EXPECT_EQ(i.where, "link 'arm'");
  EXPECT_NE(i.message.find("package://arms/meshes/arm.stl"), std::string::npos) << i.message;
  EXPECT_NE(i.message.find((dir_ / "pkgs" / "arms" / "meshes" / "arm.stl").string()),
            std::string::npos)
      << i.message;
  // Once the file exists in a package folder, it resolves.
  write("pkgs/arms/meshes/arm.stl", "solid x\nendsolid x\n");
  const UrdfRobot ok = readUrdf(path, PackagePaths({(dir_ / "pkgs").string()}));
  EXPECT_FALSE(ok.hasErrors());
  EXPECT_EQ(ok.findLink("arm")->collisions[0].mesh_path,
            (dir_ / "pkgs" / "arms" / "meshes" / "arm.stl").string());
}

TEST_F(UrdfReader, MeshUrisResolveRelativeFileAndPackageThroughEnvironment) {
  const std::string mesh = write("robot/meshes/a.stl", "solid a\nendsolid a\n");
  const PackagePaths none;
  EXPECT_EQ(*none.resolve("meshes/a.stl", (dir_ / "robot").string()).path, mesh);
  EXPECT_EQ(*none.resolve("file://" + mesh, "/elsewhere").path, mesh);
  EXPECT_FALSE(none.resolve("https://example.org/a.stl", ".").path);
  EXPECT_NE(none.resolve("package://robot/meshes/a.stl", ".").problem.find("no package path"),
            std::string::npos);
  // A search folder named like the package is the package itself.
  EXPECT_EQ(
      *PackagePaths({(dir_ / "robot").string()}).resolve("package://robot/meshes/a.stl", ".").path,
      mesh);
  setenv("ROS_PACKAGE_PATH", ("/nonexistent:" + dir_.string()).c_str(), 1);
  const PackagePaths env = PackagePaths::withEnvironment({});
  unsetenv("ROS_PACKAGE_PATH");
  EXPECT_EQ(*env.resolve("package://robot/meshes/a.stl", ".").path, mesh);
}

TEST_F(UrdfReader, UnreadableFile) {
  const std::string e = errorOf((dir_ / "none.urdf").string());
  EXPECT_NE(e.find("cannot open URDF file"), std::string::npos) << e;
}

}  // namespace
}  // namespace tribo::io
