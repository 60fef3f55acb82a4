#include "pneumachaos/identify/friction_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::identify {
namespace {

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

// Point B of one excursion: where the accelerating branch (begin..peak) and the decelerating
// one (peak..end) cross in the F-v plane, compared on a grid of speeds over both branches.
std::optional<LoopMark> branch_crossing(const FrictionEstimate& e, const std::vector<double>& Fs,
                                        std::size_t begin, std::size_t peak, std::size_t end,
                                        int dir) {
  const double top = dir * e.v_smooth_m_per_s[peak];
  const double lo = e.stick_threshold_m_per_s;
  if (!(top > 2.0 * lo) || peak - begin < 4 || end - peak < 4) return std::nullopt;
  constexpr int kGrid = 24;
  const double half = 0.5 * (0.95 * top - lo) / kGrid;
  const auto branch_mean = [&](std::size_t from, std::size_t to, double u, std::size_t& nearest) {
    double s = 0.0, best = std::numeric_limits<double>::infinity();
    std::size_t c = 0;
    for (std::size_t i = from; i < to; ++i) {
      const double d = std::abs(dir * e.v_smooth_m_per_s[i] - u);
      if (d <= half) {
        s += Fs[i];
        ++c;
      }
      if (d < best) {
        best = d;
        nearest = i;
      }
    }
    return c ? s / double(c) : std::numeric_limits<double>::quiet_NaN();
  };
  double prev_diff = std::numeric_limits<double>::quiet_NaN(), prev_u = 0.0, prev_f = 0.0;
  for (int g = 0; g < kGrid; ++g) {
    const double u = lo + (2 * g + 1) * half;
    std::size_t ia = begin, id = peak;
    const double fa = branch_mean(begin, peak + 1, u, ia);
    const double fd = branch_mean(peak, end, u, id);
    if (std::isnan(fa) || std::isnan(fd)) continue;
    const double diff = fa - fd;
    if (!std::isnan(prev_diff) && sign_of(diff) != sign_of(prev_diff) && diff != 0.0) {
      const double w = prev_diff / (prev_diff - diff);
      LoopMark b;
      b.label = 'B';
      b.v_m_per_s = dir * (prev_u + w * (u - prev_u));
      b.F_N = prev_f + w * (0.5 * (fa + fd) - prev_f);
      b.index = ia;
      return b;
    }
    prev_diff = diff;
    prev_u = u;
    prev_f = 0.5 * (fa + fd);
  }
  return std::nullopt;
}

}  // namespace

EstimateSettings estimate_settings_from(const Scenario& s) {
  EstimateSettings e;
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

std::vector<double> savitzky_golay_derivative(const std::vector<double>& y, double dt,
                                              std::size_t h) {
  const std::size_t n = y.size();
  std::vector<double> d(n, 0.0);
  if (n < 2) return d;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t w = std::min({h, i, n - 1 - i});
    if (w == 0) {
      d[i] = i == 0 ? (y[1] - y[0]) / dt : (y[n - 1] - y[n - 2]) / dt;
      continue;
    }
    double s = 0.0;
    for (std::size_t k = 1; k <= w; ++k) s += double(k) * (y[i + k] - y[i - k]);
    const double wd = double(w);
    d[i] = 3.0 * s / (wd * (wd + 1.0) * (2.0 * wd + 1.0) * dt);
  }
  return d;
}

std::size_t choose_sg_half_width(double noise, double third, double dt) {
  std::size_t best = 2;
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t h = 2; h <= 100; ++h) {
    const double hd = double(h);
    const double var = noise * noise * 3.0 / (dt * dt * hd * (hd + 1.0) * (2.0 * hd + 1.0));
    const double bias = third * dt * dt * (3.0 * hd * hd + 3.0 * hd - 1.0) / 30.0;
    const double cost = var + bias * bias;
    if (cost < best_cost) {
      best_cost = cost;
      best = h;
    }
  }
  return best;
}

double noise_sd(const std::vector<double>& y) {
  if (y.size() < 3) return 0.0;
  std::vector<double> d2(y.size() - 2);
  for (std::size_t i = 1; i + 1 < y.size(); ++i) d2[i - 1] = y[i + 1] - 2.0 * y[i] + y[i - 1];
  const double m = median(d2);
  for (double& v : d2) v = std::abs(v - m);
  return 1.4826 * median(d2) / std::sqrt(6.0);
}

FrictionEstimate estimate_friction(const MeasuredRecord& r, const EstimateSettings& s) {
  check_measured_record(r, 20);
  if (!(s.area_head_m2 > 0.0) || !(s.area_rod_m2 > 0.0) || !(s.mass_kg > 0.0))
    throw Error(r.source, "the friction estimate needs positive areas A1, A2 and a moving mass");
  const std::size_t n = r.size();
  const double dt = r.dt_s();
  FrictionEstimate e;
  e.t_s = r.t_s;
  e.v_m_per_s = r.v_m_per_s;
  e.v_smooth_m_per_s = moving_mean(r.v_m_per_s, 2);
  e.velocity_noise_m_per_s = noise_sd(r.v_m_per_s);
  e.stick_threshold_m_per_s = s.stick_threshold_m_per_s.value_or(
      std::max(4.0 * e.velocity_noise_m_per_s, 0.5e-3));
  const double thr = e.stick_threshold_m_per_s;

  // Acceleration: given, or the Savitzky-Golay derivative with the noise/bias window.
  if (r.a_m_per_s2) {
    e.a_m_per_s2 = *r.a_m_per_s2;
    e.acceleration_given = true;
  } else {
    std::size_t h = 0;
    if (s.sg_half_width) {
      h = std::max<std::size_t>(1, *s.sg_half_width);
    } else {
      // y''' from a wide fixed window (three nested 25-sample-half-width derivatives), its
      // median magnitude over the moving samples as the typical value.
      const auto a_wide = savitzky_golay_derivative(r.v_m_per_s, dt, 25);
      const auto j_wide = savitzky_golay_derivative(a_wide, dt, 25);
      const auto v3 = savitzky_golay_derivative(j_wide, dt, 25);
      std::vector<double> mags;
      for (std::size_t i = 0; i < n; ++i)
        if (std::abs(e.v_smooth_m_per_s[i]) > thr) mags.push_back(std::abs(v3[i]));
      h = choose_sg_half_width(e.velocity_noise_m_per_s, median(mags), dt);
    }
    h = std::min(h, (n - 1) / 2);
    e.sg_half_width = h;
    e.a_m_per_s2 = savitzky_golay_derivative(r.v_m_per_s, dt, h);
  }

  e.F_N.resize(n);
  e.gauge_sum_Pa.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double g1 = r.p1_Pa[i] - s.ambient_Pa, g2 = r.p2_Pa[i] - s.ambient_Pa;
    e.gauge_sum_Pa[i] = g1 + g2;
    e.F_N[i] = s.area_head_m2 * g1 - s.area_rod_m2 * g2 - s.external_force_N -
               s.mass_kg * e.a_m_per_s2[i];
  }
  const auto F_smooth = moving_mean(e.F_N, 5);
  {
    std::vector<double> dev(n);
    for (std::size_t i = 0; i < n; ++i) dev[i] = std::abs(e.F_N[i] - F_smooth[i]);
    e.force_noise_N = 1.4826 * median(dev) * std::sqrt(11.0 / 10.0);
  }

  // Stick intervals: |v| (5-point mean) below the threshold for at least min_stick_s.
  e.stuck.assign(n, 0);
  e.sliding.assign(n, 0);
  const auto min_len = static_cast<std::size_t>(std::max(2.0, std::ceil(s.min_stick_s / dt)));
  for (std::size_t i = 0; i < n;) {
    if (std::abs(e.v_smooth_m_per_s[i]) >= thr) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && std::abs(e.v_smooth_m_per_s[j]) < thr) ++j;
    if (j - i >= min_len) {
      StickInterval st;
      st.begin = i;
      st.end = j;
      st.t_begin_s = r.t_s[i];
      st.t_end_s = r.t_s[j - 1];
      if (j < n) {
        st.direction = sign_of(e.v_smooth_m_per_s[j]);
        std::vector<double> last(e.F_N.begin() + static_cast<std::ptrdiff_t>(j - std::min<std::size_t>(5, j - i)),
                                 e.F_N.begin() + static_cast<std::ptrdiff_t>(j));
        st.breakaway_N = median(last);
      } else {
        st.breakaway_N = std::numeric_limits<double>::quiet_NaN();
      }
      e.sticks.push_back(st);
      for (std::size_t k = i; k < j; ++k) e.stuck[k] = 1;
    }
    i = j;
  }
  for (std::size_t i = 0; i < n; ++i)
    e.sliding[i] = !e.stuck[i] && std::abs(e.v_smooth_m_per_s[i]) > thr;

  // The binned steady curve, per direction, from the threshold to the largest speed.
  for (int dir : {-1, 1}) {
    double top = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (e.sliding[i] && dir * e.v_m_per_s[i] > 0) top = std::max(top, dir * e.v_m_per_s[i]);
    if (!(top > thr) || s.curve_bins == 0) continue;
    const double width = (top - thr) / double(s.curve_bins);
    std::vector<CurveBin> bins(s.curve_bins);
    std::vector<double> sum_v(s.curve_bins, 0.0), sum_f(s.curve_bins, 0.0), sum_f2(s.curve_bins, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double u = dir * e.v_m_per_s[i];
      if (!e.sliding[i] || u < thr) continue;
      const auto b = std::min(s.curve_bins - 1, static_cast<std::size_t>((u - thr) / width));
      ++bins[b].count;
      sum_v[b] += e.v_m_per_s[i];
      sum_f[b] += e.F_N[i];
      sum_f2[b] += e.F_N[i] * e.F_N[i];
    }
    std::vector<CurveBin> kept;
    for (std::size_t b = 0; b < s.curve_bins; ++b) {
      const double a = thr + double(b) * width, c = a + width;
      bins[b].v_lo_m_per_s = dir > 0 ? a : -c;
      bins[b].v_hi_m_per_s = dir > 0 ? c : -a;
      if (bins[b].count == 0) continue;
      const double m = double(bins[b].count);
      bins[b].v_mean_m_per_s = sum_v[b] / m;
      bins[b].F_mean_N = sum_f[b] / m;
      bins[b].F_sd_N = bins[b].count > 1
                           ? std::sqrt(std::max(0.0, (sum_f2[b] - sum_f[b] * sum_f[b] / m) / (m - 1.0)))
                           : 0.0;
      kept.push_back(bins[b]);
    }
    if (dir < 0) std::reverse(kept.begin(), kept.end());
    e.curve.insert(e.curve.end(), kept.begin(), kept.end());
  }

  // Excursions: the runs outside sticks, split at velocity reversals (a crossing of the
  // threshold in the opposite direction; the split at the last sample of the old sign).
  for (std::size_t i = 0; i < n;) {
    if (e.stuck[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && !e.stuck[j]) ++j;
    const bool from_stick = i > 0, to_stick = j < n;
    std::size_t begin = i;
    int dir = 0;
    bool begins_at_stick = from_stick;
    for (std::size_t k = i; k < j; ++k) {
      const double v = e.v_smooth_m_per_s[k];
      if (dir == 0) {
        if (std::abs(v) > thr) dir = sign_of(v);
        continue;
      }
      if (-dir * v > thr) {
        std::size_t split = k;
        while (split > begin && sign_of(e.v_smooth_m_per_s[split - 1]) != dir) --split;
        Excursion ex;
        ex.begin = begin;
        ex.end = split;
        ex.direction = dir;
        ex.from_stick = begins_at_stick;
        e.excursions.push_back(ex);
        begin = split;
        begins_at_stick = false;
        dir = -dir;
      }
    }
    if (dir != 0) {
      Excursion ex;
      ex.begin = begin;
      ex.end = j;
      ex.direction = dir;
      ex.from_stick = begins_at_stick;
      ex.to_stick = to_stick;
      e.excursions.push_back(ex);
    }
    i = j;
  }
  // The Fig. 3 marks.
  for (Excursion& ex : e.excursions) {
    if (ex.end - ex.begin < 3) continue;
    const int dir = ex.direction;
    std::size_t peak = ex.begin;
    for (std::size_t k = ex.begin; k < ex.end; ++k)
      if (dir * e.v_smooth_m_per_s[k] > dir * e.v_smooth_m_per_s[peak]) peak = k;
    if (ex.from_stick) {
      const auto st = std::find_if(e.sticks.begin(), e.sticks.end(),
                                   [&](const StickInterval& s2) { return s2.end == ex.begin; });
      ex.marks.push_back({'A', ex.begin, e.v_m_per_s[ex.begin],
                          st != e.sticks.end() ? st->breakaway_N : F_smooth[ex.begin]});
    }
    if (auto b = branch_crossing(e, F_smooth, ex.begin, peak, ex.end, dir)) ex.marks.push_back(*b);
    ex.marks.push_back({'C', peak, e.v_m_per_s[peak], F_smooth[peak]});
    if (ex.to_stick) ex.marks.push_back({'D', ex.end - 1, e.v_m_per_s[ex.end - 1], F_smooth[ex.end - 1]});
  }
  return e;
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
