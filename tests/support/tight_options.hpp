#pragma once
// Simulation options for tests that compare with closed forms: tolerances far below the
// documented defaults, so the integration error is negligible against the checked bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

inline RunParams tight(double duration) {
  RunParams o;
  o.duration_s = duration;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-12;
  return o;
}

/// Largest difference of the velocity channels of two runs sampled alike (a run against its
/// tight-tolerance reference).
inline double largest_velocity_difference(const SimulationResult& a, const SimulationResult& b) {
  const auto& va = a.series.channel("v").values;
  const auto& vb = b.series.channel("v").values;
  EXPECT_EQ(va.size(), vb.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(va.size(), vb.size()); ++i)
    worst = std::max(worst, std::abs(va[i] - vb[i]));
  return worst;
}

}  // namespace pneumachaos
