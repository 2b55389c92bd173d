// The granular cases of bench/peers: a run's figures (GranularRun, for Tribo and for LAMMPS
// alike) and LAMMPS's run of a PeerScene of equal spheres, defined only when LAMMPS was found
// (TRIBO_PEER_LAMMPS; bench/peers/CMakeLists.txt). LAMMPS is driven through its C library
// interface (lammps/library.h), one process, no MPI, with its GRANULAR package: each sphere an
// atom (atom_style sphere), the scene's linear normal law as pair gran/hooke/history, its
// half-space and axis-aligned box walls as fix wall/gran planes. Not for spheres of different
// radii or masses, shapes other than spheres on moving bodies, or tilted walls.
#pragma once

#include <string>

#include "peer_scene.hpp"

namespace tribo::peers {

// The linear normal law of every contact point (Tribo's `normal: {law: linear}`):
// F_n = k d + c d' per point.
struct GranularLaw {
  double stiffness = 0.0;  // k [N/m]
  double damping = 0.0;    // c [N s/m]
};

// One granular run: the steps timed in `samples` chunks, the contacts counted after each
// chunk (outside the clock).
struct GranularRun {
  PeerRun run;               // seconds, cpu_seconds, steps, points (after the last step), ...
  long spheres = 0;          // moving spheres
  double threads = 1.0;      // threads the engine stepped on (a mean over its steps)
  double mean_points = 0.0;  // contact points, mean over the samples
  std::string settings;      // the engine's settings, one line
};

// LAMMPS's settings (one thread: Debian's build has no OPENMP package; velocity Verlet through
// fix nve/sphere):
//   pair gran/hooke/history kn = k, gamman = c / m_eff (m_eff = m / 2 between two spheres;
//   LAMMPS's gamman is a damping per unit effective mass), kt = 2/7 kn, gammat = gamman / 2
//   (LAMMPS's conventions), xmu = the scene's mu, dampflag 1; fix wall/gran with the same
//   law (its m_eff is the sphere's mass m, so gamman = c / m); neighbor skin `skin` [m], bin,
//   rebuilt when a sphere moved half of it (every 1 delay 0 check yes); shrink-wrapped
//   boundaries (no periodic images).
GranularRun runLammps(const PeerScene& scene, const GranularLaw& law, double skin, int samples);
std::string lammpsVersion();
// MPI_Finalize, once, before the process ends (LAMMPS called MPI_Init).
void lammpsFinish();

}  // namespace tribo::peers
