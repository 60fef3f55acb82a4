#pragma once
// The spread of a curve's local slopes (rising_slopes in linear_region.hpp), kept apart so that
// the divergence result can carry it without the line-fitting declarations.

namespace pneumachaos {

struct SlopeSpread {
  bool found = false;
  double median = 0.0, low = 0.0, high = 0.0;  ///< median, 10 % and 90 % quantiles (per step)
};

}  // namespace pneumachaos
