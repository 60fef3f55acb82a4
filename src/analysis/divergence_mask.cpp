#include "divergence_mask.hpp"

#include <algorithm>

namespace pneumachaos::detail {

std::vector<bool> excluded_vectors(const std::vector<bool>& excluded, const DelayEmbedding& e) {
  std::vector<bool> bad(e.size(), false);
  for (std::size_t j = 0; j < e.size(); ++j) {
    for (std::size_t d = 0; d < e.dimension() && !bad[j]; ++d) {
      bad[j] = excluded[j + d * e.delay()];
    }
  }
  return bad;
}

std::vector<Neighbour> nearest_allowed(const NeighbourIndex& index,
                                       std::span<const std::size_t> references,
                                       std::size_t theiler, const std::vector<bool>& bad,
                                       std::size_t first, std::size_t last, std::size_t none) {
  // A slip's vectors near its ends can have rest vectors as their nearest neighbours; a few
  // candidates beyond the nearest find the nearest one that is in a slip.
  constexpr std::size_t kCandidates = 8;
  const auto lists = index.k_nearest_each(references, kCandidates, theiler);
  std::vector<Neighbour> found(references.size(), Neighbour{none, 0.0});
  for (std::size_t r = 0; r < references.size(); ++r) {
    for (const Neighbour& nb : lists[r]) {
      if (nb.index >= first && nb.index < last && !bad[nb.index]) {
        found[r] = nb;
        break;
      }
    }
  }
  return found;
}

void mask_pair(std::span<double> d2, const std::vector<bool>& bad, std::size_t i, std::size_t j,
               bool stop) {
  for (std::size_t k = 0; k < d2.size(); ++k) {
    if (bad[i + k] || bad[j + k]) {
      if (stop) {
        std::fill(d2.begin() + static_cast<std::ptrdiff_t>(k), d2.end(), 0.0);
        return;
      }
      d2[k] = 0.0;
    }
  }
}

}  // namespace pneumachaos::detail
