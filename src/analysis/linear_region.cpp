#include "analysis/linear_region.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>

namespace pneumachaos {
namespace {

// A run holds at least kMinSegments agreeing segments (agreeing_runs' contract: "at least
// three segments"). The spacing is shrunk so that the curve has at least kMinSegmentsPerCurve
// segments, one more than a run needs.
constexpr std::size_t kMinSegments = 3;
constexpr std::size_t kMinSegmentsPerCurve = 4;

// rising_slopes finds a spread only from this many slopes (its contract: "at least three").
constexpr std::size_t kMinSlopes = 3;

// rising_slopes reads the curve until it first covers this share of its rise (the header's
// "90 %": the saturated top is no divergence), and reports these quantiles of the slopes
// (SlopeSpread: "10 % and 90 % quantiles").
constexpr double kRiseShare = 0.9;
constexpr double kLowQuantile = 0.1;
constexpr double kHighQuantile = 0.9;

// The first index at which the curve covers kRiseShare of its rise from y[0] to its maximum:
// past it the curve is at its saturated top, where a rise is the top's own wobble (e.g. the
// mean distance modulated at the orbital period), not divergence.
std::size_t saturation_index(const std::vector<double>& y) {
  if (y.empty()) return 0;
  const double top = *std::max_element(y.begin(), y.end());
  const double reach = y.front() + kRiseShare * (top - y.front());
  std::size_t end = 0;
  while (end < y.size() && y[end] < reach) ++end;
  return end;
}

}  // namespace

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

std::vector<LinearRegion> agreeing_runs(const std::vector<double>& y, std::size_t spacing,
                                        double tolerance) {
  std::vector<LinearRegion> runs;
  if (y.size() < kMinSegmentsPerCurve) return runs;
  spacing = std::max<std::size_t>(1, std::min(spacing, (y.size() - 1) / kMinSegmentsPerCurve));
  std::vector<std::size_t> at;
  for (std::size_t k = 0; k < y.size(); k += spacing) at.push_back(k);
  std::vector<double> slope(at.size() - 1);
  for (std::size_t s = 0; s + 1 < at.size(); ++s) {
    slope[s] = (y[at[s + 1]] - y[at[s]]) / static_cast<double>(at[s + 1] - at[s]);
  }
  // From each rising segment, the run of segments whose slopes agree with their running mean.
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // segments [a, b)
  for (std::size_t a = 0; a < slope.size(); ++a) {
    if (!(slope[a] > 0.0)) continue;
    double total = slope[a];
    std::size_t b = a + 1;
    for (; b < slope.size(); ++b) {
      const double mean = total / static_cast<double>(b - a);
      if (!(slope[b] > 0.0) || std::abs(slope[b] - mean) > tolerance * mean) break;
      total += slope[b];
    }
    if (b - a >= kMinSegments) spans.emplace_back(a, b);
  }
  // Only the runs no other run contains (the scan from inside a run mostly ends where it does).
  for (const auto& run : spans) {
    const bool inside = std::any_of(spans.begin(), spans.end(), [&](const auto& o) {
      return o != run && o.first <= run.first && run.second <= o.second;
    });
    if (inside) continue;
    LinearRegion r;
    r.found = true;
    r.first = at[run.first];
    r.last = at[run.second];
    const LineFit f = fit_line(y, r.first, r.last);
    r.slope = f.slope;
    r.intercept = f.intercept;
    runs.push_back(r);
  }
  return runs;
}

LinearRegion find_linear_region(const std::vector<double>& y, std::size_t spacing,
                                double tolerance) {
  LinearRegion best;
  // The longest run on the rise; ties: the earlier one (runs are in the order of their first
  // segment).
  const std::size_t top = saturation_index(y);
  for (const LinearRegion& r : agreeing_runs(y, spacing, tolerance)) {
    if (r.first >= top) break;
    if (!best.found || r.last - r.first > best.last - best.first) best = r;
  }
  return best;
}

SlopeSpread rising_slopes(const std::vector<double>& y, std::size_t w) {
  SlopeSpread r;
  if (y.size() < 2 || w == 0) return r;
  const std::size_t end = saturation_index(y);
  std::vector<double> slopes;
  for (std::size_t k = 0; k + w <= end && k + w < y.size(); ++k) {
    slopes.push_back((y[k + w] - y[k]) / static_cast<double>(w));
  }
  if (slopes.size() < kMinSlopes) return r;
  std::sort(slopes.begin(), slopes.end());
  const auto at = [&](double q) {
    return slopes[static_cast<std::size_t>(q * static_cast<double>(slopes.size() - 1) + 0.5)];
  };
  r.found = true;
  r.median = at(0.5);
  r.low = at(kLowQuantile);
  r.high = at(kHighQuantile);
  return r;
}

}  // namespace pneumachaos
