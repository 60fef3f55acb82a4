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
  nodes_.reserve(2 * (n / leaf_ + 1));
  std::vector<double> root(2 * dim_);
  const Box box{root.data(), root.data() + dim_};
  bound(0, n, box);
  build(0, n, box, 0);
}

std::vector<std::size_t> KdTree::storage_rank() const {
  std::vector<std::size_t> rank(id_.size());
  for (std::size_t row = 0; row < id_.size(); ++row) rank[id_[row]] = row;
  return rank;
}

// The box of rows [first, last) in one pass.
void KdTree::bound(std::size_t first, std::size_t last, Box box) const {
  std::fill(box.lo, box.lo + dim_, std::numeric_limits<double>::infinity());
  std::fill(box.hi, box.hi + dim_, -std::numeric_limits<double>::infinity());
  for (const double* p = points_.data() + first * dim_; p != points_.data() + last * dim_;
       p += dim_) {
    for (std::size_t d = 0; d < dim_; ++d) {
      box.lo[d] = std::min(box.lo[d], p[d]);
      box.hi[d] = std::max(box.hi[d], p[d]);
    }
  }
}

// Rows [first, last) reordered so that those with coordinate `cut` below `value` come first;
// returns the first row at or above it. Each row is classified once (and moved at most once),
// and its coordinates go into its side's box as it is: the children's boxes come with the
// partition instead of a second pass over their rows at the next level. As in the search, the
// usual dimensions get the loop with the dimension fixed at compile time.
std::size_t KdTree::partition(std::size_t first, std::size_t last, std::size_t cut, double value,
                              Box left, Box right) {
  switch (dim_) {
    case 1: return partition_in<1>(first, last, cut, value, left, right);
    case 2: return partition_in<2>(first, last, cut, value, left, right);
    case 3: return partition_in<3>(first, last, cut, value, left, right);
    case 4: return partition_in<4>(first, last, cut, value, left, right);
    case 5: return partition_in<5>(first, last, cut, value, left, right);
    case 6: return partition_in<6>(first, last, cut, value, left, right);
    case 7: return partition_in<7>(first, last, cut, value, left, right);
    case 8: return partition_in<8>(first, last, cut, value, left, right);
    default: return partition_in<0>(first, last, cut, value, left, right);
  }
}

template <std::size_t Dim>
std::size_t KdTree::partition_in(std::size_t first, std::size_t last, std::size_t cut,
                                 double value, Box left, Box right) {
  const std::size_t dim = Dim > 0 ? Dim : dim_;
  for (const Box& b : {left, right}) {
    std::fill(b.lo, b.lo + dim, std::numeric_limits<double>::infinity());
    std::fill(b.hi, b.hi + dim, -std::numeric_limits<double>::infinity());
  }
  double* const points = points_.data();
  const auto add = [&](std::size_t row, Box b) {
    const double* p = points + row * dim;
    for (std::size_t d = 0; d < dim; ++d) {
      b.lo[d] = std::min(b.lo[d], p[d]);
      b.hi[d] = std::max(b.hi[d], p[d]);
    }
  };
  const auto at = [&](std::size_t row) { return points[row * dim + cut]; };
  std::size_t i = first, j = last;
  while (true) {
    for (; i < j && at(i) < value; ++i) add(i, left);
    for (; i < j && at(j - 1) >= value; --j) add(j - 1, right);
    if (i >= j) return i;
    std::swap_ranges(points + i * dim, points + i * dim + dim, points + (j - 1) * dim);
    std::swap(id_[i], id_[j - 1]);
  }
}

// `box`: the bounding box of rows [first, last); `depth` picks the scratch of the children's.
std::uint32_t KdTree::build(std::size_t first, std::size_t last, Box box, std::size_t depth) {
  const auto n = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(Node{first, last});
  if (last - first <= leaf_) return n;
  // Cut the coordinate of widest spread.
  std::size_t cut = 0;
  for (std::size_t d = 1; d < dim_; ++d) {
    if (box.hi[d] - box.lo[d] > box.hi[cut] - box.lo[cut]) cut = d;
  }
  const double widest = box.hi[cut] - box.lo[cut], cut_lo = box.lo[cut];
  if (!(widest > 0.0)) return n;  // identical points: nothing to split
  // The middle of the spread, as nanoflann's middle split: one partition pass per level
  // instead of a median search. Neither side is empty while lo < split <= hi (rounding can
  // put the middle of two adjacent doubles on lo itself).
  double split = cut_lo + 0.5 * widest;
  if (!(split > cut_lo)) split = cut_lo + widest;
  if (boxes_.size() <= depth) boxes_.emplace_back(4 * dim_);
  double* scratch = boxes_[depth].data();
  const Box left_box{scratch, scratch + dim_}, right_box{scratch + 2 * dim_, scratch + 3 * dim_};
  const std::size_t mid = partition(first, last, cut, split, left_box, right_box);
  // The children's extents along the cut (what the search prunes with).
  nodes_[n].left_high = left_box.hi[cut];
  nodes_[n].right_low = right_box.lo[cut];
  const std::uint32_t left = build(first, mid, left_box, depth + 1);
  const std::uint32_t right = build(mid, last, right_box, depth + 1);
  nodes_[n].left = left;
  nodes_[n].right = right;
  nodes_[n].cut = cut;
  nodes_[n].split = split;
  return n;
}

}  // namespace pneumachaos::detail
