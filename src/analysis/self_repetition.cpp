#include "pneumachaos/analysis/self_repetition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// The mismatch's growth is a least-squares slope over the stretch's windows: fitted only from
// kMinFitWindows windows on (two always lie on a line).
constexpr std::size_t kMinFitWindows = 3;

// Added to the mismatch before its logarithm, so that an exact repeat (mismatch 0) reads
// ln 1e-12 ~ -27.6, a finite floor, instead of -inf.
constexpr double kExactRepeatMismatch = 1e-12;

// Fewest samples a repetition is looked for in; shorter records are not run.
constexpr std::size_t kMinSamples = 4;

// RMS of x[t + L] - x[t] over the overlap t < N - L, relative to the attractor's size
// sqrt(2 var), for every lag up to max_lag at once: the squares of the two overlapping pieces
// (prefix sums) minus twice the lag product (one FFT). Normalised per overlap, so long lags
// are not favoured by a shorter sum.
std::vector<double> relative_mismatch(std::span<const double> x, double mean,
                                      std::span<const double> products, std::size_t max_lag,
                                      double two_var) {
  const std::size_t n = x.size();
  std::vector<double> squares(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) squares[i + 1] = squares[i] + (x[i] - mean) * (x[i] - mean);
  std::vector<double> e(max_lag + 1);
  for (std::size_t L = 0; L <= max_lag; ++L) {
    const double sum = squares[n - L] + (squares[n] - squares[L]) - 2.0 * products[L];
    e[L] = std::sqrt(std::max(0.0, sum) / static_cast<double>(n - L) / two_var);
  }
  return e;
}

// The lags worth a closer look: the deepest local minima of e on [lo, hi].
std::vector<std::size_t> candidate_lags(const std::vector<double>& e, std::size_t lo,
                                        std::size_t hi, std::size_t count) {
  std::vector<std::size_t> minima;
  for (std::size_t L = lo; L <= hi; ++L) {
    const bool left = L == lo || e[L] <= e[L - 1];
    const bool right = L == hi || e[L] <= e[L + 1];
    if (left && right) minima.push_back(L);
  }
  // Equally deep minima (an exact repeat reads 0 at every multiple): the shorter lag first,
  // since it leaves the longer overlap.
  const auto by_depth = [&](std::size_t a, std::size_t b) {
    return e[a] < e[b] || (e[a] == e[b] && a < b);
  };
  const std::size_t keep = std::min(count, minima.size());
  std::partial_sort(minima.begin(), minima.begin() + static_cast<std::ptrdiff_t>(keep),
                    minima.end(), by_depth);
  minima.resize(keep);
  return minima;
}

struct Stretch {
  std::size_t first = 0, windows = 0;  ///< in windows of w samples along the overlap
  double max_mismatch = 0.0, growth_per_step = 0.0;
  std::size_t lag_first = 0, lag_last = 0;  ///< the followed lag at the stretch's two ends
};

// Least-squares slope of ln(m) against the window index, over m[first .. first + count).
double log_slope(const std::vector<double>& m, std::size_t first, std::size_t count) {
  if (count < kMinFitWindows) return 0.0;
  double st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double t = static_cast<double>(k);
    const double l = std::log(m[first + k] + kExactRepeatMismatch);
    st += t;
    sl += l;
    stt += t * t;
    stl += t * l;
  }
  const double c = static_cast<double>(count);
  return (c * stl - st * sl) / (c * stt - st * st);
}

// Sum of (x[t + L] - x[t])^2 over the window [t0, t0 + w), abandoned as soon as it reaches
// `cap` (then only "not below cap" is known): most probes of a lag walk fail, and fail early.
double window_sum(std::span<const double> x, std::size_t t0, std::size_t w, std::size_t L,
                  double cap) {
  double sum = 0.0;
  for (std::size_t t = t0; t < t0 + w && sum < cap; ++t) {
    sum += (x[t + L] - x[t]) * (x[t + L] - x[t]);
  }
  return sum;
}

// The lag that best matches the window, found by stepping from `from` while the mismatch
// falls, at most `shift` samples away and with the shifted window inside the record; m is
// its RMS mismatch relative to the attractor's size.
std::size_t follow_lag(std::span<const double> x, std::size_t t0, std::size_t w,
                       std::size_t from, std::size_t shift, double two_var, double& m) {
  constexpr double kAll = std::numeric_limits<double>::infinity();
  std::size_t L = from;
  double best = window_sum(x, t0, w, L, kAll);
  for (int step : {+1, -1}) {
    for (;;) {
      const std::size_t next = L + static_cast<std::size_t>(step);  // wraps below 0: rejected
      if (next < 1 || next > from + shift || next + shift < from || t0 + w + next > x.size()) {
        break;
      }
      const double sum = window_sum(x, t0, w, next, best);
      if (!(sum < best)) break;
      L = next;
      best = sum;
    }
  }
  m = std::sqrt(best / static_cast<double>(w) / two_var);
  return L;
}

// The longest run of windows (w samples each) in which x[t + L] - x[t] stays small, the lag
// following a slow drift of the phase (at most `shift` samples from one window to the next;
// it starts again at L0 after a window that does not match).
Stretch longest_stretch(std::span<const double> x, std::size_t L0, std::size_t w,
                        std::size_t shift, double two_var, double limit) {
  std::vector<double> m;
  std::vector<std::size_t> lags;
  std::size_t L = L0;
  for (std::size_t t0 = 0; t0 + w + L + shift <= x.size(); t0 += w) {
    double mk = 0.0;
    L = follow_lag(x, t0, w, L, shift, two_var, mk);
    m.push_back(mk);
    lags.push_back(L);
    if (mk > limit) L = L0;
  }
  Stretch best;
  std::size_t start = 0;
  for (std::size_t k = 0; k <= m.size(); ++k) {
    if (k < m.size() && m[k] <= limit) continue;
    if (k - start > best.windows) best = {start, k - start, 0.0, 0.0, 0, 0};
    start = k + 1;
  }
  if (best.windows == 0) return best;
  const auto first = m.begin() + static_cast<std::ptrdiff_t>(best.first);
  best.max_mismatch = *std::max_element(first, first + static_cast<std::ptrdiff_t>(best.windows));
  best.growth_per_step = log_slope(m, best.first, best.windows) / static_cast<double>(w);
  best.lag_first = lags[best.first];
  best.lag_last = lags[best.first + best.windows - 1];
  return best;
}

}  // namespace

void SelfRepetitionOptions::validate() const {
  using namespace validation;
  require_gt(field("self_repetition.max_mismatch"), max_mismatch, 0);
  require_gt_lt(field("self_repetition.min_share"), min_share, 0, 1);
  require_gt(field("self_repetition.min_lag_periods"), min_lag_periods, 0);
  require_ge(field("self_repetition.candidates"), static_cast<double>(candidates), 1,
             "at least one lag must be examined");
  require_between(field("self_repetition.lag_drift"), lag_drift, 0, 0.5);
}

SelfRepetition self_repetition(std::span<const double> x, double rate_Hz, double period_samples,
                               const SelfRepetitionOptions& o,
                               std::span<const double> products) {
  SelfRepetition s;
  const std::size_t n = x.size();
  if (!(period_samples >= 1.0)) {
    s.reason = "not run: no orbital period (the record has no maxima to space)";
    return s;
  }
  const auto lo = static_cast<std::size_t>(std::ceil(o.min_lag_periods * period_samples));
  const auto needed = static_cast<std::size_t>(std::ceil(o.min_share * static_cast<double>(n)));
  const std::size_t hi = n > needed ? n - needed : 0;
  if (lo > hi || n < kMinSamples) {
    s.reason = fmt::format(
        "not run: {} samples span {:.1f} orbital periods; a repeat {} periods later held over "
        "{:.0f} % of the record needs {:.1f}",
        n, static_cast<double>(n) / period_samples, o.min_lag_periods, 100.0 * o.min_share,
        o.min_lag_periods / (1.0 - o.min_share));
    return s;
  }
  const double mean = mean_of(x);
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  const double two_var = 2.0 * ss / static_cast<double>(n);
  if (!(two_var > 0.0)) {
    s.reason = "not run: the record is constant";
    return s;
  }
  const std::vector<double> own = products.size() == n ? std::vector<double>{}
                                                       : centred_lag_products(x);
  const std::vector<double> e =
      relative_mismatch(x, mean, products.size() == n ? products : std::span<const double>(own),
                        hi, two_var);
  const auto w = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(period_samples)));
  const auto shift = static_cast<std::size_t>(std::floor(o.lag_drift * static_cast<double>(w)));
  s.run = true;
  // There is always a candidate (e has a smallest value on [lo, hi]), which replaces this.
  s.mismatch = std::numeric_limits<double>::infinity();
  Stretch best;
  for (std::size_t L : candidate_lags(e, lo, hi, o.candidates)) {
    const Stretch st = longest_stretch(x, L, w, shift, two_var, o.max_mismatch);
    if (st.windows > best.windows || (st.windows == best.windows && e[L] < s.mismatch)) {
      best = st;
      s.lag = L;
      s.mismatch = e[L];
    }
  }
  s.lag_s = static_cast<double>(s.lag) / rate_Hz;
  s.lag_drift_s = (static_cast<double>(best.lag_last) - static_cast<double>(best.lag_first)) /
                  rate_Hz;
  s.stretch_s = static_cast<double>(best.windows * w) / rate_Hz;
  s.share = static_cast<double>(best.windows * w) / static_cast<double>(n);
  s.stretch_max_mismatch = best.max_mismatch;
  s.growth_per_s = best.growth_per_step * rate_Hz;
  s.repeats = s.share >= o.min_share;
  s.max_mismatch = o.max_mismatch;
  return s;
}

}  // namespace pneumachaos
