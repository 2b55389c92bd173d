// Every number Tribo reads from a URDF, set to nan, inf, -inf, a number too large for a
// double, and (where a negative value is wrong) a negative one: each is refused with a
// UrdfError naming the file, the line, the element path, the attribute, what was expected
// and what was found. The same robot with its own values loads.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/urdf_reader.hpp"

namespace tribo::io {
namespace {

// One element of every kind Tribo reads, each on its own line.
const char* kRobot = R"(<robot name="all">
<link name="base"/>
<link name="arm">
<inertial>
<origin xyz="0 0 -0.5" rpy="0 0 0"/>
<mass value="2.0"/>
<inertia ixx="0.2" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.01"/>
</inertial>
<collision><origin xyz="0 0 -0.5" rpy="0 0 0"/><geometry><box size="0.05 0.05 1.0"/></geometry></collision>
<collision><geometry><sphere radius="0.1"/></geometry></collision>
<collision><geometry><cylinder radius="0.1" length="0.2"/></geometry></collision>
<collision><geometry><capsule radius="0.1" length="0.2"/></geometry></collision>
<collision><geometry><mesh filename="arm.stl" scale="1 -1 1"/></geometry></collision>
</link>
<link name="tip"/>
<joint name="hinge" type="revolute">
<parent link="base"/><child link="arm"/>
<origin xyz="0 0 2" rpy="0 0 1.5"/>
<axis xyz="0 1 0"/>
<limit lower="-1" upper="1" effort="10" velocity="3"/>
<dynamics damping="0.1" friction="0.05"/>
</joint>
<joint name="follower" type="revolute">
<parent link="arm"/><child link="tip"/>
<limit lower="-1" upper="1" effort="10" velocity="3"/>
<mimic joint="hinge" multiplier="2" offset="0.5"/>
</joint>
<gazebo reference="arm">
<mu1>0.7</mu1>
<mu2>0.6</mu2>
<kp>100000</kp>
<kd>10</kd>
</gazebo>
</robot>
)";

struct Case {
  std::string where;      // the element path the message names
  std::string attribute;  // the attribute it names ("" for an element's text)
  std::string original;   // the text in kRobot it replaces, unique there
  std::string pattern;    // with X for the bad value
  bool non_negative;
  int line;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all{
      {"link 'arm'/inertial/origin", "xyz", "<origin xyz=\"0 0 -0.5\" rpy=\"0 0 0\"/>\n<mass",
       "<origin xyz=\"0 X -0.5\" rpy=\"0 0 0\"/>\n<mass", false, 5},
      {"link 'arm'/inertial/origin", "rpy", "<origin xyz=\"0 0 -0.5\" rpy=\"0 0 0\"/>\n<mass",
       "<origin xyz=\"0 0 -0.5\" rpy=\"0 0 X\"/>\n<mass", false, 5},
      {"link 'arm'/inertial/mass", "value", "<mass value=\"2.0\"/>", "<mass value=\"X\"/>", true,
       6},
      {"link 'arm'/inertial/inertia", "ixx", "ixx=\"0.2\"", "ixx=\"X\"", false, 7},
      {"link 'arm'/inertial/inertia", "ixy", "ixy=\"0\"", "ixy=\"X\"", false, 7},
      {"link 'arm'/inertial/inertia", "ixz", "ixz=\"0\"", "ixz=\"X\"", false, 7},
      {"link 'arm'/inertial/inertia", "iyy", "iyy=\"0.2\"", "iyy=\"X\"", false, 7},
      {"link 'arm'/inertial/inertia", "iyz", "iyz=\"0\"", "iyz=\"X\"", false, 7},
      {"link 'arm'/inertial/inertia", "izz", "izz=\"0.01\"", "izz=\"X\"", false, 7},
      {"link 'arm'/collision/origin", "xyz", "<collision><origin xyz=\"0 0 -0.5\"",
       "<collision><origin xyz=\"X 0 -0.5\"", false, 9},
      {"link 'arm'/collision/origin", "rpy", "-0.5\" rpy=\"0 0 0\"/><geometry>",
       "-0.5\" rpy=\"X 0 0\"/><geometry>", false, 9},
      {"link 'arm'/collision/geometry/box", "size", "size=\"0.05 0.05 1.0\"", "size=\"X 0.05 1.0\"",
       true, 9},
      {"link 'arm'/collision/geometry/sphere", "radius", "<sphere radius=\"0.1\"/>",
       "<sphere radius=\"X\"/>", true, 10},
      {"link 'arm'/collision/geometry/cylinder", "radius", "<cylinder radius=\"0.1\"",
       "<cylinder radius=\"X\"", true, 11},
      {"link 'arm'/collision/geometry/cylinder", "length",
       "<cylinder radius=\"0.1\" length=\"0.2\"", "<cylinder radius=\"0.1\" length=\"X\"", true,
       11},
      {"link 'arm'/collision/geometry/capsule", "radius", "<capsule radius=\"0.1\"",
       "<capsule radius=\"X\"", true, 12},
      {"link 'arm'/collision/geometry/capsule", "length", "<capsule radius=\"0.1\" length=\"0.2\"",
       "<capsule radius=\"0.1\" length=\"X\"", true, 12},
      {"link 'arm'/collision/geometry/mesh", "scale", "scale=\"1 -1 1\"", "scale=\"1 1 X\"", false,
       13},
      {"joint 'hinge'/origin", "xyz", "<origin xyz=\"0 0 2\"", "<origin xyz=\"0 0 X\"", false, 18},
      {"joint 'hinge'/origin", "rpy", "rpy=\"0 0 1.5\"", "rpy=\"0 X 1.5\"", false, 18},
      {"joint 'hinge'/axis", "xyz", "<axis xyz=\"0 1 0\"/>", "<axis xyz=\"0 1 X\"/>", false, 19},
      {"joint 'hinge'/limit", "lower",
       "lower=\"-1\" upper=\"1\" effort=\"10\" velocity=\"3\"/>\n<dyn",
       "lower=\"X\" upper=\"1\" effort=\"10\" velocity=\"3\"/>\n<dyn", false, 20},
      {"joint 'hinge'/limit", "upper",
       "lower=\"-1\" upper=\"1\" effort=\"10\" velocity=\"3\"/>\n<dyn",
       "lower=\"-1\" upper=\"X\" effort=\"10\" velocity=\"3\"/>\n<dyn", false, 20},
      {"joint 'hinge'/limit", "effort", "effort=\"10\" velocity=\"3\"/>\n<dyn",
       "effort=\"X\" velocity=\"3\"/>\n<dyn", true, 20},
      {"joint 'hinge'/limit", "velocity", "velocity=\"3\"/>\n<dyn", "velocity=\"X\"/>\n<dyn", true,
       20},
      {"joint 'hinge'/dynamics", "damping", "damping=\"0.1\"", "damping=\"X\"", true, 21},
      {"joint 'hinge'/dynamics", "friction", "friction=\"0.05\"", "friction=\"X\"", true, 21},
      {"joint 'follower'/mimic", "multiplier", "multiplier=\"2\"", "multiplier=\"X\"", false, 26},
      {"joint 'follower'/mimic", "offset", "offset=\"0.5\"", "offset=\"X\"", false, 26},
      {"gazebo reference 'arm'/mu1", "", "<mu1>0.7</mu1>", "<mu1>X</mu1>", true, 29},
      {"gazebo reference 'arm'/mu2", "", "<mu2>0.6</mu2>", "<mu2>X</mu2>", true, 30},
      {"gazebo reference 'arm'/kp", "", "<kp>100000</kp>", "<kp>X</kp>", true, 31},
      {"gazebo reference 'arm'/kd", "", "<kd>10</kd>", "<kd>X</kd>", true, 32},
  };
  return all;
}

// `pattern` with its X replaced by `value`.
std::string withValue(const std::string& pattern, const std::string& value) {
  const std::size_t at = pattern.find('X');
  std::string out;
  out.append(pattern, 0, at).append(value);
  if (at != std::string::npos) out.append(pattern, at + 1, std::string::npos);
  return out;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "not unique: " << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(UrdfValues, TheRobotWithItsOwnValuesLoads) {
  const UrdfRobot r = readUrdfFromString(kRobot, "all.urdf");
  ASSERT_EQ(r.links.size(), 3u);
  EXPECT_EQ(r.findLink("arm")->collisions.size(), 5u);
  EXPECT_DOUBLE_EQ(r.joints[1].mimic_multiplier, 2.0);
}

TEST(UrdfValues, NonFiniteAndNegativeNumbersAreRefusedNamingElementAndAttribute) {
  for (const Case& c : cases()) {
    std::vector<std::string> bad{"nan", "inf", "-inf", "NaN", "1e999", "-1e999"};
    if (c.non_negative) {
      bad.push_back("-1");
      bad.push_back("-1e-300");
    }
    for (const std::string& value : bad) {
      const std::string pattern = withValue(c.pattern, value);
      const std::string text = replaced(kRobot, c.original, pattern);
      SCOPED_TRACE(c.where + " " + c.attribute + " = " + value);
      try {
        readUrdfFromString(text, "robots/all.urdf");
        ADD_FAILURE() << "loaded";
      } catch (const UrdfError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("robots/all.urdf:" + std::to_string(c.line) + ": " + c.where + ": ", 0),
                  0u)
            << m;
        EXPECT_NE(m.find(c.attribute.empty() ? "its text" : "attribute '" + c.attribute + "'"),
                  std::string::npos)
            << m;
        EXPECT_NE(m.find(c.non_negative ? "expected finite numbers >= 0"
                                        : "expected finite numbers, found"),
                  std::string::npos)
            << m;
        EXPECT_NE(m.find("found '"), std::string::npos) << m;
        EXPECT_NE(m.find(value), std::string::npos) << m;
      }
    }
  }
}

// Zero is a value real robots write where a negative one is refused (no damping, a massless
// frame, a contact-point sphere): loaded.
TEST(UrdfValues, ZeroIsNotRefused) {
  for (const Case& c : cases()) {
    if (!c.non_negative || c.where.find("geometry") != std::string::npos) continue;
    const std::string pattern = withValue(c.pattern, "0");
    SCOPED_TRACE(c.where + " " + c.attribute);
    EXPECT_NO_THROW(readUrdfFromString(replaced(kRobot, c.original, pattern), "zero.urdf"));
  }
}

}  // namespace
}  // namespace tribo::io
