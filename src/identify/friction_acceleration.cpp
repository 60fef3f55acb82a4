// The acceleration of a measured record for the friction estimate: a Savitzky-Golay
// differentiator whose window is chosen per sample from the noise and the local third
// derivative (docs/friction.md), kept on its side of every stick boundary.
#include <algorithm>
#include <cmath>
#include <limits>

#include "friction_steps.hpp"

namespace pneumachaos::identify {
namespace {

using detail::median;

// Slope at sample i of the least-squares quadratic through samples lo..hi (one-sided
// Savitzky-Golay near a stick boundary); a line for three points or fewer, 0 for one.
double local_quadratic_slope(const std::vector<double>& y, std::size_t lo, std::size_t hi,
                             std::size_t i, double dt) {
  const std::size_t m = hi - lo + 1;
  if (m < 2) return 0.0;
  double S[5] = {0, 0, 0, 0, 0}, T[3] = {0, 0, 0};
  for (std::size_t k = lo; k <= hi; ++k) {
    const double x = double(k) - double(i);
    double p = 1.0;
    for (int q = 0; q < 5; ++q) {
      if (q < 3) T[q] += p * y[k];
      S[q] += p;
      p *= x;
    }
  }
  if (m <= 3) {  // a line
    const double den = S[0] * S[2] - S[1] * S[1];
    return den != 0.0 ? (S[0] * T[1] - S[1] * T[0]) / den / dt : 0.0;
  }
  // Normal equations [S0 S1 S2; S1 S2 S3; S2 S3 S4] c = T; the slope is c1 (Cramer).
  const auto det3 = [](double a, double b, double c, double d, double e, double f, double g,
                       double h, double k) {
    return a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
  };
  const double D = det3(S[0], S[1], S[2], S[1], S[2], S[3], S[2], S[3], S[4]);
  if (D == 0.0) return 0.0;
  const double D1 = det3(S[0], T[0], S[2], S[1], T[1], S[3], S[2], T[2], S[4]);
  return D1 / D / dt;
}

// The window half-width of every sample (docs/friction.md): the third derivative from a wide
// fixed window (three nested derivatives of half-width 25), its largest magnitude within 50
// samples either side as the local bias scale, so that transients (breakaways, stops) get a
// short window and smooth sliding a long one.
std::vector<std::size_t> chosen_half_widths(const std::vector<double>& v, double dt, double noise,
                                            std::size_t h_max) {
  const std::size_t n = v.size();
  const auto a_wide = savitzky_golay_derivative(v, dt, 25);
  const auto j_wide = savitzky_golay_derivative(a_wide, dt, 25);
  const auto v3 = savitzky_golay_derivative(j_wide, dt, 25);
  constexpr std::size_t kReach = 50;
  // Sliding maximum of |v'''| over +-kReach (monotone queue).
  std::vector<std::size_t> dq, widths(n);
  std::size_t head = 0;
  for (std::size_t i = 0, next = 0; i < n; ++i) {
    for (; next < n && next <= i + kReach; ++next) {
      while (dq.size() > head && std::abs(v3[dq.back()]) <= std::abs(v3[next])) dq.pop_back();
      dq.push_back(next);
    }
    while (dq[head] + kReach < i) ++head;
    widths[i] = std::min(h_max, choose_sg_half_width(noise, std::abs(v3[dq[head]]), dt));
  }
  return widths;
}

// Each sample's window stays on its side of a stick boundary: the acceleration jumps at a
// breakaway and at a stop, and a window across the jump would smear it (one-sided local
// quadratic fits there). Inside a stick the piston is at rest: a = 0.
std::vector<double> windowed_derivative(const std::vector<double>& v, const std::vector<char>& stuck,
                                        const std::vector<std::size_t>& widths, double dt) {
  const std::size_t n = v.size();
  std::vector<double> a(n, 0.0);
  std::size_t run_begin = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (stuck[i]) {
      run_begin = i + 1;
      continue;
    }
    std::size_t run_end = i;  // last sample of this moving run
    while (run_end + 1 < n && !stuck[run_end + 1]) ++run_end;
    const std::size_t h = widths[i];
    const std::size_t lo = std::max(run_begin, i >= h ? i - h : 0);
    const std::size_t hi = std::min(run_end, i + h);
    if (lo + h == i && i + h == hi) {
      double acc = 0.0;
      for (std::size_t k = 1; k <= h; ++k) acc += double(k) * (v[i + k] - v[i - k]);
      const double wd = double(h);
      a[i] = 3.0 * acc / (wd * (wd + 1.0) * (2.0 * wd + 1.0) * dt);
    } else {
      a[i] = local_quadratic_slope(v, lo, hi, i, dt);
    }
  }
  return a;
}

}  // namespace

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

namespace detail {

void estimate_acceleration(const MeasuredRecord& r, const EstimateSpec& s,
                           FrictionEstimate& e) {
  if (r.a_m_per_s2) {
    e.a_m_per_s2 = *r.a_m_per_s2;
    e.acceleration_given = true;
    return;
  }
  const std::size_t n = r.size();
  const std::size_t h_max = std::max<std::size_t>(1, std::min<std::size_t>(100, (n - 1) / 2));
  std::vector<std::size_t> widths =
      s.sg_half_width
          ? std::vector<std::size_t>(n, std::min(h_max, std::max<std::size_t>(1, *s.sg_half_width)))
          : chosen_half_widths(r.v_m_per_s, r.dt_s(), e.velocity_noise_m_per_s, h_max);
  e.a_m_per_s2 = windowed_derivative(r.v_m_per_s, e.stuck, widths, r.dt_s());
  std::vector<double> wd(widths.begin(), widths.end());
  e.sg_half_width = static_cast<std::size_t>(median(wd));
  e.sg_half_width_min = *std::min_element(widths.begin(), widths.end());
  e.sg_half_width_max = *std::max_element(widths.begin(), widths.end());
  e.sg_half_widths = std::move(widths);
}

}  // namespace detail
}  // namespace pneumachaos::identify
