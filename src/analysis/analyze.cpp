#include "pneumachaos/analysis/analyze.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Rest intervals: runs of at least min_len samples with |x| <= level whose spread stays
// within level / 2; a smooth passage through zero spreads over the whole band and is no rest.
void rest_statistics(std::span<const double> x, double level, std::size_t min_len,
                     RegimeEvidence& e) {
  std::size_t run = 0, at_rest = 0;
  double lo = 0.0, hi = 0.0;
  const auto close_run = [&] {
    if (run >= min_len) {
      ++e.rest_intervals;
      at_rest += run;
    }
    run = 0;
  };
  for (double v : x) {
    const bool inside = std::abs(v) <= level;
    if (inside && run > 0 && std::max(hi, v) - std::min(lo, v) <= 0.5 * level) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      ++run;
      continue;
    }
    close_run();
    if (inside) {
      run = 1;
      lo = hi = v;
    }
  }
  close_run();
  e.rest_share = static_cast<double>(at_rest) / static_cast<double>(x.size());
}

}  // namespace

AnalysisResult analyze_series(std::span<const double> x, double rate_Hz, const AnalysisOptions& o) {
  constexpr std::size_t kMinSamples = 200;
  if (x.size() < kMinSamples) {
    throw Error("analyze", fmt::format("{} samples is too short to analyse: at least {} are needed",
                                       x.size(), kMinSamples));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw Error("analyze", fmt::format("sample {} is not finite", i));
  }
  if (!(std::isfinite(rate_Hz) && rate_Hz > 0.0)) {
    throw Error("analyze", fmt::format("the sample rate must be positive, got {}", rate_Hz));
  }
  AnalysisResult r;
  r.samples = x.size();
  r.rate_Hz = rate_Hz;
  r.mean = mean_of(x);
  r.standard_deviation = standard_deviation(x);
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  if (!std::isfinite(r.standard_deviation)) {
    // Finite samples whose squares overflow: every index would be NaN or "constant".
    throw Error("analyze", fmt::format("values up to {:g} are too large to analyse in double "
                                       "precision; rescale the record (e.g. another unit)",
                                       std::max(std::abs(*lo), std::abs(*hi))));
  }
  RegimeEvidence& e = r.evidence;
  e.samples = x.size();
  e.mean = r.mean;
  e.range = *hi - *lo;
  const std::span<const double> last = x.subspan(x.size() / 2);
  e.last_half_mean = mean_of(last);
  e.last_half_std = standard_deviation(last);
  const double max_abs = std::max(std::abs(*lo), std::abs(*hi));
  rest_statistics(x, o.verdict.rest_fraction * max_abs, o.verdict.min_rest_samples, e);
  if (!(r.standard_deviation > 0.0)) {
    // A constant record: steady by definition; no index is defined.
    r.verdict = decide_regime(e, o.verdict);
    return r;
  }

  r.period_samples = mean_maxima_spacing(x);
  r.spectrum = welch_spectrum(x, rate_Hz, o.spectrum);
  r.acf = autocorrelation(x, rate_Hz);
  e.broadband_share = r.spectrum.broadband_share;
  e.late_acf = r.acf.late_envelope;
  if (is_steady(e, o.verdict)) {
    // Damped to a constant: nothing to embed; the exponents are not computed.
    r.verdict = decide_regime(e, o.verdict);
    return r;
  }
  r.delay = o.delay > 0 ? DelayChoice{o.delay, "given", {}} : choose_delay(x);
  const std::size_t tau = r.delay.delay;
  const std::size_t zero_lag =
      r.acf.first_zero_s > 0 ? static_cast<std::size_t>(std::lround(r.acf.first_zero_s * rate_Hz))
                             : 1;
  r.theiler = o.theiler > 0 ? o.theiler : std::max(tau, zero_lag);
  r.dimension =
      o.dimension > 0 ? DimensionChoice{o.dimension, {}, {}} : choose_dimension(x, tau, r.theiler);

  DivergenceOptions d;
  d.dimension = r.dimension.dimension;
  d.delay = tau;
  d.theiler = r.theiler;
  d.typical_period = static_cast<std::size_t>(std::lround(r.period_samples));
  r.divergence = divergence_exponent(x, rate_Hz, d);
  if (o.wolf) {
    WolfOptions w;
    w.dimension = d.dimension;
    w.delay = tau;
    w.theiler = r.theiler;
    w.typical_period = d.typical_period;
    r.wolf = wolf_exponent(x, rate_Hz, w);
    r.wolf_run = true;
  }
  r.poincare = poincare_section(x, tau, rate_Hz);
  r.maxima_map = successive_maxima(x);

  e.lyapunov_found = r.divergence.found_linear_region;
  e.lyapunov_per_s = r.divergence.lambda_per_s;
  e.lyapunov_uncertainty_per_s = r.divergence.uncertainty_per_s;
  for (double v : r.dimension.E2) e.determinism = std::max(e.determinism, std::abs(v - 1.0));
  r.verdict = decide_regime(e, o.verdict);
  return r;
}

}  // namespace pneumachaos
