#pragma once
// The analytic counterpart of the paper's Figs. 4-6: the stability verdict over a grid.

#include <vector>

#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/stability/stability_analysis.hpp"

namespace pneumachaos {

struct StabilityMapPoint {
  std::vector<double> coordinates;  ///< one value per axis, in the key's unit
  StabilityResult result;
  std::string error;  ///< non-empty when this point's parameters are invalid
};

struct StabilityMap {
  std::vector<GridAxis> axes;
  std::vector<StabilityMapPoint> points;  ///< product grid, last axis fastest
  std::size_t agreeing = 0;               ///< points with an equilibrium where both verdicts agree
  std::size_t with_equilibrium = 0;
};

/// Analyzes every point of the product grid. Points whose parameters are invalid are kept
/// with their error; the map goes on.
StabilityMap stability_map(const Scenario& base, const std::vector<GridAxis>& axes,
                           const StabilityOptions& options = {});

}  // namespace pneumachaos
