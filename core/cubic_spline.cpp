#include "core/cubic_spline.hpp"

namespace tribo {

std::vector<double> naturalSplineCurvatures(const std::vector<std::pair<double, double>>& p) {
  const std::size_t n = p.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  // Unknowns M_1 .. M_{n-2}: sub-diagonal h_{i-1}, diagonal 2 (h_{i-1} + h_i), super h_i.
  std::vector<double> diag(n, 0.0), rhs(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = p[i].first - p[i - 1].first, h1 = p[i + 1].first - p[i].first;
    diag[i] = 2.0 * (h0 + h1);
    rhs[i] = 6.0 * ((p[i + 1].second - p[i].second) / h1 - (p[i].second - p[i - 1].second) / h0);
  }
  // Forward elimination: row i's sub-diagonal h_{i-1} against row i-1's super h_{i-1}.
  for (std::size_t i = 2; i + 1 < n; ++i) {
    const double h = p[i].first - p[i - 1].first;
    const double w = h / diag[i - 1];
    diag[i] -= w * h;
    rhs[i] -= w * rhs[i - 1];
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    const double super = i + 2 < n ? (p[i + 1].first - p[i].first) * m[i + 1] : 0.0;
    m[i] = (rhs[i] - super) / diag[i];
  }
  return m;
}

double splineValue(const std::vector<std::pair<double, double>>& p, const std::vector<double>& m,
                   std::size_t i, double t) {
  const double h = p[i + 1].first - p[i].first;
  const double a = (p[i + 1].first - t) / h, b = 1.0 - a;
  return a * p[i].second + b * p[i + 1].second +
         ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0;
}

double splineSlope(const std::vector<std::pair<double, double>>& p, const std::vector<double>& m,
                   std::size_t i, double t) {
  const double h = p[i + 1].first - p[i].first;
  const double a = (p[i + 1].first - t) / h, b = 1.0 - a;
  return (p[i + 1].second - p[i].second) / h - (3.0 * a * a - 1.0) * h * m[i] / 6.0 +
         (3.0 * b * b - 1.0) * h * m[i + 1] / 6.0;
}

double splineCurvature(const std::vector<std::pair<double, double>>& p,
                       const std::vector<double>& m, std::size_t i, double t) {
  const double a = (p[i + 1].first - t) / (p[i + 1].first - p[i].first);
  return a * m[i] + (1.0 - a) * m[i + 1];
}

double splineIntegral(const std::vector<std::pair<double, double>>& p, const std::vector<double>& m,
                      std::size_t i, double t) {
  const double h = p[i + 1].first - p[i].first;
  const double a = (p[i + 1].first - t) / h, b = 1.0 - a;
  const double a2 = a * a, b2 = b * b;
  return h * ((1.0 - a2) * p[i].second + b2 * p[i + 1].second) / 2.0 +
         h * h * h *
             (m[i] * ((1.0 - a2 * a2) / 4.0 - (1.0 - a2) / 2.0) +
              m[i + 1] * (b2 * b2 / 4.0 - b2 / 2.0)) /
             6.0;
}

}  // namespace tribo
