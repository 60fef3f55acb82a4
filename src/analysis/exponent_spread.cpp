#include "exponent_spread.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "analysis/linear_region.hpp"
#include "divergence_uncertainty.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// The curves at m - 1 and m + 1 follow 1 / kSpreadPairShare of the main curve's reference
// pairs: a spread, not a second measurement (docs/notes/analysis.md "Divergence exponent's
// uncertainty").
constexpr std::size_t kSpreadPairShare = 4;

// A straight stretch gives the same slope on either half; a bending one does not.
double window_spread(const DivergenceResult& d, double rate_Hz) {
  const std::size_t mid = (d.fit_first + d.fit_last) / 2;
  if (mid < d.fit_first + 2 || d.fit_last < mid + 2) return 0.0;  // halves of under 3 points
  double spread = 0.0;
  for (const auto& [a, b] : {std::pair{d.fit_first, mid}, std::pair{mid, d.fit_last}}) {
    spread = std::max(spread, std::abs(fit_line(d.curve, a, b).slope * rate_Hz -
                                       d.lambda_per_s));
  }
  return spread;
}

// The window is the longest of the stretches the rule accepts; which one is longest can turn
// on a single segment, so the value is also read on each of the others.
void window_choice(const DivergenceResult& d, double tolerance, double rate_Hz,
                   ExponentSpread& s) {
  for (const LinearRegion& r : agreeing_runs(d.curve, d.slope_spacing, tolerance)) {
    if (r.first == d.fit_first && r.last == d.fit_last) continue;
    const double value = r.slope * rate_Hz;
    s.other_windows_per_s.push_back(value);
    s.window_choice_per_s = std::max(s.window_choice_per_s, std::abs(value - d.lambda_per_s));
  }
}

}  // namespace

ExponentSpread exponent_spread(std::span<const double> x, double rate_Hz, DivergenceOptions options,
                               const DivergenceResult& d, bool embeddings) {
  ExponentSpread s;
  s.window_per_s = window_spread(d, rate_Hz);
  window_choice(d, options.slope_tolerance, rate_Hz, s);
  if (!embeddings) return s;
  const std::size_t m = options.dimension;
  // A spread, not a second measurement: a quarter of the pairs (dysts's flows: the truth inside
  // the interval on 42 of 54 records, 43 with all of them, at 0.37 G instead of 0.55 G
  // instructions for Lorenz at 1e4 samples; docs/notes/exponent_validation.md).
  options.max_reference_steps /= kSpreadPairShare;
  for (const std::size_t k : {m - 1, m + 1}) {
    if (k < 1) continue;
    options.dimension = k;
    try {
      const DivergenceResult n = divergence_exponent(x, rate_Hz, options);
      if (!n.found_linear_region) continue;
      s.dimensions.push_back(k);
      s.lambda_per_s.push_back(n.lambda_per_s);
      s.embedding_per_s = std::max(s.embedding_per_s, std::abs(n.lambda_per_s - d.lambda_per_s));
    } catch (const Error&) {
      // Too short to follow pairs in dimension k: that dimension says nothing.
    }
  }
  return s;
}

double widened_uncertainty(const DivergenceResult& d, const ExponentSpread& s) {
  using detail::kNormal95;
  const double window = std::hypot(s.window_per_s, s.window_choice_per_s) / kNormal95;
  return std::hypot(d.uncertainty_per_s, window, s.embedding_per_s / kNormal95);
}

}  // namespace pneumachaos
