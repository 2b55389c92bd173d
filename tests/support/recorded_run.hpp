// A scene text run to its end with every row kept, for tests that read its recorded columns:
// the run result together with the model its recorder refers to (the recorder holds a
// reference to the model, so the model must outlive it). Fails the test when the run does not
// complete. Not here: what the columns should hold; each test states its own.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_loader.hpp"
#include "study/scene_run.hpp"

namespace tribo::test {

struct RecordedRun {
  std::shared_ptr<const Model> model;
  study::RunResult result;
};

// `yaml` loaded as the file `path` (relative files resolve against its folder) with
// `overrides`, run with every row kept.
inline RecordedRun recordRun(const std::string& yaml, const std::string& path,
                             const std::vector<std::string>& overrides = {}) {
  const io::Scene scene = io::loadSceneFromString(yaml, path, overrides);
  study::RunResult result = study::runScene(scene);
  EXPECT_TRUE(result.complete) << result.message;
  return {scene.model, std::move(result)};
}

}  // namespace tribo::test
