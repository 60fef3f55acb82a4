#include "pneumachaos/analysis/noise_floor.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pneumachaos/analysis/series_statistics.hpp"

namespace pneumachaos {
namespace {

// kMadToSd x MAD is the sd of a normal distribution (1 / Phi^-1(3/4); Hampel 1974); the median
// ignores the few large differences at a record's sharp features (a slip's onset), which a
// plain sd would count.
constexpr double kMadToSd = 1.4826;

double robust_sd(std::vector<double> d) {
  const auto median_of = [](std::vector<double>& v) {
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  };
  const double m = median_of(d);
  for (double& v : d) v = std::abs(v - m);
  return kMadToSd * median_of(d);
}

// C(2k, k): the variance gain of the k-th difference of white noise.
double central_binomial(std::size_t k) {
  double c = 1.0;
  for (std::size_t i = 1; i <= k; ++i) c = c * static_cast<double>(k + i) / static_cast<double>(i);
  return c;
}

}  // namespace

NoiseFloor estimate_noise_floor(std::span<const double> x) {
  NoiseFloor f;
  if (x.size() <= NoiseFloor::kOrders) return f;
  std::vector<double> d(x.begin(), x.end());
  for (std::size_t k = 1; k <= NoiseFloor::kOrders; ++k) {
    std::adjacent_difference(d.begin(), d.end(), d.begin());
    d.erase(d.begin());
    f.by_order.push_back(robust_sd(d) / std::sqrt(central_binomial(k)));
  }
  f.bound = *std::min_element(f.by_order.begin(), f.by_order.end());
  const double last = f.by_order.back(), before = f.by_order[f.by_order.size() - 2];
  const bool white = before > 0.0 && last >= NoiseFloor::kResolvedRatio * before;
  f.dominates = white && last > NoiseFloor::kMaxShareOfStd * standard_deviation(x);
  f.resolved = white && !f.dominates;
  f.sd = f.resolved ? last : 0.0;
  return f;
}

}  // namespace pneumachaos
