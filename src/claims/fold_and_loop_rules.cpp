// The two claims about the shape of the chaotic motion: Fig. 7c's fold and stretch bands and
// Fig. 3's friction loop without standstill (declared in claim_rules.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/local_stretching.hpp"
#include "pneumachaos/analysis/poincare.hpp"
#include "pneumachaos/claims/claim_rules.hpp"

namespace pneumachaos {
namespace {

double quantile(std::vector<double> x, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(x.size() - 1));
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(k), x.end());
  return x[k];
}

double share_at_or_above(const std::vector<std::array<double, 2>>& pairs, double edge,
                         std::size_t& count) {
  std::vector<double> maxima;
  for (const auto& p : pairs) maxima.push_back(p[0]);
  if (!pairs.empty()) maxima.push_back(pairs.back()[1]);
  count = maxima.size();
  if (maxima.empty()) return 0.0;
  const auto in = std::count_if(maxima.begin(), maxima.end(), [&](double m) { return m >= edge; });
  return static_cast<double>(in) / static_cast<double>(maxima.size());
}

struct Branch {
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  [[nodiscard]] double mean() const { return sum / static_cast<double>(n); }
  [[nodiscard]] double variance_of_mean() const {
    const double m = mean(), nn = static_cast<double>(n);
    return std::max(0.0, sum2 / nn - m * m) / (nn - 1.0);
  }
};

// Rest episodes: runs of |v| < kRestSpeed lasting at least kRestDuration.
void count_rests(const std::vector<double>& v, double rate_Hz, FrictionLoop& l) {
  std::size_t run = 0, longest = 0;
  const auto min_run = static_cast<std::size_t>(std::ceil(kRestDuration_s * rate_Hz));
  const auto close = [&] {
    if (run >= min_run) ++l.rests;
    longest = std::max(longest, run);
    run = 0;
  };
  for (double x : v) {
    if (std::abs(x) < kRestSpeed_m_per_s) {
      ++run;
    } else {
      close();
    }
  }
  close();
  l.longest_rest_s = static_cast<double>(longest) / rate_Hz;
}

void count_hysteresis(const std::vector<double>& v, const std::vector<double>& F, std::size_t n,
                      FrictionLoop& l) {
  const double lo = quantile(v, 0.05), hi = quantile(v, 0.95);
  if (!(hi > lo)) return;
  constexpr std::size_t kBins = 10;
  std::vector<Branch> up(kBins), down(kBins);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (v[k] < lo || v[k] >= hi) continue;
    const auto b = static_cast<std::size_t>((v[k] - lo) / (hi - lo) * kBins);
    Branch& br = v[k + 1] > v[k - 1] ? up[b] : down[b];  // accelerating or decelerating
    br.sum += F[k];
    br.sum2 += F[k] * F[k];
    ++br.n;
  }
  for (std::size_t b = 0; b < kBins; ++b) {
    if (up[b].n < 10 || down[b].n < 10) continue;
    ++l.bins;
    const double se = std::sqrt(up[b].variance_of_mean() + down[b].variance_of_mean());
    if (std::abs(up[b].mean() - down[b].mean()) > 3.0 * se) ++l.hysteretic_bins;
  }
}

}  // namespace

FoldStretch measure_fold_stretch(const std::vector<double>& v, double rate_Hz,
                                 std::size_t dimension, std::size_t delay, std::size_t theiler) {
  FoldStretch f;
  if (v.size() < 3) return f;
  f.low = quantile(v, 0.005);
  f.high = quantile(v, 0.995);
  const double edge = f.low + kFoldBandStart * (f.high - f.low);
  f.maxima_in_fold_band = share_at_or_above(successive_maxima(v), edge, f.maxima);
  StretchingOptions o;
  o.dimension = std::max<std::size_t>(3, dimension);
  o.delay = std::max<std::size_t>(1, delay);
  o.theiler = theiler;
  // Followed for one delay: short against the oscillation, so a pair stays in its band.
  o.horizon = o.delay;
  const auto bands = band_stretching(v, rate_Hz, {-INFINITY, edge}, o);
  f.stretch_rate = bands[0].rate_per_s;
  f.stretch_se = bands[0].standard_error_per_s;
  return f;
}

RuleResult folded_and_stretched(const FoldStretch& f) {
  if (f.maxima == 0) return {kNaN, "the record has no velocity maxima"};
  const RuleResult fold{
      (f.maxima_in_fold_band - 0.5) / 0.5,
      f.maxima_in_fold_band >= 0.5
          ? ""
          : fmt::format("only {:.0f} % of the velocity maxima lie in the top {:.0f} % of the "
                        "record's range, where the paper's trajectory folds",
                        100 * f.maxima_in_fold_band, 100 * (1 - kFoldBandStart))};
  const double scale = 3.0 * std::max(f.stretch_se, 1e-12);
  const RuleResult stretch{(f.stretch_rate - scale) / scale,
                           fmt::format("nearby trajectories do not separate significantly below "
                                       "the fold band ({:.1f} +- {:.1f} 1/s)",
                                       f.stretch_rate, f.stretch_se)};
  return both(fold, stretch);
}

FrictionLoop measure_friction_loop(const std::vector<double>& v_in, const std::vector<double>& F,
                                   double rate_Hz) {
  FrictionLoop l;
  const std::size_t n = std::min(v_in.size(), F.size());
  if (n < 3) return l;
  const std::vector<double> v(v_in.begin(), v_in.begin() + static_cast<std::ptrdiff_t>(n));
  count_rests(v, rate_Hz, l);
  count_hysteresis(v, F, n, l);
  return l;
}

RuleResult loops_without_standstill(const FrictionLoop& l) {
  const RuleResult still{1.0 - l.longest_rest_s / kRestDuration_s,
                         fmt::format("the piston rests {} times (the longest {:.0f} ms at below "
                                     "1 mm/s)",
                                     l.rests, 1e3 * l.longest_rest_s)};
  if (l.bins < 4) return both(still, {-1.0, "fewer than 4 velocity bins hold both branches"});
  const double share = static_cast<double>(l.hysteretic_bins) / static_cast<double>(l.bins);
  const RuleResult loop{(share - 0.5) / 0.5,
                        fmt::format("the friction traces no loop: hysteresis in only {} of {} "
                                    "velocity bins",
                                    l.hysteretic_bins, l.bins)};
  return both(still, loop);
}

}  // namespace pneumachaos
