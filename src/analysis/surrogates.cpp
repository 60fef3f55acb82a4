#include "pneumachaos/analysis/surrogates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>

#include "analysis/fft.hpp"
#include "core/parallel_indices.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// The surrogates are made of the longest segment whose ends match, at least (1 - 1 /
// kMaxTrimShare) of the record (docs/notes/analysis.md "Surrogate-data test": "the longest
// 90-100 % segment whose ends match"), and of at least kMinSegment samples.
constexpr std::size_t kMaxTrimShare = 10;
constexpr std::size_t kMinSegment = 4;

// Surrogate k's seed is seed x kGoldenGamma + k: the odd 64-bit golden-ratio constant
// (2^64 / phi, as in Steele, Lea & Flood 2014's SplitMix64) spreads neighbouring seeds apart.
constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ULL;

// Portable randomness: std::mt19937_64's output sequence is fixed by the standard, but the
// standard distributions are not; these two helpers are ours, so a seed gives the same
// surrogates with every standard library.
std::size_t uniform_index(std::mt19937_64& rng, std::size_t bound) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                              std::numeric_limits<std::uint64_t>::max() % bound;
  std::uint64_t v = rng();
  while (v >= limit) v = rng();  // rejection removes the modulo bias
  return static_cast<std::size_t>(v % bound);
}

void shuffle(std::vector<double>& v, std::mt19937_64& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[uniform_index(rng, i)]);
}

// Writes the sorted values into s in the rank order of s (amplitude adjustment); returns
// whether the order changed from `order` (which it updates). Sorting (value, index) pairs
// keeps the comparisons on contiguous memory: this sort is most of an iteration's cost. The
// pairs are laid out in the previous iteration's rank order, which the iteration changes less
// and less: the sort's comparisons then mostly go one way, which the processor predicts
// (twice as fast once the ranks settle). The pairs are distinct, so the sorted result, and
// the surrogate, do not depend on that layout.
bool rank_adjust(std::vector<double>& s, const std::vector<double>& sorted,
                 std::vector<std::uint32_t>& order) {
  std::vector<std::pair<double, std::uint32_t>> pairs(s.size());
  if (order.size() == s.size()) {
    for (std::size_t r = 0; r < s.size(); ++r) pairs[r] = {s[order[r]], order[r]};
  } else {
    for (std::size_t i = 0; i < s.size(); ++i) pairs[i] = {s[i], static_cast<std::uint32_t>(i)};
  }
  std::sort(pairs.begin(), pairs.end());
  bool changed = order.size() != s.size();
  order.resize(s.size());
  for (std::size_t r = 0; r < pairs.size(); ++r) {
    s[pairs[r].second] = sorted[r];
    changed = changed || order[r] != pairs[r].second;
    order[r] = pairs[r].second;
  }
  return changed;
}

// Index range [offset, offset + n) with n a fast FFT size >= 90 % of the record and the
// smallest mismatch between its ends (value and slope, as Schreiber & Schmitz advise).
std::pair<std::size_t, std::size_t> end_matched_segment(std::span<const double> x) {
  const std::size_t N = x.size();
  std::size_t best_n = 0, best_off = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t n = N; n + N / kMaxTrimShare >= N && n >= kMinSegment; --n) {
    if (fast_fft_size(n) != n) continue;
    for (std::size_t off = 0; off + n <= N; ++off) {
      const double jump = x[off + n - 1] - x[off];
      const double slope = (x[off + n - 1] - x[off + n - 2]) - (x[off + 1] - x[off]);
      const double mismatch = jump * jump + 0.5 * slope * slope;
      if (mismatch < best) {
        best = mismatch;
        best_n = n;
        best_off = off;
      }
    }
  }
  return {best_off, best_n};
}

}  // namespace

void check_surrogate_count(std::size_t count, const std::string& where) {
  if (count == 0 || (count >= kMinSurrogates && count <= kMaxSurrogates)) return;
  throw Error(where, fmt::format("{} is out of range: 0 (off) or {} to {} (fewer cannot reject "
                                 "at 5 %: the record beats them all by chance with "
                                 "probability 1/(N+1))",
                                 count, kMinSurrogates, kMaxSurrogates));
}

void SurrogateOptions::validate() const {
  using namespace validation;
  check_surrogate_count(count, "surrogates.count");
  require_ge(field("surrogates.max_iterations"), static_cast<double>(max_iterations), 1);
  require_ge(field("surrogates.spectral_tolerance"), spectral_tolerance, 0);
}

std::vector<double> iaaft_surrogate(std::span<const double> x, std::uint64_t seed,
                                    std::size_t max_iterations, double tolerance) {
  const std::size_t n = x.size();
  const DftPlan plan(n);
  std::vector<std::complex<double>> X;
  plan.forward(x, X);
  std::vector<double> amplitude(n);
  for (std::size_t k = 0; k < n; ++k) amplitude[k] = std::abs(X[k]);
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());

  std::mt19937_64 rng(seed);
  std::vector<double> s = sorted;
  shuffle(s, rng);
  std::vector<std::uint32_t> order;
  std::vector<double> modulus(n);
  double total = 0.0;
  for (double a : amplitude) total += a * a;
  for (std::size_t it = 0; it < max_iterations; ++it) {
    plan.forward(s, X);
    // Stop once the surrogate's amplitude spectrum is within `tolerance` (RMS, relative) of
    // the record's: the values are exact after every rank adjustment, the spectrum only
    // approaches (docs/notes/analysis.md "Surrogate-data test").
    // The moduli, taken once for both loops (std::abs of a complex is a hypot call).
    double mismatch = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      modulus[k] = std::abs(X[k]);
      const double d = modulus[k] - amplitude[k];
      mismatch += d * d;
    }
    if (it > 0 && mismatch <= tolerance * tolerance * total) break;
    // Impose the record's Fourier amplitudes, keep the surrogate's phases...
    for (std::size_t k = 0; k < n; ++k) {
      const double a = modulus[k];
      X[k] = a > 0.0 ? X[k] * (amplitude[k] / a) : std::complex<double>(amplitude[k], 0.0);
    }
    plan.inverse_real(X, s);
    // ...then its exact values in the new rank order; a fixed point ends the iteration.
    if (!rank_adjust(s, sorted, order)) break;
  }
  return s;
}

SurrogateTest surrogate_test(std::span<const double> x, const PredictionOptions& prediction,
                             const SurrogateOptions& o) {
  o.validate();
  prediction.validate();
  SurrogateTest t;
  if (o.count == 0) {
    t.reason = "not run (0 surrogates requested)";
    return t;
  }
  if (x.size() < o.min_samples) {
    t.reason = fmt::format("not run: {} samples, at least {} needed", x.size(), o.min_samples);
    return t;
  }
  const auto [offset, n] = end_matched_segment(x);
  const std::span<const double> segment = x.subspan(offset, n);
  t.statistic = nonlinear_prediction_error(segment, prediction);
  if (t.statistic < 0.0) {
    t.reason = "not run: the record is too short for the embedding and prediction horizon";
    return t;
  }
  t.samples = n;
  t.offset = offset;
  // Each surrogate's seed follows from the test's seed and its index alone, so the surrogates
  // are made side by side on every core (they are three quarters of an analysis) and the
  // statistics are the same at any thread count.
  t.surrogate_statistics.assign(o.count, 0.0);
  const auto one = [&](std::size_t k) {
    const auto s = iaaft_surrogate(segment, o.seed * kGoldenGamma + k, o.max_iterations,
                                  o.spectral_tolerance);
    t.surrogate_statistics[k] = nonlinear_prediction_error(s, prediction);
  };
  detail::parallel_indices(o.count, one);
  std::size_t below = 0, above = 0;
  for (double v : t.surrogate_statistics) {
    below += v < t.statistic ? 1 : 0;
    above += v > t.statistic ? 1 : 0;
  }
  t.rank = below;
  const double m = static_cast<double>(o.count + 1);
  t.p_value = std::min(1.0, 2.0 * static_cast<double>(std::min(below, above) + 1) / m);
  // Ties count against rejection: the record must lie strictly outside every surrogate.
  t.more_predictable = above == o.count;
  t.rejected = above == o.count || below == o.count;
  t.run = true;
  return t;
}

}  // namespace pneumachaos
