#include "pneumachaos/report/claim_rules.hpp"

#include <algorithm>
#include <cmath>

namespace pneumachaos {

double acf_envelope_after(const std::vector<double>& r, double rate_Hz, double after_s) {
  double m = 0.0;
  for (auto k = static_cast<std::size_t>(after_s * rate_Hz); k < r.size(); ++k)
    m = std::max(m, std::abs(r[k]));
  return m;
}

bool acf_converged(double envelope_after_1s) { return envelope_after_1s <= 0.2; }

bool spectrum_without_dominant_peak(double peak_share) { return peak_share <= 0.25; }

bool positive_exponent_of_chaos(double lambda, double uncertainty, bool record_chaotic) {
  return record_chaotic && lambda > 0.0 && lambda > 3.0 * uncertainty;
}

ChaosLocation chaos_location(const std::vector<PointSummary>& pts, std::size_t n2) {
  const auto stick = [&](std::size_t i) { return pts[i].stick_slip_incidence >= 0.5; };
  // A point is near the border when a stick-slip/non-stick-slip change along S2 (same S1)
  // lies between two cells of which one is within one step of it.
  const auto near = [&](std::size_t i) {
    const std::size_t j = i % n2, row = i - j;
    for (std::size_t k = (j >= 2 ? j - 2 : 0); k + 1 < n2 && k <= j + 1; ++k) {
      if (stick(row + k) != stick(row + k + 1)) return true;
    }
    return false;
  };
  ChaosLocation c;
  double near_sum = 0.0;
  std::size_t chaotic = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (pts[i].chaos_incidence <= 0.0) continue;
    ++chaotic;
    c.total += pts[i].chaos_incidence;
    if (near(i)) near_sum += pts[i].chaos_incidence;
  }
  if (c.total > 0.0) c.near_border = near_sum / c.total;
  if (!pts.empty()) c.map_share = static_cast<double>(chaotic) / pts.size();
  return c;
}

bool chaos_near_border(const ChaosLocation& c) {
  return c.total > 0.0 && c.near_border >= 0.75 && c.map_share <= 0.25;
}

double relative_fluctuation(const std::vector<double>& x, std::size_t from) {
  if (from >= x.size()) return 0.0;
  double sum = 0.0, sq = 0.0;
  for (std::size_t k = from; k < x.size(); ++k) sum += x[k];
  const double n = static_cast<double>(x.size() - from), mean = sum / n;
  for (std::size_t k = from; k < x.size(); ++k) sq += (x[k] - mean) * (x[k] - mean);
  return mean == 0.0 ? INFINITY : std::sqrt(sq / n) / std::abs(mean);
}

bool fluctuates_much_more(const std::vector<double>& considerable,
                          const std::vector<double>& slight) {
  if (considerable.empty() || slight.empty()) return false;
  return *std::min_element(considerable.begin(), considerable.end()) >=
         3.0 * *std::max_element(slight.begin(), slight.end());
}

bool strictly_increasing(const std::vector<double>& x) {
  for (std::size_t k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1])) return false;
  return x.size() >= 2;
}

double low_speed_slope(const std::vector<double>& v, const std::vector<double>& F, double v_max) {
  double n = 0, sv = 0, sf = 0, svv = 0, svf = 0;
  for (std::size_t k = 0; k < v.size() && k < F.size(); ++k) {
    if (v[k] <= 0.0 || v[k] > v_max) continue;
    n += 1;
    sv += v[k];
    sf += F[k];
    svv += v[k] * v[k];
    svf += v[k] * F[k];
  }
  const double d = n * svv - sv * sv;
  return n < 3 || d <= 0.0 ? NAN : (n * svf - sv * sf) / d;
}

}  // namespace pneumachaos
