// Where the tests find the shared URDF corpus (real robot files with their expected facts):
// the folder TRIBO_URDF_CORPUS names, else ../shared/urdf beside the checkout (the source
// folder, so a worktree or a clean clone with shared/ beside it finds it alike). A test that
// needs the corpus fails when it is missing, so a run without it never passes for one with
// it; TRIBO_URDF_CORPUS=none opts out explicitly, and those tests then skip.
// Not here: reading the corpus' expected.json (each test reads the facts it checks).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace tribo::test {

// The corpus folder, or nothing when TRIBO_URDF_CORPUS=none.
inline std::optional<std::filesystem::path> urdfCorpusFolder() {
  if (const char* env = std::getenv("TRIBO_URDF_CORPUS")) {
    if (std::string(env) == "none") return std::nullopt;
    return std::filesystem::path(env);
  }
  return std::filesystem::path(TRIBO_SOURCE_DIR) / ".." / "shared" / "urdf";
}

inline std::string urdfCorpusMissing(const std::filesystem::path& folder) {
  return "URDF corpus not found at " + folder.string() +
         " (no expected.json): put the shared corpus beside the checkout as ../shared/urdf, "
         "point TRIBO_URDF_CORPUS at it, or set TRIBO_URDF_CORPUS=none to skip these tests";
}

}  // namespace tribo::test

// In a test body or SetUp: declares `var`, the corpus folder; skips with
// TRIBO_URDF_CORPUS=none, fails when the corpus is missing.
#define TRIBO_REQUIRE_URDF_CORPUS(var)                                                    \
  const std::filesystem::path var = ::tribo::test::urdfCorpusFolder().value_or("");       \
  if (var.empty()) GTEST_SKIP() << "TRIBO_URDF_CORPUS=none: the URDF corpus is not used"; \
  ASSERT_TRUE(std::filesystem::exists(var / "expected.json"))                             \
      << ::tribo::test::urdfCorpusMissing(var)
