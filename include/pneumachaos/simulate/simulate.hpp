#pragma once
// Time responses of the cylinder: integrate a Plant and sample it at a fixed rate.

#include <string>
#include <vector>

#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/event_integrator.hpp"

namespace pneumachaos {

struct SimulationOptions {
  double duration_s = 10.0;
  double sample_rate_Hz = 1000.0;
  double relative_tolerance = 1e-7;
  double absolute_tolerance = 1e-10;
  double max_step_s = 2e-3;
  StepperKind stepper = StepperKind::kDopri5;

  /// The run settings of a scenario (its [run] table).
  static SimulationOptions from(const RunParams& run);
  [[nodiscard]] IntegratorOptions integrator_options() const;
};

struct SimulationResult {
  /// Channels: x [m], v [m/s], P1 [Pa], P2 [Pa], F_friction [N] (seal), the friction internal
  /// states, then for spring coupling x_load [m], v_load [m/s], F_guide [N], and stuck [-].
  TimeSeries series{1000.0};
  IntegrationSummary summary;
};

/// Simulates from the start of a run of docs/model.md (directional valve switching at t = 0).
SimulationResult simulate(const Plant& plant, const SimulationOptions& options);

/// Simulates from a given state (e.g. near an equilibrium).
SimulationResult simulate_from(const Plant& plant, std::vector<double> initial_state,
                               const SimulationOptions& options);

/// A one-paragraph human-readable account of a run's summary.
std::string describe(const IntegrationSummary& summary);

}  // namespace pneumachaos
