// URDF trees of hostile size and shape: chains (each link the child of the one before) and
// wide trees (one root with every other link its child) of 10 to 30 000 links load with the
// right tree, through the reader, the assembly and the model; a file past the documented
// limits (kMaxUrdfLinks links, kMaxUrdfNesting nested elements) is refused with both numbers;
// loops and second roots in long chains are refused naming them. Sizes are such that a
// recursion per link overflowed the stack (30 000 links under AddressSanitizer) and a
// quadratic walk took minutes.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/model_builder.hpp"
#include "io/urdf_assembly.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"
#include "io/urdf_xml_checks.hpp"
#include "support/urdf_tree_text.hpp"

namespace tribo::io {
namespace {

using test::urdfLinkName;

std::string chain(int n) { return test::urdfChain(n); }
std::string wide(int n) { return test::urdfWide(n); }

std::string errorOf(const std::string& text, const std::string& name) {
  try {
    readUrdfFromString(text, name);
  } catch (const UrdfError& e) {
    return e.what();
  }
  return "";
}

// Every link is read once, parents first, each under the joint its file gives it.
template <class Parent>
void expectTree(const UrdfRobot& r, int n, Parent parent) {
  ASSERT_EQ(r.links.size(), static_cast<std::size_t>(n));
  ASSERT_EQ(r.joints.size(), static_cast<std::size_t>(n - 1));
  EXPECT_EQ(r.root, "l0");
  EXPECT_EQ(r.links.front().name, "l0");
  std::map<std::string, int> position;
  for (std::size_t k = 0; k < r.links.size(); ++k)
    position.emplace(r.links[k].name, static_cast<int>(k));
  ASSERT_EQ(position.size(), static_cast<std::size_t>(n));  // no link twice
  for (const UrdfJoint& j : r.joints) {
    const int child = std::stoi(j.child.substr(1));
    EXPECT_EQ(j.parent, urdfLinkName(parent(child))) << j.name;
    EXPECT_LT(position.at(j.parent), position.at(j.child)) << j.name;
  }
  EXPECT_DOUBLE_EQ(r.totalMass(), n);
  EXPECT_FALSE(r.hasErrors());
}

TEST(UrdfTreeSize, ChainsOfTenToThirtyThousandLinksLoad) {
  for (int n : {10, 1000, 30000}) {
    SCOPED_TRACE(n);
    const UrdfRobot r = readUrdfFromString(chain(n), "chain.urdf");
    expectTree(r, n, [](int i) { return i - 1; });
    // A chain is read in its order: link i after link i - 1.
    for (int i = 0; i < n; ++i) ASSERT_EQ(r.links[i].name, urdfLinkName(i));
  }
}

TEST(UrdfTreeSize, WideTreesOfTenToThirtyThousandLinksLoad) {
  for (int n : {10, 1000, 30000}) {
    SCOPED_TRACE(n);
    expectTree(readUrdfFromString(wide(n), "wide.urdf"), n, [](int) { return 0; });
  }
}

// Forward kinematics down a straight chain at zero positions: link i is 0.1 i above the
// root; every movable joint is its own body.
TEST(UrdfTreeSize, LongChainAssemblesAndBuilds) {
  for (int n : {100, 20000}) {
    SCOPED_TRACE(n);
    const UrdfRobot r = readUrdfFromString(chain(n), "chain.urdf");
    const UrdfAssembly a = assembleUrdf(r, Eigen::Isometry3d::Identity());
    ASSERT_EQ(a.groups.size(), static_cast<std::size_t>(n));
    for (int i = 0; i < n; i += n / 10)
      EXPECT_NEAR(a.link_world[i].translation().z(), 0.1 * i, 1e-9 * n) << i;
    ModelBuilder builder;
    addUrdfRobot(builder, r, UrdfPlacement{});
    EXPECT_EQ(builder.bodies().size(), static_cast<std::size_t>(n));
  }
}

TEST(UrdfTreeSize, MoreLinksThanTheLimitAreRefusedWithCountAndLimit) {
  const int n = static_cast<int>(kMaxUrdfLinks) + 1;
  std::string text = "<robot name=\"big\">";
  for (int i = 0; i < n; ++i) text += "<link name=\"" + urdfLinkName(i) + "\"/>";
  text += "</robot>";
  const std::string e = errorOf(text, "many.urdf");
  EXPECT_NE(e.find("many.urdf: " + std::to_string(n) + " links: expected at most " +
                   std::to_string(kMaxUrdfLinks)),
            std::string::npos)
      << e;
}

TEST(UrdfTreeSize, NestingPastTheLimitIsRefusedAndWithinItLoads) {
  auto nested = [](int depth) {
    std::string s = "<robot name=\"r\"><link name=\"a\"/><gazebo reference=\"a\">";
    for (int i = 0; i < depth; ++i) s += "<x>";
    for (int i = 0; i < depth; ++i) s += "</x>";
    return s + "</gazebo></robot>";
  };
  // <robot> and <gazebo> are two levels.
  EXPECT_EQ(readUrdfFromString(nested(kMaxUrdfNesting - 2), "ok.urdf").links.size(), 1u);
  for (int depth : {kMaxUrdfNesting - 1, 10000, 300000}) {
    const std::string e = errorOf(nested(depth), "deep.urdf");
    EXPECT_NE(e.find("deep.urdf:1: elements nested more than " + std::to_string(kMaxUrdfNesting)),
              std::string::npos)
        << depth << ": " << e;
  }
  // Quoted '>' and '/>', comments and CDATA do not count as elements.
  EXPECT_EQ(readUrdfFromString("<robot name=\"a/>b>\"><!-- <x><x> --><link name=\"a\"/>"
                               "<gazebo reference=\"a\"><![CDATA[<x><x>]]></gazebo></robot>",
                               "quoted.urdf")
                .links.size(),
            1u);
}

TEST(UrdfTreeSize, LoopsAndSecondRootsInLongChainsAreRefused) {
  for (int n : {3, 20, 20000}) {
    SCOPED_TRACE(n);
    // The chain's root hung from its last link: a loop through every link.
    std::string loop = chain(n);
    loop.insert(loop.find("</robot>"), "<joint name=\"back\" type=\"fixed\"><parent link=\"" +
                                           urdfLinkName(n - 1) +
                                           "\"/><child link=\"l0\"/></joint>\n");
    const std::string e = errorOf(loop, "loop.urdf");
    EXPECT_NE(e.find("closes the kinematic loop"), std::string::npos) << e.substr(0, 300);
    EXPECT_LT(e.size(), 600u) << "a long loop is told by its ends";
    if (n > 12) {
      EXPECT_NE(e.find("(" + std::to_string(n) + " links in all)"), std::string::npos) << e;
    }

    // A link that hangs from nothing: two roots.
    std::string two = chain(n);
    two.insert(two.find("</robot>"), "<link name=\"stray\"/>\n");
    const std::string r = errorOf(two, "two.urdf");
    EXPECT_NE(r.find("two.urdf: expected one root link"), std::string::npos) << r;
    EXPECT_NE(r.find("found 2: 'l0' (line 2), 'stray' (line " + std::to_string(n + 1 + n) + ")"),
              std::string::npos)
        << r;
  }
}

}  // namespace
}  // namespace tribo::io
