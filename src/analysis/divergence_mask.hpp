#pragma once
// The divergence curve with some samples out of it (docs/analysis.md "The divergence curve
// without its rests"): a delay vector that holds an excluded sample is neither a reference
// nor a neighbour, and a pair adds nothing at a step where either of its vectors holds one.
// Internal to the analysis module.

#include <cstddef>
#include <span>
#include <vector>

#include "pneumachaos/analysis/delay_embedding.hpp"

namespace pneumachaos::detail {

/// bad[j]: delay vector j of `e` holds a sample i with excluded[i] (excluded: one flag per
/// sample of the series `e` embeds).
std::vector<bool> excluded_vectors(const std::vector<bool>& excluded, const DelayEmbedding& e);

/// For each reference, its nearest neighbour among the `candidates` nearest that is not a bad
/// vector and lies in [first, last); index == `none` when none of them qualifies.
std::vector<Neighbour> nearest_allowed(const NeighbourIndex& index,
                                       std::span<const std::size_t> references,
                                       std::size_t theiler, const std::vector<bool>& bad,
                                       std::size_t first, std::size_t last, std::size_t none);

/// Zeroes d2[k] (no term: add_log_distances skips d2 = 0) wherever vector i + k or j + k is
/// bad; with `stop`, also at every later step (the pair is followed only up to its first rest).
void mask_pair(std::span<double> d2, const std::vector<bool>& bad, std::size_t i, std::size_t j,
               bool stop);

}  // namespace pneumachaos::detail
