#include "evaluator.hpp"

#include <cmath>

#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

double claims_objective(const std::vector<double>& margins, const std::vector<double>& weights) {
  // tanh keeps one claim's large margin (the margins are unbounded ratios) from outweighing
  // the others, and still rewards a claim passed with room over one passed at its border.
  double sum = 0.0, total = 0.0;
  for (std::size_t i = 0; i < margins.size(); ++i) {
    sum += weights[i] * (std::isnan(margins[i]) ? 1.0 : -std::tanh(margins[i]));
    total += weights[i];
  }
  return total > 0.0 ? sum / total : 1.0;
}

namespace detail {

Evaluator::Evaluator(const CalibrationSpec& spec, RunSettings settings,
                     std::optional<MeasuredMap> measured)
    : spec_(spec), settings_(settings), measured_(std::move(measured)) {}

std::vector<std::string> Evaluator::term_names() const {
  if (spec_.objective.kind == ObjectiveKind::kIncidenceMap)
    return {"stick_slip_rms_error", "chaos_rms_error"};
  std::vector<std::string> names;
  for (const ClaimWeight& c : spec_.objective.fit.claims) names.push_back(c.id);
  return names;
}

Evaluation Evaluator::map_errors(const Scenario& s, const std::string& dir) const {
  const MeasuredMap& m = *measured_;
  SweepSpec sweep;
  sweep.base = s;
  sweep.base.run.duration_s = spec_.objective.maps.duration_s;
  sweep.axes = {GridAxis{"circuit.S1_mm2", m.s1}, GridAxis{"circuit.S2_mm2", m.s2}};
  sweep.repeats = spec_.objective.maps.repeats;
  sweep.adaptive.enabled = spec_.objective.maps.adaptive;
  Evaluation e{1.0, {kNaN, kNaN}};
  try {
    sweep.validate();
  } catch (const RunError&) {
    throw;
  } catch (const Error&) {
    return e;  // the model refuses this scenario: the worst value
  }
  const SweepSummary r = run_map(sweep, dir + "/map", settings_);
  double ss = 0.0, ch = 0.0;
  for (std::size_t i = 0; i < r.per_point.size(); ++i) {
    ss += std::pow(r.per_point[i].stick_slip_incidence - m.stick_slip[i], 2);
    ch += std::pow(r.per_point[i].chaos_incidence - m.chaos[i], 2);
  }
  const auto n = static_cast<double>(r.per_point.size());
  e.terms = {std::sqrt(ss / n), std::sqrt(ch / n)};
  const double ws = spec_.objective.stick_slip_weight, wc = spec_.objective.chaos_weight;
  e.objective = (ws * e.terms[0] + wc * e.terms[1]) / (ws + wc);
  return e;
}

Evaluation Evaluator::evaluate(const std::vector<double>& u, const std::string& dir) const {
  std::optional<Scenario> s;
  try {
    s = spec_.scenario_at(u);
    s->validate();
  } catch (const RunError&) {
    throw;
  } catch (const Error&) {
    s.reset();  // a combination the model refuses: every term missing, the worst value
  }
  if (spec_.objective.kind == ObjectiveKind::kIncidenceMap)
    return s ? map_errors(*s, dir) : Evaluation{1.0, {kNaN, kNaN}};
  const auto& fit = spec_.objective.fit.claims;
  ClaimInputs inputs;
  if (s) run_conditions(spec_.objective, *s, spec_.objective.fit, dir, settings_, inputs);
  const std::vector<Claim> claims = s ? evaluate_claims(inputs) : std::vector<Claim>{};
  Evaluation e;
  std::vector<double> weights;
  for (const ClaimWeight& w : fit) {
    double margin = kNaN;
    for (const Claim& c : claims)
      if (c.id == w.id) margin = c.margin;
    e.terms.push_back(margin);
    weights.push_back(w.weight);
  }
  e.objective = claims_objective(e.terms, weights);
  return e;
}

}  // namespace detail
}  // namespace pneumachaos
