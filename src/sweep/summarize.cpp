#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/core/error.hpp"
#include "grid_refinement.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

const std::vector<std::string>& sweep_regime_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (Regime r : {Regime::kSteady, Regime::kPeriodic, Regime::kQuasiPeriodic, Regime::kStickSlip,
                     Regime::kChaotic, Regime::kStochastic, Regime::kUndetermined}) {
      n.emplace_back(regime_name(r));
    }
    return n;
  }();
  return names;
}

namespace {

// Exponent beyond 3 standard errors: the model's own evidence of chaos over the run.
bool model_chaotic(const RunRecord& r) {
  return std::isfinite(r.lambda_model) && std::isfinite(r.lambda_model_uncertainty) &&
         r.lambda_model > 3.0 * r.lambda_model_uncertainty;
}

// Mean, its standard error and the 3-sigma incidence of the model's exponent at one point.
void summarize_model_exponent(const std::vector<const RunRecord*>& runs, PointSummary& ps) {
  double sum = 0.0, var = 0.0, chaotic = 0.0;
  std::size_t n = 0, ok = 0;
  for (const RunRecord* r : runs) {
    if (!r->ok) continue;
    ++ok;
    chaotic += model_chaotic(*r) ? 1.0 : 0.0;
    if (!std::isfinite(r->lambda_model)) continue;
    sum += r->lambda_model;
    var += r->lambda_model_uncertainty * r->lambda_model_uncertainty;
    ++n;
  }
  if (ok > 0) ps.model_chaos_incidence = chaotic / static_cast<double>(ok);
  if (n == 0) return;
  ps.mean_lambda_model = sum / static_cast<double>(n);
  ps.lambda_model_uncertainty = std::sqrt(var) / static_cast<double>(n);
}

// A point the map judges: one with a successful run, or one inferred from such a point.
bool judged(const PointSummary& p) { return p.runs > p.failed || p.inferred; }

// The chaos regions as the verdict draws them: points chaotic in every / in some run.
void count_chaos(const std::vector<PointSummary>& points, std::size_t& full, std::size_t& any) {
  full = any = 0;
  for (const PointSummary& ps : points) {
    if (chaos_class(ps) == ChaosClass::kAll) ++full;
    if (chaos_class(ps) != ChaosClass::kNone) ++any;
  }
}

// The paper's judge in the verdict's place at every point (NaN: the sweep did not run it).
std::vector<PointSummary> paper_judged(std::vector<PointSummary> points) {
  for (PointSummary& ps : points)
    ps.chaos_incidence = std::isfinite(ps.paper_chaos_incidence) ? ps.paper_chaos_incidence : 0.0;
  return points;
}

bool judged_by_paper(const SweepSummary& s) {
  return std::any_of(s.per_point.begin(), s.per_point.end(),
                     [](const PointSummary& p) { return std::isfinite(p.paper_chaos_incidence); });
}

void count_regions(const SweepSpec& spec, SweepSummary& s) {
  s.stick_slip_points = 0;
  s.model_chaos_full_points = s.model_chaos_any_points = 0;
  count_chaos(s.per_point, s.chaos_full_points, s.chaos_any_points);
  s.paper_chaos_full_points = s.paper_chaos_any_points = 0;
  if (spec.paper_judge)
    count_chaos(paper_judged(s.per_point), s.paper_chaos_full_points, s.paper_chaos_any_points);
  for (const PointSummary& ps : s.per_point) {
    if (in_stick_slip_region(ps)) ++s.stick_slip_points;
    if (!spec.model_exponent.enabled) continue;
    if (ps.model_chaos_incidence >= 1.0) ++s.model_chaos_full_points;
    if (ps.model_chaos_incidence > 0.0) ++s.model_chaos_any_points;
  }
}

// The points an adaptive map of this grid runs first (every point of a grid it cannot refine).
std::vector<char> lattice_of(const SweepSpec& spec) {
  if (spec.axes.size() != 2) return std::vector<char>(spec.points(), 1);
  return coarse_lattice(spec.axes[0].values.size(), spec.axes[1].values.size(),
                        std::max<std::size_t>(spec.adaptive.coarse_step, 1));
}

}  // namespace

bool in_stick_slip_region(const PointSummary& p) {
  return judged(p) && p.stick_slip_incidence >= 0.5;
}

Motion point_motion(const PointSummary& p) {
  // regime_incidence follows sweep_regime_names(): steady first, undetermined last.
  if (!judged(p) || p.regime_incidence.empty()) return Motion::kUndecided;
  const double steady = p.regime_incidence.front();
  const double determined = 1.0 - p.regime_incidence.back();
  if (determined < 0.5) return Motion::kUndecided;
  return steady > 0.5 * determined ? Motion::kSteady : Motion::kOscillating;
}

ChaosClass chaos_class(const PointSummary& p) {
  if (!judged(p) || p.chaos_incidence <= 0.0) return ChaosClass::kNone;
  return p.chaos_incidence >= 1.0 ? ChaosClass::kAll : ChaosClass::kSome;
}

SweepSummary summarize(const SweepSpec& spec, const std::vector<RunRecord>& records) {
  SweepSummary s;
  s.points = spec.points();
  s.runs = records.size();
  s.per_point.resize(s.points);
  std::vector<std::size_t> lambda_count(s.points, 0);
  std::vector<double> paper_chaotic(s.points, 0.0);
  std::vector<std::vector<const RunRecord*>> by_point(s.points);
  for (const RunRecord& r : records) by_point.at(r.point).push_back(&r);
  const std::vector<char> lattice = lattice_of(spec);
  for (std::size_t p = 0; p < s.points; ++p) {
    PointSummary& ps = s.per_point[p];
    ps.point = p;
    ps.on_lattice = lattice[p] != 0;
    const auto index = grid_index(spec.axes, p);
    for (std::size_t a = 0; a < spec.axes.size(); ++a)
      ps.coordinates.push_back(spec.axes[a].values[index[a]]);
    ps.mean_v = 0.0;
    ps.mean_lambda = 0.0;
    ps.regime_incidence.assign(sweep_regime_names().size(), 0.0);
  }
  for (const RunRecord& r : records) {
    PointSummary& ps = s.per_point.at(r.point);
    ++ps.runs;
    if (!r.ok) {
      ++ps.failed;
      ++s.failed;
      continue;
    }
    ps.stick_slip_incidence += r.stick_slip ? 1.0 : 0.0;
    ps.chaos_incidence += r.chaotic ? 1.0 : 0.0;
    if (spec.paper_judge) paper_chaotic[r.point] += r.paper_chaotic.value_or(false) ? 1.0 : 0.0;
    const auto& names = sweep_regime_names();
    const auto at = std::find(names.begin(), names.end(), r.regime);
    if (at != names.end()) ps.regime_incidence[at - names.begin()] += 1.0;
    ps.mean_v += r.mean_v;
    if (std::isfinite(r.lambda)) {
      ps.mean_lambda += r.lambda;
      ++lambda_count[r.point];
    }
  }
  for (PointSummary& ps : s.per_point) {
    const double ok = static_cast<double>(ps.runs - ps.failed);
    if (ok > 0) {
      ps.stick_slip_incidence /= ok;
      ps.chaos_incidence /= ok;
      if (spec.paper_judge) ps.paper_chaos_incidence = paper_chaotic[ps.point] / ok;
      for (double& f : ps.regime_incidence) f /= ok;
      ps.mean_v /= ok;
    } else {
      ps.mean_v = kNaN;
    }
    ps.mean_lambda = lambda_count[ps.point] > 0 ? ps.mean_lambda / lambda_count[ps.point] : kNaN;
    if (spec.model_exponent.enabled) summarize_model_exponent(by_point[ps.point], ps);
  }
  count_regions(spec, s);
  return s;
}

SweepSummary summarize_adaptive(const SweepSpec& spec, const std::vector<RunRecord>& records,
                                const std::vector<std::size_t>& source) {
  SweepSummary s = summarize(spec, records);
  if (source.size() != s.points) throw Error("summarize_adaptive", "one source per grid point");
  for (std::size_t p = 0; p < s.points; ++p) {
    if (source[p] == p) continue;
    PointSummary& ps = s.per_point[p];
    const PointSummary& from = s.per_point.at(source[p]);
    ps.stick_slip_incidence = from.stick_slip_incidence;
    ps.chaos_incidence = from.chaos_incidence;
    ps.paper_chaos_incidence = from.paper_chaos_incidence;
    ps.regime_incidence = from.regime_incidence;
    ps.model_chaos_incidence = from.model_chaos_incidence;
    ps.mean_v = ps.mean_lambda = kNaN;  // values, unlike classes, are not carried over
    ps.inferred = true;
    ++s.inferred_points;
  }
  count_regions(spec, s);
  return s;
}

SweepSummary under_paper_judge(const SweepSummary& s) {
  if (!judged_by_paper(s))
    throw Error("paper judge", "the sweep did not judge its runs by the paper's indices");
  SweepSummary out = s;
  out.per_point = paper_judged(s.per_point);
  out.chaos_full_points = s.paper_chaos_full_points;
  out.chaos_any_points = s.paper_chaos_any_points;
  return out;
}

}  // namespace pneumachaos
