// Overrides of any scene value by its path, for the command line's `--set` (and Python's
// `set=`), beside the parameters' `--set NAME=VALUE`: a NAME with a '.' or a '[' is a path
// into the scene file, map keys separated by '.', a list's element chosen by its index or
// by its `name:` in brackets:
//   --set output.interval=0.002            --set output.summary.channel=box.vx
//   --set 'bodies[box].mass=2'             --set 'contacts[0].material=rubber'
//   --set 'output.summary={channel: box.vx, last_cycles: 5}'
// The value is read as YAML (a number, a word, a flow list or map) and replaces the value
// at the path before the scene is read, so it is checked as the file's own value is and
// may use parameters ($name) and expressions. A list element must exist; a missing map key
// on the path is added (as an empty map on the way), and the reader refuses unknown keys.
// Not here: parameters (io/scene_parameters.hpp), reading the scene (io/scene_reader.hpp).
#pragma once

#include <string>
#include <string_view>

#include "io/scene_parameters.hpp"

namespace YAML {
class Node;
}

namespace tribo::io {

// Is `item` (NAME=VALUE) a path override rather than a parameter's?
bool isPathOverride(std::string_view item);

// Applies one path override to `root`, a document of its own (the file read again: the
// change is in place, the other values keep their lines), and returns the path as the reader's
// messages spell it (list elements by index: "bodies[1].mass"). Throws SceneError naming `file`,
// the override, the missing step and what the level holds.
std::string applyPathOverride(YAML::Node& root, const std::string& item, const std::string& file);

// `error` (the reader's) said again naming the override it comes from: at the overridden
// value or inside it, "(from --set ITEM)" without a line (the value is not in the file); at
// a level that holds it, "(with --set ITEM)". Others unchanged.
SceneError attributedToOverride(const SceneError& error, const std::string& path,
                                const std::string& item);

}  // namespace tribo::io
