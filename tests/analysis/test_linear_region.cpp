// The linear region of a divergence curve is read on its rise, not on its saturated top
// (src/analysis/linear_region.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/linear_region.hpp"

namespace pneumachaos {
namespace {

// S(k) rises 0.5 per step to 10 at k = 20, then wobbles on its top between 9.1 and 10 in
// straight 30-step rises and falls of 0.03 per step (the mean distance of a noisy cycle
// modulated at its period). Each rise of the wobble is a longer straight stretch than the
// curve's own rise, but it starts past 90 % of the rise (9 at k = 18): the region is the rise.
TEST(LinearRegion, TheSaturatedTopsWobbleIsNoDivergence) {
  std::vector<double> y;
  for (int k = 0; k <= 20; ++k) y.push_back(0.5 * k);
  for (int cycle = 0; cycle < 4; ++cycle) {
    for (int k = 1; k <= 30; ++k) y.push_back(10.0 - 0.03 * k);
    for (int k = 1; k <= 30; ++k) y.push_back(9.1 + 0.03 * k);
  }
  const LinearRegion region = find_linear_region(y, 5, 0.2);
  ASSERT_TRUE(region.found);
  EXPECT_EQ(region.first, 0u);
  EXPECT_EQ(region.last, 20u);
  EXPECT_NEAR(region.slope, 0.5, 1e-12);
  EXPECT_GT(agreeing_runs(y, 5, 0.2).size(), 1u);  // the wobble's runs, for the uncertainty
  // The same wobble alone, from its bottom, is a rise of its own: its first stretch is found.
  const std::vector<double> wobble(y.begin() + 50, y.end());
  const LinearRegion alone = find_linear_region(wobble, 5, 0.2);
  ASSERT_TRUE(alone.found);
  EXPECT_EQ(alone.first, 0u);
  EXPECT_NEAR(alone.slope, 0.03, 1e-12);
}

// The rule reads the rise's share, not its size: a curve that never saturates keeps the whole
// straight stretch, however late it starts.
TEST(LinearRegion, AStraightCurveIsOneRegion) {
  std::vector<double> y;
  for (int k = 0; k <= 100; ++k) y.push_back(k < 40 ? 0.0 : 0.1 * (k - 40));
  const LinearRegion region = find_linear_region(y, 5, 0.2);
  ASSERT_TRUE(region.found);
  EXPECT_EQ(region.first, 40u);
  EXPECT_EQ(region.last, 100u);
}

}  // namespace
}  // namespace pneumachaos
