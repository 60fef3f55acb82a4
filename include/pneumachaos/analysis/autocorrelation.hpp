#pragma once
// Autocorrelation of a series by FFT (Wiener-Khinchin), mean removed, normalised to 1 at lag 0.

#include <span>
#include <vector>

namespace pneumachaos {

struct Autocorrelation {
  std::vector<double> r;  ///< r[k], k = 0 .. max_lag (biased estimator)
  double rate_Hz = 1.0;
  double first_zero_s = -1.0;  ///< first lag where r <= 0; -1 if none
  double one_over_e_s = -1.0;  ///< first lag where r < 1/e; -1 if none
  /// Decay rate of the envelope of |r| (local maxima), from a least-squares fit of its log
  /// while above the noise level 2/sqrt(N) [1/s]; 0 if the envelope does not decay.
  double envelope_decay_per_s = 0.0;
  /// pi/2 x mean |r| over lags N/8 .. N/4 (the envelope, for an oscillation): ~0.8 for a
  /// periodic record (the biased estimator's taper), ~1/sqrt(N) for noise; the paper's
  /// "converged to zero" when small.
  double late_envelope = 0.0;
  /// centred_lag_products of the series (all N lags), kept for the self-repetition check.
  std::vector<double> lag_products;
};

/// sum_t y[t] y[t + k] for k = 0 .. N-1, y = x minus its mean (by FFT, zero padded).
std::vector<double> centred_lag_products(std::span<const double> x);

/// ACF up to max_lag (default N/4). Throws Error for fewer than 16 samples or a constant series.
Autocorrelation autocorrelation(std::span<const double> x, double rate_Hz, std::size_t max_lag = 0);

}  // namespace pneumachaos
