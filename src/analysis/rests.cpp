#include "analysis/rests.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "pneumachaos/analysis/series_statistics.hpp"

namespace pneumachaos {
namespace {

// Noise of sd up to the clean band / kCleanBandNoiseShare leaves the clean rule standing
// (docs/notes/analysis.md "Noise floor": a 12-bit converter's rounding); why, at its use.
constexpr double kCleanBandNoiseShare = 12.0;

// sqrt(pi / 2): the sd of a median of many normal samples against their mean's.
constexpr double kMedianSdGain = 1.2533141373155003;

struct RestBounds {
  double level = 0.0;         ///< |x| at most this
  double spread = 0.0;        ///< max - min within a run at most this
  double clean_change = 0.0;  ///< the trend test's allowance without noise
  double noise_sd = 0.0;
  double trend_sigmas = 0.0;
  double max_rms = 0.0;  ///< RMS about zero, in noise sd
};

// The least-squares line through x[first, first + n): its change over the n - 1 steps; and
// the RMS of the samples about zero.
struct RunShape {
  double change = 0.0, rms = 0.0;
};
RunShape shape_of(std::span<const double> x, std::size_t first, std::size_t n) {
  const double t_mean = 0.5 * static_cast<double>(n - 1);
  double sxy = 0.0, sxx = 0.0, ss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) - t_mean;
    sxy += t * x[first + i];
    sxx += t * t;
    ss += x[first + i] * x[first + i];
  }
  const double slope = sxx > 0.0 ? sxy / sxx : 0.0;
  return {std::abs(slope) * static_cast<double>(n - 1), std::sqrt(ss / static_cast<double>(n))};
}

// A rest under white noise of sd s is the noise about zero. Under the noise alone the fitted
// change over n samples has sd s sqrt(12 (n - 1)^2 / (n^3 - n)) (the slope's variance is
// s^2 / sum t^2): a passage through zero keeps its slope. And the samples' RMS about zero
// stays near s: a slow noise-driven wander that lingers in the band (an AR(1) process) sits
// off zero most of the time.
bool rests_under_noise(std::span<const double> x, std::size_t first, std::size_t n,
                       const RestBounds& b) {
  if (b.noise_sd <= 0.0) return true;
  const double nn = static_cast<double>(n);
  const double change_sd =
      b.noise_sd * std::sqrt(12.0 * (nn - 1.0) * (nn - 1.0) / (nn * nn * nn - nn));
  const RunShape run = shape_of(x, first, n);
  return run.change <= b.clean_change + b.trend_sigmas * change_sd &&
         run.rms <= b.clean_change + b.max_rms * b.noise_sd;
}

// The rests of x as runs [first, first + n), with the bounds they were judged by.
struct Rests {
  RestBounds bounds;
  double raw_level = 0.0;  ///< the band on the raw samples, which decides `judged`
  bool judged = false;     ///< false: the raw band is too wide to tell a rest from the noise
  std::vector<std::pair<std::size_t, std::size_t>> runs;
};

Rests find_rests(std::span<const double> x, const VerdictOptions& o, double record_noise_sd) {
  double max_abs = 0.0;
  for (double v : x) max_abs = std::max(max_abs, std::abs(v));
  const double clean_level = o.rest_fraction * max_abs;
  // Noise whose range over a rest (about 6 sigma for ten samples) fits in the clean rule's
  // spread allowance of half the band does not break that rule: the clean rule stands (a
  // 12-bit converter's rounding, a record's last digits).
  const double noise_sd =
      record_noise_sd > clean_level / kCleanBandNoiseShare ? record_noise_sd : 0.0;
  // Under noise the band is judged on the running median over a window, whose noise is about
  // sqrt(window) times smaller: a rest's edges, where the body speeds up out of it, then stay
  // outside the run instead of failing its trend test. A median, not a mean: a rest shorter
  // than the window between two slips still sets the median while it fills more than half
  // the window, where the slips' samples pull a mean out of the band (rests of 5-19 samples
  // at 0.5 % noise; docs/notes/analysis.md "Noise floor").
  const std::size_t window = noise_sd > 0.0 ? o.rest_window_in_noise : 1;
  const std::vector<double> smooth = noise_sd > 0.0 ? moving_median(x, window)
                                                    : std::vector<double>(x.begin(), x.end());
  // The median of w normal samples has sd sqrt(pi / 2) sigma / sqrt(w) for large w (its
  // efficiency 2 / pi against the mean).
  const double noisy_band = o.rest_noise_sigmas * kMedianSdGain * noise_sd /
                            std::sqrt(static_cast<double>(window));
  Rests r;
  // Whether a rest can be told from the noise at all is the single sample's question: where
  // the raw noise's band exceeds max_rest_band, a noise-driven wander lingers in it (a noisy
  // Lorenz x passing zero), and no running median makes it a rest.
  r.raw_level = clean_level + o.rest_noise_sigmas * noise_sd;
  r.judged = r.raw_level <= o.max_rest_band * max_abs;
  r.bounds = RestBounds{.level = clean_level + noisy_band,
                        .spread = 0.5 * clean_level + 2.0 * noisy_band,
                        .clean_change = 0.5 * clean_level,
                        .noise_sd = noise_sd,
                        .trend_sigmas = o.rest_trend_sigmas,
                        .max_rms = o.rest_max_rms};
  const RestBounds& b = r.bounds;
  if (!r.judged) return r;
  std::size_t first = 0, run = 0;
  double lo = 0.0, hi = 0.0;
  const auto close_run = [&] {
    if (run >= o.min_rest_samples && rests_under_noise(x, first, run, b)) {
      r.runs.emplace_back(first, run);
    }
    run = 0;
  };
  // Each raw sample of a rest lies within the raw band too (a resting sample stays within
  // 3.5 sigma of the clean band with probability 99.95 %): the median over a symmetric
  // ringing about zero after a slip stays near zero, and without this the ringing joined the
  // rest and failed its RMS test with it (the default rig at S2 = 0.2 mm^2 with 0.3-0.5 mm/s
  // of noise lost every rest: tests/sweep/test_rig_rests_in_noise.cpp).
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = smooth[i];
    const bool inside = std::abs(v) <= b.level && std::abs(x[i]) <= r.raw_level;
    if (inside && run > 0 && std::max(hi, v) - std::min(lo, v) <= b.spread) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      ++run;
      continue;
    }
    close_run();
    if (inside) {
      first = i;
      run = 1;
      lo = hi = v;
    }
  }
  close_run();
  return r;
}

}  // namespace

void rest_statistics(std::span<const double> x, const VerdictOptions& o, double record_noise_sd,
                     RegimeEvidence& e) {
  const Rests r = find_rests(x, o, record_noise_sd);
  e.rest_noise_sd = r.bounds.noise_sd;
  e.rest_level = r.judged ? r.bounds.level : r.raw_level;
  e.rests_above_noise = r.judged;
  e.rest_intervals = r.runs.size();
  std::size_t at_rest = 0;
  for (const auto& run : r.runs) at_rest += run.second;
  e.rest_share = static_cast<double>(at_rest) / static_cast<double>(x.size());
}

}  // namespace pneumachaos
