#pragma once
// The largest Lyapunov exponent of a model itself (not of a sampled record): two nearby
// trajectories integrated side by side, their separation measured and renormalised at fixed
// intervals (Benettin, Galgani, Giorgilli & Strelcyn 1980, Meccanica 15). Each trajectory is a
// full hybrid integration, so stick/slip and stop events are located on both; the separation
// is renormalised only when both are in the same discrete mode, which keeps the perturbed
// state consistent (a stuck piston has v = 0 exactly on both).

#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/hybrid_system.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/simulate/event_integrator.hpp"

namespace pneumachaos {

struct ModelLyapunovOptions {
  double transient_s = 5.0;     ///< integrated and discarded first
  double measure_s = 40.0;      ///< time over which the stretching is averaged
  double renormalize_s = 0.02;  ///< interval between renormalisations
  /// Initial and renormalised separation in the scaled norm: far above the integration error,
  /// far below the size of the motion (for the cylinder 1e-3 = 10 Pa on P1, 1e6 x the default
  /// rtol; docs/notes/analysis.md "The model exponent's separation floor").
  double separation = 1e-3;
  /// Per-state scales of the norm (empty: all 1); states with scale 0 are not perturbed.
  std::vector<double> scales;
  /// Index of the state the initial separation lies along (a pressure, which does not
  /// disturb a stuck contact).
  std::size_t perturbed_state = 0;
  double relative_tolerance = 1e-9;
  double absolute_tolerance = 1e-12;
  double max_step_s = 2e-3;
  StepperKind stepper = StepperKind::kDopri5;
  std::size_t blocks = 10;  ///< for the uncertainty (standard error between blocks)
  /// A terminal event (the piston at its stroke end) during the measurement ends it there
  /// instead of failing it: the exponent and its blocks then span the time measured. A run
  /// with moving volumes has no fixed length, so a sweep measures "the rest of the stroke".
  /// On by default: the default scenario's stroke ends at 7.5 s, before 5 s of transient and
  /// 40 s of measurement would; false makes a stroke end fail the measurement.
  bool until_terminal_event = true;
  static constexpr ErrorField kTransientField{"lyapunov.transient_s", "lyapunov.transient_s"};
  static constexpr ErrorField kMeasureField{"lyapunov.measure_s", "lyapunov.measure_s"};
  static constexpr ErrorField kRenormalizeField{"lyapunov.renormalize_s",
                                                "lyapunov.renormalize_s"};
  static constexpr ErrorField kSeparationField{"lyapunov.separation", "lyapunov.separation"};
  static constexpr ErrorField kBlocksField{"lyapunov.blocks", "lyapunov.blocks"};
  /// Throws Error about one of the fields above.
  void validate() const;
};

struct ModelLyapunovResult {
  bool ok = true;
  std::string message;
  double lambda_per_s = 0.0;
  double uncertainty_per_s = 0.0;
  std::vector<double> running_time_s, running_per_s;  ///< convergence of the estimate
  std::size_t renormalizations = 0;
  std::size_t postponed = 0;  ///< intervals that ended with the two in different modes
  double measured_s = 0.0;    ///< time the exponent spans (less than asked after a stroke end)
};

/// Starts from (x0, mode0) at t = 0.
ModelLyapunovResult model_lyapunov(const HybridSystem& system, const std::vector<double>& x0,
                                   const ModelLyapunovOptions& options);

class Plant;

/// The cylinder's smallest separation per unit of relative tolerance. Below it the two
/// trajectories' integration errors, accumulated over an interval, are renormalised as if they
/// were divergence and the exponent grows as the separation shrinks (docs/notes/analysis.md, "The
/// model exponent's separation floor": at rtol 1e-9 a periodic point reads 0.0 at 1e-3,
/// 0.7-1.8 1/s at 1e-4 and 3.7-8.5 1/s at 3e-5).
inline constexpr double kPlantSeparationPerTolerance = 1e6;
/// The cylinder's largest separation in the scaled norm: 1 = 10 kPa on P1, already a tenth
/// of the pressures' swing; a larger one measures no tangent growth, and one beyond the
/// motion reaches the stroke end before any renormalisation.
inline constexpr double kPlantMaxSeparation = 1.0;

/// The cylinder's exponent from the start of a run: the plant's state scales, the separation
/// along P1 (which leaves a stuck contact stuck), rtol 1e-9 and atol 1e-12 times
/// tolerance_factor; the largest step and the stepper from the scenario's `run`; transient,
/// measuring time, intervals and separation from `base`. A separation below 1e6 x rtol (the
/// default 1e-3, 10 Pa, is exactly that) is refused: the exponent would read integration error.
ModelLyapunovResult plant_lyapunov(const Plant& plant, const RunParams& run,
                                   ModelLyapunovOptions base = {}, double tolerance_factor = 1.0);

/// The same from the state `x0` (a run that starts sliding: run_start_state).
ModelLyapunovResult plant_lyapunov_from(const Plant& plant, const std::vector<double>& x0,
                                        const RunParams& run, ModelLyapunovOptions base = {},
                                        double tolerance_factor = 1.0);

}  // namespace pneumachaos
