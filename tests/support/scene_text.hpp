// Helpers for tests that change a scene's text and read the error it gives: a file's text
// (failing the test when it cannot be read), a copy with one piece replaced (failing the test
// when the piece is not there), and the SceneError message of loading a text. Not here:
// expectations about the messages; each test states its own.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/scene_loader.hpp"

namespace tribo::test {

inline std::string fileText(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not in the scene text: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The message of the SceneError that loading `yaml` (named `name` in messages, and the
// folder relative files resolve against) raises; "" when it loads.
inline std::string sceneErrorOf(const std::string& yaml, const std::string& name = "test.yaml",
                                const std::vector<std::string>& overrides = {}) {
  try {
    io::loadSceneFromString(yaml, name, overrides);
  } catch (const io::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace tribo::test
