#include "analysis/delay_embedding.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "kd_tree.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

DelayEmbedding::DelayEmbedding(std::span<const double> x, std::size_t dimension, std::size_t delay)
    : x_(x), m_(dimension), tau_(delay), count_(0) {
  if (dimension == 0 || delay == 0) {
    throw Error("embedding", "dimension and delay must be at least 1");
  }
  const std::size_t span = (dimension - 1) * delay;
  if (x.size() <= span) {
    throw Error("embedding", fmt::format("{} samples cannot hold one vector of dimension {} "
                                         "and delay {}",
                                         x.size(), dimension, delay));
  }
  count_ = x.size() - span;
}

double DelayEmbedding::distance2(std::size_t i, std::size_t j) const {
  double d2 = 0.0;
  for (std::size_t d = 0; d < m_; ++d) {
    const double diff = coordinate(i, d) - coordinate(j, d);
    d2 += diff * diff;
  }
  return d2;
}

namespace {

// What the indices of one analysis need to know about its values: the shortest prefix of x
// that holds a repeated value (x.size() + 1 if none) and, when there are repeats, every
// value's rank among the distinct values (equal values, -0 and +0 included, share one). One
// analysis builds about ten indices on the same series, so this is worked out once, keyed by
// the series' address, length and a hash of its contents.
struct ValueOrder {
  const double* data = nullptr;
  std::size_t size = 0;
  std::uint64_t hash = 0;
  std::size_t repeat_length = 0;
  std::vector<std::uint32_t> rank;  ///< empty without repeats (nothing needs it then)
  std::size_t distinct = 0;
};

const ValueOrder& value_order(std::span<const double> x) {
  thread_local ValueOrder memo;
  // FNV-1a over the values' bit patterns (Fowler, Noll & Vo): its 64-bit offset basis and prime.
  constexpr std::uint64_t kFnvOffsetBasis = 1469598103934665603ULL;
  constexpr std::uint64_t kFnvPrime = 1099511628211ULL;
  std::uint64_t hash = kFnvOffsetBasis;
  for (double v : x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    hash = (hash ^ bits) * kFnvPrime;
  }
  if (memo.data == x.data() && memo.size == x.size() && memo.hash == hash) return memo;
  std::vector<std::pair<double, std::size_t>> v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) v[i] = {x[i], i};
  std::sort(v.begin(), v.end());
  std::size_t length = x.size() + 1;
  for (std::size_t i = 1; i < v.size(); ++i) {
    // Equal values sit together in ascending index order: the second one ends a prefix.
    if (v[i].first == v[i - 1].first && (i < 2 || v[i - 2].first != v[i].first)) {
      length = std::min(length, v[i].second + 1);
    }
  }
  memo = {x.data(), x.size(), hash, length, {}, 0};
  if (length <= x.size()) {
    memo.rank.resize(x.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0 && v[i].first != v[i - 1].first) ++memo.distinct;
      memo.rank[v[i].second] = static_cast<std::uint32_t>(memo.distinct);
    }
    ++memo.distinct;
  }
  return memo;
}

// Vectors 0 .. points-1 in lexicographic order of their coordinates, equal vectors by time,
// for a series with repeats. A stable counting sort by each coordinate's value rank, last
// coordinate first: the same order as comparing whole vectors (and then indices), in
// dimension x (N + distinct values) steps. A comparison sort costs 2.5 % of a sweep, whose
// records rest (docs/notes/performance.md, "Neighbour search").
std::vector<std::size_t> lexicographic_order(const DelayEmbedding& e, std::size_t points) {
  const ValueOrder& values = value_order(e.series());
  std::vector<std::size_t> order(points), next(points);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<std::size_t> start(values.distinct + 1);
  for (std::size_t d = e.dimension(); d-- > 0;) {
    const std::uint32_t* rank = values.rank.data() + d * e.delay();
    std::fill(start.begin(), start.end(), std::size_t{0});
    for (std::size_t i = 0; i < points; ++i) ++start[rank[i] + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (const std::size_t i : order) next[start[rank[i]]++] = i;
    order.swap(next);
  }
  return order;
}

// Distinct delay vectors and the times at which each occurs. Records that rest (a stuck
// piston's v = 0) or are quantised repeat one vector thousands of times; the tree holds each
// distinct vector once, so a query does not wade through its repeats.
struct Groups {
  std::vector<std::size_t> representative;  ///< tree point k -> first index of its vector
  std::vector<std::size_t> start;           ///< members of k: member[start[k] .. start[k+1])
  std::vector<std::size_t> member;          ///< ascending indices within each group

  Groups(const DelayEmbedding& e, std::size_t points) {
    if (points < value_order(e.series()).repeat_length) {
      // Equal vectors need equal first coordinates: with no repeated value among them, every
      // group is one vector, in time order. This skips the lexicographic sort of the vectors,
      // most of the cost of an index on a record without repeats; the neighbours are the same.
      // The tables are then the identity and are not stored (3 x 8 bytes a vector: 24 MB of
      // a 1e6-sample analysis' peak memory).
      identity = true;
      count = points;
      return;
    }
    const std::vector<std::size_t> order = lexicographic_order(e, points);
    for (std::size_t n = 0; n < order.size(); ++n) {
      if (n == 0 || e.distance2(order[n - 1], order[n]) != 0.0) {
        start.push_back(member.size());
        representative.push_back(order[n]);
      }
      member.push_back(order[n]);
    }
    start.push_back(member.size());
    count = representative.size();
  }

  bool identity = false;  ///< every vector distinct: tree point k is vector k, no tables
  std::size_t count = 0;  ///< tree points

  // group[i]: the tree point of vector i, for i < the indexed points.
  [[nodiscard]] std::vector<std::size_t> group_of_vectors() const {
    std::vector<std::size_t> group(identity ? count : member.size());
    if (identity) {
      std::iota(group.begin(), group.end(), std::size_t{0});
      return group;
    }
    for (std::size_t k = 0; k < count; ++k) {
      for (std::size_t m = start[k]; m < start[k + 1]; ++m) group[member[m]] = k;
    }
    return group;
  }

  [[nodiscard]] std::size_t first_of(std::size_t k) const {
    return identity ? k : representative[k];
  }

  // The first occurrence of tree point k outside query i's Theiler window, or npos.
  [[nodiscard]] std::size_t resolve(std::size_t k, std::size_t i, std::size_t theiler) const {
    if (identity) return k + theiler < i || k > i + theiler ? k : std::string::npos;
    const auto first = member.begin() + static_cast<std::ptrdiff_t>(start[k]);
    const auto last = member.begin() + static_cast<std::ptrdiff_t>(start[k + 1]);
    if (*first + theiler < i) return *first;
    const auto after = std::upper_bound(first, last, i + theiler);
    return after == last ? std::string::npos : *after;
  }
};

// The distinct vectors, copied once into one contiguous row-major block for the tree.
std::vector<double> tree_points(const DelayEmbedding& e, const Groups& groups) {
  std::vector<double> coords(groups.count * e.dimension());
  double* out = coords.data();
  for (std::size_t k = 0; k < groups.count; ++k) {
    const std::size_t i = groups.first_of(k);
    for (std::size_t d = 0; d < e.dimension(); ++d) *out++ = e.coordinate(i, d);
  }
  return coords;
}

// Result sets in nanoflann's protocol (kept by kd_tree.hpp) that drop the query's own repeats
// and temporal neighbours while the tree is searched, so no over-fetching is needed.
class ExcludingKnn {
 public:
  // With a limit, only points closer than it are taken: the tree's pruning is monotone in
  // worstDist(), so those are met in the same order as without one, and the answer is the
  // unlimited answer's entries below the limit.
  ExcludingKnn(const Groups& g, std::size_t query, std::size_t theiler, std::size_t k,
               double min_d2, double limit2 = std::numeric_limits<double>::max())
      : g_(g), query_(query), theiler_(theiler), k_(k), min_d2_(min_d2), limit2_(limit2) {}
  [[nodiscard]] std::size_t size() const { return found_.size(); }
  [[nodiscard]] bool full() const { return found_.size() == k_; }
  bool addPoint(double d2, std::size_t k) {
    if (d2 <= min_d2_) return true;
    if (d2 >= worstDist()) return true;
    const std::size_t j = g_.resolve(k, query_, theiler_);
    if (j == std::string::npos) return true;
    auto pos = std::upper_bound(found_.begin(), found_.end(), d2,
                                [](double v, const Neighbour& n) { return v < n.distance2; });
    found_.insert(pos, Neighbour{j, d2});
    if (found_.size() > k_) found_.pop_back();
    return true;
  }
  [[nodiscard]] double worstDist() const {
    return full() ? std::min(found_.back().distance2, limit2_) : limit2_;
  }
  std::vector<Neighbour> take() { return std::move(found_); }

 private:
  const Groups& g_;
  std::size_t query_, theiler_, k_;
  double min_d2_, limit2_;
  std::vector<Neighbour> found_;
};

// The nearest alone, as ExcludingKnn with k = 1 (the first found among equals stays) but
// without a list: Cao and the divergence curve ask this once per reference.
class ExcludingNearest {
 public:
  ExcludingNearest(const Groups& g, std::size_t query, std::size_t theiler, double min_d2)
      : g_(g), query_(query), theiler_(theiler), min_d2_(min_d2) {}
  bool addPoint(double d2, std::size_t k) {
    if (d2 <= min_d2_ || d2 >= best_.distance2) return true;
    const std::size_t j = g_.resolve(k, query_, theiler_);
    if (j != std::string::npos) best_ = Neighbour{j, d2};
    return true;
  }
  [[nodiscard]] double worstDist() const { return best_.distance2; }
  [[nodiscard]] bool found() const { return best_.distance2 < kNone; }
  [[nodiscard]] Neighbour best() const { return best_; }

 private:
  static constexpr double kNone = std::numeric_limits<double>::max();
  const Groups& g_;
  std::size_t query_, theiler_;
  double min_d2_;
  Neighbour best_{0, kNone};
};

class ExcludingRadius {
 public:
  ExcludingRadius(const Groups& g, std::size_t query, std::size_t theiler, double r2, double min_d2)
      : g_(g), query_(query), theiler_(theiler), r2_(r2), min_d2_(min_d2) {}
  [[nodiscard]] std::size_t size() const { return found_.size(); }
  [[nodiscard]] bool full() const { return true; }
  bool addPoint(double d2, std::size_t k) {
    if (d2 >= r2_ || d2 <= min_d2_) return true;
    const std::size_t j = g_.resolve(k, query_, theiler_);
    if (j != std::string::npos) found_.push_back({j, d2});
    return true;
  }
  [[nodiscard]] double worstDist() const { return r2_; }
  std::vector<Neighbour> take() { return std::move(found_); }

 private:
  const Groups& g_;
  std::size_t query_, theiler_;
  double r2_, min_d2_;
  std::vector<Neighbour> found_;
};

}  // namespace

struct NeighbourIndex::Impl {
  const DelayEmbedding* embedding;
  std::size_t points;
  Groups groups;
  detail::KdTree tree;
  std::vector<double> query;
  double min_d2;
  Impl(const DelayEmbedding& e, std::size_t n, double resolution)
      : embedding(&e),
        points(n),
        groups(e, n),
        tree(tree_points(e, groups), e.dimension()),
        query(e.dimension()),
        min_d2(resolution * resolution) {}
  // A query outside the embedding is a caller's bug: refused rather than read past the record.
  const double* point(std::size_t i) {
    if (i >= embedding->size()) throw std::out_of_range("NeighbourIndex: query past the embedding");
    for (std::size_t d = 0; d < embedding->dimension(); ++d) query[d] = embedding->coordinate(i, d);
    return query.data();
  }
};

NeighbourIndex::NeighbourIndex(const DelayEmbedding& embedding, std::size_t points,
                               double resolution)
    : impl_(std::make_unique<Impl>(
          embedding, points == 0 ? embedding.size() : std::min(points, embedding.size()),
          resolution)) {}

double repeat_resolution(std::span<const double> x) {
  constexpr double kRepeatShareOfSd = 1e-9;  // the header's contract: see repeat_resolution
  return kRepeatShareOfSd * standard_deviation(x);
}
NeighbourIndex::~NeighbourIndex() = default;

std::size_t NeighbourIndex::size() const { return impl_->points; }

std::vector<Neighbour> NeighbourIndex::k_nearest(std::size_t i, std::size_t k,
                                                 std::size_t theiler) const {
  ExcludingKnn result(impl_->groups, i, theiler, k, impl_->min_d2);
  impl_->tree.search(impl_->point(i), result);
  return result.take();
}

std::vector<Neighbour> NeighbourIndex::k_nearest_within(std::size_t i, std::size_t k,
                                                        std::size_t theiler, double r) const {
  ExcludingKnn result(impl_->groups, i, theiler, k, impl_->min_d2, r * r);
  impl_->tree.search(impl_->point(i), result);
  return result.take();
}

Neighbour NeighbourIndex::nearest(std::size_t i, std::size_t theiler) const {
  ExcludingNearest result(impl_->groups, i, theiler, impl_->min_d2);
  impl_->tree.search(impl_->point(i), result);
  return result.found() ? result.best() : Neighbour{size(), 0.0};
}

// Queries keyed by where their own vector sits in the tree (after every indexed vector if it
// is not indexed): successive searches then walk the same cells while they are in cache. On
// 1e5 samples of white noise in dimension 7 that made the divergence curve's searches ~1.4x
// faster (docs/notes/performance.md, "Neighbour search").
std::vector<std::size_t> NeighbourIndex::search_order(std::span<const std::size_t> queries) const {
  const std::vector<std::size_t> group = impl_->groups.group_of_vectors();
  const std::vector<std::size_t> rank = impl_->tree.storage_rank();
  std::vector<std::pair<std::size_t, std::size_t>> keyed(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const std::size_t i = queries[q];
    keyed[q] = {i < group.size() ? rank[group[i]] : rank.size(), q};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> order(queries.size());
  for (std::size_t n = 0; n < keyed.size(); ++n) order[n] = keyed[n].second;
  return order;
}

std::vector<Neighbour> NeighbourIndex::nearest_each(std::span<const std::size_t> queries,
                                                    std::size_t theiler) const {
  std::vector<Neighbour> found(queries.size());
  for (const std::size_t q : search_order(queries)) found[q] = nearest(queries[q], theiler);
  return found;
}

std::vector<std::vector<Neighbour>> NeighbourIndex::k_nearest_each(
    std::span<const std::size_t> queries, std::size_t k, std::size_t theiler) const {
  std::vector<std::vector<Neighbour>> found(queries.size());
  for (const std::size_t q : search_order(queries)) found[q] = k_nearest(queries[q], k, theiler);
  return found;
}

std::vector<Neighbour> NeighbourIndex::within(std::size_t i, double r, std::size_t theiler) const {
  ExcludingRadius result(impl_->groups, i, theiler, r * r, impl_->min_d2);
  impl_->tree.search(impl_->point(i), result);
  return result.take();
}

}  // namespace pneumachaos
