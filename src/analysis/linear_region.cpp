#include "pneumachaos/analysis/linear_region.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace pneumachaos {

// Least squares by Eigen's QR of the design matrix (1, k): no cancellation of raw sums.
LineFit fit_line(const std::vector<double>& y, std::size_t first, std::size_t last) {
  LineFit f;
  if (first >= y.size() || last <= first) return f;
  const std::size_t end = std::min(last, y.size() - 1);
  const auto n = static_cast<Eigen::Index>(end - first + 1);
  if (n < 2) return f;
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd values(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    design(i, 0) = 1.0;
    design(i, 1) = static_cast<double>(first) + static_cast<double>(i);
    values(i) = y[first + static_cast<std::size_t>(i)];
  }
  const Eigen::Vector2d c = design.colPivHouseholderQr().solve(values);
  f.intercept = c(0);
  f.slope = c(1);
  return f;
}

LinearRegion find_linear_region(const std::vector<double>& y, std::size_t spacing,
                                double tolerance) {
  LinearRegion best;
  if (y.size() < 4) return best;
  spacing = std::max<std::size_t>(1, std::min(spacing, (y.size() - 1) / 4));
  std::vector<std::size_t> at;
  for (std::size_t k = 0; k < y.size(); k += spacing) at.push_back(k);
  std::vector<double> slope(at.size() - 1);
  for (std::size_t s = 0; s + 1 < at.size(); ++s) {
    slope[s] = (y[at[s + 1]] - y[at[s]]) / static_cast<double>(at[s + 1] - at[s]);
  }
  // Longest run of rising segments whose slopes agree with their running mean.
  std::size_t best_len = 0;
  for (std::size_t a = 0; a < slope.size(); ++a) {
    if (!(slope[a] > 0.0)) continue;
    double total = slope[a];
    std::size_t b = a + 1;
    for (; b < slope.size(); ++b) {
      const double mean = total / static_cast<double>(b - a);
      if (!(slope[b] > 0.0) || std::abs(slope[b] - mean) > tolerance * mean) break;
      total += slope[b];
    }
    const std::size_t len = b - a;
    if (len >= 3 && len > best_len) {
      best_len = len;
      best.found = true;
      best.first = at[a];
      best.last = at[b];
    }
  }
  if (best.found) {
    const LineFit f = fit_line(y, best.first, best.last);
    best.slope = f.slope;
    best.intercept = f.intercept;
  }
  return best;
}

}  // namespace pneumachaos
