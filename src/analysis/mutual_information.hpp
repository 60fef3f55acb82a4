#pragma once
// The average mutual information of a series with itself at any lag, from integer counts of
// equiprobable bins. Internal to the analysis module (embedding_parameters.cpp uses it).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pneumachaos::detail {

class LaggedMutualInformation {
 public:
  /// `bins` per axis, at least 1; x at least 2 samples. Values within `resolution` of the
  /// first value of their bin share it (0: only exact ties do).
  LaggedMutualInformation(std::span<const double> x, std::size_t bins, double resolution = 0.0);

  /// I(lag) [nats] of the pairs (x_i, x_{i+lag}), i < N - lag; lag < N.
  [[nodiscard]] double at(std::size_t lag);

 private:
  void count_pairs(std::size_t lag);
  [[nodiscard]] double joint_sum();
  [[nodiscard]] double marginal_sum(std::size_t skip_first, std::size_t skip_last);
  [[nodiscard]] double c_log_c(std::uint32_t c) const { return table_[c]; }

  std::size_t bins_;
  std::vector<std::uint32_t> bin_;     ///< bin of every sample
  std::vector<std::uint32_t> total_;   ///< samples per bin over the whole record
  std::vector<double> table_;          ///< c ln c for c = 0 .. the largest bin's count
  std::vector<std::uint32_t> joint_;   ///< kCopies interleaved pair histograms (scratch)
  std::vector<std::uint32_t> margin_;  ///< one marginal's counts (scratch)
};

/// How many of `bins` equiprobable bins merging values within `resolution` leaves unused
/// beyond those exact ties leave unused (0 for resolution 0).
std::size_t bins_merged_by(std::span<const double> x, std::size_t bins, double resolution);

}  // namespace pneumachaos::detail
