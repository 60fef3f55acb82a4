#pragma once
// The optimizer behind calibrate: pagmo2's CMA-ES or xNES over the unit box (each free
// parameter mapped to [0, 1]), seeded, so the same spec and seed ask for the same points in
// the same order (docs/guide/calibrate.md says why pagmo2).

#include <cstddef>
#include <functional>
#include <vector>

#include "pneumachaos/calibrate/calibration_spec.hpp"

namespace pneumachaos {

/// The objective on the unit box: a point u (each coordinate in [0, 1]) -> a finite value to
/// minimize. Called once per evaluation, one call at a time, in the optimizer's order.
using UnitObjective = std::function<double(const std::vector<double>& u)>;

struct OptimizerTrace {
  std::vector<std::vector<double>> u;  ///< every point asked, in order
  std::vector<double> f;               ///< its value
  std::size_t best = 0;                ///< index of the lowest value (the first among equals)
};

/// Minimizes `objective` over [0, 1]^dimension with spec's algorithm: an initial population
/// drawn uniformly (seeded), then spec.generations() generations; spec.evaluations() calls in
/// all. Throws Error for dimension 0; rethrows what the objective throws.
OptimizerTrace minimize(const OptimizerSpec& spec, std::size_t dimension,
                        const UnitObjective& objective);

}  // namespace pneumachaos
