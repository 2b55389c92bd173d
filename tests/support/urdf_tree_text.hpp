// URDF text of generated trees for size tests and benches: n links l0..l(n-1), each of mass
// 1, link i > 0 hanging from link parent(i) on a revolute joint 0.1 m above it; chains
// (each link under the one before) and wide trees (every link under l0). With
// `collision_box`, each link also has a 5 cm collision box (so a robot on the ground gets
// automatic contacts, a surface per link).
#pragma once

#include <string>

namespace tribo::test {

inline std::string urdfLinkName(int i) {
  std::string name = "l";
  name += std::to_string(i);
  return name;
}

template <class Parent>
std::string urdfTree(int n, Parent parent, bool collision_box = false) {
  const std::string box =
      collision_box ? "<collision><geometry><box size=\"0.05 0.05 0.05\"/></geometry></collision>"
                    : "";
  std::string s = "<robot name=\"big\">\n";
  for (int i = 0; i < n; ++i)
    s += "<link name=\"" + urdfLinkName(i) +
         "\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" "
         "iyz=\"0\" izz=\"1\"/></inertial>" +
         box + "</link>\n";
  for (int i = 1; i < n; ++i)
    s += "<joint name=\"j" + std::to_string(i) + "\" type=\"revolute\"><parent link=\"" +
         urdfLinkName(parent(i)) + "\"/><child link=\"" + urdfLinkName(i) +
         "\"/><origin xyz=\"0 0 0.1\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" "
         "effort=\"1\" velocity=\"1\"/></joint>\n";
  return s + "</robot>\n";
}

inline std::string urdfChain(int n, bool collision_box = false) {
  return urdfTree(
      n, [](int i) { return i - 1; }, collision_box);
}
inline std::string urdfWide(int n, bool collision_box = false) {
  return urdfTree(
      n, [](int) { return 0; }, collision_box);
}

}  // namespace tribo::test
