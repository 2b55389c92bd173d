// The start of a branch of periodic orbits at a Hopf point of steady sliding: where the
// leading oscillatory mode of `tribo modes` (study/modes/modes.hpp) crosses the imaginary axis
// as a parameter p moves, a family of small orbits is born, with period 2 pi / omega at the
// crossing and amplitude growing like sqrt|p - p_H| (the Hopf bifurcation theorem: Kuznetsov,
// "Elements of Applied Bifurcation Theory", 3rd ed., Springer 2004, sec. 3.4; its use as a
// continuation's start: Seydel, "Practical Bifurcation and Stability Analysis", 3rd ed.,
// Springer 2010, sec. 7.6.1). Born on the side where steady sliding is unstable the orbits
// are stable (supercritical); born where it is stable they are unstable (subcritical), and a
// settling run never finds them: this start does.
// locateHopf scans the range at `samples` + 1 values of p for a sign change of the growth rate
// sigma(p) of the leading mode with omega > 0, then bisects to |dp| <= 1e-12 max(1, |p|).
// hopfDirection is the first guess's direction in orbit coordinates: the mode's real part at
// the phase where the observed coordinate peaks (velocity zero there, as the orbit's phase
// condition asks): position entries m_j cos(phi_j - phi_obs), velocity entries
// -omega m_j sin(phi_j - phi_obs), scaled so the observed coordinate's entry is 1.
// Laws with internal states are taken (their states left at steady sliding's in the guess).
// Not here: the corrector that solves for the first orbit with its amplitude fixed
// (study/orbit/orbit_branch.cpp); laws keeping contact anchors (the modes analysis refuses
// them); a Hopf point of any mode but the leading oscillatory one; a crossing between two
// samples of the scan that crosses back before the next (twice in one interval).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "core/model.hpp"
#include "core/state.hpp"
#include "io/scene_loader.hpp"
#include "study/modes/modes.hpp"
#include "study/orbit/orbit_coordinates.hpp"

namespace tribo::study {

// The first orbit's amplitude when none is given: the observed coordinate peaks this far above
// steady sliding [m or rad].
inline constexpr double kDefaultHopfAmplitude = 1e-3;

struct HopfPoint {
  double parameter = 0;           // p_H
  double omega = 0;               // [rad/s] the mode's angular frequency at p_H
  State steady;                   // steady sliding at p_H
  std::vector<ShapeEntry> shape;  // the mode's shape at p_H (study/modes/modes.hpp)
  int analyses = 0;               // modes analyses done
};

// The Hopf point in [from, to] of the scenes `sceneAt(p)` gives. Throws OrbitError when sigma
// keeps its sign over the scan (naming the growth rates at both ends), when there is no
// oscillatory mode, or when the modes analysis fails at some p (naming p and why).
HopfPoint locateHopf(const std::function<io::Scene(double)>& sceneAt, double from, double to,
                     int samples = 16);

// The first guess's direction (above) for the coordinates `coords` of `model`, observing body
// `body`'s coordinate `axis`. Throws OrbitError when the mode leaves that coordinate at rest.
Eigen::VectorXd hopfDirection(const HopfPoint& hopf, const Model& model,
                              const OrbitCoordinates& coords, int body, int axis);

}  // namespace tribo::study
