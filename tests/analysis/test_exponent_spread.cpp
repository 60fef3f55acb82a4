// The divergence exponent's uncertainty covers the choices behind its value: the window (its
// halves and the other stretches the window rule accepts) and the embedding dimension
// (src/analysis/exponent_spread.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/exponent_spread.hpp"
#include "analysis/linear_region.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "support/reference_series.hpp"

namespace pneumachaos {
namespace {

// S(k) = k^2 on the window 0..10: the least-squares slope is 10 over the whole window, 5 over
// 0..5 and 15 over 5..10 (the slope of k^2 over a symmetric set of k is twice their mean), so
// the window's spread is 5 per step.
TEST(ExponentSpread, TheWindowsHalvesOfABendingCurve) {
  DivergenceResult d;
  for (int k = 0; k <= 10; ++k) d.curve.push_back(k * k);
  d.fit_first = 0;
  d.fit_last = 10;
  d.slope_spacing = 5;  // two segments: no stretch of three for the window rule to pass over
  d.found_linear_region = true;
  const double rate_Hz = 100.0;
  d.lambda_per_s = 10.0 * rate_Hz;
  d.uncertainty_per_s = 3.0;
  const std::vector<double> unused;
  const ExponentSpread s = exponent_spread(unused, rate_Hz, {}, d, false);
  EXPECT_NEAR(s.window_per_s, 5.0 * rate_Hz, 1e-9);
  EXPECT_TRUE(s.dimensions.empty());
  EXPECT_NEAR(widened_uncertainty(d, s), std::hypot(3.0, 500.0 / 1.96), 1e-9);
  // A straight line has none.
  for (int k = 0; k <= 10; ++k) d.curve[k] = 2.0 * k;
  d.lambda_per_s = 2.0 * rate_Hz;
  EXPECT_NEAR(exponent_spread(unused, rate_Hz, {}, d, false).window_per_s, 0.0, 1e-9);
}

// S(k) rises 1 per step up to k = 30, then 0.25 per step up to k = 50: with segments of 5 steps
// the window rule accepts both stretches and takes the longer one; the other's value lies
// inside the widened 95 % interval. A straight line leaves no other stretch.
TEST(ExponentSpread, TheOtherStretchesTheWindowRuleAccepts) {
  DivergenceResult d;
  for (int k = 0; k <= 50; ++k) d.curve.push_back(k <= 30 ? k : 30.0 + 0.25 * (k - 30));
  d.slope_spacing = 5;
  const double rate_Hz = 100.0;
  const LinearRegion region = find_linear_region(d.curve, d.slope_spacing, 0.2);
  ASSERT_TRUE(region.found);
  EXPECT_EQ(region.first, 0u);
  EXPECT_EQ(region.last, 30u);
  EXPECT_EQ(agreeing_runs(d.curve, d.slope_spacing, 0.2).size(), 2u);
  d.fit_first = region.first;
  d.fit_last = region.last;
  d.found_linear_region = true;
  d.lambda_per_s = region.slope * rate_Hz;
  const std::vector<double> unused;
  DivergenceOptions o;
  o.slope_tolerance = 0.2;
  const ExponentSpread s = exponent_spread(unused, rate_Hz, o, d, false);
  ASSERT_EQ(s.other_windows_per_s.size(), 1u);
  EXPECT_NEAR(s.other_windows_per_s[0], 25.0, 1e-9);
  EXPECT_NEAR(s.window_choice_per_s, 75.0, 1e-9);
  EXPECT_GE(1.96 * widened_uncertainty(d, s), 75.0 - 1e-9);
  for (int k = 0; k <= 50; ++k) d.curve[k] = 2.0 * k;
  d.fit_last = 50;
  d.lambda_per_s = 2.0 * rate_Hz;
  const ExponentSpread line = exponent_spread(unused, rate_Hz, o, d, false);
  EXPECT_TRUE(line.other_windows_per_s.empty());
  EXPECT_EQ(line.window_choice_per_s, 0.0);
}

// On Lorenz the values at m - 1 and m + 1 lie inside the widened 95 % interval, which is
// never narrower than the curve's own; the value and the verdict do not move.
TEST(ExponentSpread, NeighbouringEmbeddingsFallInsideTheInterval) {
  const std::vector<double> x = testing::lorenz_x(10000);
  AnalysisOptions with;
  with.wolf = false;
  with.embedding_spread = true;
  AnalysisOptions without = with;
  without.embedding_spread = false;
  const AnalysisResult a = analyze_series(x, 100.0, with);
  const AnalysisResult b = analyze_series(x, 100.0, without);
  ASSERT_TRUE(a.divergence.found_linear_region);
  ASSERT_FALSE(a.exponent_spread.dimensions.empty());
  EXPECT_TRUE(b.exponent_spread.dimensions.empty());
  EXPECT_EQ(a.divergence.lambda_per_s, b.divergence.lambda_per_s);
  EXPECT_EQ(a.verdict.regime, b.verdict.regime);
  EXPECT_GE(a.divergence.uncertainty_per_s, b.divergence.uncertainty_per_s);
  for (const double other : a.exponent_spread.lambda_per_s) {
    EXPECT_LE(std::abs(other - a.divergence.lambda_per_s), 1.96 * a.divergence.uncertainty_per_s);
  }
}

}  // namespace
}  // namespace pneumachaos
