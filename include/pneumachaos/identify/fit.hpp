#pragma once
// Model identification from a measured record (docs/notes/model_fit.md): the scenario keys named free are
// adjusted until segment-wise simulations of the plant reproduce the measured P1, P2 and v.
// Ceres Solver minimises the noise-scaled simulation error; its covariance gives the standard
// errors.

#include <iosfwd>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/measured_record.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos::identify {

struct FitOptions {
  /// Length of each simulated segment (multiple shooting): every segment starts from the
  /// measured state, so a chaotic or stick-slip record never has to be followed longer.
  double segment_length_s = 0.2;
  /// Global stage: from the start values, one fit with each of these segment lengths and one
  /// with segment_length_s; the candidate whose simulation error is least with
  /// segment_length_s segments (the start values included) starts the final fit. Short
  /// segments keep a mistimed slip cheap, long ones see the slow dynamics: which of them
  /// leads to the global minimum depends on the record (docs/notes/model_fit.md). Empty: no global stage.
  std::vector<double> first_segment_lengths_s = {0.05, 0.1, 0.2, 0.5};
  /// Noise scales dividing the residuals: what one unit of error is worth in each signal.
  /// Not the sensor noise alone but the error a segment simulation makes: a slip a
  /// millisecond early is tens of mm/s of velocity error, so v is scaled by 30 mm/s, else
  /// the slip timing drowns the pressure signals that carry S2 (docs/notes/model_fit.md).
  double pressure_scale_Pa = 1000.0;
  double velocity_scale_m_per_s = 0.03;
  /// Multiple shooting proper: each segment's starting P1, P2 are fitted too (two parameters
  /// per segment, eliminated by the Schur complement), so transducer noise in the starting
  /// values does not bias the valve areas. Off: the smoothed measured values are used as they are.
  bool fit_start_pressures = true;
  /// Samples (each side) of the local straight-line fit that gives a segment's initial
  /// P1, P2, v from the noisy record.
  std::size_t start_half_window = 5;
  /// A segment whose smoothed starting speed is below this starts at rest (v = 0; the plant
  /// decides from the forces whether it is stuck or breaks away).
  double rest_speed_m_per_s = 1.0e-3;
  /// Piston position at the first sample when the record has no x column (x is then the
  /// integral of v from here).
  double x0_m = 0.0;
  /// Central-difference step in the scaled parameters (natural log of value / start value):
  /// 1e-3 changes a parameter by 0.1 %, far above the integrator's tolerance noise.
  double difference_step = 1.0e-3;
  /// Each free parameter may move at most this factor from its start value (bounds).
  double max_factor = 20.0;
  int max_iterations = 50;
  double function_tolerance = 1.0e-8;
  double parameter_tolerance = 1.0e-7;
  /// Integrator tolerances of the segment simulations.
  double relative_tolerance = 1.0e-8;
  double absolute_tolerance = 1.0e-10;
  bool verbose = false;  ///< print Ceres's per-iteration progress to stderr
  /// Throws Error naming the first field out of its range.
  void validate() const;
};

/// A scenario key as fitted (the friction fits have their own FittedParameter, named as the
/// friction keys are).
struct FittedKey {
  std::string key;     ///< scenario key, e.g. "circuit.S1_mm2"
  std::string unit;    ///< the key's unit, e.g. "mm^2"
  double start = 0.0;  ///< start value (key's unit)
  double value = 0.0;  ///< fitted value (key's unit)
  double standard_error = 0.0;  ///< key's unit, from the covariance
};

/// Measured and simulated signals on the record's time base (segment-wise simulation with
/// the fitted parameters; each segment restarts from the measured state).
struct ValidationSeries {
  std::vector<double> t_s;
  std::vector<double> v_meas, v_sim;    ///< m/s
  std::vector<double> p1_meas, p1_sim;  ///< Pa absolute
  std::vector<double> p2_meas, p2_sim;
  std::vector<std::size_t> segment_starts;  ///< sample index where each segment starts
};

struct FitResult {
  Scenario scenario;  ///< the start scenario with the fitted values set
  std::vector<FittedKey> parameters;
  std::size_t segments = 0;
  std::size_t residuals = 0;
  double initial_cost = 0.0;  ///< Ceres cost 1/2 sum r^2 (scaled residuals)
  double final_cost = 0.0;
  /// RMS errors of the fitted segment simulations against the record.
  double rms_P1_Pa = 0.0, rms_P2_Pa = 0.0, rms_v_m_per_s = 0.0;
  /// Reduced chi-square 2 cost / (residuals - parameters); the standard errors include it.
  double reduced_chi2 = 0.0;
  int iterations = 0;  ///< Ceres iterations, all stages
  /// The global stage: segment length of each candidate fit, its cost with the final
  /// segments (NaN when it failed), and which candidate started the final fit (-1: start).
  std::vector<double> candidate_segment_lengths_s, candidate_costs;
  int chosen_candidate = -1;
  double wall_time_s = 0.0;
  std::string summary;  ///< Ceres's BriefReport
  ValidationSeries validation;
};

/// The keys fitted when none are named: S1, S2 and the seal's Fc and Fs.
std::vector<std::string> default_free_keys(const Scenario& start);

inline constexpr ErrorField kFreeKeysField{"fit.free_keys", "free parameter"};

/// Throws Error about kFreeKeysField naming a key that is unknown, not a number, or cannot be
/// fitted (a number whose value is zero or which is not a positive physical quantity), or
/// repeated.
void check_free_keys(const Scenario& start, const std::vector<std::string>& free_keys);

/// Fits the free keys. Throws Error for bad input (record, keys, a start scenario the plant
/// rejects) and RunError when the fit does not converge or its covariance is rank-deficient
/// (the message holds Ceres's reason).
FitResult fit_model(const MeasuredRecord& record, const Scenario& start,
                    const std::vector<std::string>& free_keys, const FitOptions& options = {});

/// The segment-wise simulation of `scenario` against `record` (no fitting): what fit_model
/// reports as its validation series, for any scenario.
ValidationSeries segment_simulation(const MeasuredRecord& record, const Scenario& scenario,
                                    const FitOptions& options = {});

/// The --json document of `pneumachaos fit`: parameters.<key>.{value, stderr, unit, start},
/// rms, cost, method settings, the Ceres summary (docs/reference/outputs.md lists every field).
std::string fit_json(const FitResult& result, const FitOptions& options,
                     const MeasuredRecord& record);

/// The validation series as CSV: t[s], v_meas[m/s], v_sim[m/s], P1_meas[Pa], P1_sim[Pa],
/// P2_meas[Pa], P2_sim[Pa], segment[-] (the segment's index).
std::string validation_csv(const ValidationSeries& series);

/// gnuplot commands (no terminal) plotting `csv_file` (validation_csv) as three panels:
/// v, P1, P2, measured against simulated.
std::string validation_plot_commands(const std::string& csv_file);

}  // namespace pneumachaos::identify
