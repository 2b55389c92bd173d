// What each libFuzzer harness does with one input, as inline functions, so that the harnesses
// (fuzz/*_fuzzer.cpp) and the GoogleTest replay of the committed seeds and regressions
// (tests/study/fuzz_regressions_test.cpp, in every build) run the same code. Each function
// swallows the typed error its loader promises for bad input; anything else (another
// exception, a crash, a sanitizer report, an abort on a broken contract) is a finding.
// Input formats are described in docs/fuzzing.md.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/mesh_loader.hpp"
#include "io/scene_expression.hpp"
#include "io/scene_loader.hpp"
#include "io/scene_parameters.hpp"
#include "io/urdf_reader.hpp"
#include "study/sweep/sweep_grid.hpp"

namespace tribo::fuzz {

// The pieces of `text` between '\n's (an empty text gives one empty piece).
inline std::vector<std::string> lines(std::string_view text) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find('\n', begin);
    out.emplace_back(text.substr(begin, end == std::string_view::npos ? end : end - begin));
    if (end == std::string_view::npos) return out;
    begin = end + 1;
  }
}

// Scene YAML text; lines "#set NAME=VALUE" (YAML comments, so seeds stay valid scenes) are
// also --set overrides. Bad input: io::SceneError.
inline void sceneYaml(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  constexpr std::string_view kSet = "#set ";
  for (const auto& line : lines(text))
    if (line.starts_with(kSet)) overrides.push_back(line.substr(kSet.size()));
  try {
    (void)io::loadSceneFromString(text, "fuzz.yaml", overrides);
  } catch (const io::SceneError&) {
  }
}

// URDF text. Bad input: io::UrdfError, or issues in the robot read.
inline void urdf(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    (void)io::readUrdfFromString(xml, "fuzz.urdf").hasErrors();
  } catch (const io::UrdfError&) {
  }
}

// First byte: the format hint (0 stl, 1 obj, 2 dae; modulo 3), then the file's bytes.
// Bad input: contact::MeshError.
inline void mesh(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  static const char* const kHints[] = {"stl", "obj", "dae"};
  const std::string hint = kHints[data[0] % 3];
  try {
    (void)io::loadMeshFromMemory(std::span(data + 1, size - 1), hint, "fuzz." + hint);
  } catch (const contact::MeshError&) {
  }
}

inline void spanGrid(study::SweepAxis axis) {
  std::vector<study::SweepAxis> axes;
  axes.push_back(std::move(axis));
  const study::SweepGrid grid(std::move(axes));
  if (grid.size() == 0) std::abort();  // an axis without values must have thrown
  (void)grid.overrides(0);
  (void)grid.values(grid.size() - 1);
}

// First byte: the parser (modulo 4), then the argument text:
//   0 io::parseNumber (must give a finite number or nothing)
//   1 --set: the '\n'-separated overrides through ParameterTable::applyOverrides, on a table
//     with a numeric parameter k and a word parameter friction (k must keep a finite value:
//     a number, or an expression that evaluates)
//   2 --grid: study::parseGridAxis, the SweepGrid it spans, its first and last point (text
//     whose COUNT field is a plain number from 100001 to 1000000 is skipped)
//   3 --list: study::parseListAxis, the same
// Bad input: io::SceneError, study::SweepSpecError.
inline void cliValues(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 4) {
      case 0: {
        const auto v = io::parseNumber(text);
        if (v && !std::isfinite(*v)) std::abort();
        break;
      }
      case 1: {
        io::ParameterTable table;
        table.add("k", "2.5e5", {"fuzz.yaml", 1, 1});
        table.add("friction", "coulomb", {"fuzz.yaml", 2, 1});
        table.applyOverrides(lines(text), "fuzz.yaml");
        // k was checked when overridden: it must evaluate to a finite number.
        double k = 0;
        try {
          k = io::evaluateExpression("$k", table, {"fuzz.yaml", 1, 1}, "k");
        } catch (const io::SceneError&) {
          std::abort();
        }
        if (!std::isfinite(k)) std::abort();
        break;
      }
      case 2: {
        // COUNT from 1e5 to kMaxPoints: skipped. Such grids are made value by value (a
        // million take 0.5 s in Release, longer under ASan) and only slow the fuzzer down; above
        // kMaxPoints they are refused before any value is made, and are fuzzed.
        const std::string_view count = text.substr(text.rfind(':') + 1);
        if (count.size() == 7 && count <= "1000000" && count > "100000") break;
        if (count.size() == 6 && count > "100000") break;
        spanGrid(study::parseGridAxis(text));
        break;
      }
      default:
        spanGrid(study::parseListAxis(text));
        break;
    }
  } catch (const io::SceneError&) {
  } catch (const study::SweepSpecError&) {
  }
}

}  // namespace tribo::fuzz
