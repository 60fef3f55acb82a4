#include "pneumachaos/identify/friction_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "friction_steps.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos::identify {

namespace detail {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::vector<double> moving_mean(const std::vector<double>& y, std::size_t h) {
  const std::size_t n = y.size();
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t w = std::min({h, i, n - 1 - i});
    double s = 0.0;
    for (std::size_t j = i - w; j <= i + w; ++j) s += y[j];
    out[i] = s / double(2 * w + 1);
  }
  return out;
}

int sign_of(double v) { return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0); }

}  // namespace detail

namespace {

using detail::median;
using detail::moving_mean;
using detail::sign_of;

using Rest = std::pair<std::size_t, std::size_t>;

// Stick intervals: |v| (5-point mean) below the threshold for at least min_stick_s; marks
// e.stuck and returns the intervals [begin, end).
std::vector<Rest> find_rests(FrictionEstimate& e, double min_stick_s, double dt) {
  const std::size_t n = e.v_m_per_s.size();
  const double thr = e.stick_threshold_m_per_s;
  e.stuck.assign(n, 0);
  const auto min_len = static_cast<std::size_t>(std::max(2.0, std::ceil(min_stick_s / dt)));
  std::vector<Rest> rests;
  for (std::size_t i = 0; i < n;) {
    if (std::abs(e.v_smooth_m_per_s[i]) >= thr) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && std::abs(e.v_smooth_m_per_s[j]) < thr) ++j;
    if (j - i >= min_len) {
      // The smoothed velocity leaves the band a sample or two before the raw one does: the
      // stick extends over the raw samples still at rest, so that the breakaway and the stop
      // (kinks of v) fall between a stuck and a moving sample.
      std::size_t b = i, end = j;
      while (end < n && std::abs(e.v_m_per_s[end]) < thr) ++end;
      const std::size_t floor = rests.empty() ? 0 : rests.back().second;
      while (b > floor && std::abs(e.v_m_per_s[b - 1]) < thr) --b;
      rests.emplace_back(b, end);
      for (std::size_t k = b; k < end; ++k) e.stuck[k] = 1;
      j = std::max(j, end);
    }
    i = j;
  }
  return rests;
}

// F = A1 (P1 - Pa) - A2 (P2 - Pa) - F_ext - m a, or the force given in the settings.
void compute_forces(const MeasuredRecord& r, const EstimateSpec& s, FrictionEstimate& e) {
  const std::size_t n = r.size();
  e.F_N.resize(n);
  e.drive_N.resize(n);
  e.gauge_sum_Pa.resize(n);
  e.mass_kg = s.mass_kg;
  for (std::size_t i = 0; i < n; ++i) {
    const double g1 = r.p1_Pa[i] - s.ambient_Pa, g2 = r.p2_Pa[i] - s.ambient_Pa;
    e.gauge_sum_Pa[i] = g1 + g2;
    e.drive_N[i] = s.area_head_m2 * g1 - s.area_rod_m2 * g2 - s.external_force_N;
    e.F_N[i] = e.drive_N[i] - s.mass_kg * e.a_m_per_s2[i];
  }
  if (s.force_N) {
    if (s.force_N->size() != n)
      throw Error(r.source, fmt::format("the given force has {} samples, the record {}",
                                        s.force_N->size(), n));
    e.F_N = *s.force_N;
  }
}

// The breakaway force of the stick [i, j): at the last sample of the stick whose velocity is
// still within the velocity noise (a slow Stribeck breakaway creeps through the stick band for
// a few samples while the drive keeps rising), from a line through the 10 samples up to it
// (the force is rising; a line averages the noise without lag).
double breakaway_force(const FrictionEstimate& e, std::size_t i, std::size_t j, int direction) {
  const double dir = double(direction);
  std::size_t last = j - 1;
  while (last > i && dir * e.v_m_per_s[last] > 2.0 * e.velocity_noise_m_per_s) --last;
  const std::size_t m = std::min<std::size_t>(10, last + 1 - i);
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t k = last + 1 - m; k <= last; ++k) {
    const double x = double(k) - double(last);
    sx += x;
    sy += e.F_N[k];
    sxx += x * x;
    sxy += x * e.F_N[k];
  }
  const double md = double(m), den = md * sxx - sx * sx;
  const double slope = den > 0.0 ? (md * sxy - sx * sy) / den : 0.0;
  return (sy - slope * sx) / md;  // the line's value at x = 0 (sample `last`)
}

void add_sticks(const MeasuredRecord& r, const std::vector<Rest>& rests, FrictionEstimate& e) {
  const std::size_t n = r.size();
  for (const auto& [i, j] : rests) {
    StickInterval st;
    st.begin = i;
    st.end = j;
    st.t_begin_s = r.t_s[i];
    st.t_end_s = r.t_s[j - 1];
    st.breakaway_N = std::numeric_limits<double>::quiet_NaN();
    if (j < n) {
      st.direction = sign_of(e.v_smooth_m_per_s[j]);
      st.breakaway_N = breakaway_force(e, i, j, st.direction);
    }
    e.sticks.push_back(st);
  }
}

// The samples the curve and the fits use: outside sticks, |v| above the threshold both raw
// and smoothed, and not just before a stop. A stop is abrupt (the velocity drops to rest
// within a sample or two): the differentiator's window straddling it smears an impulsive
// deceleration over its width, so the samples within a half-width (+2) before a stick go.
void mark_sliding(FrictionEstimate& e) {
  const std::size_t n = e.v_m_per_s.size();
  const double thr = e.stick_threshold_m_per_s;
  e.sliding.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    e.sliding[i] = !e.stuck[i] && std::abs(e.v_smooth_m_per_s[i]) > thr &&
                   e.v_m_per_s[i] * sign_of(e.v_smooth_m_per_s[i]) > thr;
  for (const StickInterval& st : e.sticks) {
    const std::size_t guard =
        (e.acceleration_given || st.begin == 0 ? 0 : e.sg_half_widths[st.begin - 1]) + 2;
    for (std::size_t k = st.begin > guard ? st.begin - guard : 0; k < st.begin; ++k) e.sliding[k] = 0;
  }
}

// Robust sd of F(t) about its 11-point mean (MAD, corrected for the mean's own share).
double force_noise(const std::vector<double>& F, const std::vector<double>& F_smooth) {
  std::vector<double> dev(F.size());
  for (std::size_t i = 0; i < F.size(); ++i) dev[i] = std::abs(F[i] - F_smooth[i]);
  return 1.4826 * median(dev) * std::sqrt(11.0 / 10.0);
}

}  // namespace

void set_smoothing_window(EstimateSpec& settings, long long window, const std::string& field) {
  if (window < 3 || window % 2 == 0)
    throw Error(field, fmt::format("expected an odd number of samples >= 3, got {}", window));
  settings.sg_half_width = static_cast<std::size_t>(window / 2);
}

void EstimateSpec::validate() const {
  using namespace validation;
  require_finite_gt(field("estimate.area_head_m2"), area_head_m2, 0, "A1");
  require_finite_gt(field("estimate.area_rod_m2"), area_rod_m2, 0, "A2");
  require_finite_gt(field("estimate.mass_kg"), mass_kg, 0, "the moving mass");
  require_finite_gt(field("estimate.ambient_Pa"), ambient_Pa, 0, "Pa abs");
  require_finite(field("estimate.external_force_N"), external_force_N);
  if (stick_threshold_m_per_s) {
    require_finite_ge(field("estimate.stick_threshold_m_per_s"), *stick_threshold_m_per_s, 0,
                      "when set");
  }
  require_finite_ge(field("estimate.min_stick_s"), min_stick_s, 0);
  require_ge(field("estimate.curve_bins"), static_cast<double>(curve_bins), 1);
}

EstimateSpec estimate_spec_from(const Scenario& s) {
  EstimateSpec e;
  e.area_head_m2 = s.cylinder.area_head_m2();
  e.area_rod_m2 = s.cylinder.area_rod_m2();
  e.mass_kg = s.load.coupling == LoadCoupling::kRigid ? s.load.mass_kg
                                                       : s.load.piston_mass_kg + s.load.mass_kg;
  e.ambient_Pa = s.ambient_pressure_Pa;
  e.external_force_N = s.load.external_force_N;
  return e;
}

std::size_t FrictionEstimate::sliding_count() const {
  return static_cast<std::size_t>(std::count(sliding.begin(), sliding.end(), 1));
}

FrictionEstimate estimate_friction(const MeasuredRecord& r, const EstimateSpec& s) {
  check_measured_record(r, 20);
  s.validate();
  FrictionEstimate e;
  e.t_s = r.t_s;
  e.v_m_per_s = r.v_m_per_s;
  e.v_smooth_m_per_s = moving_mean(r.v_m_per_s, 2);
  e.velocity_noise_m_per_s = noise_sd(r.v_m_per_s);
  e.stick_threshold_m_per_s = s.stick_threshold_m_per_s.value_or(
      std::max(4.0 * e.velocity_noise_m_per_s, 0.5e-3));
  const std::vector<Rest> rests = find_rests(e, s.min_stick_s, r.dt_s());
  detail::estimate_acceleration(r, s, e);
  compute_forces(r, s, e);
  const auto F_smooth = moving_mean(e.F_N, 5);
  e.force_noise_N = force_noise(e.F_N, F_smooth);
  add_sticks(r, rests, e);
  mark_sliding(e);
  detail::add_steady_curve(e, s.curve_bins);
  detail::add_excursions(e);
  detail::add_loop_marks(e, F_smooth);
  return e;
}

FrictionEstimate estimate_friction_of_run(const TimeSeries& run, const Scenario& scenario,
                                          bool model_force) {
  std::vector<double> t(run.size());
  for (std::size_t k = 0; k < run.size(); ++k) t[k] = run.time_s(k);
  const MeasuredRecord r = record_from_columns(
      std::move(t), run.channel("v").values, run.channel("P1").values, run.channel("P2").values,
      run.has_channel("x") ? run.channel("x").values : std::vector<double>{}, "simulation");
  EstimateSpec s = estimate_spec_from(scenario);
  if (model_force && run.has_channel("F_friction")) s.force_N = run.channel("F_friction").values;
  return estimate_friction(r, s);
}

MeasuredRecord record_from_columns(std::vector<double> t_s, std::vector<double> v_m_per_s,
                                   std::vector<double> p1_Pa, std::vector<double> p2_Pa,
                                   std::vector<double> x_m, std::string source) {
  MeasuredRecord r;
  r.t_s = std::move(t_s);
  r.v_m_per_s = std::move(v_m_per_s);
  r.p1_Pa = std::move(p1_Pa);
  r.p2_Pa = std::move(p2_Pa);
  if (!x_m.empty()) r.x_m = std::move(x_m);
  r.source = std::move(source);
  return r;
}

}  // namespace pneumachaos::identify
