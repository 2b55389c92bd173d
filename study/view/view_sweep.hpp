// The page of a parameter sweep: `tribo view SWEEP_DIR` (a folder with sweep.json and
// results.csv) writes SWEEP_DIR/view.html: a heat map of a chosen result over two swept
// parameters (lines over one; with more, the first two at the others' first values), each
// point linked to its own replay page when the sweep kept its trajectory (points/<point>/,
// whose view.html is written too, up to a count). No three.js: a canvas only.
// Not here: a run's replay (study/view/view_page.hpp), running sweeps (study/sweep/).
#pragma once

#include <cstddef>
#include <filesystem>

#include "study/view/view_page.hpp"

namespace tribo::study {

// Kept points beyond this many get no page of their own (tribo view makes one on demand).
inline constexpr std::size_t kSweepPointViewCap = 50;

struct SweepViewInfo {
  std::filesystem::path file;
  std::size_t bytes = 0;
  std::size_t points = 0;
  std::size_t linked = 0;  // points whose replay page was written and is linked
};

// True when `dir` holds sweep.json.
bool isSweepDir(const std::filesystem::path& dir);

// Throws std::runtime_error naming what is missing or malformed.
SweepViewInfo writeSweepView(const std::filesystem::path& dir, const ViewOptions& options = {});

}  // namespace tribo::study
