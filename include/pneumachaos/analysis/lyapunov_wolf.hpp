#pragma once
// Largest Lyapunov exponent by Wolf, Swift, Swinney & Vastano (1985), "Determining Lyapunov
// exponents from a time series", Physica D 16, 285-317: the fixed-evolution-time program.
// One fiducial trajectory is followed with one neighbour; after every evolution interval the
// log stretching is accumulated, and a neighbour that has separated beyond max_scale is
// replaced by the point that is close and best preserves the separation's orientation.
//
// Additions for finite, oversampled records (each switchable): neighbours aligned in
// continuous time; for flows each new pair settles for one orbital period before it is
// measured (a fresh nearest neighbour first grows faster than the Lyapunov rate, the initial
// transient of every divergence curve) while the pair it replaces is still measured, so no
// stretch of the fiducial trajectory is skipped; several staggered fiducial chains pooled.
// Measured accuracy with the defaults (1e4 samples; docs/notes/analysis.md): logistic 0 %,
// Henon -8 %, Lorenz -8 ... +8 % over eight records, Rossler -16 ... -2 % over eight.

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

struct WolfOptions {
  std::size_t dimension = 3;
  std::size_t delay = 1;
  std::size_t theiler = 1;
  std::size_t evolve = 0;          ///< steps per evolution interval; 0: max(1, period / 4)
  std::size_t typical_period = 0;  ///< samples per oscillation; 0: mean_maxima_spacing
  double max_scale = 0.0;          ///< replacement threshold; 0: scale_factor x median NN distance
  double scale_factor = 5.0;
  /// Radius within which a replacement is the best-oriented point; 0: the median NN distance
  /// for flows, max_scale for maps.
  double candidate_scale = 0.0;
  double min_scale = 0.0;  ///< smallest accepted separation; 0: 1e-4 x diameter
  /// Steps a new pair evolves before it is measured; 0: one period for flows (delay >= 3),
  /// none for maps.
  std::size_t settle = 0;
  /// Continuous-time alignment of neighbours, as in the divergence estimator (delay >= 3).
  bool align = true;
  /// Fiducial chains started at staggered points of the first orbit; their stretching is
  /// pooled (1 = Wolf's single trajectory).
  std::size_t chains = 8;
  void validate(std::size_t n_samples) const;
};

struct WolfResult {
  double lambda_per_s = 0.0;
  /// Standard error from batch means: the exponents of 10 contiguous stretches of the record
  /// (all chains pooled), weighted by their measured time.
  double uncertainty_per_s = 0.0;
  std::vector<double> running_time_s;  ///< first chain: end time of each measured interval
  std::vector<double> running_per_s;   ///< first chain's running estimate (its convergence)
  std::size_t replacements = 0;
  std::size_t intervals = 0;  ///< measured intervals of the first chain
  double measured_s = 0.0;    ///< time over which stretching was measured, all chains
};

WolfResult wolf_exponent(std::span<const double> x, double rate_Hz, const WolfOptions& options);

}  // namespace pneumachaos
