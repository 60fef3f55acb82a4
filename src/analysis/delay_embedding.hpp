#pragma once
// Delay vectors y_i = (x_i, x_{i+tau}, ..., x_{i+(m-1)tau}) of a scalar series (Takens), and
// nearest-neighbour queries on them through a k-d tree (src/analysis/kd_tree.hpp), so that the cost grows
// about as N log N rather than N^2.

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace pneumachaos {

class DelayEmbedding {
 public:
  /// Throws Error if dimension or delay is 0 or the series is too short for one vector.
  DelayEmbedding(std::span<const double> x, std::size_t dimension, std::size_t delay);

  [[nodiscard]] std::size_t size() const { return count_; }  ///< number of delay vectors
  [[nodiscard]] std::size_t dimension() const { return m_; }
  [[nodiscard]] std::size_t delay() const { return tau_; }
  [[nodiscard]] double coordinate(std::size_t i, std::size_t d) const { return x_[i + d * tau_]; }
  [[nodiscard]] double distance2(std::size_t i, std::size_t j) const;
  [[nodiscard]] std::span<const double> series() const { return x_; }

 private:
  std::span<const double> x_;
  std::size_t m_, tau_, count_;
};

struct Neighbour {
  std::size_t index = 0;
  double distance2 = 0.0;  ///< squared Euclidean distance
};

/// Distances at or below this count as exact repeats: 1e-9 of the series' standard deviation,
/// far below any measurement resolution but above the rounding of computed samples (a sine
/// sampled at a whole number of points per period repeats to within 1e-16).
double repeat_resolution(std::span<const double> x);

/// Fewest samples the largest exponent is estimated from (divergence curve and Wolf alike);
/// their options' validate() refuses shorter records.
inline constexpr std::size_t kMinExponentSamples = 100;

/// k-d tree over the first `points` delay vectors of an embedding (all by default).
class NeighbourIndex {
 public:
  /// Neighbours closer than `resolution` are treated as exact repeats and skipped.
  explicit NeighbourIndex(const DelayEmbedding& embedding, std::size_t points = 0,
                          double resolution = 0.0);
  ~NeighbourIndex();
  NeighbourIndex(const NeighbourIndex&) = delete;
  NeighbourIndex& operator=(const NeighbourIndex&) = delete;

  /// Nearest vector to vector i with |i - j| > theiler and distance > resolution (exact
  /// repeats, as in quantised records, carry no direction). index == size() when none exists.
  [[nodiscard]] Neighbour nearest(std::size_t i, std::size_t theiler) const;
  /// nearest(i, theiler) of every i in `queries`, in that order. The searches run in the
  /// order of the tree's points, so that successive ones walk the same cells while they are
  /// in cache; the answers are the same as one nearest() call each.
  [[nodiscard]] std::vector<Neighbour> nearest_each(std::span<const std::size_t> queries,
                                                    std::size_t theiler) const;
  /// k_nearest(i, k, theiler) of every i in `queries`, in that order, searched as nearest_each.
  [[nodiscard]] std::vector<std::vector<Neighbour>> k_nearest_each(
      std::span<const std::size_t> queries, std::size_t k, std::size_t theiler) const;
  /// Up to k nearest under the same rules, nearest first.
  [[nodiscard]] std::vector<Neighbour> k_nearest(std::size_t i, std::size_t k,
                                                 std::size_t theiler) const;
  /// The entries of k_nearest(i, k, theiler) closer than r (squared distance below r^2),
  /// nearest first: a search that prunes from the start what an open one prunes late.
  [[nodiscard]] std::vector<Neighbour> k_nearest_within(std::size_t i, std::size_t k,
                                                        std::size_t theiler, double r) const;
  /// All vectors within distance r of vector i under the same rules.
  [[nodiscard]] std::vector<Neighbour> within(std::size_t i, double r, std::size_t theiler) const;
  [[nodiscard]] std::size_t size() const;

 private:
  /// Positions in `queries` in the order their vectors are stored in the tree.
  [[nodiscard]] std::vector<std::size_t> search_order(std::span<const std::size_t> queries) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pneumachaos
