#include "study/orbit/branch_return_map.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <exception>
#include <vector>

#include "study/orbit/picard.hpp"

namespace tribo::study::branch {

namespace {
// Subspace iterations before the Ritz values: one left the forced oscillator's damped pair
// 20% off, two bring it within 1e-4 (tests/study/branch_return_map_test.cpp).
constexpr int kSweeps = 2;
}  // namespace

ReturnMapStep returnMapStep(const BranchShooter& shooter, const Eigen::VectorXd& z_pred,
                            double tolerance, double below) {
  ReturnMapStep out;
  const OrbitCoordinates& coords = shooter.coordinates();
  const Eigen::Index n = coords.size();
  const double p = z_pred[n + 1];
  Eigen::VectorXd y = z_pred.head(n);
  double T = z_pred[n];
  try {
    const io::Scene at = shooter.sceneAt(p);
    const shooting::Flow flow(at.model, coords);
    const double h = std::min(at.model->options.time_step, 0.01 * T);
    shooting::PicardOutcome o;
    if (shooter.forced()) {
      T = shooter.forcedPeriod(at);
      o = shooting::picardForced(flow, y, T, tolerance);
    } else {
      o = shooting::picardAutonomous(flow, y, T, shooter.phase(), h, tolerance);
    }
    out.iterations = o.iterations;
    out.residual = o.residual;
    if (!o.converged) {
      out.why = "the return map did not converge at " + shooting::messageNumber(p) + " (residual " +
                shooting::messageNumber(o.residual) + ")";
      return out;
    }
    // Products with the monodromy in the unknowns over their scales, each a forward
    // difference of the flow from the orbit's own end.
    const Eigen::VectorXd scale = y.cwiseAbs().cwiseMax(shooter.floor());
    auto product = [&](const Eigen::VectorXd& u) {
      const double size = u.cwiseAbs().maxCoeff();
      const double eps = shooter.fdStep() / size;
      return Eigen::VectorXd(
          ((flow(y + eps * scale.cwiseProduct(u), T) - o.end) / eps).cwiseQuotient(scale));
    };
    // The flow's direction, deflated from the others (an autonomous orbit's trivial one). The
    // vector field's difference errs by about (h omega)^2, which the deflation would leak into
    // the others as a multiplier of that size: one product with M takes out all but the other
    // multipliers' part of that error (M f = f, the rest contracts), and gives the trivial one.
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    std::vector<std::complex<double>> values;
    if (!shooter.forced()) {
      f = shooting::vectorField(flow, y, h).cwiseQuotient(scale).normalized();
      const Eigen::VectorXd Mf = product(f);
      values.emplace_back(f.dot(Mf));
      f = Mf.normalized();
    }
    auto deflated = [&](Eigen::VectorXd u) { return Eigen::VectorXd(u - f * f.dot(u)); };
    const Eigen::Index block = std::min<Eigen::Index>(2, n - (shooter.forced() ? 0 : 1));
    if (block < 1) {
      out.why = "no multiplier besides the trivial one";
      return out;
    }
    // A start that is no special direction: sin and cos of the index.
    Eigen::MatrixXd W(n, block);
    for (Eigen::Index i = 0; i < n; ++i) {
      W(i, 0) = std::sin(1.0 + static_cast<double>(i));
      if (block > 1) W(i, 1) = std::cos(1.0 + 2.0 * static_cast<double>(i));
    }
    auto orthonormal = [&](const Eigen::MatrixXd& M) {
      Eigen::MatrixXd D(n, block);
      for (Eigen::Index j = 0; j < block; ++j) D.col(j) = deflated(M.col(j));
      return Eigen::MatrixXd(Eigen::HouseholderQR<Eigen::MatrixXd>(D).householderQ() *
                             Eigen::MatrixXd::Identity(n, block));
    };
    W = orthonormal(W);
    Eigen::MatrixXd MW(n, block);
    for (int sweep = 0; sweep < kSweeps; ++sweep) {
      for (Eigen::Index j = 0; j < block; ++j) MW.col(j) = product(W.col(j));
      W = orthonormal(MW);
    }
    for (Eigen::Index j = 0; j < block; ++j) MW.col(j) = deflated(product(W.col(j)));
    const Eigen::MatrixXd H = W.transpose() * MW;
    const Eigen::VectorXcd ritz = Eigen::EigenSolver<Eigen::MatrixXd>(H, false).eigenvalues();
    for (Eigen::Index j = 0; j < ritz.size(); ++j) values.push_back(ritz[j]);
    out.floquet = shooting::classify(values, !shooter.forced());
    if (!(out.floquet.largest < below)) {
      out.why = "the orbit at " + shooting::messageNumber(p) +
                " contracts too slowly for the return map (a multiplier of modulus " +
                shooting::messageNumber(out.floquet.largest) + ")";
      return out;
    }
  } catch (const std::exception& e) {  // a failed step, or p outside the scene's range
    out.why = e.what();
    return out;
  }
  out.z.resize(n + 2);
  out.z << y, T, p;
  out.ok = true;
  return out;
}

}  // namespace tribo::study::branch
