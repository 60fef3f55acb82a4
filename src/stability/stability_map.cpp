#include "pneumachaos/stability/stability_map.hpp"

#include <exception>
#include <string>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

StabilityMap stability_map(const Scenario& base, const std::vector<GridAxis>& axes,
                           const StabilityOptions& options) {
  validate_grid(axes);
  StabilityMap map;
  map.axes = axes;
  const std::size_t n = grid_size(axes);
  map.points.reserve(n);
  for (std::size_t flat = 0; flat < n; ++flat) {
    const auto index = grid_index(axes, flat);
    StabilityMapPoint point;
    for (std::size_t i = 0; i < axes.size(); ++i)
      point.coordinates.push_back(axes[i].values[index[i]]);
    try {
      const Plant plant(scenario_at(base, axes, index));
      point.result = analyze_stability(plant, options);
    } catch (const Error& e) {
      point.error = e.what();
    } catch (const std::exception& e) {
      // A numerical breakdown at one point (Boost.Math, Eigen) marks that point; the map
      // goes on.
      point.error = std::string("numerical failure: ") + e.what();
    }
    if (point.result.has_equilibrium()) {
      ++map.with_equilibrium;
      if (point.result.agree()) ++map.agreeing;
    }
    map.points.push_back(std::move(point));
  }
  return map;
}

}  // namespace pneumachaos
