#include "pneumachaos/analysis/spectrum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "analysis/fft.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// Welch's default segment: the largest power of two <= N / kMinSegments within
// [kMinSegmentLength, kMaxSegmentLength] (docs/notes/analysis.md, "segment = largest power of
// two <= N/8 in [64, 8192]"): at least eight segments (fifteen with 50 % overlap) to average.
constexpr std::size_t kMinSegments = 8;
constexpr std::size_t kMinSegmentLength = 64;
constexpr std::size_t kMaxSegmentLength = 8192;

// Shortest segment accepted for SpectrumOptions::segment_length: a floor on the user's choice
// (the default never goes below kMinSegmentLength).
constexpr std::size_t kShortestSegment = 8;

// Exact zeros of the PSD (a constant record) enter the flatness's log-mean as this instead.
constexpr double kPowerFloor = 1e-300;

std::size_t default_segment(std::size_t n) {
  std::size_t L = kMinSegmentLength;
  while (L * 2 <= n / kMinSegments && L * 2 <= kMaxSegmentLength) L *= 2;
  return L;
}

}  // namespace

std::size_t welch_segment_length(std::size_t n_samples, const SpectrumOptions& options) {
  return options.segment_length == 0 ? default_segment(n_samples) : options.segment_length;
}

void SpectrumOptions::validate(std::size_t n_samples) const {
  using namespace validation;
  const std::size_t L = segment_length == 0 ? default_segment(n_samples) : segment_length;
  require_ge(field("spectrum.segment_length"), static_cast<double>(L),
             static_cast<double>(kShortestSegment), "samples");
  if (n_samples < L) {
    throw Error("spectrum",
                fmt::format("{} samples is shorter than one segment of {}", n_samples, L));
  }
  require_ge_lt(field("spectrum.overlap"), overlap, 0, 1);
}

Spectrum welch_spectrum(std::span<const double> x, double rate_Hz, const SpectrumOptions& o) {
  o.validate(x.size());
  const std::size_t L = o.segment_length == 0 ? default_segment(x.size()) : o.segment_length;
  const std::size_t hop = std::max<std::size_t>(1, static_cast<std::size_t>(L * (1.0 - o.overlap)));
  std::vector<double> window(L);
  for (std::size_t i = 0; i < L; ++i) {
    window[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * i / L);  // periodic Hann
  }
  const double window_power = std::inner_product(window.begin(), window.end(), window.begin(), 0.0);
  const std::size_t bins = L / 2 + 1;
  Spectrum s;
  s.psd.assign(bins, 0.0);
  std::vector<double> segment(L);
  for (std::size_t start = 0; start + L <= x.size(); start += hop) {
    const double mean = std::accumulate(x.begin() + start, x.begin() + start + L, 0.0) / L;
    for (std::size_t i = 0; i < L; ++i) segment[i] = (x[start + i] - mean) * window[i];
    const auto X = forward_dft(segment, L);
    for (std::size_t k = 0; k < bins; ++k) s.psd[k] += std::norm(X[k]);
    ++s.segments;
  }
  // One-sided density: |X|^2 / (fs sum w^2), doubled except at DC and Nyquist.
  for (std::size_t k = 0; k < bins; ++k) {
    const double one_sided = (k == 0 || 2 * k == L) ? 1.0 : 2.0;
    s.psd[k] *= one_sided / (rate_Hz * window_power * s.segments);
  }
  s.resolution_Hz = rate_Hz / L;
  s.frequency_Hz.resize(bins);
  for (std::size_t k = 0; k < bins; ++k) s.frequency_Hz[k] = k * s.resolution_Hz;

  const double total = std::accumulate(s.psd.begin() + 1, s.psd.end(), 0.0);
  const auto peak = std::max_element(s.psd.begin() + 1, s.psd.end());
  const std::size_t kp = static_cast<std::size_t>(peak - s.psd.begin());
  s.peak_frequency_Hz = s.frequency_Hz[kp];
  if (total > 0.0) {
    double lobe = 0.0;
    for (std::size_t k = std::max<std::size_t>(1, kp - 1); k <= std::min(bins - 1, kp + 1); ++k)
      lobe += s.psd[k];
    s.peak_share = lobe / total;
    std::vector<double> sorted(s.psd.begin() + 1, s.psd.end());
    const std::size_t top = std::min(o.strongest_bins, sorted.size());
    std::partial_sort(sorted.begin(), sorted.begin() + top, sorted.end(), std::greater<>());
    s.broadband_share = 1.0 - std::accumulate(sorted.begin(), sorted.begin() + top, 0.0) / total;
    // Flatness on the bins that carry power; exact zeros (a pure tone between bins is never
    // exactly zero, but a constant record is) count as kPowerFloor.
    double log_sum = 0.0;
    for (std::size_t k = 1; k < bins; ++k) log_sum += std::log(std::max(s.psd[k], kPowerFloor));
    s.spectral_flatness = std::exp(log_sum / (bins - 1)) / (total / (bins - 1));
  }
  return s;
}

}  // namespace pneumachaos
