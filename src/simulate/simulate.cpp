#include "pneumachaos/simulate/simulate.hpp"

#include <algorithm>

#include <vector>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

IntegratorOptions integrator_options(const RunParams& run) {
  IntegratorOptions o;
  o.t_start_s = 0.0;
  o.t_end_s = run.duration_s;
  o.relative_tolerance = run.relative_tolerance;
  o.absolute_tolerance = run.absolute_tolerance;
  o.max_step_s = run.max_step_s;
  o.stepper = run.stepper;
  o.sample_rate_Hz = run.sample_rate_Hz;
  // A budget of steps per simulated second, 10-100x what the stiffest default-rig runs need,
  // so that an absurd step size or stiffness fails within about a second of work, not minutes.
  constexpr double kStepsPerSimulatedSecond = 1e5;
  o.max_steps = static_cast<std::size_t>(
      std::clamp(kStepsPerSimulatedSecond * run.duration_s, 1e5, static_cast<double>(o.max_steps)));
  return o;
}

std::vector<double> rest_start(const Plant& plant, const RunParams& run) {
  if (run.start != RunStart::kRest)
    throw Error("run.start",
                "sliding: the steady motion comes from the stability analysis "
                "(run_start_state, then simulate_from)");
  return plant.initial_state();
}

SimulationResult simulate(const Plant& plant, const RunParams& run) {
  return simulate_from(plant, rest_start(plant, run), run);
}

SimulationResult simulate_from(const Plant& plant, std::vector<double> initial_state,
                               const RunParams& run) {
  const IntegratorOptions io = integrator_options(run);
  io.validate();
  SimulationResult result{TimeSeries(run.sample_rate_Hz), {}};
  TimeSeries& ts = result.series;
  for (const OutputChannel& c : plant.channels()) ts.add_channel(c.name, c.unit);
  std::vector<double> row;
  const auto observer = [&](double /*t*/, std::span<const double> x, const Mode& mode) {
    plant.sample(mode, x, row);
    ts.append(row);
  };
  Mode mode = plant.initial_mode(initial_state, 0.0);
  result.summary = integrate_hybrid(plant, initial_state, mode, io, observer);
  return result;
}

}  // namespace pneumachaos
