// The neighbour index alone: building it and querying the nearest neighbour of every tenth
// point, on 1e4 and 1e5 samples of the Lorenz x coordinate (dt = 0.01) embedded with delay
// 17, and on 1e5 samples of white noise in dimension 7. BM_Reference* is the
// reference index: nanoflann's tree reading the delay
// coordinates from the series (docs/notes/performance.md); same neighbours, printed beside ours.
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_neighbours
#include <benchmark/benchmark.h>

#include <limits>
#include <cstdint>
#include <map>
#include <utility>
#include <nanoflann.hpp>

#include "../tests/support/reference_series.hpp"
#include "analysis/delay_embedding.hpp"

namespace {

using namespace pneumachaos;

// Arguments: samples, dimension, record (0: Lorenz x, delay 17; 1: white noise, delay 1, as
// the analysis embeds them).
const std::vector<double>& series(const benchmark::State& state) {
  static std::map<std::pair<std::int64_t, std::int64_t>, std::vector<double>> cache;
  const auto key = std::make_pair(state.range(0), state.range(2));
  auto it = cache.find(key);
  if (it == cache.end()) {
    const auto n = static_cast<std::size_t>(key.first);
    it = cache.emplace(key, key.second == 0 ? testing::lorenz_x(n) : testing::white_noise(n)).first;
  }
  return it->second;
}

DelayEmbedding embedding(const benchmark::State& state) {
  return {series(state), static_cast<std::size_t>(state.range(1)), state.range(2) == 0 ? 17u : 1u};
}

// The reference index's dataset: the coordinates read from the series on demand (this record
// has no repeated value, so grouping equal points would change nothing).
struct SeriesAdaptor {
  const DelayEmbedding* e;
  [[nodiscard]] std::size_t kdtree_get_point_count() const { return e->size(); }
  [[nodiscard]] double kdtree_get_pt(std::size_t k, std::size_t d) const {
    return e->coordinate(k, d);
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using ReferenceTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, SeriesAdaptor>,
                                        SeriesAdaptor, -1, std::size_t>;

// The nearest neighbour outside the Theiler window, in nanoflann's result-set protocol.
struct NearestOutside {
  std::size_t query, theiler, best = 0;
  double d2 = std::numeric_limits<double>::max();
  [[nodiscard]] std::size_t size() const { return 1; }
  [[nodiscard]] bool full() const { return true; }
  bool addPoint(double dist2, std::size_t k) {
    const std::size_t gap = k > query ? k - query : query - k;
    if (gap > theiler && dist2 < d2 && dist2 > 0.0) {
      d2 = dist2;
      best = k;
    }
    return true;
  }
  [[nodiscard]] double worstDist() const { return d2; }
};

void BM_ReferenceBuild(benchmark::State& state) {
  const auto& x = series(state);
  const DelayEmbedding e = embedding(state);
  const SeriesAdaptor adaptor{&e};
  for (auto _ : state) {
    ReferenceTree tree(static_cast<int>(e.dimension()), adaptor,
                       nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    benchmark::DoNotOptimize(tree.root_node);
  }
}

void BM_ReferenceNearestAll(benchmark::State& state) {
  const auto& x = series(state);
  const DelayEmbedding e = embedding(state);
  const SeriesAdaptor adaptor{&e};
  ReferenceTree tree(static_cast<int>(e.dimension()), adaptor,
                     nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::vector<double> q(e.dimension());
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < e.size(); i += 10) {
      for (std::size_t d = 0; d < e.dimension(); ++d) q[d] = e.coordinate(i, d);
      NearestOutside r{i, e.delay()};
      tree.findNeighbors(r, q.data(), nanoflann::SearchParams());
      sum += r.d2;
    }
    benchmark::DoNotOptimize(sum);
  }
}

void BM_Build(benchmark::State& state) {
  const auto& x = series(state);
  const DelayEmbedding e = embedding(state);
  for (auto _ : state) {
    const NeighbourIndex index(e, 0, repeat_resolution(x));
    benchmark::DoNotOptimize(index.size());
  }
}

void BM_NearestAll(benchmark::State& state) {
  const auto& x = series(state);
  const DelayEmbedding e = embedding(state);
  const NeighbourIndex index(e, 0, repeat_resolution(x));
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < index.size(); i += 10) sum += index.nearest(i, e.delay()).distance2;
    benchmark::DoNotOptimize(sum);
  }
}

// The same queries as BM_NearestAll, asked in one batch: searched in the tree's storage order.
void BM_NearestEach(benchmark::State& state) {
  const auto& x = series(state);
  const DelayEmbedding e = embedding(state);
  const NeighbourIndex index(e, 0, repeat_resolution(x));
  std::vector<std::size_t> queries;
  for (std::size_t i = 0; i < index.size(); i += 10) queries.push_back(i);
  for (auto _ : state) {
    double sum = 0.0;
    for (const Neighbour& nb : index.nearest_each(queries, e.delay())) sum += nb.distance2;
    benchmark::DoNotOptimize(sum);
  }
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Args({10000, 1, 0})->Args({10000, 3, 0})->Args({10000, 6, 0})->Args({100000, 3, 0});
  b->Args({100000, 7, 1});
  b->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_ReferenceBuild)->Apply(sizes);
BENCHMARK(BM_Build)->Apply(sizes);
BENCHMARK(BM_ReferenceNearestAll)->Apply(sizes);
BENCHMARK(BM_NearestAll)->Apply(sizes);
BENCHMARK(BM_NearestEach)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
