#pragma once
// Integration of a HybridSystem with event location: Boost.Odeint steppers advance the smooth
// segments, events are located on the stepper's dense output with Boost.Math's TOMS 748
// bracketing root finder, and samples are taken at a fixed rate from the dense output.

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/hybrid_system.hpp"

namespace pneumachaos {

/// How dopri5's step size follows its error estimate (docs/notes/performance.md, "Step-size
/// control": the PI controller takes 7 % fewer evaluations on the default rig but changed a
/// claim of `reproduce --quick`, so it is not the default).
enum class StepControl {
  kOdeint,  ///< Boost.Odeint's default: grows only below half the tolerance, shrinks as err^-1/3
  kPI,      ///< Hairer's DOPRI5 controller: err^-0.17 * err_prev^0.04, no growth after a rejection
};

struct IntegratorOptions {
  double t_start_s = 0.0;
  double t_end_s = 1.0;
  double relative_tolerance = 1e-7;
  double absolute_tolerance = 1e-10;
  double max_step_s = 2e-3;
  double initial_step_s = 1e-5;
  StepperKind stepper = StepperKind::kDopri5;
  StepControl step_control = StepControl::kOdeint;  ///< dopri5 only
  double sample_rate_Hz = 1000.0;  ///< 0: no samples
  /// Events allowed at one instant before the run is called chattering (Zeno).
  std::size_t max_events_at_one_instant = 64;
  std::size_t max_steps = 20'000'000;
  bool record_events = true;  ///< keep the time and kind of each event in the summary
  static constexpr ErrorField kRelativeToleranceField{"integrator.relative_tolerance",
                                                      "relative_tolerance"};
  static constexpr ErrorField kAbsoluteToleranceField{"integrator.absolute_tolerance",
                                                      "absolute_tolerance"};

  /// Throws Error naming the offending option.
  void validate() const;
};

enum class Termination {
  kDurationReached,  ///< integrated to t_end
  kTerminalEvent,    ///< an event ended the run (e.g. end of stroke)
  kSolverFailure,    ///< step size underflow, non-finite state, step limit
  kChattering,       ///< too many events at one instant (Zeno behaviour)
};
const char* termination_name(Termination t);

struct EventCounts {
  std::size_t stick = 0, slip = 0, reversal = 0, stop_hit = 0, stop_release = 0;
};

struct EventRecord {
  double t_s = 0.0;
  EventKind kind = EventKind::kSlip;
};

/// What happened in a run (docs/architecture.md: options in, summary out).
struct IntegrationSummary {
  Termination termination = Termination::kDurationReached;
  std::string message;
  double t_final_s = 0.0;
  std::size_t steps_accepted = 0;
  std::size_t steps_rejected = 0;
  std::size_t rhs_evaluations = 0;
  EventCounts events;
  std::vector<EventRecord> event_log;  ///< every event in time order (when recorded)
  double wall_time_s = 0.0;
  [[nodiscard]] bool ok() const {
    return termination == Termination::kDurationReached ||
           termination == Termination::kTerminalEvent;
  }
};

/// Receives each sample: time, state, mode.
using SampleObserver = std::function<void(double t, std::span<const double> x, const Mode& mode)>;

/// Integrates `system` from (x, mode) at options.t_start_s to options.t_end_s or a terminal
/// event. On return x and mode hold the final state. Never throws for numerical trouble: a
/// failure is reported in the summary (bad options still throw Error).
IntegrationSummary integrate_hybrid(const HybridSystem& system, std::vector<double>& x, Mode& mode,
                                    const IntegratorOptions& options,
                                    const SampleObserver& observer = {});

}  // namespace pneumachaos
