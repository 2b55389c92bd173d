// The page of a branch of periodic orbits: `tribo view BRANCH_DIR` (a folder of
// `tribo orbit --continue`: branch.json, branch.csv, branch_orbits.csv) writes
// BRANCH_DIR/view.html: the bifurcation diagram (each orbit's peak-to-peak amplitude against
// the continued parameter, stable orbits solid and unstable ones dashed, steady sliding on the
// parameter axis by its growth rate, the located events and the Hopf start marked), and the
// orbit of a chosen point replayed over one period. The page embeds the points' columns, the
// events and every point's sampled orbit (decimated to ViewOptions' caps), and after a branch
// switch the branch it left (primary_branch.csv, drawn in grey, its points not chosen); a
// canvas only, no three.js. docs/view.md describes the page.
// Not here: the page's behaviour (view/branch.js), computing the branch (study/orbit/).
#pragma once

#include <cstddef>
#include <filesystem>

#include "study/view/view_page.hpp"

namespace tribo::study {

struct BranchViewInfo {
  std::filesystem::path file;
  std::size_t bytes = 0;
  std::size_t points = 0;          // rows of branch.csv
  std::size_t events = 0;          // events of branch.json
  std::size_t orbit_rows = 0;      // rows of branch_orbits.csv
  std::size_t orbit_samples = 0;   // of them, the samples the page holds
  bool steady_growth = false;      // branch.csv has steady sliding's growth rates
  std::size_t primary_points = 0;  // rows of primary_branch.csv (after a branch switch)
};

// True when `dir` holds branch.json.
bool isBranchDir(const std::filesystem::path& dir);

// Reads DIR/branch.json, branch.csv and branch_orbits.csv (bounded reads) and writes
// DIR/view.html (whole or not at all). Each orbit keeps at most options.frame_cap samples and
// all orbits together at most options.value_budget numbers (every k-th sample, the last and
// the extremes kept). Throws std::runtime_error naming the file and what is missing or
// malformed (a required column or key, a number, a row's width, a point without its orbit).
BranchViewInfo writeBranchView(const std::filesystem::path& dir, const ViewOptions& options = {});

}  // namespace tribo::study
