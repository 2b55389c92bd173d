#include "study/orbit/branch_switch.hpp"

#include <algorithm>
#include <cmath>

namespace tribo::study {

std::string branchSwitchName(BranchSwitch kind) {
  switch (kind) {
    case BranchSwitch::kNone:
      return "none";
    case BranchSwitch::kPeriodDoubling:
      return "period_doubling";
    case BranchSwitch::kBranchPoint:
      return "branch_point";
  }
  return "none";
}

std::string switchWords(BranchSwitch kind) {
  return kind == BranchSwitch::kPeriodDoubling ? "period doubling" : "branch point";
}

std::optional<BranchEvent> switchEvent(const std::vector<BranchEvent>& events, BranchSwitch kind) {
  for (const BranchEvent& e : events) {
    if (kind == BranchSwitch::kPeriodDoubling && e.kind == BranchEventKind::kPeriodDoubling)
      return e;
    if (kind == BranchSwitch::kBranchPoint && e.kind == BranchEventKind::kStabilityChange &&
        std::none_of(events.begin(), events.end(), [&](const BranchEvent& f) {
          return f.kind == BranchEventKind::kFold && f.after == e.after;
        }))
      return e;
  }
  return std::nullopt;
}

CriticalMode criticalMode(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& flow,
                          BranchSwitch kind, bool autonomous) {
  const Eigen::EigenSolver<Eigen::MatrixXd> es(monodromy);
  CriticalMode m;
  if (es.info() != Eigen::Success) return m;
  const Eigen::Index count = monodromy.rows();
  // A real eigenvector from a complex one: turned so that its largest entry is real.
  auto realVector = [&](Eigen::Index i) {
    Eigen::VectorXcd v = es.eigenvectors().col(i);
    Eigen::Index k = 0;
    v.cwiseAbs().maxCoeff(&k);
    v *= std::conj(v[k]) / std::abs(v[k]);
    return Eigen::VectorXd(v.real());
  };
  const double sign = kind == BranchSwitch::kPeriodDoubling ? -1.0 : 1.0;
  Eigen::Index trivial = -1;
  if (autonomous && kind == BranchSwitch::kBranchPoint && flow.norm() > 0.0) {
    double parallel = -1.0;
    for (Eigen::Index i = 0; i < count; ++i) {
      if (std::abs(es.eigenvalues()[i] - 1.0) > 0.5) continue;
      const Eigen::VectorXd v = realVector(i);
      const double c = std::abs(v.dot(flow)) / (v.norm() * flow.norm());
      if (c > parallel) {
        parallel = c;
        trivial = i;
      }
    }
  }
  double nearest = INFINITY;
  Eigen::Index pick = -1;
  for (Eigen::Index i = 0; i < count; ++i) {
    const std::complex<double> mu = es.eigenvalues()[i];
    if (i == trivial || !(sign * mu.real() > 0.0)) continue;
    if (std::abs(mu - sign) < nearest) {
      nearest = std::abs(mu - sign);
      pick = i;
    }
  }
  if (pick < 0) return m;
  m.ok = true;
  m.mu = es.eigenvalues()[pick];
  m.v = realVector(pick);
  return m;
}

Eigen::VectorXd normalizedMode(Eigen::VectorXd v, const OrbitCoordinates& coords,
                               Eigen::Index observed) {
  double largest = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (const char c = coords.kind(i); c == 'x' || c == 'r')
      largest = std::max(largest, std::abs(v[i]));
  if (!(largest > 0.0)) largest = v.cwiseAbs().maxCoeff();
  v /= largest;
  if (v[observed] < 0.0) v = -v;
  return v;
}

}  // namespace tribo::study
