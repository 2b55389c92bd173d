#include "study/orbit/branch_shooter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace tribo::study::branch {

std::string assignment(const std::string& name, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return name + "=" + buf;
}

Eigen::VectorXd unitTangent(const Eigen::MatrixXd& A, const Eigen::VectorXd& along,
                            const Eigen::VectorXd& w) {
  const Eigen::Index rows = A.rows(), cols = A.cols();
  Eigen::MatrixXd J(rows + 1, cols);
  J.topRows(rows) = A * w.asDiagonal();
  J.row(rows) = along.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows + 1);
  rhs[rows] = 1.0;
  Eigen::VectorXd t = J.colPivHouseholderQr().solve(rhs);
  t.normalize();
  if (t.dot(along) < 0.0) t = -t;
  return t;
}

Correction newtonWithRow(const BranchShooter& shooter, const Eigen::VectorXd& z0,
                         const Eigen::VectorXd& row, double value, double reach,
                         const Eigen::VectorXd& w, int max_iterations, double tolerance) {
  Correction c;
  c.z = z0;
  const Eigen::Index n = z0.size() - 2;
  for (int it = 0;; ++it) {
    try {
      shooter.evaluate(c.z, c.F, c.A, c.monodromy);
    } catch (const std::exception& e) {  // OrbitError, io::SceneError
      c.why = e.what();
      return c;
    }
    c.iterations = it;
    const double gap = row.dot(c.z) - value;
    c.residual = std::hypot(c.F.norm(), gap) / (1.0 + c.z.head(n).norm());
    if (c.residual <= tolerance) {
      c.ok = true;
      return c;
    }
    if (it == max_iterations) {
      c.why = "Newton's iteration did not converge in " + std::to_string(max_iterations) +
              " iterations (residual " + shooting::messageNumber(c.residual) + ")";
      return c;
    }
    Eigen::MatrixXd J(n + 2, n + 2);
    J.topRows(n + 1) = c.A;
    J.row(n + 1) = row.transpose();
    Eigen::VectorXd rhs(n + 2);
    rhs.head(n + 1) = -c.F;
    rhs[n + 1] = -gap;
    const Eigen::VectorXd dz = J.colPivHouseholderQr().solve(rhs);
    // A damped step: the period changes by at most a quarter of itself.
    const double T = c.z[n];
    const double scale = std::min(1.0, 0.25 * T / std::max(std::abs(dz[n]), 1e-300));
    c.z += scale * dz;
    if (!(c.z[n] > 0.0) || !c.z.allFinite()) {
      c.why =
          "Newton's iteration left the orbit (period " + shooting::messageNumber(c.z[n]) + " s)";
      return c;
    }
    const double moved = (c.z - z0).cwiseQuotient(w).norm();
    if (moved > reach) {
      c.why = "the correction (" + shooting::messageNumber(moved) +
              ") went farther than the step (" + shooting::messageNumber(reach) + ")";
      return c;
    }
  }
}

Correction correct(const BranchShooter& shooter, const Eigen::VectorXd& z_pred,
                   const Eigen::VectorXd& d, double ds, const Eigen::VectorXd& w,
                   int max_iterations, double tolerance) {
  const Eigen::VectorXd row = d.cwiseQuotient(w);
  return newtonWithRow(shooter, z_pred, row, row.dot(z_pred), ds, w, max_iterations, tolerance);
}

Correction solveFixedAmplitude(const BranchShooter& shooter, const Eigen::VectorXd& z0,
                               Eigen::Index index, double value, int max_iterations,
                               double tolerance) {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(z0.size());
  row[index] = 1.0;
  return newtonWithRow(shooter, z0, row, value, INFINITY, Eigen::VectorXd::Ones(z0.size()),
                       max_iterations, tolerance);
}

Eigen::VectorXd stateScales(const shooting::Flow& flow, const OrbitCoordinates& coords,
                            const Eigen::VectorXd& y0, double T, const Eigen::VectorXd& floor) {
  Eigen::VectorXd lo = y0, hi = y0;
  flow(y0, T, [&](double, const State& state) {
    const Eigen::VectorXd y = coords.toVector(state);
    lo = lo.cwiseMin(y);
    hi = hi.cwiseMax(y);
  });
  const Eigen::VectorXd range = hi - lo;
  auto kind = [&](Eigen::Index i) { return coords.kind(i); };
  std::map<char, double> largest;
  for (Eigen::Index i = 0; i < range.size(); ++i)
    largest[kind(i)] = std::max(largest[kind(i)], range[i]);
  Eigen::VectorXd w(range.size());
  for (Eigen::Index i = 0; i < range.size(); ++i) {
    const double group = largest[kind(i)];
    w[i] = std::max({range[i], 1e-3 * group, 1e-3 * floor[i]});
  }
  return w;
}

}  // namespace tribo::study::branch
