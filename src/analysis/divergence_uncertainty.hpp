#pragma once
// The divergence exponent measured separately on contiguous segments of the record
// (docs/notes/analysis.md "Divergence exponent's uncertainty"); internal to the analysis module.

#include <cstddef>
#include <vector>

namespace pneumachaos::detail {

/// The standard normal's 97.5 % quantile: +-kNormal95 standard errors is a two-sided 95 %
/// interval (the segments' standard error and the widened uncertainty are scaled to it).
inline constexpr double kNormal95 = 1.96;

struct SegmentSlopes {
  std::vector<double> slopes;  ///< per step, in record order
  std::size_t without_region = 0;
  /// Standard error of the segments' mean slope, scaled by t(0.975, n-1) / 1.96 so that
  /// +-1.96 of it is a 95 % interval although n is small (per step).
  double standard_error = 0.0;
};

/// Per-block sums of ln d(k) and their counts (blocks in record order) are merged into
/// `segments` contiguous segments (2 <= segments <= blocks); each segment's own curve gets its
/// own linear region (find_linear_region with `spacing`, `tolerance`) and its own slope; a
/// segment without one is fitted over the whole record's region [record_first, record_last].
SegmentSlopes segment_slopes(const std::vector<std::vector<double>>& sum,
                             const std::vector<std::vector<double>>& count, std::size_t segments,
                             std::size_t spacing, double tolerance, std::size_t record_first,
                             std::size_t record_last);

}  // namespace pneumachaos::detail
