#pragma once
// Power spectral density by Welch's method (Welch 1967, IEEE Trans. Audio Electroacoust. 15):
// Hann-windowed segments with 50 % overlap, each mean-removed, periodograms averaged.

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

struct SpectrumOptions {
  /// Samples per segment; 0 picks the largest power of two <= N/8, clipped to [64, 8192]
  /// (about 17 averaged segments for 1e4 samples).
  std::size_t segment_length = 0;
  double overlap = 0.5;
  /// Bins counted as "concentrated" power: the strongest ones, each main lobe included.
  std::size_t strongest_bins = 10;
  void validate(std::size_t n_samples) const;
};

struct Spectrum {
  std::vector<double> frequency_Hz;  ///< 0 .. rate/2
  std::vector<double> psd;           ///< one-sided PSD [unit^2/Hz]
  std::size_t segments = 0;
  double resolution_Hz = 0.0;
  double peak_frequency_Hz = 0.0;  ///< strongest bin above DC
  double peak_share = 0.0;         ///< power within +-1 bin of the peak / total (DC excluded)
  double spectral_flatness = 0.0;  ///< geometric / arithmetic mean of the PSD (1 = white)
  double broadband_share = 0.0;    ///< power outside the strongest bins / total
};

/// The segment length welch_spectrum takes for n_samples under `options`: its frequency
/// resolution is the rate divided by it (what a spectral rule can tell apart).
std::size_t welch_segment_length(std::size_t n_samples, const SpectrumOptions& options = {});

/// Welch PSD of x sampled at rate_Hz. Throws Error if x is shorter than one segment of 64.
Spectrum welch_spectrum(std::span<const double> x, double rate_Hz,
                        const SpectrumOptions& options = {});

}  // namespace pneumachaos
