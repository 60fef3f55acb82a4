#include "evaluator.hpp"

#include <fmt/format.h>

#include <cmath>

#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"

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

Evaluator::Evaluator(const CalibrationSpec& spec, ConditionRunOptions settings,
                     std::optional<MeasuredMap> measured,
                     std::vector<identify::MeasuredRecord> records)
    : spec_(spec), settings_(settings), measured_(std::move(measured)),
      records_(std::move(records)) {}

double scaled_record_error(const identify::ValidationSeries& v, double pressure_scale_Pa,
                           double velocity_scale_m_per_s) {
  const auto sq = [](double a, double b, double scale) { return std::pow((a - b) / scale, 2); };
  double sum = 0.0;
  for (std::size_t i = 0; i < v.t_s.size(); ++i)
    sum += sq(v.p1_sim[i], v.p1_meas[i], pressure_scale_Pa) +
           sq(v.p2_sim[i], v.p2_meas[i], pressure_scale_Pa) +
           sq(v.v_sim[i], v.v_meas[i], velocity_scale_m_per_s);
  return v.t_s.empty() ? kNaN : std::sqrt(sum / (3.0 * static_cast<double>(v.t_s.size())));
}

std::vector<std::string> Evaluator::term_names() const {
  if (spec_.objective.kind == ObjectiveKind::kIncidenceMap)
    return {"stick_slip_rms_error", "chaos_rms_error"};
  if (spec_.objective.kind == ObjectiveKind::kRecords) {
    std::vector<std::string> names;
    for (std::size_t k = 0; k < spec_.objective.records.size(); ++k)
      names.push_back(fmt::format("record_{}_error", k + 1));
    return names;
  }
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
  sweep.paper_judge = spec_.objective.paper_judge;
  Evaluation e{1.0, {kNaN, kNaN}};
  try {
    sweep.validate();
  } catch (const RunError&) {
    throw;
  } catch (const Error&) {
    return e;  // the model refuses this scenario: the worst value
  }
  const SweepSummary swept = run_map(sweep, dir + "/map", settings_);
  const SweepSummary r = sweep.paper_judge ? under_paper_judge(swept) : swept;
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

namespace {

// The record's conditions on the evaluated scenario, as a map condition sets them.
Scenario at_record_conditions(Scenario s, const RecordCondition& c) {
  if (c.S1_mm2) apply_setting(s, "circuit.S1_mm2", *c.S1_mm2, c.where);
  if (c.S2_mm2) apply_setting(s, "circuit.S2_mm2", *c.S2_mm2, c.where);
  if (c.Ps_MPa) apply_setting(s, "supply.pressure_MPa", *c.Ps_MPa, c.where);
  if (c.m_kg) s.set_total_moving_mass(*c.m_kg);
  s.validate();
  return s;
}

}  // namespace

Evaluation Evaluator::record_errors(const Scenario& s) const {
  const ObjectiveSpec& o = spec_.objective;
  identify::FitOptions fit;
  fit.segment_length_s = o.segment_s;
  fit.pressure_scale_Pa = o.pressure_scale_kPa * 1e3;
  fit.velocity_scale_m_per_s = o.velocity_scale_mm_per_s * 1e-3;
  Evaluation e{0.0, {}};
  for (std::size_t k = 0; k < records_.size(); ++k) {
    double error = kNaN;
    try {
      identify::FitOptions f = fit;
      if (o.records[k].x0_mm) f.x0_m = *o.records[k].x0_mm * 1e-3;
      const Scenario sk = at_record_conditions(s, o.records[k]);
      error = scaled_record_error(identify::segment_simulation(records_[k], sk, f),
                                  fit.pressure_scale_Pa, fit.velocity_scale_m_per_s);
    } catch (const Error&) {
      // The model refuses the point, or its segments do not simulate (a RunError of the
      // simulation, not of a file): this record's worst.
    }
    e.terms.push_back(error);
    // e / (1 + e) keeps the objective in [0, 1] like the other kinds, 1 the worst, with the
    // same order as the errors themselves.
    e.objective += std::isnan(error) ? 1.0 : error / (1.0 + error);
  }
  e.objective /= static_cast<double>(records_.size());
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
  if (spec_.objective.kind == ObjectiveKind::kRecords)
    return s ? record_errors(*s)
             : Evaluation{1.0, std::vector<double>(spec_.objective.records.size(), kNaN)};
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
