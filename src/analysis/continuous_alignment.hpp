#pragma once
// Delay vectors between samples, for oversampled flows: cubic interpolation of the series and
// the time offset that brings a neighbouring trajectory closest to a reference point. The
// nearest SAMPLE on a neighbouring orbit is off by up to half a sample spacing along the
// flow; that offset never grows and biases divergence-based exponents low.

#include <cstddef>
#include <span>
#include <vector>

#include "analysis/delay_embedding.hpp"

namespace pneumachaos {

/// Cubic interpolation of x at fractional index t; within one sample of either end the
/// cubic through the four end samples is extended (no read outside the record).
double interpolate_series(std::span<const double> x, double t);

/// Coordinate d of the delay vector at fractional index t.
inline double interpolated_coordinate(const DelayEmbedding& e, double t, std::size_t d) {
  return interpolate_series(e.series(), t + static_cast<double>(d * e.delay()));
}

/// Offset s in [-1, 1] samples minimising |y_i - y_{j+s}|: two Newton steps along the
/// trajectory's tangent. Needs 1 <= j - 1 and j + 2 + (m-1) delay < size.
double closest_offset(const DelayEmbedding& e, std::size_t i, std::size_t j);

/// |y_i - y_{j+s}|^2 with the neighbour at fractional time j + s.
double distance2_to(const DelayEmbedding& e, std::size_t i, double j_plus_s);

/// x[j + s + k] for k = 0..count-1 (s in [-1, 1]), by cubic interpolation with the weights of
/// the fixed fractional offset computed once; returns a view of `buffer`.
std::span<const double> shifted_series(std::span<const double> x, std::size_t j, double s,
                                       std::size_t count, std::vector<double>& buffer);

/// Smallest delay of an oversampled flow, whose values between samples are meaningful; maps and
/// barely sampled records have none (docs/notes/analysis.md "Continuous-time alignment":
/// "delay >= 3").
inline constexpr std::size_t kMinFlowDelay = 3;

/// Whether a record with this delay is treated as an oversampled flow (alignment applies).
inline bool is_oversampled_flow(std::size_t delay) { return delay >= kMinFlowDelay; }

}  // namespace pneumachaos
