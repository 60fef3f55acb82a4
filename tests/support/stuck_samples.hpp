#pragma once
// The samples a run spends held by stiction away from the start stop (stuck now and at the
// previous sample, x > 0): on each the velocity must be exactly zero and the position frozen,
// whatever other states keep evolving. Shared by the tests of every model with true stiction.
#include <gtest/gtest.h>

#include <cstddef>

#include "pneumachaos/core/time_series.hpp"

namespace pneumachaos {

/// Checks v == 0 and x frozen on every held sample, calls visit(i) on it, returns the count.
template <typename Visit>
std::size_t for_each_stuck_sample(const TimeSeries& series, Visit&& visit) {
  const auto& x = series.channel("x").values;
  const auto& v = series.channel("v").values;
  const auto& stuck = series.channel("stuck").values;
  std::size_t held = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (stuck[i] == 1.0 && stuck[i - 1] == 1.0 && x[i] > 0.0) {
      ++held;
      EXPECT_EQ(v[i], 0.0) << "sample " << i;
      EXPECT_EQ(x[i], x[i - 1]) << "sample " << i;
      visit(i);
    }
  }
  return held;
}

}  // namespace pneumachaos
