// The pieces of branch switching (study/orbit/orbit_branch.hpp, BranchSpec::switch_at) that
// do not shoot: which event of a primary branch a switch leaves from, the critical Floquet
// multiplier and its eigenvector at the located bifurcation (the direction the secondary
// branch leaves in: Kuznetsov, "Elements of Applied Bifurcation Theory", 3rd ed., Springer
// 2004, sec. 10.3; Seydel, "Practical Bifurcation and Stability Analysis", 3rd ed., Springer
// 2010, sec. 7.6), and that eigenvector scaled for a first step. Internal to study/orbit/.
// Not here: locating the bifurcation and solving the first secondary orbit, which need the
// branch's shooting rows (orbit_branch.cpp).
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "study/orbit/orbit_branch.hpp"
#include "study/orbit/orbit_coordinates.hpp"

namespace tribo::study {

// "period doubling", "branch point": for messages.
std::string switchWords(BranchSwitch kind);

// The first event of `events` that `kind` switches at: a period doubling, or a stability
// change through +1 that no fold between the same points explains (a branch point).
std::optional<BranchEvent> switchEvent(const std::vector<BranchEvent>& events, BranchSwitch kind);

// The multiplier a switch follows and its eigenvector (real): at a period doubling the one
// nearest -1 among those with a negative real part; at a branch point the one nearest +1
// among those with a positive real part, less (autonomous) the trivial one, whose
// eigenvector is the flow's direction `flow` (the Jacobian's T column: d phi / dT = f(y0) on
// an orbit). ok false when there is none (or the eigensolver failed).
struct CriticalMode {
  bool ok = false;
  std::complex<double> mu;
  Eigen::VectorXd v;
};
CriticalMode criticalMode(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& flow,
                          BranchSwitch kind, bool autonomous);

// v scaled so that its largest position or rotation entry (any entry if none moves) is 1,
// its entry `observed` made >= 0.
Eigen::VectorXd normalizedMode(Eigen::VectorXd v, const OrbitCoordinates& coords,
                               Eigen::Index observed);

}  // namespace tribo::study
