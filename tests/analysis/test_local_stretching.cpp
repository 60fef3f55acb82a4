// Local stretching rates against an analytic answer: for the logistic map x -> 4x(1-x) a pair
// of nearby points at x separates in one step by |f'(x)| = |4 - 8x|, so the band mean of the
// one-step rate is the mean of ln|4 - 8x| over the band under the map's invariant density
// 1 / (pi sqrt(x(1-x))) (Ott, "Chaos in Dynamical Systems", 2nd ed., sect. 2.3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pneumachaos/analysis/local_stretching.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

std::vector<double> logistic(std::size_t n) {
  std::vector<double> x(n);
  x[0] = 0.3141592;
  for (std::size_t k = 1; k < n; ++k) x[k] = 4.0 * x[k - 1] * (1.0 - x[k - 1]);
  return x;
}

// Band mean of ln|4 - 8x| under the invariant density, by the substitution x = sin^2(theta),
// under which the density is uniform in theta (midpoint rule, 2e5 nodes).
double expected_rate(double lo, double hi) {
  const double a = std::asin(std::sqrt(lo)), b = std::asin(std::sqrt(hi));
  const int n = 200000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double s = std::sin(a + (b - a) * (k + 0.5) / n);
    sum += std::log(std::abs(4.0 - 8.0 * s * s));
  }
  return sum / n;
}

TEST(LocalStretching, LogisticMapBandsMatchTheDerivative) {
  const auto x = logistic(100000);
  StretchingOptions o;
  o.dimension = 1;
  o.horizon = 1;
  const std::vector<double> edges{0.0, 0.1, 0.45, 0.55, 0.9, 1.0};
  const auto bands = band_stretching(x, 1.0, edges, o);
  ASSERT_EQ(bands.size(), 5u);
  for (std::size_t k : {0u, 2u, 4u}) {
    const double want = expected_rate(edges[k], edges[k + 1]);
    EXPECT_NEAR(bands[k].rate_per_s, want, 0.01 + 4 * bands[k].standard_error_per_s)
        << "band " << edges[k] << "-" << edges[k + 1];
    EXPECT_GT(bands[k].pairs, 1000u);
  }
  // The edges stretch (ln 4 at x = 0 and 1), the middle folds.
  EXPECT_GT(bands[0].rate_per_s, 1.0);
  EXPECT_LT(bands[2].rate_per_s, -0.5);
}

TEST(LocalStretching, RejectsBadEdgesAndShortSeries) {
  const auto x = logistic(1000);
  EXPECT_THROW(band_stretching(x, 1.0, {0.5}, {}), Error);
  EXPECT_THROW(band_stretching(x, 1.0, {0.5, 0.2}, {}), Error);
  EXPECT_THROW(band_stretching(std::vector<double>(5, 0.1), 1.0, {0.0, 1.0}, {}), Error);
}

}  // namespace
}  // namespace pneumachaos
