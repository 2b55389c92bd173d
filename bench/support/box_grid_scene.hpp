// The box grids the benches share (scale, threads, peers): a scene text in the form of
// scenes/box_grid20.yaml, n x n boxes of 0.2 m and 8 kg at a 0.25 m pitch, starting at their
// static depth m g / (4 k) with k = 6e5 N/m a corner, semi-implicit Euler at 1 ms; the ground
// a half-space or (box_ground) a kinematic box 0.2 m thick whose top is the plane z = 0,
// reaching 0.5 m past the grid on every side. The boxes are one `bodies[].pattern` entry
// (box_i_j_0), so the text is a few lines at any n.
#pragma once

#include <string>

namespace tribo::bench {

std::string boxGridYaml(int n, bool box_ground = false);

}  // namespace tribo::bench
