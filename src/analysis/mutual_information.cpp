#include "mutual_information.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pneumachaos::detail {
namespace {

// Pairs are counted into this many histograms in turn: a record at rest puts thousands of
// successive pairs into one cell, and a single histogram then waits for each increment to
// reach memory before the next (docs/notes/performance.md, "Mutual information").
constexpr std::size_t kCopies = 4;

// Equiprobable bin of every sample: its rank scaled to [0, bins). Values a bin cannot tell
// apart share one: exact ties (quantised data), and values within `resolution` of the one
// that opened the bin (the record's noise: equiprobable bins crowd where samples do, and on a
// noisy rest they would split the noise into bins that measure nothing of the motion).
std::vector<std::uint32_t> rank_bins(std::span<const double> x, std::size_t bins,
                                     double resolution) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<std::uint32_t> bin(x.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    bin[order[r]] = static_cast<std::uint32_t>(r * bins / order.size());
  }
  std::uint32_t current = bin[order[0]];
  double opened_at = x[order[0]];
  for (std::size_t r = 1; r < order.size(); ++r) {
    const double v = x[order[r]];
    if (v == x[order[r - 1]] || v - opened_at <= resolution) {
      bin[order[r]] = current;
    } else if (bin[order[r]] != current) {
      current = bin[order[r]];
      opened_at = v;
    }
  }
  return bin;
}

std::size_t bins_in_use(const std::vector<std::uint32_t>& bin) {
  std::vector<std::uint32_t> sorted = bin;
  std::sort(sorted.begin(), sorted.end());
  return static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

}  // namespace

std::size_t bins_merged_by(std::span<const double> x, std::size_t bins, double resolution) {
  if (resolution <= 0.0 || x.empty()) return 0;
  return bins_in_use(rank_bins(x, bins, 0.0)) - bins_in_use(rank_bins(x, bins, resolution));
}

// No count exceeds the largest bin's count over the whole record, so the table of c ln c up
// to it (about N / bins entries; more where ties fill one bin) serves every cell and marginal
// at every lag: one logarithm per entry instead of one per histogram cell per lag.
LaggedMutualInformation::LaggedMutualInformation(std::span<const double> x, std::size_t bins,
                                                 double resolution)
    : bins_(bins),
      bin_(rank_bins(x, bins, resolution)),
      total_(bins, 0),
      joint_(kCopies * bins * bins, 0),
      margin_(bins, 0) {
  for (const std::uint32_t b : bin_) ++total_[b];
  const std::uint32_t largest = *std::max_element(total_.begin(), total_.end());
  table_.resize(static_cast<std::size_t>(largest) + 1, 0.0);
  for (std::size_t c = 2; c < table_.size(); ++c) {
    table_[c] = static_cast<double>(c) * std::log(static_cast<double>(c));
  }
}

void LaggedMutualInformation::count_pairs(std::size_t lag) {
  const std::size_t n = bin_.size() - lag, cells = bins_ * bins_;
  const std::uint32_t* a = bin_.data();
  const std::uint32_t* b = bin_.data() + lag;
  std::uint32_t* joint = joint_.data();
  std::size_t i = 0;
  for (; i + kCopies <= n; i += kCopies) {
    for (std::size_t k = 0; k < kCopies; ++k) ++joint[k * cells + a[i + k] * bins_ + b[i + k]];
  }
  for (; i < n; ++i) ++joint[a[i] * bins_ + b[i]];
}

// Sum of c ln c over the pair histogram (the copies added), which is cleared for the next lag.
double LaggedMutualInformation::joint_sum() {
  const std::size_t cells = bins_ * bins_;
  double sum = 0.0;
  for (std::size_t cell = 0; cell < cells; ++cell) {
    std::uint32_t c = 0;
    for (std::size_t k = 0; k < kCopies; ++k) c += joint_[k * cells + cell];
    sum += c_log_c(c);
  }
  std::fill(joint_.begin(), joint_.end(), 0);
  return sum;
}

// Sum of c ln c over the histogram of the samples but the first skip_first and the last
// skip_last: the whole record's counts less those few.
double LaggedMutualInformation::marginal_sum(std::size_t skip_first, std::size_t skip_last) {
  std::copy(total_.begin(), total_.end(), margin_.begin());
  for (std::size_t i = 0; i < skip_first; ++i) --margin_[bin_[i]];
  for (std::size_t i = bin_.size() - skip_last; i < bin_.size(); ++i) --margin_[bin_[i]];
  double sum = 0.0;
  for (const std::uint32_t c : margin_) sum += c_log_c(c);
  return sum;
}

// With counts c over n pairs, I = sum p_ab ln(p_ab / (p_a p_b)) = ln n + (1/n) [sum c_ab ln c_ab
// - sum c_a ln c_a - sum c_b ln c_b] (the cells of each row add up to the row's marginal).
double LaggedMutualInformation::at(std::size_t lag) {
  const std::size_t n = bin_.size() - lag;
  count_pairs(lag);
  const double cells = joint_sum();
  const double first = marginal_sum(0, lag);   // x_i, i < n
  const double second = marginal_sum(lag, 0);  // x_{i+lag}
  const auto nd = static_cast<double>(n);
  return std::log(nd) + (cells - first - second) / nd;
}

}  // namespace pneumachaos::detail
