#include "pneumachaos/analysis/spectral_lines.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "analysis/fft.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"

namespace pneumachaos {
namespace {

// Hann's main lobe spans +-2 bins; a line's power is summed over it, and peaks closer than
// this to the first line are its own lobe, not a second line.
constexpr std::size_t kLobe = 2;
constexpr std::size_t kExclude = 4;

// Shortest record whose periodogram has lines to tell apart: below it, no lines.
constexpr std::size_t kMinSamples = 16;

// A second line is rational when f2 / f1 lies near p/q with q <= kMaxDenominator
// (docs/notes/analysis.md: "rational if p/q with q <= 3"): a period-2 or period-3 response.
constexpr int kMaxDenominator = 3;

// The maxima follow the faster mode when their rate matches its frequency within this share
// (docs/notes/analysis.md "Orbital period": "within 10 %").
constexpr double kMaximaRateTolerance = 0.1;

std::vector<double> periodogram(std::span<const double> x) {
  const std::size_t n = x.size();
  const double m = mean_of(x);
  std::vector<double> w(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double hann = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * i / static_cast<double>(n));
    w[i] = (x[i] - m) * hann;
  }
  const auto X = forward_dft(w, fast_fft_size(n));
  std::vector<double> p(X.size() / 2 + 1);
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = std::norm(X[k]);
  return p;
}

// Bin of the peak refined by a parabola through the log power of its neighbours.
double refined_bin(const std::vector<double>& p, std::size_t k) {
  if (k == 0 || k + 1 >= p.size() || !(p[k - 1] > 0 && p[k] > 0 && p[k + 1] > 0)) return k;
  const double a = std::log(p[k - 1]), b = std::log(p[k]), c = std::log(p[k + 1]);
  const double den = a - 2.0 * b + c;
  return den < 0.0 ? static_cast<double>(k) + 0.5 * (a - c) / den : static_cast<double>(k);
}

double lobe_power(const std::vector<double>& p, std::size_t k) {
  double s = 0.0;
  for (std::size_t j = k > kLobe ? k - kLobe : 0; j <= std::min(p.size() - 1, k + kLobe); ++j) {
    s += p[j];
  }
  return s;
}

// f2 / f1 near p/q (q <= 3), within a bin plus half a bin per unit of p/q (f1's own error
// scaled up).
bool rational(double b1, double b2) {
  for (int q = 1; q <= kMaxDenominator; ++q) {
    const double pq = std::round(q * b2 / b1) / q;
    if (pq > 0.0 && std::abs(b2 - pq * b1) <= 1.0 + 0.5 * pq) return true;
  }
  return false;
}

}  // namespace

SpectralLines spectral_lines(std::span<const double> x) {
  SpectralLines s;
  if (x.size() < kMinSamples) return s;
  const std::vector<double> p = periodogram(x);
  const double n = static_cast<double>(2 * (p.size() - 1));
  // Skip DC's lobe (a mean offset or a slow drift is no line).
  std::size_t k1 = kLobe + 1;
  for (std::size_t k = kLobe + 1; k < p.size(); ++k) k1 = p[k] > p[k1] ? k : k1;
  std::size_t k2 = 0;
  for (std::size_t k = kLobe + 1; k + 1 < p.size(); ++k) {
    const bool far = k + kExclude < k1 || k > k1 + kExclude;
    if (far && p[k] >= p[k - 1] && p[k] > p[k + 1] && (k2 == 0 || p[k] > p[k2])) k2 = k;
  }
  const double b1 = refined_bin(p, k1);
  s.first_frequency = b1 / n;
  if (k2 == 0 || !(lobe_power(p, k1) > 0.0)) return s;
  const double b2 = refined_bin(p, k2);
  s.second_frequency = b2 / n;
  s.second_power = lobe_power(p, k2) / lobe_power(p, k1);
  s.incommensurate = !rational(b1, b2);
  return s;
}

double orbital_period(double maxima_spacing, const SpectralLines& lines, std::size_t samples) {
  if (!(lines.second_frequency > 0.0) || samples < kMinSamples) return maxima_spacing;
  const double bins = static_cast<double>(fast_fft_size(samples));
  const double slow = std::min(lines.first_frequency, lines.second_frequency) * bins;
  const double fast = std::max(lines.first_frequency, lines.second_frequency) * bins;
  // A faster mode: at least about twice the slower line's frequency, and the slower line
  // resolved well enough to tell that multiple from the next (the tolerance rational() grants
  // a ratio near q, a bin plus half a bin per unit of q, below half the slower line's bin);
  // a slow "line" a few bins from DC (Lorenz x's lobe switching) is no orbit.
  const double q = std::round(fast / slow);
  if (q < 2.0 || 1.0 + 0.5 * q >= 0.5 * slow) return maxima_spacing;
  // The maxima follow the faster mode when their rate is its frequency (the faster mode's
  // swings each make a maximum); the state repeats only after the slower line's period.
  const double mismatch = std::abs(maxima_spacing * fast / bins - 1.0);
  return mismatch <= kMaximaRateTolerance ? bins / slow : maxima_spacing;
}

}  // namespace pneumachaos
