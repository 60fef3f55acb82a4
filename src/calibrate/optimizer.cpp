#include "calibrate/optimizer.hpp"

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/xnes.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include <cmath>
#include <memory>
#include <utility>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

struct Shared {
  UnitObjective objective;
  OptimizerTrace trace;
};

// pagmo copies its problem: the objective and the trace live behind a shared pointer, so every
// copy records into the one trace.
struct UnitBoxProblem {
  std::shared_ptr<Shared> shared;
  std::size_t dimension = 1;
  [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    const std::vector<double> u(x.begin(), x.end());
    const double f = shared->objective(u);
    if (!std::isfinite(f)) throw RunError("calibrate", "the objective returned a non-finite value");
    shared->trace.u.push_back(u);
    shared->trace.f.push_back(f);
    return {f};
  }
  [[nodiscard]] std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(dimension, 0.0), pagmo::vector_double(dimension, 1.0)};
  }
};

pagmo::algorithm make_algorithm(const OptimizerSpec& spec) {
  const auto gen = static_cast<unsigned>(spec.generations());
  const auto seed = static_cast<unsigned>(spec.seed);
  // Stopping tolerances far below anything a simulated objective resolves: the budget decides.
  constexpr double kTol = 1e-300;
  // force_bounds: every point asked lies in the box, so every scenario is within the spec's
  // bounds (pagmo: "the fitness will never be called outside the bounds").
  if (spec.algorithm == "xnes")
    return pagmo::algorithm(pagmo::xnes(gen, -1, -1, -1, spec.sigma0, kTol, kTol, false, true, seed));
  return pagmo::algorithm(
      pagmo::cmaes(gen, -1, -1, -1, -1, spec.sigma0, kTol, kTol, false, true, seed));
}

}  // namespace

OptimizerTrace minimize(const OptimizerSpec& spec, std::size_t dimension,
                        const UnitObjective& objective) {
  spec.validate();
  if (dimension == 0) throw Error("calibrate", "nothing to optimize: no free parameter");
  auto shared = std::make_shared<Shared>();
  shared->objective = objective;
  const pagmo::problem problem{UnitBoxProblem{shared, dimension}};
  // The initial population is drawn with the spec's seed too (pagmo's population seed).
  pagmo::population pop(problem, spec.population, spec.seed);
  pagmo::algorithm algo = make_algorithm(spec);
  algo.evolve(pop);
  OptimizerTrace trace = std::move(shared->trace);
  for (std::size_t i = 1; i < trace.f.size(); ++i)
    if (trace.f[i] < trace.f[trace.best]) trace.best = i;
  return trace;
}

}  // namespace pneumachaos
