#include "divergence_uncertainty.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "analysis/linear_region.hpp"

namespace pneumachaos::detail {

namespace {

// Mean curve of blocks [first, last).
std::vector<double> curve_of(const std::vector<std::vector<double>>& sum,
                             const std::vector<std::vector<double>>& count, std::size_t first,
                             std::size_t last) {
  const std::size_t points = sum.front().size();
  std::vector<double> S(points, 0.0);
  for (std::size_t k = 0; k < points; ++k) {
    double s = 0.0, c = 0.0;
    for (std::size_t b = first; b < last; ++b) {
      s += sum[b][k];
      c += count[b][k];
    }
    S[k] = c > 0 ? s / c : 0.0;
  }
  return S;
}

// Student's t, two-sided 95 %, for 1..9 degrees of freedom (any t table, e.g. Abramowitz &
// Stegun 1964, table 26.10); the normal's kNormal95 beyond (the table's values are t's
// definition, not tuning).
double t95(std::size_t dof) {
  static constexpr std::array<double, 9> t{12.706, 4.303, 3.182, 2.776, 2.571,
                                           2.447,  2.365, 2.306, 2.262};
  return dof >= 1 && dof <= t.size() ? t[dof - 1] : kNormal95;
}

}  // namespace

SegmentSlopes segment_slopes(const std::vector<std::vector<double>>& sum,
                             const std::vector<std::vector<double>>& count, std::size_t segments,
                             std::size_t spacing, double tolerance, std::size_t record_first,
                             std::size_t record_last) {
  SegmentSlopes r;
  const std::size_t blocks = sum.size();
  segments = std::clamp<std::size_t>(segments, 2, blocks);
  for (std::size_t s = 0; s < segments; ++s) {
    const std::vector<double> curve =
        curve_of(sum, count, s * blocks / segments, (s + 1) * blocks / segments);
    const LinearRegion region = find_linear_region(curve, spacing, tolerance);
    // A segment without a rising region of its own (its curve has a fifth of the references,
    // so noise can break the run of agreeing slopes) is fitted over the whole record's window:
    // left out, it would drop exactly the segments that disagree. Without a window of the
    // record's either, it has no slope (NaN), not a slope of 0.
    const bool record_window = record_last > record_first;
    r.slopes.push_back(region.found    ? region.slope
                       : record_window ? fit_line(curve, record_first, record_last).slope
                                       : std::numeric_limits<double>::quiet_NaN());
    r.without_region += region.found ? 0 : 1;
  }
  const double n = static_cast<double>(segments);
  const double mean = std::accumulate(r.slopes.begin(), r.slopes.end(), 0.0) / n;
  double var = 0.0;
  for (double v : r.slopes) var += (v - mean) * (v - mean);
  r.standard_error = std::sqrt(var / (n - 1.0) / n) * t95(segments - 1) / kNormal95;
  return r;
}

}  // namespace pneumachaos::detail
