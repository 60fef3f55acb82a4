#include "pneumachaos/analysis/linear_region.hpp"

#include <algorithm>
#include <cmath>

namespace pneumachaos {

LineFit fit_line(const std::vector<double>& y, std::size_t first, std::size_t last) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t k = first; k <= last && k < y.size(); ++k) {
    const double t = static_cast<double>(k);
    n += 1;
    st += t;
    sy += y[k];
    stt += t * t;
    sty += t * y[k];
  }
  LineFit f;
  const double den = n * stt - st * st;
  if (n < 2 || den == 0.0) return f;
  f.slope = (n * sty - st * sy) / den;
  f.intercept = (sy - f.slope * st) / n;
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
