#include "pneumachaos/analysis/series_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace pneumachaos {
namespace {

// A maximum counts after a fall of kHysteresisSds standard deviations, or of kNoiseRangeSds
// sd of a known white noise (its range over about a hundred samples), whichever is larger
// (docs/notes/analysis.md "Noise floor", Maxima).
constexpr double kHysteresisSds = 0.25;
constexpr double kNoiseRangeSds = 6.0;

// The centred window [lo, hi) of `width` samples around sample i of n: from i - width / 2,
// cut at the record's end (so shorter at the ends).
std::pair<std::size_t, std::size_t> centred_window(std::size_t i, std::size_t n,
                                                   std::size_t width) {
  const std::size_t half = width / 2;
  const std::size_t lo = i >= half ? i - half : 0;
  return {lo, std::min(n, lo + std::max<std::size_t>(width, 1))};
}

}  // namespace

double mean_of(std::span<const double> x) {
  return x.empty() ? 0.0 : std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

double standard_deviation(std::span<const double> x) {
  const double m = mean_of(x);
  double v = 0.0;
  for (double xi : x) v += (xi - m) * (xi - m);
  return x.empty() ? 0.0 : std::sqrt(v / static_cast<double>(x.size()));
}

std::vector<std::size_t> maxima_indices(std::span<const double> x, double noise_sd) {
  // Peaks separated by a fall of at least a quarter standard deviation (hysteresis), so that
  // measurement noise riding on an oscillation does not count as extra maxima; with a known
  // white noise, by at least its range over about a hundred samples (6 sd).
  const double h = std::max(kHysteresisSds * standard_deviation(x), kNoiseRangeSds * noise_sd);
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

double mean_maxima_spacing(std::span<const double> x, double noise_sd) {
  const auto peaks = maxima_indices(x, noise_sd);
  return peaks.size() >= 2 ? static_cast<double>(peaks.back() - peaks.front()) /
                                 static_cast<double>(peaks.size() - 1)
                           : static_cast<double>(x.size());
}

std::vector<double> moving_average(std::span<const double> x, std::size_t width) {
  std::vector<double> prefix(x.size() + 1, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) prefix[i + 1] = prefix[i] + x[i];
  std::vector<double> y(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto [lo, hi] = centred_window(i, x.size(), width);
    y[i] = (prefix[hi] - prefix[lo]) / static_cast<double>(hi - lo);
  }
  return y;
}

// Selecting each window's median anew (O(n w)) is enough for the rests' windows of a few tens
// of samples; a two-heap running median would only pay for wide windows.
std::vector<double> moving_median(std::span<const double> x, std::size_t width) {
  std::vector<double> y(x.size()), window;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto [lo, hi] = centred_window(i, x.size(), width);
    window.assign(x.begin() + static_cast<std::ptrdiff_t>(lo),
                  x.begin() + static_cast<std::ptrdiff_t>(hi));
    const auto mid = window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2);
    std::nth_element(window.begin(), mid, window.end());
    // An even count: the mean of the two middle values (the lower one is the largest below).
    y[i] = window.size() % 2 == 1 ? *mid : 0.5 * (*mid + *std::max_element(window.begin(), mid));
  }
  return y;
}

double smoothed_period(std::span<const double> x, std::size_t width) {
  if (width <= 1) return mean_maxima_spacing(x);
  return mean_maxima_spacing(moving_average(x, width));
}

}  // namespace pneumachaos
