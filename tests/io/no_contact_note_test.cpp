// A scene whose geometries could touch but that models no contact at all (no contacts: list,
// no default material, no surface pairs) says so before the run: the box that starts on the
// floor would otherwise fall through it and the run end `complete`. Scenes that model some
// contact, or whose geometries cannot meet (one body, nothing moving), say nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/scene_loader.hpp"

namespace tribo::io {
namespace {

const std::string kHeader =
    "friction_laws:\n  coulomb: {mu: 0.3}\n"
    "bodies:\n"
    "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace}]}\n";

bool saysNoContact(const Scene& scene) {
  return std::any_of(scene.notes.begin(), scene.notes.end(), [](const std::string& n) {
    return n.find("no contact is modelled") != std::string::npos;
  });
}

Scene load(const std::string& bodies, const std::string& material_extra,
           const std::string& tail = "") {
  const std::string yaml = kHeader + bodies + "materials:\n  - {name: m, friction: coulomb" +
                           material_extra + "}\n" + tail;
  return loadSceneFromString(yaml, "no_contact.yaml");
}

const std::string kBox =
    "  - {name: box, mass: 1, position: [0, 0, 0.1], geometry: [{name: b, shape: box, size: "
    "[0.2, 0.2, 0.2]}]}\n";

TEST(NoContactNote, ABoxOnAFloorWithNoContactRuleIsNamed) {
  for (const char* mass : {"0.001", "1", "1000"}) {
    std::string bodies = kBox;
    bodies.replace(bodies.find("mass: 1"), 7, std::string("mass: ") + mass);
    const Scene scene = load(bodies, "");
    ASSERT_TRUE(saysNoContact(scene)) << mass;
    const std::string note = *std::find_if(scene.notes.begin(), scene.notes.end(), [](auto& n) {
      return n.find("no contact") != std::string::npos;
    });
    EXPECT_NE(note.find("'b'"), std::string::npos) << note;
    EXPECT_NE(note.find("'floor'"), std::string::npos) << note;
    EXPECT_NE(note.find("default: true"), std::string::npos) << note;
  }
  // Two moving bodies and no ground: they still could touch.
  const std::string two =
      kBox +
      "  - {name: ball, mass: 1, position: [0, 0, 1], geometry: [{name: s, shape: "
      "sphere, radius: 0.1}]}\n";
  EXPECT_TRUE(saysNoContact(load(two, "")));
}

TEST(NoContactNote, AnyContactRuleOrGeometriesThatCannotMeetSayNothing) {
  EXPECT_FALSE(saysNoContact(load(kBox, ", default: true")));
  const std::string with_surfaces =
      "friction_laws:\n  coulomb: {mu: 0.3}\nbodies:\n"
      "  - {name: ground, kind: kinematic, geometry: [{name: floor, shape: halfspace, surface: "
      "steel}]}\n"
      "  - {name: box, mass: 1, position: [0, 0, 0.1], geometry: [{name: b, shape: box, size: "
      "[0.2, 0.2, 0.2], surface: rubber}]}\n"
      "materials:\n  - {name: m, friction: coulomb, surfaces: [[steel, rubber]]}\n";
  EXPECT_FALSE(saysNoContact(loadSceneFromString(with_surfaces, "surfaces.yaml")));
  EXPECT_FALSE(saysNoContact(load(kBox, "", "contacts:\n  - {a: floor, b: b, material: m}\n")));
  // Nothing moves: kinematic bodies only.
  EXPECT_FALSE(saysNoContact(load(
      "  - {name: belt, kind: kinematic, geometry: [{name: k, shape: box, size: [1, 1, 1]}]}\n",
      "")));
  // One moving body and nothing else to meet: its two geometries are one rigid body.
  const std::string alone =
      "friction_laws:\n  coulomb: {mu: 0.3}\nbodies:\n"
      "  - {name: arm, mass: 1, geometry: [{name: a1, shape: box, size: [0.1, 0.1, 0.1]}, "
      "{name: a2, shape: sphere, radius: 0.05, position: [0, 0, 0.3]}]}\n"
      "materials:\n  - {name: m, friction: coulomb}\n";
  EXPECT_FALSE(saysNoContact(loadSceneFromString(alone, "alone.yaml")));
}

}  // namespace
}  // namespace tribo::io
