#pragma once
// Time responses of the cylinder: integrate a Plant and sample it at a fixed rate.

#include <string>
#include <vector>

#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/core/run_params.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/event_integrator.hpp"

namespace pneumachaos {

/// The integrator's settings for a run of `run.duration_s` from t = 0, with a step budget
/// that makes an absurd step size or stiffness fail fast.
IntegratorOptions integrator_options(const RunParams& run);

struct SimulationResult {
  /// Channels: x [m], v [m/s], P1 [Pa], P2 [Pa], F_friction [N] (seal), the friction internal
  /// states, then for spring coupling x_load [m], v_load [m/s], F_guide [N], and stuck [-].
  TimeSeries series{1000.0};
  IntegrationSummary summary;
};

/// Simulates from the start of a run of docs/model.md (directional valve switching at t = 0).
/// A run with run.start = sliding starts from the steady motion, which the stability module
/// finds (run_start_state): here it throws Error naming run.start rather than start at rest.
SimulationResult simulate(const Plant& plant, const RunParams& run);

/// The plant's state at rest (Plant::initial_state) for a run that starts at rest; throws
/// Error naming run.start for one that starts sliding.
std::vector<double> rest_start(const Plant& plant, const RunParams& run);

/// Simulates from a given state (e.g. near an equilibrium).
SimulationResult simulate_from(const Plant& plant, std::vector<double> initial_state,
                               const RunParams& run);

/// A one-paragraph human-readable account of a run's summary. smooth_seal: the seal model has
/// no stiction (gms, lugre), so a run without stick/slip mode switches may still stick.
std::string describe(const IntegrationSummary& summary, bool smooth_seal = false);

}  // namespace pneumachaos
