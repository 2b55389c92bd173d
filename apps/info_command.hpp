// `tribo info FILE.urdf [--package-path DIR ...] [--strict] [--verbose]`: prints a URDF
// robot's link tree with joint types and masses, the total mass, joint counts by type and the
// model checks, then builds the same scene `tribo run FILE.urdf` would (io/urdf_scene.hpp) and
// prints what that run would refuse (exit 2) or note: its automatic settings (contact
// stiffness, step, integrator), the stable step and what bounds it, and the notes grouped by
// kind. A file that passes info does not fail run at load.
// Also here: grouping of notes and warnings for both commands (one line per kind with a
// count; verbose lists each).
// Exit status 0 when the robot can be simulated, 1 usage, 2 when the file or a check is an
// error.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "apps/command.hpp"

namespace tribo::app {

// Adds `info` and its options to `tribo`.
Command addInfoCommand(CLI::App& tribo);

// Prints `lines` to `out` as "tribo: LABEL: line": notes of one kind (the same text once the
// quoted names and the numbers are set aside) on one line with "(and N more like it)",
// unless `verbose`.
void printGrouped(std::FILE* out, const char* label, const std::vector<std::string>& lines,
                  bool verbose);

}  // namespace tribo::app
