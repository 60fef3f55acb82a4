#include "pneumachaos/analysis/lyapunov_divergence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pneumachaos/analysis/continuous_alignment.hpp"
#include "pneumachaos/analysis/linear_region.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

void DivergenceOptions::validate(std::size_t n) const {
  if (dimension == 0 || delay == 0) throw Error("lyapunov", "dimension and delay must be >= 1");
  if (n < 100) throw Error("lyapunov", fmt::format("{} samples: at least 100 are needed", n));
  if (!(slope_tolerance > 0.0)) throw Error("lyapunov.slope_tolerance", "must be positive");
  if (jackknife_blocks < 2) throw Error("lyapunov.jackknife_blocks", "must be at least 2");
}

DivergenceResult divergence_exponent(std::span<const double> x, double rate_Hz,
                                     const DivergenceOptions& o) {
  o.validate(x.size());
  DivergenceResult r;
  r.aligned = o.alignment == DivergenceOptions::Alignment::kOn ||
              (o.alignment == DivergenceOptions::Alignment::kAuto && is_oversampled_flow(o.delay));
  const std::size_t period = o.typical_period > 0
                                 ? o.typical_period
                                 : static_cast<std::size_t>(std::lround(mean_maxima_spacing(x)));
  const std::size_t K =
      o.horizon > 0 ? o.horizon : std::max<std::size_t>(20, std::min(x.size() / 10, 8 * period));
  const DelayEmbedding e(x, o.dimension, o.delay);
  // Room for K steps ahead, and for the interpolation stencil around shifted neighbours.
  const std::size_t margin = r.aligned ? 2 : 0;
  if (e.size() <= K + 2 * margin + o.theiler + 10) {
    throw Error("lyapunov", fmt::format("{} samples are too few to follow {} steps with "
                                        "dimension {} and delay {}",
                                        x.size(), K, o.dimension, o.delay));
  }
  const std::size_t usable = e.size() - K - margin;
  const NeighbourIndex index(e, usable, repeat_resolution(x));
  const std::size_t max_refs = std::max<std::size_t>(200, o.max_reference_steps / (K + 1));
  const std::size_t span = K + 1 + (o.dimension - 1) * o.delay;  // samples one pair reads
  std::vector<double> shifted;
  const std::size_t stride = std::max<std::size_t>(1, usable / max_refs);
  const std::size_t blocks = o.jackknife_blocks;
  // Per block sums of ln d(k) and counts, for the jackknife.
  std::vector<std::vector<double>> sum(blocks, std::vector<double>(K + 1, 0.0));
  std::vector<std::vector<double>> count(blocks, std::vector<double>(K + 1, 0.0));
  for (std::size_t i = margin; i < usable; i += stride) {
    const Neighbour nb = index.nearest(i, o.theiler);
    if (nb.index >= usable || nb.index < margin) continue;
    const std::size_t b = std::min(blocks - 1, (i * blocks) / usable);
    // The neighbour's series, shifted by its (constant) offset: interpolated once per sample
    // with fixed weights rather than once per coordinate per step.
    const std::span<const double> other =
        r.aligned ? shifted_series(x, nb.index, closest_offset(e, i, nb.index), span, shifted)
                  : x.subspan(nb.index, span);
    for (std::size_t k = 0; k <= K; ++k) {
      double d2 = 0.0;
      for (std::size_t d = 0; d < e.dimension(); ++d) {
        const double diff = x[i + k + d * o.delay] - other[k + d * o.delay];
        d2 += diff * diff;
      }
      if (d2 > 0.0) {
        sum[b][k] += 0.5 * std::log(d2);
        count[b][k] += 1.0;
      }
    }
    ++r.references;
  }
  if (r.references < 20) throw Error("lyapunov", "fewer than 20 reference points have neighbours");

  const auto curve_without = [&](std::size_t skip) {
    std::vector<double> S(K + 1, 0.0);
    for (std::size_t k = 0; k <= K; ++k) {
      double s = 0.0, c = 0.0;
      for (std::size_t b = 0; b < blocks; ++b) {
        if (b == skip) continue;
        s += sum[b][k];
        c += count[b][k];
      }
      S[k] = c > 0 ? s / c : 0.0;
    }
    return S;
  };
  r.curve = curve_without(blocks);  // skip none

  const std::size_t spacing =
      o.slope_spacing > 0 ? o.slope_spacing : std::max<std::size_t>(1, period / 2);
  const LinearRegion region = find_linear_region(r.curve, spacing, o.slope_tolerance);
  r.found_linear_region = region.found;
  r.fit_first = region.first;
  r.fit_last = region.last;
  r.slope_per_step = region.slope;
  r.intercept = region.intercept;
  r.lambda_per_s = region.slope * rate_Hz;

  // Jackknife over blocks of references on the chosen window, plus the change when the window
  // is narrowed by one spacing at either end (the choice of window is part of the estimate).
  std::vector<double> slopes;
  for (std::size_t b = 0; b < blocks; ++b) {
    slopes.push_back(fit_line(curve_without(b), r.fit_first, r.fit_last).slope);
  }
  const double mean = std::accumulate(slopes.begin(), slopes.end(), 0.0) / blocks;
  double var = 0.0;
  for (double s : slopes) var += (s - mean) * (s - mean);
  const double jack = std::sqrt(var * (blocks - 1.0) / blocks);
  double window = 0.0;
  if (r.fit_last - r.fit_first > 4 * spacing) {
    const double a = fit_line(r.curve, r.fit_first + spacing, r.fit_last).slope;
    const double c = fit_line(r.curve, r.fit_first, r.fit_last - spacing).slope;
    window = 0.5 * std::max(std::abs(a - r.slope_per_step), std::abs(c - r.slope_per_step));
  }
  r.uncertainty_per_s = std::hypot(jack, window) * rate_Hz;
  return r;
}

}  // namespace pneumachaos
