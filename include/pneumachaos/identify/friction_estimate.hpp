#pragma once
// Friction from a measured record (docs/friction.md): the force from the equation of motion,
// Savitzky-Golay acceleration, stick intervals, breakaway forces, the binned steady
// friction-velocity curve and the loops with the A, B, C, D marks of the paper's Fig. 3.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/identify/measured_record.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos::identify {

/// What the equation of motion needs: geometry, moving mass, ambient and external force.
struct EstimateSpec {
  double area_head_m2 = 0.0;   ///< A1
  double area_rod_m2 = 0.0;    ///< A2
  double mass_kg = 0.0;        ///< moving mass m
  double ambient_Pa = 101325.0;
  double external_force_N = 0.0;  ///< load.external_force_N, opposing extension
  /// Savitzky-Golay half-width (samples) for every sample; unset: chosen per sample from the
  /// noise and the local third derivative (docs/friction.md).
  std::optional<std::size_t> sg_half_width;
  /// |v| below this is "at rest" (m/s); unset: 4 x the velocity noise, at least 0.5 mm/s.
  std::optional<double> stick_threshold_m_per_s;
  double min_stick_s = 0.010;  ///< a stick lasts at least this long
  /// When given (one value per sample): F(t) itself, e.g. a simulation's own seal friction,
  /// instead of the equation of motion; sticks, curve and loops are then computed on it.
  std::optional<std::vector<double>> force_N;
  std::size_t curve_bins = 16;  ///< bins of the steady curve per direction of motion
  /// Throws Error naming the first field out of its range (core/validation.hpp): positive
  /// areas, mass and ambient pressure, a finite external force, a set stick threshold >= 0,
  /// min_stick_s >= 0 and curve_bins >= 1 (a half-width of 0 is taken as 1).
  void validate() const;
};

/// From a scenario: A1, A2 from cylinder.bore_mm/rod_mm, ambient.pressure_kPa,
/// load.external_force_N and the moving mass. Rigid coupling: load.mass_kg (piston, rod and
/// load as one). Spring coupling: load.piston_mass_kg + load.mass_kg, i.e. the load taken as
/// moving rigidly with the rod; the spring's dynamics are ignored (an approximation
/// documented in docs/friction.md; its error is m_load times the load's relative
/// acceleration).
EstimateSpec estimate_spec_from(const Scenario& scenario);

/// Sets sg_half_width from a Savitzky-Golay window of `window` samples (odd, >= 3); throws
/// Error(field), naming the option or argument, for any other.
void set_smoothing_window(EstimateSpec& settings, long long window, const std::string& field);

struct StickInterval {
  std::size_t begin = 0, end = 0;  ///< samples [begin, end)
  double t_begin_s = 0.0, t_end_s = 0.0;
  /// Net force at the stick's end (N), signed; NaN when the record ends in the stick.
  double breakaway_N = 0.0;
  int direction = 0;  ///< sign of the motion after the stick (0: the record ends stuck)
};

struct CurveBin {
  double v_lo_m_per_s = 0.0, v_hi_m_per_s = 0.0;
  double v_mean_m_per_s = 0.0;
  double F_mean_N = 0.0;
  double F_sd_N = 0.0;
  std::size_t count = 0;
};

/// A point of the paper's Fig. 3 loop A -> B -> C -> B -> D -> A (docs/friction.md):
/// A breakaway (end of the stick), C the largest speed, D the stop, B where the accelerating
/// (A -> C) and decelerating (C -> D) branches cross in the F-v plane.
struct LoopMark {
  char label = 'A';
  std::size_t index = 0;  ///< sample (for B: the accelerating branch's sample nearest the crossing)
  double v_m_per_s = 0.0;
  double F_N = 0.0;
};

/// One excursion: samples between two stick intervals or velocity reversals.
struct Excursion {
  std::size_t begin = 0, end = 0;  ///< samples [begin, end)
  int direction = 0;
  bool from_stick = false;  ///< begins at the end of a stick interval
  bool to_stick = false;    ///< ends at the start of one
  std::vector<LoopMark> marks;  ///< A, B, C, D as far as present
};

struct FrictionEstimate {
  std::vector<double> t_s, v_m_per_s, a_m_per_s2, F_N, gauge_sum_Pa;
  std::vector<double> drive_N;  ///< A1 (P1 - Pa) - A2 (P2 - Pa) - external force
  double mass_kg = 0.0;
  std::vector<double> v_smooth_m_per_s;  ///< 5-point centred mean, for stick and direction tests
  std::vector<char> stuck;    ///< 1 inside a stick interval
  std::vector<char> sliding;  ///< 1 outside sticks with |v| above the threshold: the fits' samples
  bool acceleration_given = false;
  std::size_t sg_half_width = 0;  ///< median half-width h (window = 2 h + 1 samples)
  std::size_t sg_half_width_min = 0, sg_half_width_max = 0;
  std::vector<std::size_t> sg_half_widths;  ///< per sample (empty when a is given)
  double velocity_noise_m_per_s = 0.0;
  double stick_threshold_m_per_s = 0.0;
  double force_noise_N = 0.0;  ///< sd of F(t) against its smoothed value
  std::vector<StickInterval> sticks;
  std::vector<CurveBin> curve;  ///< negative velocities first
  std::vector<Excursion> excursions;
  std::size_t sliding_count() const;
};

/// Savitzky-Golay first derivative (local quadratic, half-width h, step dt): the centred
/// weights c_k = 3 k / (h (h+1) (2h+1) dt); near the ends the window shrinks to fit.
std::vector<double> savitzky_golay_derivative(const std::vector<double>& y, double dt,
                                              std::size_t h);

/// The half-width that minimises noise variance + squared bias of the derivative:
/// var = sigma^2 3 / (dt^2 h (h+1) (2h+1)), bias = y''' dt^2 (3h^2 + 3h - 1) / 30, with sigma
/// the noise sd of y and y''' its typical third derivative (docs/friction.md). Within [2, 100].
std::size_t choose_sg_half_width(double noise_sd, double third_derivative, double dt);

/// Noise sd of a series from its second differences (robust: median absolute deviation),
/// which remove a smooth signal.
double noise_sd(const std::vector<double>& y);

/// Throws Error naming the record when the settings are unusable (no areas, no mass).
FrictionEstimate estimate_friction(const MeasuredRecord& record, const EstimateSpec& settings);

/// A simulated run (channels t, v, P1, P2, x as `simulate` writes them) through the same
/// estimate, for the report's Fig. 3: with `model_force` and an F_friction channel, F(t) is
/// the simulation's own seal friction (exact, whatever the coupling); otherwise the equation
/// of motion with the scenario's geometry and mass. Loops carry their A-D marks.
FrictionEstimate estimate_friction_of_run(const TimeSeries& run, const Scenario& scenario,
                                          bool model_force = true);

/// For a simulated trajectory (e.g. the report's Fig. 3): a MeasuredRecord from the columns
/// of a simulation (t, v, P1, P2, x), no noise added.
MeasuredRecord record_from_columns(std::vector<double> t_s, std::vector<double> v_m_per_s,
                                   std::vector<double> p1_Pa, std::vector<double> p2_Pa,
                                   std::vector<double> x_m, std::string source = "simulation");

}  // namespace pneumachaos::identify
