#pragma once
// The divergence exponent's dependence on the choices behind it, the window and the embedding
// dimension, which its 95 % interval is widened to cover (docs/notes/analysis.md "Divergence
// exponent's uncertainty"). Internal to the analysis module.

#include <span>

#include "pneumachaos/analysis/analyze.hpp"

namespace pneumachaos {

/// The value on each half of `d`'s window and on the curve's other agreeing runs (the windows
/// the rule passed over for a longer one), and (with `embeddings`) the value at dimensions
/// m - 1 and m + 1 measured with `options` on a quarter of its reference pairs. `d` must have
/// a linear region.
ExponentSpread exponent_spread(std::span<const double> x, double rate_Hz, DivergenceOptions options,
                               const DivergenceResult& d, bool embeddings);

/// The value's uncertainty with each spread added in quadrature as a 95 % half-width (/ 1.96):
/// the interval +-1.96 u then reaches the values the other choices give.
double widened_uncertainty(const DivergenceResult& d, const ExponentSpread& s);

}  // namespace pneumachaos
