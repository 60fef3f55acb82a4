// Interpolation between samples never reads outside the record, at its ends too, from either
// Lyapunov estimator (a read past the end is a heap-buffer overflow).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "analysis/continuous_alignment.hpp"

namespace pneumachaos {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A record of n samples of a parabola (which both cubic interpolants reproduce exactly), fenced by
// a NaN on either side: a read outside the record turns the result into NaN, even in a build
// without sanitizers.
struct FencedParabola {
  std::vector<double> storage;
  explicit FencedParabola(std::size_t n) : storage(n + 2, kNaN) {
    for (std::size_t i = 0; i < n; ++i) storage[i + 1] = value(static_cast<double>(i));
  }
  static double value(double t) { return -0.03 * t * t + 2.0 * t - 1.0; }
  [[nodiscard]] std::span<const double> record() const {
    return {storage.data() + 1, storage.size() - 2};
  }
};

// closest_offset's two Newton steps written with the interpolant at every point (its first
// step reads whole samples directly, a shortcut): the offsets must be the same bit for bit,
// near the record's ends too (where the stencils are clamped and the shortcut is not taken),
// and on a record that rests at exactly 0 (signs of zero).
double closest_offset_by_interpolation(const DelayEmbedding& e, std::size_t i, std::size_t j) {
  double s = 0.0;
  for (int iteration = 0; iteration < 2; ++iteration) {
    double num = 0.0, den = 0.0;
    const double t = static_cast<double>(j) + s;
    for (std::size_t d = 0; d < e.dimension(); ++d) {
      const double here = interpolated_coordinate(e, t, d);
      const double tangent =
          0.5 * (interpolated_coordinate(e, t + 1.0, d) - interpolated_coordinate(e, t - 1.0, d));
      num += (here - e.coordinate(i, d)) * tangent;
      den += tangent * tangent;
    }
    if (den <= 0.0) break;
    s = std::clamp(s - num / den, -1.0, 1.0);
  }
  return s;
}

TEST(ContinuousAlignment, ClosestOffsetSameAsByInterpolationEverywhere) {
  std::vector<double> x(600);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double t = 0.07 * static_cast<double>(k);
    // slips (a sine and its harmonic) between rests at exactly 0, -0 every third rest sample
    x[k] = (k / 40) % 2 == 0 ? std::sin(t) + 0.3 * std::sin(2.9 * t) : (k % 3 == 0 ? -0.0 : 0.0);
  }
  const DelayEmbedding e(x, 3, 7);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < e.size(); i += 5) {
    for (std::size_t j = 1; j + 2 * 7 + 2 < x.size(); j += 3) {
      const double s = closest_offset(e, i, j);
      EXPECT_EQ(s, closest_offset_by_interpolation(e, i, j)) << i << " " << j;
      if (s != 0.0) ++moved;
    }
  }
  EXPECT_GT(moved, 1000u);  // the offsets are not all 0: the comparison is not vacuous
}

TEST(ContinuousAlignment, InterpolationStaysInsideTheRecordAtBothEnds) {
  const FencedParabola c(40);
  const auto x = c.record();
  for (double t : {0.0, 0.25, 1.0, 1.5, 37.5, 38.0, 38.75, 39.0}) {
    EXPECT_NEAR(interpolate_series(x, t), FencedParabola::value(t), 1e-9) << "t = " << t;
  }
}

TEST(ContinuousAlignment, ShiftedSeriesReachingTheLastSampleStaysInside) {
  const FencedParabola c(40);
  const auto x = c.record();
  std::vector<double> buffer;
  // The neighbour at j = 30 shifted by a whole sample reads up to sample 39, the last one:
  // the four-point stencil must not reach sample 40.
  for (double s : {1.0, 0.5, -1.0}) {
    const std::size_t count = s > 0.0 ? 9 : 10;
    const auto shifted = shifted_series(x, 30, s, count, buffer);
    for (std::size_t k = 0; k < count; ++k) {
      EXPECT_NEAR(shifted[k], FencedParabola::value(30.0 + s + static_cast<double>(k)), 1e-9)
          << "s = " << s << ", k = " << k;
    }
  }
  EXPECT_NEAR(shifted_series(x, 1, -1.0, 5, buffer)[0], FencedParabola::value(0.0), 1e-9);
}

TEST(ContinuousAlignment, TooShortARecordIsAnError) {
  const FencedParabola c(3);
  std::vector<double> buffer;
  EXPECT_THROW(interpolate_series(c.record(), 1.0), std::exception);
  EXPECT_THROW(shifted_series(c.record(), 0, 0.0, 2, buffer), std::exception);
}

}  // namespace
}  // namespace pneumachaos
