// The rules of the chaotic example's indices, Fig. 2's transients, the damping trend and the
// friction slope (declared in claim_rules.hpp).
#include "pneumachaos/claims/claim_rules.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace pneumachaos {

RuleResult rule_result(double margin, std::string why) {
  return {margin, margin >= 0.0 ? std::string() : std::move(why)};
}

RuleResult both(const RuleResult& a, const RuleResult& b) {
  if (!a.evaluated()) return a;
  if (!b.evaluated()) return b;
  RuleResult r = a.margin <= b.margin ? a : b;
  if (r.passes()) r.why.clear();
  return r;
}

RuleResult acf_converged(double envelope) {
  return rule_result((kPaperAcfEnvelope - envelope) / kPaperAcfEnvelope,
                     fmt::format("the autocorrelation still reaches {:.2f} after {} s, above {}",
                                 envelope, kPaperAcfAfter_s, kPaperAcfEnvelope));
}

RuleResult spectrum_without_dominant_peak(double peak_share) {
  return rule_result((kPaperPeakShare - peak_share) / kPaperPeakShare,
                 fmt::format("one spectral line holds {:.0f} % of the power, more than a quarter",
                             100 * peak_share));
}

RuleResult positive_exponent(double lambda, double uncertainty) {
  const double scale = kPaperExponentSigmas * std::max(uncertainty, 1e-12);
  return rule_result((lambda - scale) / scale,
                 fmt::format("the exponent {:.2f} 1/s is not above 3 times its uncertainty "
                             "({:.2f} 1/s)",
                             lambda, uncertainty));
}

RuleResult judged_chaotic(bool chaotic, const std::string& regime) {
  return rule_result(chaotic ? 1.0 : -1.0,
                 "the record's verdict is " + regime + ", not chaotic");
}

Settling settling(const std::vector<double>& v, double rate_Hz) {
  Settling s;
  if (v.empty() || !(rate_Hz > 0.0)) return s;
  const auto n = v.size();
  const std::size_t tail = std::max<std::size_t>(n / 2, 1);
  double sum = 0.0;
  for (std::size_t k = n - tail; k < n; ++k) sum += v[k];
  s.final_value = sum / static_cast<double>(tail);
  std::size_t start = 0;
  while (start < n && v[start] == 0.0) ++start;  // at rest until the breakaway
  std::size_t last_out = start;
  for (std::size_t k = start; k < n; ++k)
    if (std::abs(v[k] - s.final_value) > 0.05 * std::abs(s.final_value)) last_out = k;
  s.start_s = static_cast<double>(start) / rate_Hz;
  // Out of the band within the second half: it has not settled in this record.
  s.settled = last_out + tail < n;
  s.settle_s = static_cast<double>(s.settled ? last_out : n) / rate_Hz;
  s.decay_rate_per_s = std::log(20.0) / std::max(s.settle_s - s.start_s, 1.0 / rate_Hz);
  return s;
}

RuleResult attenuates_faster(const std::vector<double>& fast, const std::vector<double>& slow) {
  if (fast.empty() || slow.empty()) return {kNaN, "no responses"};
  const double slowest_fast = *std::min_element(fast.begin(), fast.end());
  const double fastest_slow = *std::max_element(slow.begin(), slow.end());
  const double ratio = slowest_fast / fastest_slow;
  return rule_result(std::log2(ratio) - 1.0,
                 fmt::format("the slowest-settling meter-in response decays only {:.2f} times as "
                             "fast as the fastest meter-out one (twice needed)",
                             ratio));
}

RuleResult rises_with_area(const std::vector<double>& x) {
  if (x.size() < 2) return {kNaN, "fewer than two openings"};
  double m = INFINITY;
  for (std::size_t k = 1; k < x.size(); ++k) m = std::min(m, x[k] / x[k - 1] - 1.0);
  return rule_result(m, "the speed does not rise with every larger opening");
}

RuleResult damping_improves(const std::vector<DampingPair>& points) {
  if (points.empty()) return {kNaN, "no steady motion to linearise"};
  RuleResult r{INFINITY, ""};
  for (const DampingPair& p : points) {
    const double b1 = (p.b1_after - p.b1_before) / std::max(std::abs(p.b1_before), 1e-12);
    const double re =
        (p.max_re_before - p.max_re_after) / std::max(std::abs(p.max_re_before), 1e-12);
    r = both(r, rule_result(b1, fmt::format("b1 falls ({:.1f} -> {:.1f} N s/m)", p.b1_before,
                                        p.b1_after)));
    r = both(r, rule_result(re, fmt::format("the full model's largest real part rises ({:.2f} -> "
                                        "{:.2f} 1/s)",
                                        p.max_re_before, p.max_re_after)));
  }
  return r;
}

LineFit low_speed_line(const std::vector<double>& v, const std::vector<double>& F, double v_max) {
  double n = 0, sv = 0, sf = 0, svv = 0, svf = 0;
  for (std::size_t k = 0; k < v.size() && k < F.size(); ++k) {
    if (v[k] <= 0.0 || v[k] > v_max) continue;
    n += 1;
    sv += v[k];
    sf += F[k];
    svv += v[k] * v[k];
    svf += v[k] * F[k];
  }
  LineFit f;
  f.n = static_cast<std::size_t>(n);
  const double d = n * svv - sv * sv;
  if (n < 3 || d <= 0.0) return f;
  f.slope = (n * svf - sv * sf) / d;
  f.intercept = (sf - f.slope * sv) / n;
  return f;
}

RuleResult negative_low_speed_slope(const LineFit& line, double v_max) {
  if (std::isnan(line.slope)) return {kNaN, "too few samples at low speed"};
  const double drop = -line.slope * v_max / std::max(std::abs(line.intercept), 1e-12);
  return rule_result(drop, fmt::format("the friction rises with speed ({:.0f} N s/m)", line.slope));
}

}  // namespace pneumachaos
