// What the urdf_tree_fuzzer harness does with one input: its bytes choose a URDF robot's
// tree (a chain, a wide tree, random parents, a binary tree) of 1 to 12 000 links, optionally
// wrapped in deeply nested elements, and every number it writes (masses, inertias, collision
// sizes and origins, joint origins, axes, limits, dynamics, <gazebo> tags) from a table of
// ordinary, zero, negative, tiny, huge and non-finite texts; the text is read by
// io::readUrdfFromString and, when the robot has no errors and at most 2 000 links, built
// into a model. Inline,
// so the harness and the GoogleTest replay (tests/study/fuzz_regressions_test.cpp) run the
// same code. The input format is in docs/fuzzing.md.
// Contract: bad input ends in io::UrdfError, or in error findings; a robot read without
// errors has only finite numbers, none negative where a negative is wrong; the model
// refuses what it cannot use with ModelError or std::invalid_argument. Anything else is a
// finding (std::abort on a broken contract).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/model_builder.hpp"
#include "io/urdf_model.hpp"
#include "io/urdf_reader.hpp"

namespace tribo::fuzz {

// The texts a number may take: the first 8 ordinary (the only ones in clean mode).
inline constexpr const char* kUrdfValueTexts[32] = {
    "1",     "0.5",   "2",    "0.1",      "10",    "1e-3",   "3",   "0.25",
    "0",     "-1",    "-0.5", "1e-300",   "1e300", "-1e300", "nan", "inf",
    "-inf",  "1e999", "-0",   "1e-9",     "1e9",   "-1e-9",  "NaN", "-nan",
    "0x1p3", "1e308", "-2",   "4.9e-324", "100",   "0.75",   "7",   "1.5"};

inline constexpr std::size_t kUrdfTreeModelLinks = 2000;

// Aborts, saying what, when a robot read without errors breaks the contract above.
inline void requireUrdf(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "urdf contract broken: %s\n", what);
  std::abort();
}

inline void checkReadRobot(const io::UrdfRobot& r) {
  const auto fine = [](double v) { return std::isfinite(v); };
  const auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  for (const io::UrdfLink& l : r.links) {
    requireUrdf(!l.has_inertial || nonNegative(l.mass), "mass");
    requireUrdf(l.inertia.allFinite() && l.inertial_origin.matrix().allFinite(), "inertial");
    for (const io::UrdfCollision& c : l.collisions) {
      requireUrdf(c.origin.matrix().allFinite(), "collision origin");
      requireUrdf(c.size.allFinite() && c.size.minCoeff() >= 0.0, "box size");
      requireUrdf(nonNegative(c.radius) && nonNegative(c.length), "radius or length");
      requireUrdf(c.scale.allFinite(), "mesh scale");
    }
    for (const auto& tag : {l.contact.mu1, l.contact.mu2, l.contact.kp, l.contact.kd})
      requireUrdf(!tag || nonNegative(*tag), "gazebo tag");
  }
  for (const io::UrdfJoint& j : r.joints) {
    requireUrdf(j.origin.matrix().allFinite() && j.axis.allFinite(), "joint origin or axis");
    requireUrdf(fine(j.lower) && fine(j.upper), "joint limits");
    requireUrdf(nonNegative(j.effort) && nonNegative(j.velocity), "effort or velocity");
    requireUrdf(nonNegative(j.damping) && nonNegative(j.friction), "damping or friction");
    requireUrdf(fine(j.mimic_multiplier) && fine(j.mimic_offset), "mimic");
  }
}

// Byte 0: bits 0-1 the shape (0 chain, 1 wide: every link under the root, 2 each link under
// one of the 256 before it, 3 binary), bit 2 clean (ordinary values only), bit 3 big (links
// from bytes 1-2, up to 12 000; else 1 + byte 1 % 64), bit 4 nest (the <gazebo> tags wrapped
// in as many nested elements as links). The rest: the value bytes, read in turn and over
// again (each picks kUrdfValueTexts[b % 32], or [b % 8] when clean; a missing one is 0).
class UrdfTreeText {
 public:
  UrdfTreeText(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::string text() {
    const unsigned mode = byte(0);
    const unsigned shape = mode & 3u;
    clean_ = (mode & 4u) != 0;
    const bool big = (mode & 8u) != 0, nest = (mode & 16u) != 0;
    const int n =
        big ? 1 + static_cast<int>((byte(1) | (byte(2) << 8)) % 12000u) : 1 + byte(1) % 64;
    std::string s = "<robot name=\"fuzz\">\n";
    for (int i = 0; i < n; ++i) link(s, i);
    static const char* const kTypes[] = {"fixed",     "revolute", "continuous",
                                         "prismatic", "floating", "planar"};
    for (int i = 1; i < n; ++i) {
      const int parent = shape == 0   ? i - 1
                         : shape == 1 ? 0
                         : shape == 2 ? i - 1 - static_cast<int>(next() % std::min(i, 256))
                                      : (i - 1) / 2;
      s += "<joint name=\"j" + std::to_string(i) + "\" type=\"" + kTypes[next() % 6] +
           "\"><parent link=\"l" + std::to_string(parent) + "\"/><child link=\"l" +
           std::to_string(i) + "\"/><origin xyz=\"" + values(3) + "\" rpy=\"" + values(3) +
           "\"/><axis xyz=\"" + values(3) + "\"/><limit lower=\"" + value() + "\" upper=\"" +
           value() + "\" effort=\"" + value() + "\" velocity=\"" + value() +
           "\"/><dynamics damping=\"" + value() + "\" friction=\"" + value() + "\"/></joint>\n";
    }
    s += "<gazebo reference=\"l0\">";
    if (nest)
      for (int i = 0; i < n; ++i) s += "<n>";
    s += "<mu1>" + value() + "</mu1><kp>" + value() + "</kp><kd>" + value() + "</kd>";
    if (nest)
      for (int i = 0; i < n; ++i) s += "</n>";
    return s + "</gazebo>\n</robot>\n";
  }

 private:
  unsigned byte(std::size_t i) const { return i < size_ ? data_[i] : 0u; }
  unsigned next() { return size_ > 3 ? data_[3 + (at_++ % (size_ - 3))] : 0u; }
  std::string value() { return kUrdfValueTexts[next() % (clean_ ? 8u : 32u)]; }
  std::string values(int count) {
    std::string out = value();
    for (int k = 1; k < count; ++k) out.append(" ").append(value());
    return out;
  }

  void link(std::string& s, int i) {
    s += "<link name=\"l" + std::to_string(i) + "\"><inertial><mass value=\"" + value() +
         "\"/><inertia ixx=\"" + value() + "\" ixy=\"0\" ixz=\"0\" iyy=\"" + value() +
         "\" iyz=\"0\" izz=\"" + value() + "\"/></inertial>";
    static const char* const kShapes[] = {"box", "sphere", "cylinder", "capsule"};
    const unsigned kind = next() % 5;
    if (kind > 0) {
      s += "<collision><origin xyz=\"" + values(3) + "\" rpy=\"" + values(3) + "\"/><geometry><" +
           kShapes[kind - 1];
      s += kind == 1   ? " size=\"" + values(3) + "\""
           : kind == 2 ? " radius=\"" + value() + "\""
                       : " radius=\"" + value() + "\" length=\"" + value() + "\"";
      s += "/></geometry></collision>";
    }
    s += "</link>\n";
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
  bool clean_ = false;
};

inline void urdfTree(const std::uint8_t* data, std::size_t size) {
  const std::string text = UrdfTreeText(data, size).text();
  io::UrdfRobot robot;
  try {
    robot = io::readUrdfFromString(text, "fuzz_tree.urdf");
  } catch (const io::UrdfError&) {
    return;
  }
  if (robot.hasErrors()) return;
  checkReadRobot(robot);
  // The model only for trees of up to kUrdfTreeModelLinks links: the core's model build is
  // quadratic in the bodies and geometries (docs/urdf.md), not what this harness is for.
  if (robot.links.size() > kUrdfTreeModelLinks) return;
  try {
    ModelBuilder builder;
    (void)io::addUrdfRobot(builder, robot, io::UrdfPlacement{});
    (void)builder.build();
  } catch (const ModelError&) {
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace tribo::fuzz
