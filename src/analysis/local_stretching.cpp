#include "pneumachaos/analysis/local_stretching.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/delay_embedding.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

struct Accumulator {
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  void add(double r) {
    sum += r;
    sum2 += r * r;
    ++n;
  }
};

std::size_t band_of(double value, const std::vector<double>& edges) {
  const auto it = std::upper_bound(edges.begin(), edges.end(), value);
  if (it == edges.begin() || it == edges.end()) return edges.size();  // outside every band
  return static_cast<std::size_t>(it - edges.begin()) - 1;
}

void check_inputs(std::span<const double> x, const std::vector<double>& edges,
                  const StretchingOptions& o) {
  if (edges.size() < 2 || !std::is_sorted(edges.begin(), edges.end()) ||
      std::adjacent_find(edges.begin(), edges.end()) != edges.end())
    throw Error("band edges", "at least two strictly increasing values are needed");
  o.validate();
  const std::size_t span = (o.dimension - 1) * o.delay + o.horizon;
  if (x.size() <= span + 2 * o.theiler + 2)
    throw Error("stretching", fmt::format("{} samples are too few for dimension {}, delay {} and "
                                          "a horizon of {} steps",
                                          x.size(), o.dimension, o.delay, o.horizon));
}

}  // namespace

void StretchingOptions::validate() const {
  using namespace validation;
  require_ge(field("stretching.dimension"), static_cast<double>(dimension), 1);
  require_ge(field("stretching.delay"), static_cast<double>(delay), 1);
  require_ge(field("stretching.horizon"), static_cast<double>(horizon), 1, "steps");
  require_ge(field("stretching.stride"), static_cast<double>(stride), 1);
}

std::vector<BandStretching> band_stretching(std::span<const double> x, double rate_Hz,
                                            const std::vector<double>& edges,
                                            const StretchingOptions& o) {
  check_inputs(x, edges, o);
  const DelayEmbedding embedding(x, o.dimension, o.delay);
  // Only vectors that can still be followed for `horizon` steps are indexed, so every
  // neighbour found has a future to compare with.
  const std::size_t usable = embedding.size() - o.horizon;
  const NeighbourIndex index(embedding, usable, repeat_resolution(x));
  std::vector<Accumulator> acc(edges.size() - 1);
  const double horizon_s = static_cast<double>(o.horizon) / rate_Hz;
  for (std::size_t i = 0; i < usable; i += o.stride) {
    const std::size_t band = band_of(x[i], edges);
    if (band >= acc.size()) continue;
    const Neighbour nb = index.nearest(i, o.theiler);
    if (nb.index >= usable || nb.distance2 <= 0.0) continue;
    const double later = embedding.distance2(i + o.horizon, nb.index + o.horizon);
    if (later <= 0.0) continue;
    acc[band].add(0.5 * std::log(later / nb.distance2) / horizon_s);
  }
  std::vector<BandStretching> out;
  for (std::size_t k = 0; k < acc.size(); ++k) {
    BandStretching b{edges[k], edges[k + 1], 0.0, 0.0, acc[k].n};
    if (b.pairs > 0) {
      const double n = static_cast<double>(b.pairs), mean = acc[k].sum / n;
      b.rate_per_s = mean;
      if (b.pairs > 1)
        b.standard_error_per_s = std::sqrt(std::max(0.0, acc[k].sum2 / n - mean * mean) / (n - 1));
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace pneumachaos
