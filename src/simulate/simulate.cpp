#include "pneumachaos/simulate/simulate.hpp"

#include <algorithm>

#include <vector>

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

SimulationResult simulate(const Plant& plant, const RunParams& run) {
  return simulate_from(plant, plant.initial_state(), run);
}

SimulationResult simulate_from(const Plant& plant, std::vector<double> initial_state,
                               const RunParams& run) {
  const IntegratorOptions io = integrator_options(run);
  io.validate();
  SimulationResult result{TimeSeries(run.sample_rate_Hz), {}};
  TimeSeries& ts = result.series;
  const StateLayout& L = plant.layout();
  ts.add_channel("x", "m");
  ts.add_channel("v", "m/s");
  ts.add_channel("P1", "Pa");
  ts.add_channel("P2", "Pa");
  ts.add_channel("F_friction", "N");
  for (std::size_t i = 0; i < L.seal_z_count; ++i) {
    ts.add_channel(L.entries[L.seal_z + i].name, L.entries[L.seal_z + i].unit);
  }
  if (L.has_load_body()) {
    ts.add_channel("x_load", "m");
    ts.add_channel("v_load", "m/s");
    ts.add_channel("F_guide", "N");
    for (std::size_t i = 0; i < L.guide_z_count; ++i) {
      ts.add_channel(L.entries[L.guide_z + i].name, L.entries[L.guide_z + i].unit);
    }
  }
  if (L.has_temperatures()) {
    ts.add_channel("T1", "K");
    ts.add_channel("T2", "K");
  }
  if (L.has_supply_line()) ts.add_channel("P0", "Pa");
  if (L.has_valve_opening()) ts.add_channel("S1_open", "-");
  ts.add_channel("stuck", "-");

  std::vector<double> row;
  const auto observer = [&](double /*t*/, std::span<const double> x, const Mode& mode) {
    const PlantOutputs out = plant.outputs(mode, x);
    row.clear();
    row.insert(row.end(), {x[L.x], x[L.v], x[L.P1], x[L.P2], out.seal_friction_N});
    for (std::size_t i = 0; i < L.seal_z_count; ++i) row.push_back(x[L.seal_z + i]);
    if (L.has_load_body()) {
      row.insert(row.end(), {x[L.load_x], x[L.load_v], out.guide_friction_N});
      for (std::size_t i = 0; i < L.guide_z_count; ++i) row.push_back(x[L.guide_z + i]);
    }
    if (L.has_temperatures()) row.insert(row.end(), {x[L.T1], x[L.T2]});
    if (L.has_supply_line()) row.push_back(x[L.P0]);
    if (L.has_valve_opening()) row.push_back(x[L.S1_open]);
    row.push_back(out.piston_stuck ? 1.0 : 0.0);
    ts.append(row);
  };
  Mode mode = plant.initial_mode(initial_state, 0.0);
  result.summary = integrate_hybrid(plant, initial_state, mode, io, observer);
  return result;
}

}  // namespace pneumachaos
