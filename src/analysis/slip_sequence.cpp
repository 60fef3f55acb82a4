#include "pneumachaos/analysis/slip_sequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/analysis/surrogates.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Leave-one-out local-constant prediction of s(n + 1) from the return-map point
// (s(n), ..., s(n - m + 1)): the mean image of its nearest neighbours, slips n - 1 .. n + 1
// excluded (an adjacent slip shares the point's own step). RMS error / std; negative when
// too few points have neighbours. O(N^2): a sequence holds tens to hundreds of slips.
double return_map_error(std::span<const double> s, std::size_t m, std::size_t k) {
  const std::size_t n = s.size();
  if (n < m + 4 + k) return -1.0;
  const auto distance = [&](std::size_t a, std::size_t b) {
    double d = 0.0;
    for (std::size_t j = 0; j < m; ++j) d += (s[a - j] - s[b - j]) * (s[a - j] - s[b - j]);
    return d;
  };
  std::vector<std::pair<double, std::size_t>> near;
  double sse = 0.0;
  for (std::size_t i = m - 1; i + 1 < n; ++i) {
    near.clear();
    for (std::size_t j = m - 1; j + 1 < n; ++j) {
      if (j + 1 >= i && j <= i + 1) continue;
      near.emplace_back(distance(i, j), j);
    }
    const std::size_t use = std::min(k, near.size());
    std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(use), near.end());
    double p = 0.0;
    for (std::size_t r = 0; r < use; ++r) p += s[near[r].second + 1];
    const double err = s[i + 1] - p / static_cast<double>(use);
    sse += err * err;
  }
  const double count = static_cast<double>(n - m);
  return std::sqrt(sse / count) / standard_deviation(s);
}

// The best return map over dimensions 1 .. max_dimension: {error, dimension}. The
// surrogates get the same choice, so choosing does not favour the sequence.
std::pair<double, std::size_t> best_return_map(std::span<const double> s,
                                               const SlipSequenceOptions& o) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t dim = 0;
  for (std::size_t m = 1; m <= o.max_dimension; ++m) {
    const double e = return_map_error(s, m, o.neighbours);
    if (e >= 0.0 && e < best) {
      best = e;
      dim = m;
    }
  }
  return {best, dim};
}

// Smallest RMS of s(n + L) - s(n) over lags 1 .. N/2, relative to sqrt(2) std: a
// periodic sequence (all slips alike, alternating, ...) or a torus's near return reads small.
void note_repetition(std::span<const double> s, SlipSequenceTest& t) {
  const double size = std::numbers::sqrt2 * standard_deviation(s);
  t.repeat_mismatch = std::numeric_limits<double>::infinity();
  for (std::size_t L = 1; L <= s.size() / 2; ++L) {
    double sum = 0.0;
    for (std::size_t i = 0; i + L < s.size(); ++i) sum += (s[i + L] - s[i]) * (s[i + L] - s[i]);
    const double m = std::sqrt(sum / static_cast<double>(s.size() - L)) / size;
    if (m < t.repeat_mismatch) {
      t.repeat_mismatch = m;
      t.repeat_lag = L;
    }
  }
}

// The rank test against IAAFT surrogates of the sequence (values exact, spectrum close):
// the null "a monotonic transform of a linear Gaussian sequence", which slip-to-slip noise
// with memory (a texture along the stroke, a slowly varying supply) satisfies.
void note_determinism(std::span<const double> s, const SlipSequenceOptions& o,
                      SlipSequenceTest& t) {
  std::tie(t.prediction_error, t.dimension) = best_return_map(s, o);
  std::vector<double> errors;
  for (std::size_t k = 0; k < o.surrogates; ++k) {
    const auto surrogate = iaaft_surrogate(s, o.seed * 0x9E3779B97F4A7C15ULL + k);
    errors.push_back(best_return_map(surrogate, o).first);
  }
  if (errors.empty()) return;
  t.surrogates_below = static_cast<std::size_t>(
      std::count_if(errors.begin(), errors.end(), [&](double e) { return e <= t.prediction_error; }));
  std::sort(errors.begin(), errors.end());
  t.surrogate_min = errors.front();
  t.surrogate_median = errors[errors.size() / 2];
  t.deterministic =
      t.surrogates_below == 0 && t.prediction_error <= o.max_error_ratio * t.surrogate_median;
}

}  // namespace

Rests find_rests(std::span<const double> x, double level, std::size_t min_samples) {
  Rests found{level, {}};
  std::vector<RestInterval>& rests = found.intervals;
  std::size_t run = 0;
  double lo = 0.0, hi = 0.0;
  const auto close_run = [&](std::size_t end) {
    if (run >= min_samples) rests.push_back({end - run, end});
    run = 0;
  };
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = x[i];
    const bool inside = std::abs(v) <= level;
    if (inside && run > 0 && std::max(hi, v) - std::min(lo, v) <= 0.5 * level) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      ++run;
      continue;
    }
    close_run(i);
    if (inside) {
      run = 1;
      lo = hi = v;
    }
  }
  close_run(x.size());
  return found;
}

std::vector<double> slip_displacements(std::span<const double> x, double rate_Hz,
                                       const Rests& rests, double min_peak) {
  const double threshold = std::max(min_peak, rests.level);
  std::vector<double> slips;
  const std::vector<RestInterval>& r = rests.intervals;
  for (std::size_t k = 0; k + 1 < r.size(); ++k) {
    double sum = 0.0, peak = 0.0;
    for (std::size_t i = r[k].last; i < r[k + 1].first; ++i) {
      sum += x[i];
      peak = std::max(peak, std::abs(x[i]));
    }
    if (peak > threshold) slips.push_back(sum / rate_Hz);
  }
  return slips;
}

void SlipSequenceOptions::validate() const {
  if (min_slips < 8) throw Error("slip_sequence.min_slips", "must be at least 8");
  if (neighbours == 0) throw Error("slip_sequence.neighbours", "must be at least 1");
  if (max_dimension == 0) throw Error("slip_sequence.max_dimension", "must be at least 1");
  if (!(max_error_ratio > 0.0)) throw Error("slip_sequence.max_error_ratio", "must be > 0");
  if (!(min_peak_fraction >= 0.0 && min_peak_fraction <= 1.0)) {
    throw Error("slip_sequence.min_peak_fraction", "must be in [0, 1]");
  }
  if (!(min_variation >= 0.0)) throw Error("slip_sequence.min_variation", "must be >= 0");
  if (!(max_repeat_mismatch >= 0.0)) {
    throw Error("slip_sequence.max_repeat_mismatch", "must be >= 0");
  }
}

SlipSequenceTest slip_sequence_test(std::span<const double> s, const SlipSequenceOptions& o) {
  o.validate();
  SlipSequenceTest t;
  t.slips = s.size();
  if (s.size() < o.min_slips) {
    t.reason = fmt::format("not run: {} slips between rests, at least {} needed", s.size(),
                           o.min_slips);
    return t;
  }
  if (o.surrogates == 0) {
    t.reason = "not run (0 surrogates requested)";
    return t;
  }
  t.run = true;
  t.mean = mean_of(s);
  const double sd = standard_deviation(s);
  t.variation = std::abs(t.mean) > 0.0 ? sd / std::abs(t.mean) : (sd > 0.0 ? 1.0 : 0.0);
  t.varies = t.variation > o.min_variation;
  if (!t.varies) return t;  // all slips alike: a periodic stick-slip, nothing to predict
  note_repetition(s, t);
  t.repeats = t.repeat_mismatch <= o.max_repeat_mismatch;
  note_determinism(s, o, t);
  t.chaotic = t.varies && t.deterministic && !t.repeats;
  return t;
}

SlipSequenceTest slip_sequence_test(std::span<const double> x, double rate_Hz,
                                    const Rests& rests,
                                    const SlipSequenceOptions& o) {
  double max_abs = 0.0;
  for (double v : x) max_abs = std::max(max_abs, std::abs(v));
  const std::vector<double> slips =
      slip_displacements(x, rate_Hz, rests, o.min_peak_fraction * max_abs);
  return slip_sequence_test(slips, o);
}

}  // namespace pneumachaos
