#include "pneumachaos/analysis/lyapunov_divergence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "divergence_uncertainty.hpp"
#include "analysis/continuous_alignment.hpp"
#include "analysis/delay_embedding.hpp"
#include "analysis/linear_region.hpp"
#include "log_array.hpp"
#include "pair_distances.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// The horizon's default, min(N / kHorizonRecordShare, kHorizonPeriods orbital periods) and at
// least kMinHorizon steps (DivergenceOptions::horizon; docs/notes/analysis.md, "horizon 8
// orbital periods"): several orbits for the curve to rise and saturate, capped at a tenth of
// the record so that the rest holds the references.
constexpr std::size_t kMinHorizon = 20;
constexpr std::size_t kHorizonRecordShare = 10;
constexpr std::size_t kHorizonPeriods = 8;

// Delay vectors a record must have beyond the horizon, margins and Theiler window; with fewer
// the estimator refuses it (a longer record is needed).
constexpr std::size_t kMinSpareVectors = 10;

// References are capped by max_reference_steps / horizon, but the cap never falls below this
// many, however long the horizon.
constexpr std::size_t kMinReferenceCap = 200;

// Fewest references with a neighbour the curve is averaged over: two per block at the default
// 10 jackknife blocks.
constexpr std::size_t kMinReferences = 20;

// The window's sensitivity is measured by trimming one spacing from either end, and only on
// windows of more than this many spacings, where the trimmed window keeps three.
constexpr std::size_t kMinSpacingsToTrim = 4;

}  // namespace

void DivergenceOptions::validate(std::size_t n) const {
  using namespace validation;
  require_ge(field("lyapunov.dimension"), static_cast<double>(dimension), 1);
  require_ge(field("lyapunov.delay"), static_cast<double>(delay), 1);
  if (n < kMinExponentSamples) {
    throw Error("lyapunov",
                fmt::format("{} samples: at least {} are needed", n, kMinExponentSamples));
  }
  require_gt(field("lyapunov.slope_tolerance"), slope_tolerance, 0);
  require_ge(field("lyapunov.jackknife_blocks"), static_cast<double>(jackknife_blocks), 2);
  require_between(field("lyapunov.segments"), static_cast<double>(segments), 2,
                  static_cast<double>(jackknife_blocks), "jackknife_blocks at most");
}

namespace {

// How far pairs are followed and which references can be followed that far.
struct Plan {
  bool aligned = false;
  std::size_t period = 0, K = 0, margin = 0, usable = 0;
};

Plan make_plan(std::span<const double> x, const DelayEmbedding& e, const DivergenceOptions& o) {
  Plan p;
  p.aligned = o.alignment == DivergenceOptions::Alignment::kOn ||
              (o.alignment == DivergenceOptions::Alignment::kAuto && is_oversampled_flow(o.delay));
  p.period = o.typical_period > 0 ? o.typical_period
                                  : static_cast<std::size_t>(std::lround(mean_maxima_spacing(x)));
  p.K = o.horizon > 0 ? o.horizon
                      : std::max<std::size_t>(kMinHorizon, std::min(x.size() / kHorizonRecordShare,
                                                                    kHorizonPeriods * p.period));
  // Room for K steps ahead, and for the interpolation stencil around shifted neighbours.
  p.margin = p.aligned ? 2 : 0;
  if (e.size() <= p.K + 2 * p.margin + o.theiler + kMinSpareVectors) {
    throw Error("lyapunov", fmt::format("{} samples are too few to follow {} steps with "
                                        "dimension {} and delay {}: a longer record is needed",
                                        x.size(), p.K, o.dimension, o.delay));
  }
  p.usable = e.size() - p.K - p.margin;
  return p;
}

// Per block of references, the sums of ln d(k) and their counts (for the jackknife).
struct BlockSums {
  std::vector<std::vector<double>> sum, count;
  std::size_t references = 0;
  // The mean curve over every block but `skip` (skip = blocks: all of them).
  [[nodiscard]] std::vector<double> curve_without(std::size_t skip) const {
    const std::size_t points = sum.front().size();
    std::vector<double> S(points, 0.0);
    for (std::size_t k = 0; k < points; ++k) {
      double s = 0.0, c = 0.0;
      for (std::size_t b = 0; b < sum.size(); ++b) {
        if (b == skip) continue;
        s += sum[b][k];
        c += count[b][k];
      }
      S[k] = c > 0 ? s / c : 0.0;
    }
    return S;
  }
};

// sum[k] += ln d(k) = ln(d2[k]) / 2 and count[k] += 1 where d2[k] > 0. Adding 0 elsewhere
// leaves the sums bit for bit as skipping would (they start at +0 and no term is -0), and
// keeps the loop free of branches so it vectorises.
void add_log_distances(std::span<const double> d2, std::span<const double> logs,
                       std::vector<double>& sum, std::vector<double>& count) {
  const double* __restrict l = logs.data();
  double* __restrict s = sum.data();
  double* __restrict c = count.data();
  for (std::size_t k = 0; k < d2.size(); ++k) {
    const bool positive = d2[k] > 0.0;
    s[k] += positive ? 0.5 * l[k] : 0.0;
    c[k] += positive ? 1.0 : 0.0;
  }
}

BlockSums follow_pairs(std::span<const double> x, const DelayEmbedding& e, const Plan& p,
                       const DivergenceOptions& o) {
  const NeighbourIndex index(e, p.usable, repeat_resolution(x));
  const std::size_t max_refs =
      std::max<std::size_t>(kMinReferenceCap, o.max_reference_steps / (p.K + 1));
  const std::size_t span = p.K + 1 + (o.dimension - 1) * o.delay;  // samples one pair reads
  const std::size_t stride = std::max<std::size_t>(1, p.usable / max_refs);
  const std::size_t blocks = o.jackknife_blocks;
  BlockSums bs{std::vector<std::vector<double>>(blocks, std::vector<double>(p.K + 1, 0.0)),
               std::vector<std::vector<double>>(blocks, std::vector<double>(p.K + 1, 0.0))};
  std::vector<std::size_t> references;
  for (std::size_t i = p.margin; i < p.usable; i += stride) references.push_back(i);
  // All neighbours first (searched in the tree's order: docs/notes/performance.md), then the sums
  // in the references' order, so every sum adds its terms in record order whatever the search's.
  const std::vector<Neighbour> neighbours = index.nearest_each(references, o.theiler);
  std::vector<double> shifted, d2(p.K + 1), logs(p.K + 1);
  for (std::size_t r = 0; r < references.size(); ++r) {
    const std::size_t i = references[r];
    const Neighbour& nb = neighbours[r];
    if (nb.index >= p.usable || nb.index < p.margin) continue;
    const std::size_t b = std::min(blocks - 1, (i * blocks) / p.usable);
    // The neighbour's series, shifted by its (constant) offset: interpolated once per sample
    // with fixed weights rather than once per coordinate per step.
    const std::span<const double> other =
        p.aligned ? shifted_series(x, nb.index, closest_offset(e, i, nb.index), span, shifted)
                  : x.subspan(nb.index, span);
    squared_pair_distances(x.data() + i, other.data(), e.dimension(), o.delay, d2);
    log_array(d2, logs);  // vectorised: scalar logarithms take half the curve's time
    add_log_distances(d2, logs, bs.sum[b], bs.count[b]);
    ++bs.references;
  }
  if (bs.references < kMinReferences) {
    throw Error("lyapunov", fmt::format("only {} reference points have a neighbour outside the "
                                        "Theiler window ({} samples); at least {} are needed: "
                                        "a longer record, or a shorter --theiler",
                                        bs.references, o.theiler, kMinReferences));
  }
  return bs;
}

// The slope's uncertainty on the chosen window, per step: the jackknife over blocks of
// references, and the change when the window is narrowed by one spacing at either end.
double slope_uncertainty(const BlockSums& bs, std::size_t spacing, const DivergenceResult& r) {
  const std::size_t blocks = bs.sum.size();
  std::vector<double> slopes;
  for (std::size_t b = 0; b < blocks; ++b) {
    slopes.push_back(fit_line(bs.curve_without(b), r.fit_first, r.fit_last).slope);
  }
  const double mean = std::accumulate(slopes.begin(), slopes.end(), 0.0) / blocks;
  double var = 0.0;
  for (double s : slopes) var += (s - mean) * (s - mean);
  const double jack = std::sqrt(var * (blocks - 1.0) / blocks);
  double window = 0.0;
  if (r.fit_last - r.fit_first > kMinSpacingsToTrim * spacing) {
    const double a = fit_line(r.curve, r.fit_first + spacing, r.fit_last).slope;
    const double c = fit_line(r.curve, r.fit_first, r.fit_last - spacing).slope;
    window = 0.5 * std::max(std::abs(a - r.slope_per_step), std::abs(c - r.slope_per_step));
  }
  return std::hypot(jack, window);
}

// The value's uncertainty adds, in quadrature, the spread of the exponent fitted separately
// on contiguous segments of the record, each with its own window (docs/notes/analysis.md
// "Divergence exponent's uncertainty"). Fills both uncertainties and the segments.
void uncertainties(const BlockSums& bs, std::size_t spacing, const DivergenceOptions& o,
                   double rate_Hz, DivergenceResult& r) {
  const double slope = slope_uncertainty(bs, spacing, r);
  const detail::SegmentSlopes seg = detail::segment_slopes(
      bs.sum, bs.count, o.segments, spacing, o.slope_tolerance, r.fit_first, r.fit_last);
  r.segment_slopes_per_step = seg.slopes;
  r.segments_without_region = seg.without_region;
  r.slope_uncertainty_per_s = slope * rate_Hz;
  r.uncertainty_per_s = std::hypot(slope, seg.standard_error) * rate_Hz;
}

}  // namespace

DivergenceResult divergence_exponent(std::span<const double> x, double rate_Hz,
                                     const DivergenceOptions& o) {
  o.validate(x.size());
  const DelayEmbedding e(x, o.dimension, o.delay);
  const Plan plan = make_plan(x, e, o);
  const BlockSums sums = follow_pairs(x, e, plan, o);
  DivergenceResult r;
  r.aligned = plan.aligned;
  r.references = sums.references;
  r.curve = sums.curve_without(o.jackknife_blocks);
  const std::size_t spacing =
      o.slope_spacing > 0 ? o.slope_spacing : std::max<std::size_t>(1, plan.period / 2);
  const LinearRegion region = find_linear_region(r.curve, spacing, o.slope_tolerance);
  r.slope_spacing = spacing;
  r.found_linear_region = region.found;
  r.fit_first = region.first;
  r.fit_last = region.last;
  r.slope_per_step = region.slope;
  r.intercept = region.intercept;
  r.lambda_per_s = region.slope * rate_Hz;
  uncertainties(sums, spacing, o, rate_Hz, r);
  // One orbit (the spacing is half of one) so that the orbital modulation averages out.
  if (!region.found) r.local_slopes = rising_slopes(r.curve, 2 * spacing);
  return r;
}

}  // namespace pneumachaos
