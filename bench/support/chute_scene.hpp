// The sphere chute the benches share (the detection's skin, the granular peers): a scene
// text of nx x ny x nz spheres (r = 0.05 m, 0.5 kg) on a lattice of 0.105 m pitch, each moved
// by up to 2 mm on each axis (seeded), so that none touch at the start, above a flat
// frictional floor (a half-space), gravity tilted by 26 degrees along +x (the angle of LAMMPS's
// chute example, past the floor's friction angle, atan 0.4 = 21.8 degrees); a linear normal
// law of k = 1.5e5 N/m and c = 35 N s/m a point, regularized Coulomb mu = 0.4, semi-implicit
// Euler at 1 ms, for `duration` seconds. One `bodies[].pattern` entry, so a few lines at any
// size. No side walls, no periodic boundaries (Tribo has none), no frozen rough bottom: the
// slab spreads at its edges while it flows down the slope.
#pragma once

#include <string>

namespace tribo::bench {

std::string chuteYaml(int nx, int ny, int nz, double duration);

}  // namespace tribo::bench
