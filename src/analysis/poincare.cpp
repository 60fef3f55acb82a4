#include "pneumachaos/analysis/poincare.hpp"

#include <cmath>

#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

PoincareSection poincare_section(std::span<const double> x, std::size_t delay, double rate_Hz,
                                 double level) {
  if (delay == 0) throw Error("poincare", "the delay must be at least 1");
  PoincareSection s;
  s.level = std::isnan(level) ? mean_of(x) : level;
  if (x.size() <= 2 * delay + 1) return s;
  const std::size_t n = x.size() - 2 * delay;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (x[i] < s.level && x[i + 1] >= s.level) {
      const double u = (s.level - x[i]) / (x[i + 1] - x[i]);
      const auto lerp = [&](std::size_t j) { return x[j] + u * (x[j + 1] - x[j]); };
      s.points.push_back({lerp(i + delay), lerp(i + 2 * delay)});
      s.time_s.push_back((static_cast<double>(i) + u) / rate_Hz);
    }
  }
  return s;
}

std::vector<std::array<double, 2>> successive_maxima(std::span<const double> x) {
  std::vector<double> maxima;
  for (std::size_t i : maxima_indices(x)) {
    double m = x[i];
    if (i > 0 && i + 1 < x.size()) {
      // Vertex of the parabola through the three samples around the maximum.
      const double a = x[i - 1], b = x[i], c = x[i + 1];
      const double den = a - 2.0 * b + c;
      if (den < 0.0) m = b - 0.125 * (c - a) * (c - a) / den;
    }
    maxima.push_back(m);
  }
  std::vector<std::array<double, 2>> pairs;
  for (std::size_t k = 0; k + 1 < maxima.size(); ++k) pairs.push_back({maxima[k], maxima[k + 1]});
  return pairs;
}

}  // namespace pneumachaos
