// The rules read from the maps (Figs. 4-6): where the chaos lies, how regions change, the
// "no chaos" tolerance and the paper's sign rule against the runs (claim_rules.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>

#include "pneumachaos/claims/claim_rules.hpp"

namespace pneumachaos {
namespace {

bool stick(const PointSummary& p) { return in_stick_slip_region(p); }

// Within one grid step of the stick-slip border: a 4-neighbour of another class.
bool near_border(const std::vector<PointSummary>& pts, std::size_t n1, std::size_t n2,
                 std::size_t i) {
  const std::size_t a = i / n2, b = i % n2;
  const auto differs = [&](std::size_t j) { return stick(pts[j]) != stick(pts[i]); };
  return (b > 0 && differs(i - 1)) || (b + 1 < n2 && differs(i + 1)) ||
         (a > 0 && differs(i - n2)) || (a + 1 < n1 && differs(i + n2));
}

// Mean incidence of the points in and out of a set, and the rule comparing them.
RuleResult compare_means(const std::vector<PointSummary>& pts, const std::vector<bool>& in_set,
                         const char* in_name, const char* out_name) {
  double sum_in = 0, sum_out = 0;
  std::size_t n_in = 0, n_out = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    (in_set[i] ? sum_in : sum_out) += pts[i].chaos_incidence;
    ++(in_set[i] ? n_in : n_out);
  }
  if (n_in == 0 || n_out == 0)
    return {kNaN, fmt::format("the grid has no point {}", n_in == 0 ? in_name : out_name)};
  const double a = sum_in / static_cast<double>(n_in), b = sum_out / static_cast<double>(n_out);
  if (a + b == 0.0) return {kNaN, "no chaotic run on the map"};
  return rule_result((a - b) / (a + b),
                 fmt::format("the mean chaos incidence {} ({:.3f}) is not above that {} "
                             "({:.3f})",
                             in_name, a, out_name, b));
}

bool grid_fits(const std::vector<PointSummary>& pts, const MapGrid& g) {
  return !g.s1.empty() && !g.s2.empty() && pts.size() == g.s1.size() * g.s2.size();
}

// Where the map's chaos lies along one axis against the middle of that axis' range.
double centre_margin(const std::vector<PointSummary>& pts, const MapGrid& g, bool first,
                     double& weighted_mean) {
  double w = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = first ? g.s1[i / g.s2.size()] : g.s2[i % g.s2.size()];
    w += pts[i].chaos_incidence;
    sum += pts[i].chaos_incidence * x;
  }
  const auto& axis = first ? g.s1 : g.s2;
  const auto [lo, hi] = std::minmax_element(axis.begin(), axis.end());
  weighted_mean = sum / w;
  const double half = (*hi - *lo) / 2.0;
  return half > 0.0 ? (*lo + half - weighted_mean) / half : kNaN;
}

}  // namespace

std::vector<std::size_t> stick_slip_border_points(const std::vector<PointSummary>& pts,
                                                  const MapGrid& g) {
  std::vector<std::size_t> out;
  if (!grid_fits(pts, g)) return out;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (near_border(pts, g.s1.size(), g.s2.size(), i)) out.push_back(i);
  return out;
}

std::vector<std::size_t> points_where(const SweepSummary& s, bool (*keep)(const PointSummary&)) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < s.per_point.size(); ++i)
    if (keep(s.per_point[i])) out.push_back(i);
  return out;
}

RuleResult chaos_highest_near_border(const std::vector<PointSummary>& pts, const MapGrid& g) {
  if (!grid_fits(pts, g)) return {kNaN, "no map"};
  std::vector<bool> near(pts.size());
  for (std::size_t i : stick_slip_border_points(pts, g)) near[i] = true;
  return compare_means(pts, near, "near the stick-slip border", "elsewhere");
}

RuleResult chaos_highest_where_s1_above_s2(const std::vector<PointSummary>& pts,
                                           const MapGrid& g) {
  if (!grid_fits(pts, g)) return {kNaN, "no map"};
  std::vector<bool> above(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    above[i] = g.s1[i / g.s2.size()] > g.s2[i % g.s2.size()];
  return compare_means(pts, above, "where S1 > S2", "where S1 <= S2");
}

RuleResult chaos_where_s1_and_s2_small(const std::vector<PointSummary>& pts, const MapGrid& g) {
  if (!grid_fits(pts, g)) return {kNaN, "no map"};
  const auto ever = std::count_if(pts.begin(), pts.end(),
                                  [](const PointSummary& p) { return p.chaos_incidence > 0.0; });
  if (ever == 0) return {kNaN, "no chaotic run on the map"};
  double m1 = 0.0, m2 = 0.0;
  const double c1 = centre_margin(pts, g, true, m1), c2 = centre_margin(pts, g, false, m2);
  const RuleResult s1 = rule_result(
      c1, fmt::format("the chaos is centred at S1 = {:.2f} mm^2, not in the lower half of S1", m1));
  const RuleResult s2 = rule_result(
      c2, fmt::format("the chaos is centred at S2 = {:.2f} mm^2, not in the lower half of S2", m2));
  const double share = static_cast<double>(ever) / static_cast<double>(pts.size());
  const RuleResult limited =
      rule_result((0.5 - share) / 0.5,
              fmt::format("{:.0f} % of the points are chaotic at least once: not a limited "
                          "region",
                          100 * share));
  return both(both(s1, s2), limited);
}

std::size_t min_region_for_change(double f) {
  return static_cast<std::size_t>(std::ceil(4.0 * (2.0 - f) / (f * f)));
}

RuleResult region_shrinks(std::size_t before, std::size_t after) {
  if (before == 0) return {kNaN, "the region is empty before the change"};
  const double b = static_cast<double>(before), a = static_cast<double>(after);
  return rule_result((b - 1.0 - a) / b, fmt::format("the region does not shrink ({} -> {} points)",
                                                before, after));
}

RuleResult region_grows(std::size_t before, std::size_t after) {
  const double b = static_cast<double>(before), a = static_cast<double>(after);
  return rule_result((a - b - 1.0) / std::max(b, 1.0),
                 fmt::format("the region does not grow ({} -> {} points)", before, after));
}

RuleResult region_more_than_halved(std::size_t before, std::size_t after) {
  const std::size_t need = min_region_for_change(0.5);
  if (before < need)
    return {kNaN, fmt::format("the region has {} points before the change; halving it is "
                              "counting noise below {}",
                              before, need)};
  const double b = static_cast<double>(before), a = static_cast<double>(after);
  return rule_result((b - 1.0 - 2.0 * a) / b,
                 fmt::format("it keeps {} of {} points, not fewer than half", after, before));
}

RuleResult a_few_points(std::size_t n, std::size_t points) {
  const double most = std::max(3.0, std::floor(0.013 * static_cast<double>(points)));
  const double x = static_cast<double>(n);
  return rule_result(std::min(x - 1.0, most - x) / most,
                 n == 0 ? std::string("no point is chaotic in every run")
                        : fmt::format("{} points are chaotic in every run, more than a few "
                                      "(at most {:.0f})",
                                      n, most));
}

std::size_t false_positive_allowance(std::size_t judged, double rate) {
  if (judged == 0) return 0;
  const boost::math::binomial_distribution<double> d(static_cast<double>(judged), rate);
  return static_cast<std::size_t>(boost::math::quantile(d, 0.95));
}

RuleResult no_chaos_beyond_false_positives(std::size_t chaotic, std::size_t judged) {
  const double allow = static_cast<double>(false_positive_allowance(judged));
  const double c = static_cast<double>(chaotic);
  return rule_result((allow - c) / std::max(allow, 1.0),
                     fmt::format("{} runs are chaotic, more than the verdict's false-positive "
                                 "rate ({:.1f} % of {} judged runs) gives (at most {:.0f})",
                                 chaotic, 100 * kVerdictFalsePositiveRate, judged, allow));
}

namespace {

// The runs a point stands for on the map: its successful runs, or for a point an adaptive map
// inferred from its cell, as many as an evaluated point has (the map's repeats), so that counts
// over the map mean the same with and without refinement.
std::vector<double> runs_standing_for(const SweepSummary& s) {
  std::size_t repeats = 0;
  for (const PointSummary& p : s.per_point) repeats = std::max(repeats, p.runs);
  std::vector<double> w;
  for (const PointSummary& p : s.per_point)
    w.push_back(static_cast<double>(p.inferred ? repeats : p.runs - p.failed));
  return w;
}

}  // namespace

std::size_t chaotic_runs(const SweepSummary& s) {
  const std::vector<double> w = runs_standing_for(s);
  double n = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) n += s.per_point[i].chaos_incidence * w[i];
  return static_cast<std::size_t>(std::lround(n));
}

std::size_t judged_runs(const SweepSummary& s) {
  const std::vector<double> w = runs_standing_for(s);
  double n = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const PointSummary& p = s.per_point[i];
    if (p.regime_incidence.empty()) continue;
    n += (1.0 - p.regime_incidence.front() - p.regime_incidence.back()) * w[i];
  }
  return static_cast<std::size_t>(std::lround(n));
}

bool chaos_beyond_false_positives(const SweepSummary& s) {
  return chaotic_runs(s) > false_positive_allowance(judged_runs(s));
}

std::size_t oscillating_points(const SweepSummary& s) {
  return static_cast<std::size_t>(
      std::count_if(s.per_point.begin(), s.per_point.end(), [](const PointSummary& p) {
        return p.on_lattice && point_motion(p) == Motion::kOscillating;
      }));
}

std::size_t lattice_points(const SweepSummary& s) {
  return static_cast<std::size_t>(std::count_if(
      s.per_point.begin(), s.per_point.end(), [](const PointSummary& p) { return p.on_lattice; }));
}

RuleResult sign_rule_holds(const SignRuleCounts& s) {
  // Both halves of the rule must be tested: a class with no decided point leaves it open.
  if (s.damped == 0 || s.excited == 0)
    return {kNaN, fmt::format("no decided point the rule calls {} ({} points undecided: records "
                              "too short or too irregular to judge)",
                              s.damped == 0 ? "damped" : "self-excited", s.undecided)};
  const auto share = [](std::size_t k, std::size_t n) {
    return (static_cast<double>(k) / static_cast<double>(n) - 0.8) / 0.8;
  };
  return both(rule_result(share(s.damped_steady, s.damped),
                      fmt::format("only {} of {} decided points called damped are steady",
                                  s.damped_steady, s.damped)),
              rule_result(share(s.excited_moving, s.excited),
                      fmt::format("only {} of {} decided points called self-excited oscillate",
                                  s.excited_moving, s.excited)));
}

SignRuleCounts count_sign_rule(const std::vector<std::optional<bool>>& damped,
                               const SweepSummary& sweep) {
  SignRuleCounts c;
  for (std::size_t i = 0; i < damped.size() && i < sweep.per_point.size(); ++i) {
    if (!damped[i] || !sweep.per_point[i].on_lattice) continue;
    const Motion m = point_motion(sweep.per_point[i]);
    if (m == Motion::kUndecided) {
      ++c.undecided;
    } else if (*damped[i]) {
      ++c.damped;
      c.damped_steady += m == Motion::kSteady ? 1 : 0;
    } else {
      ++c.excited;
      c.excited_moving += m == Motion::kSteady ? 0 : 1;
    }
  }
  return c;
}

}  // namespace pneumachaos
