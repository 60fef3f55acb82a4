// The two claims about the shape of the chaotic motion: Fig. 7c's fold and stretch bands and
// Fig. 3's friction loop without standstill (declared in claim_rules.hpp).
#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/local_stretching.hpp"
#include "pneumachaos/analysis/poincare.hpp"
#include "pneumachaos/report/claim_rules.hpp"

namespace pneumachaos {
namespace {

// The paper's band edges (Fig. 7c), in m/s.
constexpr double kFoldLow = 0.140, kFoldHigh = 0.180;

double share_in_fold_band(const std::vector<std::array<double, 2>>& pairs, std::size_t& count) {
  std::vector<double> maxima;
  for (const auto& p : pairs) maxima.push_back(p[0]);
  if (!pairs.empty()) maxima.push_back(pairs.back()[1]);
  count = maxima.size();
  if (maxima.empty()) return 0.0;
  const auto in = std::count_if(maxima.begin(), maxima.end(),
                                [](double m) { return m >= kFoldLow && m <= kFoldHigh; });
  return static_cast<double>(in) / static_cast<double>(maxima.size());
}

struct Branch {
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  double mean() const { return sum / static_cast<double>(n); }
  double variance_of_mean() const {
    const double m = mean(), nn = static_cast<double>(n);
    return std::max(0.0, sum2 / nn - m * m) / (nn - 1.0);
  }
};

double quantile(std::vector<double> x, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(x.size() - 1));
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(k), x.end());
  return x[k];
}

}  // namespace

FoldStretch measure_fold_stretch(const std::vector<double>& v, double rate_Hz,
                                 std::size_t dimension, std::size_t delay, std::size_t theiler) {
  FoldStretch f;
  f.maxima_in_fold_band = share_in_fold_band(successive_maxima(v), f.maxima);
  StretchingOptions o;
  o.dimension = std::max<std::size_t>(3, dimension);
  o.delay = std::max<std::size_t>(1, delay);
  o.theiler = theiler;
  // Followed for one delay: short against the oscillation, so a pair stays in its band.
  o.horizon = o.delay;
  const auto bands = band_stretching(v, rate_Hz, {0.0, kFoldLow, kFoldHigh}, o);
  f.stretch_rate = bands[0].rate_per_s;
  f.stretch_se = bands[0].standard_error_per_s;
  f.fold_rate = bands[1].rate_per_s;
  f.fold_se = bands[1].standard_error_per_s;
  return f;
}

bool folded_and_stretched(const FoldStretch& f) {
  const double diff_se = std::hypot(f.stretch_se, f.fold_se);
  return f.maxima > 0 && f.maxima_in_fold_band >= 0.5 && f.stretch_rate > 3.0 * f.stretch_se &&
         f.stretch_rate - f.fold_rate > 3.0 * diff_se;
}

FrictionLoop measure_friction_loop(const std::vector<double>& v, const std::vector<double>& F) {
  FrictionLoop l;
  const std::size_t n = std::min(v.size(), F.size());
  if (n < 3) return l;
  const auto still = std::count_if(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n),
                                   [](double x) { return std::abs(x) < 1e-3; });
  l.standstill_share = static_cast<double>(still) / static_cast<double>(n);
  const double lo = quantile(v, 0.05), hi = quantile(v, 0.95);
  if (!(hi > lo)) return l;
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
  return l;
}

bool loops_without_standstill(const FrictionLoop& l) {
  return l.standstill_share < 0.01 && l.bins >= 4 && 2 * l.hysteretic_bins >= l.bins;
}

}  // namespace pneumachaos
