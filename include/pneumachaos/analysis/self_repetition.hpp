#pragma once
// Does the record repeat itself at one fixed lag over most of its length? A chaotic record
// cannot: a near-repeat x(t + L) ~ x(t) is a pair of nearby states, and nearby states separate
// at the rate of the largest exponent until the separation reaches the attractor's size. So a
// mismatch that stays small over a long stretch refutes a claimed exponential divergence
// (docs/notes/analysis.md "Regime verdict", the self-repetition veto).

#include <cstddef>
#include <span>
#include <string>

namespace pneumachaos {

struct SelfRepetitionOptions {
  /// "Small": the windowed RMS mismatch at most this fraction of the attractor's size (the
  /// RMS distance of two independent samples, sqrt(2) x std). Measurement noise of relative
  /// std s alone gives ~s, so periodic records with up to ~7 % noise still repeat; a chaotic
  /// separation saturates at ~1 (docs/notes/analysis.md).
  double max_mismatch = 0.1;
  /// ...over a stretch of at least this share of the record ("most of its length").
  double min_share = 0.5;
  /// Lags from this many orbital periods on (up to half the record): a repeat seen once, one
  /// cycle later, says little; one held over several cycles does.
  double min_lag_periods = 2.0;
  /// Local minima of the whole-overlap mismatch examined window by window.
  std::size_t candidates = 5;
  /// The lag may follow a slow phase drift, by at most this fraction of a period from one
  /// period-long window to the next: a shift along the flow is neutral (zero exponent), so
  /// it cannot hide an exponential separation across it. 0: one fixed lag.
  double lag_drift = 0.25;
  void validate() const;  ///< throws Error naming the option
};

struct SelfRepetition {
  bool run = false;
  std::string reason;   ///< why not run, when not
  std::size_t lag = 0;  ///< samples: the lag with the longest small-mismatch stretch
  double lag_s = 0.0;
  double lag_drift_s = 0.0;  ///< how far the followed lag moved along the stretch
  double mismatch = 0.0;  ///< RMS over the whole overlap at that lag / attractor size
  /// The longest run of one-period windows whose mismatch stays <= max_mismatch: its
  /// duration, share of the record, largest window mismatch, and the least-squares growth
  /// rate of ln(window mismatch) along it (0 with fewer than 3 windows).
  double stretch_s = 0.0, share = 0.0, stretch_max_mismatch = 0.0, growth_per_s = 0.0;
  bool repeats = false;  ///< share >= min_share
  double max_mismatch = 0.0;  ///< the "small" it was judged by (the option's, or raised by noise)
};

/// period_samples: the orbital period (sets the shortest lag and the window length).
/// products: centred_lag_products(x) when already at hand (Autocorrelation::lag_products),
/// else empty and computed here (one FFT of 2N points).
SelfRepetition self_repetition(std::span<const double> x, double rate_Hz, double period_samples,
                               const SelfRepetitionOptions& options = {},
                               std::span<const double> products = {});

}  // namespace pneumachaos
