#pragma once
// Where on the attractor nearby trajectories separate: the finite-time stretching rate of
// nearest-neighbour pairs, sorted by the value of the series where each pair starts. A
// chaotic flow stretches in one part of its state space and folds (turns back, bringing
// distant parts together) in another; this is the measurement behind a statement such as
// "the trajectory is folded between 180 and 140 and stretched between 140 and 0"
// (docs/notes/analysis.md, "Local stretching").

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

struct StretchingOptions {
  std::size_t dimension = 3;  ///< embedding dimension
  std::size_t delay = 1;      ///< embedding delay [samples]
  std::size_t theiler = 1;    ///< temporal neighbours closer than this are skipped
  std::size_t horizon = 10;   ///< steps over which each pair's separation is followed
  std::size_t stride = 1;     ///< every stride-th vector is a reference
  /// Throws Error naming the field that is out of range.
  void validate() const;
};

struct BandStretching {
  double low = 0.0, high = 0.0;  ///< the band of series values [low, high)
  double rate_per_s = 0.0;       ///< mean ln(d(horizon) / d(0)) / (horizon / rate)
  double standard_error_per_s = 0.0;
  std::size_t pairs = 0;         ///< references whose value falls in the band
};

/// One entry per band [edges[k], edges[k+1]); edges must increase. Throws Error when the
/// series is too short for one reference followed over the horizon.
std::vector<BandStretching> band_stretching(std::span<const double> x, double rate_Hz,
                                            const std::vector<double>& edges,
                                            const StretchingOptions& options);

}  // namespace pneumachaos
