#include "study/orbit/branch_return_map.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <exception>
#include <functional>
#include <vector>

#include "study/orbit/picard.hpp"

namespace tribo::study::branch {

namespace {
// Subspace iterations before the Ritz values: one left the forced oscillator's damped pair
// 20% off, two bring it within 1e-4 (tests/study/branch_return_map_test.cpp).
constexpr int kSweeps = 2;
// Where the start block's Ritz values and those after one iteration are all below this, the
// second iteration is left out: every non-trivial multiplier is then far below the return
// map's bound (0.05, orbit_branch.cpp), and its estimate (the finite differences' noise on a
// stick-slip orbit, about 1e-6) is no better for another flow.
constexpr double kNegligible = 1e-3;

// Products with the monodromy at an iterate (y, T) of the return map, in the unknowns over
// their scales: M u = (phi_T(y + eps s u) - phi_T(y)) / (eps s), s the scales; the flow's end
// phi_T(y), the vector field f there (autonomous) and, per column u of W, the moved flow's end
// (empty until computed).
struct Products {
  Eigen::VectorXd y, end, scale, f;
  double T = 0;
  Eigen::MatrixXd W;
  std::vector<Eigen::VectorXd> moved;
};
}  // namespace

ReturnMapStep returnMapStep(const BranchShooter& shooter, const Eigen::VectorXd& z_pred,
                            double tolerance, double below, const Alongside& alongside) {
  ReturnMapStep out;
  const OrbitCoordinates& coords = shooter.coordinates();
  const Eigen::Index n = coords.size();
  const double p = z_pred[n + 1];
  Eigen::VectorXd y = z_pred.head(n);
  double T = z_pred[n];
  const bool autonomous = !shooter.forced();
  const Eigen::Index block = std::min<Eigen::Index>(2, n - (autonomous ? 1 : 0));
  if (block < 1) {
    out.why = "no multiplier besides the trivial one";
    return out;
  }
  try {
    const io::Scene at = shooter.sceneAt(p);
    const shooting::Flow flow(at.model, coords);
    const double h = std::min(at.model->options.time_step, 0.01 * T);
    auto epsFor = [&](const Eigen::VectorXd& u) {
      return shooter.fdStep() / u.cwiseAbs().maxCoeff();
    };
    auto moved = [&](const Products& at_y, const Eigen::VectorXd& u) {
      return flow(at_y.y + epsFor(u) * at_y.scale.cwiseProduct(u), at_y.T);
    };
    // The columns' products, from their moved ends.
    auto productsOf = [&](const Products& at_y) {
      Eigen::MatrixXd MW(n, at_y.W.cols());
      for (Eigen::Index j = 0; j < at_y.W.cols(); ++j)
        MW.col(j) = ((at_y.moved[static_cast<std::size_t>(j)] - at_y.end) / epsFor(at_y.W.col(j)))
                        .cwiseQuotient(at_y.scale);
      return MW;
    };
    // An orthonormal basis of the block's columns with g deflated (the flow's direction,
    // whose multiplier is the trivial one: M f = f, so in a basis (f, rest) M is block
    // triangular and Q M Q, Q = I - g g^T, has the others).
    auto orthonormal = [&](const Eigen::MatrixXd& M, const Eigen::VectorXd& g) {
      Eigen::MatrixXd D(n, block);
      for (Eigen::Index j = 0; j < block; ++j) D.col(j) = M.col(j) - g * g.dot(M.col(j));
      return Eigen::MatrixXd(Eigen::HouseholderQR<Eigen::MatrixXd>(D).householderQ() *
                             Eigen::MatrixXd::Identity(n, block));
    };
    auto productsAt = [&](const Eigen::VectorXd& z, double period) {
      Products q;
      q.y = z;
      q.T = period;
      q.scale = z.cwiseAbs().cwiseMax(shooter.floor());
      q.f = autonomous ? Eigen::VectorXd(
                             shooting::vectorField(flow, z, h).cwiseQuotient(q.scale).normalized())
                       : Eigen::VectorXd(Eigen::VectorXd::Zero(n));
      return q;
    };
    auto flowOf = [&](const Eigen::VectorXd& z, double period) {
      return alongside ? alongside(at, flow, z, period) : flow(z, period);
    };

    // The subspace iteration's first block (sin and cos of the index: no special direction)
    // is multiplied at the first iterate, its two products beside the first two iterates'
    // flows (a forced one's both beside the first), on the core they leave idle: any block is
    // a start, and the iterate lies within the prediction's error of the orbit. From the
    // iterate that may be the last (an autonomous orbit's third: the first two move the
    // phase's error into T and take it out again, picard.hpp; a forced one's second), the next
    // block's products and M f run beside its flow, as if it were the orbit (it is, on a
    // stick-slip stretch), else at the orbit found. f is the vector field by a difference,
    // which errs by about (h omega)^2; the deflation would leak that error into the others as
    // a multiplier of that size, so f is refined by its product (M f = f, the rest
    // contracts), which also gives the trivial multiplier.
    const int hopeful = autonomous ? 2 : 1;
    Products first, last;
    std::size_t first_done = 0;
    auto startBlock = [&](const Eigen::VectorXd& z, double period) {
      first = productsAt(z, period);
      Eigen::MatrixXd W(n, block);
      for (Eigen::Index i = 0; i < n; ++i) {
        W(i, 0) = std::sin(1.0 + static_cast<double>(i));
        if (block > 1) W(i, 1) = std::cos(1.0 + 2.0 * static_cast<double>(i));
      }
      first.W = orthonormal(W, first.f);
      first.moved.assign(static_cast<std::size_t>(block), Eigen::VectorXd());
      first_done = 0;
    };
    // Runs `own` (an iterate's flow) and the first block's next `count` products side by side.
    auto withFirst = [&](std::size_t count, const std::function<Eigen::VectorXd()>& own) {
      count = std::min(count, static_cast<std::size_t>(block) - first_done);
      Eigen::VectorXd end;
      shooting::parallelColumns(
          static_cast<Eigen::Index>(1 + count), shooter.threads(), [&](Eigen::Index j) {
            if (j == 0) {
              end = own();
            } else {
              const std::size_t c = first_done + static_cast<std::size_t>(j - 1);
              first.moved[c] = moved(first, first.W.col(static_cast<Eigen::Index>(c)));
            }
          });
      first_done += count;
      return end;
    };
    // The next block (from the first's products) and M f at (z, period), beside its flow.
    Eigen::VectorXd Mf_moved;
    auto lastRound = [&](const Eigen::VectorXd& z, double period) {
      withFirst(static_cast<std::size_t>(block), [] { return Eigen::VectorXd(); });
      last = productsAt(z, period);
      last.W = orthonormal(productsOf(first), last.f);
      last.moved.assign(static_cast<std::size_t>(block), Eigen::VectorXd());
      const Eigen::Index count = 1 + block + (autonomous ? 1 : 0);
      shooting::parallelColumns(count, shooter.threads(), [&](Eigen::Index j) {
        if (j == 0)
          last.end = flowOf(z, period);
        else if (j <= block)
          last.moved[static_cast<std::size_t>(j - 1)] = moved(last, last.W.col(j - 1));
        else
          Mf_moved = moved(last, last.f);
      });
      return last.end;
    };
    const shooting::IterateFlow iterateFlow = [&](const Eigen::VectorXd& z, double period,
                                                  int iterate) {
      if (iterate >= hopeful) return lastRound(z, period);
      if (iterate == 0) startBlock(z, period);
      // One product beside each flow before the hopeful iterate, the rest beside the last.
      const std::size_t count = iterate + 1 == hopeful ? static_cast<std::size_t>(block) : 1;
      const Eigen::VectorXd end = withFirst(count, [&] { return flow(z, period); });
      if (iterate == 0) first.end = end;
      return end;
    };

    shooting::PicardOutcome o;
    if (autonomous) {
      o = shooting::picardAutonomous(flow, y, T, shooter.phase(), h, tolerance, iterateFlow);
    } else {
      T = shooter.forcedPeriod(at);
      o = shooting::picardForced(flow, y, T, tolerance, iterateFlow);
    }
    out.iterations = o.iterations;
    out.residual = o.residual;
    if (!o.converged) {
      out.why = "the return map did not converge at " + shooting::messageNumber(p) + " (residual " +
                shooting::messageNumber(o.residual) + ")";
      return out;
    }
    // Converged before the hopeful iterate, or on one before the last: the round there.
    if (!(last.T == T && last.y.size() == y.size() && last.y == y)) lastRound(y, T);

    std::vector<std::complex<double>> values;
    Eigen::VectorXd f = last.f;
    if (autonomous) {
      const Eigen::VectorXd Mf = ((Mf_moved - last.end) / epsFor(last.f)).cwiseQuotient(last.scale);
      values.emplace_back(f.dot(Mf));
      f = Mf.normalized();
    }
    // The Ritz values of a block W and its products MW (deflated): Saad, "Numerical Methods
    // for Large Eigenvalue Problems", 2nd ed., SIAM 2011, sec. 5.1.
    auto ritz = [&](const Eigen::MatrixXd& W, Eigen::MatrixXd MW) {
      for (Eigen::Index j = 0; j < block; ++j) MW.col(j) -= f * f.dot(MW.col(j));
      return Eigen::VectorXcd(
          Eigen::EigenSolver<Eigen::MatrixXd>(W.transpose() * MW, false).eigenvalues());
    };
    auto negligible = [](const Eigen::VectorXcd& v) {
      return v.size() == 0 || v.cwiseAbs().maxCoeff() < kNegligible;
    };
    Eigen::VectorXcd values_before = ritz(first.W, productsOf(first));
    Eigen::MatrixXd W = last.W, MW = productsOf(last);
    Eigen::VectorXcd estimate = ritz(W, MW);
    // Further rounds at the orbit, each block's products one a core.
    for (int sweep = 1; sweep < kSweeps; ++sweep) {
      if (negligible(values_before) && negligible(estimate)) break;
      values_before = estimate;
      W = orthonormal(MW, f);
      Eigen::MatrixXd next(n, block);
      shooting::parallelColumns(block, shooter.threads(), [&](Eigen::Index j) {
        next.col(j) =
            ((moved(last, W.col(j)) - last.end) / epsFor(W.col(j))).cwiseQuotient(last.scale);
      });
      MW = next;
      estimate = ritz(W, MW);
    }
    for (Eigen::Index j = 0; j < estimate.size(); ++j) values.push_back(estimate[j]);
    out.floquet = shooting::classify(values, autonomous);
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
