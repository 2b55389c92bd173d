// A continuation step by the return map (study/orbit/orbit_branch.hpp, internal to
// study/orbit/), for a stretch of branch whose orbits contract strongly (a stick-slip cycle:
// every non-trivial multiplier far inside the unit circle). Where the pseudo-arclength
// corrector spends 2 (n + 2) flows an iteration on its Jacobian, this step fixes the parameter
// at the prediction's, p = p_pred, and lets the return-map iterations (study/orbit/picard.hpp)
// bring the predicted orbit onto the orbit at p: three periods on stick-slip. The leading
// multipliers are then estimated without the monodromy matrix: subspace iteration on two
// vectors with the flow's direction deflated (M f = f, so in a basis (f, rest) M is block
// triangular and Q M Q, Q = I - f f^T, has the other multipliers), and the Ritz values of the
// 2 x 2 projection (Saad, "Numerical Methods for Large Eigenvalue Problems", 2nd ed., SIAM
// 2011, sec. 5.1); the trivial multiplier is f . M f, f the vector field refined by that
// product. Each product is a forward difference of the flow from an iterate's own end.
// Scheduled so that no flow waits for a core (two cores): the start block's two products at
// the first iterate, beside the first two iterates' flows (any block is a start, and that
// iterate lies within the prediction's error of the orbit); the next block's two products and
// M f at the iterate that may be the last (an autonomous orbit's third, a forced one's
// second), beside its flow, the caller's sampling of the orbit riding on that flow (taken
// again at the orbit found if another iterate turns out to be the last); the Ritz values of
// that block are the estimate where they and the start block's are all below 1e-3, else one
// more block at the orbit. Eight flows of a period in four flows' time a point on stick-slip,
// against ten one after the other before, and the monodromy's 2 n.
// The step is taken only where the estimate confirms the contraction (every estimated
// non-trivial multiplier below `below`); the caller falls back on the arclength corrector
// otherwise, and near folds, Hopf points, period doublings and tori, whose multipliers reach
// the unit circle, it never applies. Natural-parameter stepping cannot turn round a fold: the
// arclength corrector does that.
// Not here: the branch's loop, events and files (orbit_branch.cpp, branch_events.cpp).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>

#include "study/orbit/branch_shooter.hpp"
#include "study/orbit/shooting.hpp"

namespace tribo::study::branch {

struct ReturnMapStep {
  bool ok = false;
  std::string why;            // when not ok
  Eigen::VectorXd z;          // (y0, T, p) with p the prediction's
  int iterations = 0;         // return-map iterations
  double residual = 0;        // |F| / (1 + |y0|)
  shooting::Floquet floquet;  // the estimated trivial multiplier and the two leading others
};

// The flow of an iterate (the scene at p, its flow, y0, T) done by the caller: it must return
// flow(y0, T) and may sample the trajectory on the way (the branch samples the orbit so). It
// runs on any core, beside the products, and must only read what it is given and write its
// own data; the last call was the orbit's.
using Alongside = std::function<Eigen::VectorXd(const io::Scene&, const shooting::Flow&,
                                                const Eigen::VectorXd&, double)>;

// From the prediction z_pred. Never throws: a scene that cannot be loaded at the predicted
// parameter or a failed step is a step not taken (`why`).
ReturnMapStep returnMapStep(const BranchShooter& shooter, const Eigen::VectorXd& z_pred,
                            double tolerance, double below, const Alongside& alongside = {});

}  // namespace tribo::study::branch
