// Reading a sweep's sweep.json back (study/sweep/sweep_runner.cpp writes it): the axes and
// the analysis, enough to know the grid, the columns and the rows of a folder without its
// scene (tribo sweep --merge DIR); and, when two manifests differ, which of their entries do,
// so a refusal can say what changed (scene, axes, settle, ...).
// Not here: writing it, running anything, the folder's other files.
#pragma once

#include <string>
#include <vector>

#include "study/sweep/sweep_grid.hpp"
#include "study/sweep/sweep_point.hpp"

namespace tribo::study {

struct ManifestGrid {
  SweepGrid grid;
  SweepAnalysis analysis = SweepAnalysis::kRun;
};

// The grid and analysis of the sweep.json text `manifest` (`path` names it in messages).
// Throws SweepOutputError (kOtherSweep) when it is not a sweep.json tribo wrote.
ManifestGrid readManifestGrid(const std::string& manifest, const std::string& path);

// The top-level entries whose values differ between two sweep.json texts, in the first's
// order, then those only in the second ("scene_fnv1a64, axes"); "the whole file" when
// either is not JSON; empty when they are the same JSON.
std::string manifestDifferences(const std::string& a, const std::string& b);

}  // namespace tribo::study
