// `tribo view RUN_DIR [--frames N] [--three PATH]`: writes RUN_DIR/view.html, a replay of
// the run that opens in a browser without a server (study/view/view_page.hpp; docs/view.md).
// Also used by `tribo run ... --view` after the run. Exit status: 0 written, 1 usage,
// 2 the run folder, its scene or three.js cannot be read, 4 the page cannot be written.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "apps/command.hpp"

namespace tribo::app {

// Adds `view` and its options to `tribo`.
Command addViewCommand(CLI::App& tribo);

// Writes the page of a finished run and prints where; returns the exit status above.
int writeView(const std::filesystem::path& run_dir, std::size_t frame_cap,
              const std::string& three_js, const std::vector<std::string>& package_paths = {});

}  // namespace tribo::app
