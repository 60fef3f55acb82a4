#include "kd_tree.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

namespace pneumachaos::detail {

KdTree::KdTree(std::vector<double> coords, std::size_t dim, std::size_t leaf_size)
    : dim_(dim), leaf_(std::max<std::size_t>(1, leaf_size)), points_(std::move(coords)) {
  const std::size_t n = dim_ == 0 ? 0 : points_.size() / dim_;
  id_.resize(n);
  std::iota(id_.begin(), id_.end(), std::size_t{0});
  if (n == 0) return;
  lo_.resize(dim_);
  hi_.resize(dim_);
  nodes_.reserve(2 * (n / leaf_ + 1));
  build(0, n);
}

void KdTree::swap_rows(std::size_t a, std::size_t b) {
  std::swap_ranges(points_.begin() + static_cast<std::ptrdiff_t>(a * dim_),
                   points_.begin() + static_cast<std::ptrdiff_t>(a * dim_ + dim_),
                   points_.begin() + static_cast<std::ptrdiff_t>(b * dim_));
  std::swap(id_[a], id_[b]);
}

// Rows [first, last) reordered so that those with coordinate `cut` below `value` come first;
// returns the first row at or above it, and the two sides' extents along the cut. One pass,
// each row moved at most once.
std::size_t KdTree::partition(std::size_t first, std::size_t last, std::size_t cut, double value,
                              double& left_high, double& right_low) {
  const auto at = [&](std::size_t row) { return points_[row * dim_ + cut]; };
  std::size_t i = first, j = last;
  while (true) {
    for (; i < j && at(i) < value; ++i) left_high = std::max(left_high, at(i));
    for (; i < j && at(j - 1) >= value; --j) right_low = std::min(right_low, at(j - 1));
    if (i >= j) return i;
    swap_rows(i, j - 1);
  }
}

std::uint32_t KdTree::build(std::size_t first, std::size_t last) {
  const auto n = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(Node{first, last});
  if (last - first <= leaf_) return n;
  // Cut the coordinate of widest spread; the cell's box in one pass over its rows.
  std::fill(lo_.begin(), lo_.end(), std::numeric_limits<double>::infinity());
  std::fill(hi_.begin(), hi_.end(), -std::numeric_limits<double>::infinity());
  for (const double* p = points_.data() + first * dim_; p != points_.data() + last * dim_;
       p += dim_) {
    for (std::size_t d = 0; d < dim_; ++d) {
      lo_[d] = std::min(lo_[d], p[d]);
      hi_[d] = std::max(hi_[d], p[d]);
    }
  }
  std::size_t cut = 0;
  for (std::size_t d = 1; d < dim_; ++d) {
    if (hi_[d] - lo_[d] > hi_[cut] - lo_[cut]) cut = d;
  }
  const double widest = hi_[cut] - lo_[cut], cut_lo = lo_[cut];
  if (!(widest > 0.0)) return n;  // identical points: nothing to split
  // The middle of the spread, as nanoflann's middle split: one partition pass per level
  // instead of a median search. Neither side is empty while lo < split <= hi (rounding can
  // put the middle of two adjacent doubles on lo itself).
  double split = cut_lo + 0.5 * widest;
  if (!(split > cut_lo)) split = cut_lo + widest;
  double left_high = cut_lo, right_low = hi_[cut];
  const std::size_t mid = partition(first, last, cut, split, left_high, right_low);
  nodes_[n].left_high = left_high;
  nodes_[n].right_low = right_low;
  const std::uint32_t left = build(first, mid);
  const std::uint32_t right = build(mid, last);
  nodes_[n].left = left;
  nodes_[n].right = right;
  nodes_[n].cut = cut;
  nodes_[n].split = split;
  return n;
}

}  // namespace pneumachaos::detail
