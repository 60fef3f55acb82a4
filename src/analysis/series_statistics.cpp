#include "pneumachaos/analysis/series_statistics.hpp"

#include <cmath>
#include <numeric>

namespace pneumachaos {

double mean_of(std::span<const double> x) {
  return x.empty() ? 0.0 : std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

double standard_deviation(std::span<const double> x) {
  const double m = mean_of(x);
  double v = 0.0;
  for (double xi : x) v += (xi - m) * (xi - m);
  return x.empty() ? 0.0 : std::sqrt(v / static_cast<double>(x.size()));
}

std::vector<std::size_t> maxima_indices(std::span<const double> x) {
  // Peaks separated by a fall of at least a quarter standard deviation (hysteresis), so that
  // measurement noise riding on an oscillation does not count as extra maxima.
  const double h = 0.25 * standard_deviation(x);
  std::vector<std::size_t> peaks;
  bool rising = true;
  double extreme = x.empty() ? 0.0 : x[0];
  std::size_t at = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (rising) {
      if (x[i] > extreme) {
        extreme = x[i];
        at = i;
      } else if (x[i] < extreme - h) {
        peaks.push_back(at);
        rising = false;
        extreme = x[i];
      }
    } else if (x[i] < extreme) {
      extreme = x[i];
    } else if (x[i] > extreme + h) {
      rising = true;
      extreme = x[i];
      at = i;
    }
  }
  return peaks;
}

double mean_maxima_spacing(std::span<const double> x) {
  const auto peaks = maxima_indices(x);
  return peaks.size() >= 2 ? static_cast<double>(peaks.back() - peaks.front()) /
                                 static_cast<double>(peaks.size() - 1)
                           : static_cast<double>(x.size());
}

}  // namespace pneumachaos
