#include "pneumachaos/stability/run_start.hpp"

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/stability/equilibrium.hpp"

namespace pneumachaos {

std::vector<double> run_start_state(const Plant& plant, const RunParams& run) {
  if (run.start == RunStart::kRest) return plant.initial_state();
  const EquilibriumResult e = find_equilibria(plant);
  if (!e.exists()) throw Error("run.start", "sliding: no steady sliding exists here (" + e.reason + ")");
  return e.primary().state;
}

}  // namespace pneumachaos
