#pragma once
// An exact k-d tree whose points are stored in tree order: each node's points are one
// contiguous block of rows, so building and searching read memory in sequence rather than
// gathering each coordinate through a permutation (nanoflann's layout), a gather that costs
// half of a whole analysis (docs/notes/performance.md). Internal to the analysis module;
// results are reported through nanoflann's result-set protocol (addPoint, worstDist), and the
// search prunes with the incremental distance to the cell (Arya & Mount), as nanoflann does.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pneumachaos::detail {

/// Points per leaf: leaves of 8 or 32 are slower (docs/notes/performance.md "Our own k-d tree").
inline constexpr std::size_t kDefaultLeafSize = 16;

class KdTree {
 public:
  /// `coords`: point k at coords[k * dim .. k * dim + dim); the tree reports k.
  KdTree(std::vector<double> coords, std::size_t dim, std::size_t leaf_size = kDefaultLeafSize);

  /// rank[k]: the place of point k in the tree's storage order (leaf by leaf).
  [[nodiscard]] std::vector<std::size_t> storage_rank() const;

  /// Offers every point that may be closer than result.worstDist() to result.addPoint(d2, k).
  template <class Result>
  void search(const double* query, Result& result) const {
    if (nodes_.empty()) return;
    // The usual embedding dimensions get a search with the dimension fixed at compile time:
    // the distance loops unroll (the same sums in the same order, so the same values).
    switch (dim_) {
      case 1: return search_in<1>(query, result);
      case 2: return search_in<2>(query, result);
      case 3: return search_in<3>(query, result);
      case 4: return search_in<4>(query, result);
      case 5: return search_in<5>(query, result);
      case 6: return search_in<6>(query, result);
      case 7: return search_in<7>(query, result);
      case 8: return search_in<8>(query, result);
      default: return search_in<0>(query, result);
    }
  }

 private:
  struct Node {
    std::size_t first = 0, last = 0;  ///< rows [first, last) below this node
    std::uint32_t left = 0, right = 0;  ///< children; both 0 for a leaf
    std::size_t cut = 0;               ///< coordinate split on
    double split = 0.0;  ///< left rows have coordinate < split, right rows >= split
    double left_high = 0.0, right_low = 0.0;  ///< the children's extents along the cut
  };

  /// A cell's bounding box: lo[d], hi[d] of its rows.
  struct Box {
    double* lo;
    double* hi;
  };

  std::uint32_t build(std::size_t first, std::size_t last, Box box, std::size_t depth);
  void bound(std::size_t first, std::size_t last, Box box) const;
  std::size_t partition(std::size_t first, std::size_t last, std::size_t cut, double value,
                        Box left, Box right);
  template <std::size_t Dim>
  std::size_t partition_in(std::size_t first, std::size_t last, std::size_t cut, double value,
                           Box left, Box right);

  // Dim > 0: the dimension as a constant; 0: dim_ at run time.
  template <std::size_t Dim, class Result>
  void search_in(const double* query, Result& result) const {
    // Per-query scratch on the stack: a heap allocation per query cost as much as a search.
    constexpr std::size_t kStack = 16;
    double stack[kStack] = {};
    std::vector<double> heap(dim_ > kStack ? dim_ : 0, 0.0);
    visit<Dim>(0, query, result, dim_ > kStack ? heap.data() : stack, 0.0);
  }

  template <std::size_t Dim, class Result>
  void visit(std::uint32_t n, const double* q, Result& result, double* offset,
             double bound) const {
    const Node& node = nodes_[n];
    if (node.left == 0) {
      const std::size_t dim = Dim > 0 ? Dim : dim_;
      for (std::size_t row = node.first; row < node.last; ++row) {
        const double* p = &points_[row * dim];
        const double worst = result.worstDist();
        double d2 = 0.0;
        for (std::size_t d = 0; d < dim; ++d) d2 += (q[d] - p[d]) * (q[d] - p[d]);
        if (d2 < worst) result.addPoint(d2, id_[row]);
      }
      return;
    }
    const bool left_first = q[node.cut] < node.split;
    visit<Dim>(left_first ? node.left : node.right, q, result, offset, bound);
    // The far child's points lie at least |diff| away along the cut (its extent, as
    // nanoflann): replace this coordinate's share of the lower bound on their distance.
    const double diff =
        left_first ? node.right_low - q[node.cut] : q[node.cut] - node.left_high;
    const double saved = offset[node.cut];
    const double far_bound = bound - saved * saved + diff * diff;
    if (far_bound < result.worstDist()) {
      offset[node.cut] = diff;
      visit<Dim>(left_first ? node.right : node.left, q, result, offset, far_bound);
      offset[node.cut] = saved;
    }
  }

  std::size_t dim_, leaf_;
  std::vector<double> points_;   ///< rows in tree order
  std::vector<std::size_t> id_;  ///< row -> point k
  std::vector<Node> nodes_;      ///< nodes_[0] is the root
  /// Scratch of the build: per depth, the two children's boxes (4 * dim_; inner buffers do
  /// not move when the outer vector grows, so a parent's pointers stay valid).
  std::vector<std::vector<double>> boxes_;
};

}  // namespace pneumachaos::detail
