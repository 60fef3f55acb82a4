#pragma once
// The white measurement noise of a record, estimated from the record alone
// (docs/notes/analysis.md "Noise floor"). Differencing a record k times leaves white noise of
// sd sigma with sd sigma * sqrt(C(2k, k)), while an oversampled smooth signal shrinks by about
// (omega h)^k: the estimates sigma_k = robust sd(diff^k x) / sqrt(C(2k, k)) fall with k while
// the signal dominates and level off at sigma once the noise does.

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

struct NoiseFloor {
  /// The noise's sd [record units] where it is resolved, else 0: a record whose smallest
  /// scales are still the signal's carries no noise the analysis could mistake for motion.
  double sd = 0.0;
  /// The smallest estimate over the orders: the white noise is at most this.
  double bound = 0.0;
  /// The two highest orders agree (within kResolvedRatio): white noise dominates there, and
  /// it is at most kMaxShareOfStd of the record's sd.
  bool resolved = false;
  /// The smallest scales are white, but the "noise" is most of the record: white noise
  /// itself, or a map's alternation at the Nyquist frequency, which differences cannot tell
  /// from noise. No noise is then separated from the motion (sd 0).
  bool dominates = false;
  /// sigma_k for k = 1 .. kOrders (robust: 1.4826 x the median absolute deviation).
  std::vector<double> by_order;

  static constexpr std::size_t kOrders = 5;
  /// White noise gives equal estimates up to the MAD's scatter (~3 % at 1,000 samples); a
  /// smooth signal sampled at 10 or more points per period falls by a factor 0.4 or more
  /// per order.
  static constexpr double kResolvedRatio = 0.85;
  /// Noise of a third of the record's sd leaves little motion above it to judge.
  static constexpr double kMaxShareOfStd = 1.0 / 3.0;
};

/// Estimates the record's white noise floor; x needs more than kOrders samples (else all 0).
NoiseFloor estimate_noise_floor(std::span<const double> x);

}  // namespace pneumachaos
