#include "calibration_outputs.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <nlohmann/json.hpp>

#include "claim_front.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/plot/figure.hpp"

namespace pneumachaos::detail {
namespace {

std::vector<ScoredClaim> pick(const std::vector<Claim>& all, const std::vector<ClaimWeight>& ids,
                              bool weighted) {
  std::vector<ScoredClaim> out;
  for (const ClaimWeight& w : ids)
    for (const Claim& c : all)
      if (c.id == w.id) out.push_back({c, weighted ? w.weight : 0.0});
  return out;
}

std::string evaluations_csv(const CalibrationSpec& spec, const std::vector<JournalEntry>& entries,
                            const std::vector<std::string>& terms) {
  std::string out = "evaluation";
  for (const FreeParameter& p : spec.free) out += "," + p.key;
  out += ",objective";
  for (const std::string& t : terms) out += "," + t;
  out += "\n";
  for (std::size_t k = 0; k < entries.size(); ++k) {
    out += std::to_string(k);
    for (std::size_t i = 0; i < spec.free.size(); ++i)
      out += "," + exact_text(spec.free[i].value(entries[k].u[i]));
    out += "," + exact_text(entries[k].objective);
    for (double t : entries[k].terms) out += "," + exact_text(t);
    out += "\n";
  }
  return out;
}

nlohmann::json margin_json(double m) { return std::isnan(m) ? nlohmann::json() : nlohmann::json(m); }

nlohmann::json claims_rows(const std::vector<ScoredClaim>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const ScoredClaim& s : rows)
    a.push_back({{"id", s.claim.id}, {"weight", s.weight}, {"verdict", s.claim.verdict},
                 {"margin", margin_json(s.claim.margin)}, {"ours", s.claim.ours},
                 {"why", s.claim.why}});
  return a;
}

nlohmann::json front_json(const ClaimFront& f) {
  nlohmann::json j;
  j["accepted_evaluations"] = f.accepted;
  for (const ClaimReach& r : f.reach)
    j["claims"].push_back({{"id", r.id}, {"agreed_at", r.agreed}, {"judged_at", r.evaluated},
                           {"best_margin", margin_json(r.best_margin)},
                           {"best_evaluation", std::isnan(r.best_margin)
                                                   ? nlohmann::json()
                                                   : nlohmann::json(r.best_evaluation)}});
  j["front"] = nlohmann::json::array();
  for (const AgreedSet& s : f.front) {
    nlohmann::json ids = nlohmann::json::array();
    for (const std::size_t i : s.claims) ids.push_back(f.ids[i]);
    j["front"].push_back({{"claims", ids}, {"evaluations", s.evaluations}, {"best", s.example}});
  }
  j["conflicts"] = nlohmann::json::array();
  for (const ClaimConflict& c : f.conflicts)
    j["conflicts"].push_back({{"claims", {f.ids[c.a], f.ids[c.b]}},
                              {"margin_correlation", margin_json(c.correlation)}});
  return j;
}

std::string judge_name(const ObjectiveSpec& o) { return o.paper_judge ? "paper" : "strict"; }

std::string calibration_json(const CalibrationSpec& spec, const CalibrationResult& r,
                             const std::vector<std::string>& terms,
                             const std::optional<ClaimFront>& front) {
  nlohmann::json j;
  j["spec"] = spec.path;
  j["algorithm"] = spec.optimizer.algorithm;
  j["seed"] = spec.optimizer.seed;
  j["evaluations"] = r.evaluations;
  if (spec.objective.kind != ObjectiveKind::kRecords) j["judge"] = judge_name(spec.objective);
  j["best"]["evaluation"] = r.best;
  j["best"]["objective"] = r.best_objective;
  for (std::size_t i = 0; i < spec.free.size(); ++i)
    j["best"]["parameters"].push_back({{"key", spec.free[i].key}, {"value", r.best_values[i]},
                                       {"lower", spec.free[i].lower}, {"upper", spec.free[i].upper},
                                       {"source", spec.free[i].source}});
  j["fitted"] = claims_rows(r.fitted);
  j["predicted"] = claims_rows(r.predicted);
  for (std::size_t i = 0; i < r.map_errors.size(); ++i) j["map_errors"][terms[i]] = margin_json(r.map_errors[i]);
  for (std::size_t i = 0; i < r.record_errors.size(); ++i)
    j["record_errors"].push_back({{"file", spec.objective.records[i].file},
                                  {"error", margin_json(r.record_errors[i])}});
  if (front) j["evaluations_together"] = front_json(*front);
  return j.dump(2) + "\n";
}

std::string claims_table_md(const std::vector<ScoredClaim>& rows) {
  std::string out = "| claim | verdict | margin | ours |\n|---|---|---|---|\n";
  for (const ScoredClaim& s : rows)
    out += fmt::format("| {} | {} | {} | {} |\n", s.claim.id, s.claim.verdict,
                       std::isnan(s.claim.margin) ? std::string("-") : fmt::format("{:.3f}", s.claim.margin),
                       s.claim.ours);
  return out;
}

std::string objective_meaning(ObjectiveKind kind) {
  switch (kind) {
    case ObjectiveKind::kClaims: return "the weighted mean of -tanh(margin), -1 best, +1 worst";
    case ObjectiveKind::kIncidenceMap:
      return "the weighted mean of the incidences' RMS errors, 0 best, 1 worst";
    case ObjectiveKind::kRecords: return "the mean of e / (1 + e) over the records' errors e, 0 best, 1 worst";
  }
  return "";
}

std::string summary_md(const CalibrationSpec& spec, const CalibrationResult& r,
                       const std::optional<ClaimFront>& front) {
  std::string out = fmt::format(
      "# Calibration: {}\n\n{} ({} population, seed {}): {} evaluations; the best is evaluation "
      "{} with objective {:.4f} ({}).\n\n"
      "## Best point\n\n| key | value | bounds | source |\n|---|---|---|---|\n",
      spec.path, spec.optimizer.algorithm, spec.optimizer.population, spec.optimizer.seed,
      r.evaluations, r.best, r.best_objective, objective_meaning(spec.objective.kind));
  if (spec.objective.kind != ObjectiveKind::kRecords)
    out.insert(out.find("## Best point"),
               spec.objective.paper_judge
                   ? "Chaos judged by the paper's three indices (`judge = \"paper\"`).\n\n"
                   : "Chaos judged by the regime verdict (`judge = \"strict\"`).\n\n");
  for (std::size_t i = 0; i < spec.free.size(); ++i)
    out += fmt::format("| {} | {:.6g} | {:g} to {:g}{} | {} |\n", spec.free[i].key,
                       r.best_values[i], spec.free[i].lower, spec.free[i].upper,
                       spec.free[i].log_scale ? " (log)" : "", spec.free[i].source);
  out += "\n## Fitted (in sample)\n\n" + claims_table_md(r.fitted);
  for (std::size_t i = 0; i < r.map_errors.size(); ++i)
    out += fmt::format("{}RMS incidence error ({}): {:.4f}\n", i ? "" : "\n",
                       i ? "chaos" : "stick-slip", r.map_errors[i]);
  if (!r.record_errors.empty()) {
    out += "\n| measured record | error (RMS of the scaled residuals of P1, P2, v) |\n|---|---|\n";
    for (std::size_t i = 0; i < r.record_errors.size(); ++i)
      out += fmt::format("| {} | {} |\n", spec.objective.records[i].file,
                         std::isnan(r.record_errors[i]) ? std::string("failed")
                                                        : fmt::format("{:.4g}", r.record_errors[i]));
  }
  out += "\n## Predicted (out of sample: judged only at the best point)\n\n" +
         (r.predicted.empty() ? std::string("none asked\n") : claims_table_md(r.predicted));
  if (front) out += "\n" + claim_front_md(*front);
  return out;
}

FigureSpec convergence_figure(const std::vector<JournalEntry>& entries, std::size_t population) {
  std::string data = "# evaluation objective best_so_far\n";
  double best = 1e300;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    best = std::min(best, entries[k].objective);
    data += fmt::format("{} {} {}\n", k, entries[k].objective, best);
  }
  FigureSpec f;
  f.name = "convergence";
  f.caption = fmt::format("The objective of every evaluation (points) and the best so far (line); "
                          "a population of {} per generation.", population);
  f.data = {{"convergence.dat", data}};
  f.plot = "set grid\nset xlabel 'evaluation'\nset ylabel 'objective (lower is better)'\n"
           "set key below\nplot 'convergence.dat' using 1:2 with points pt 7 ps 0.6 title "
           "'evaluation', '' using 1:3 with steps lw 2 title 'best so far'";
  return f;
}

}  // namespace

CalibrationResult best_point_result(const CalibrationSpec& spec, const OptimizerTrace& trace,
                                    const std::vector<JournalEntry>& entries,
                                    const std::string& dir, const ConditionRunOptions& settings) {
  CalibrationResult r;
  r.evaluations = trace.f.size();
  r.best = trace.best;
  r.best_objective = trace.f[trace.best];
  const std::vector<double>& u = trace.u[trace.best];
  for (std::size_t i = 0; i < spec.free.size(); ++i) r.best_values.push_back(spec.free[i].value(u[i]));
  if (spec.objective.kind == ObjectiveKind::kIncidenceMap) r.map_errors = entries[trace.best].terms;
  if (spec.objective.kind == ObjectiveKind::kRecords) r.record_errors = entries[trace.best].terms;
  ConditionSet all = spec.objective.fit;
  all.example = all.example || spec.predict.example;
  all.maps.insert(all.maps.end(), spec.predict.maps.begin(), spec.predict.maps.end());
  ClaimInputs in;
  try {
    const Scenario s = spec.scenario_at(u);
    s.validate();
    run_conditions(spec.objective, s, all, dir, settings, in);
  } catch (const RunError&) {
    throw;
  } catch (const Error&) {
    // Every point was refused by the model: the claims stay "not reproduced".
  }
  r.all_claims = evaluate_claims(in);
  // The fitted claims as the objective saw them: without the predicted maps (a claim over
  // Figs. 4-6 reads the maps it is given).
  ClaimInputs fit_only = in;
  for (const MapCondition& m : spec.predict.maps) clear_role(fit_only, m.role);
  r.fitted = pick(evaluate_claims(fit_only), spec.objective.fit.claims, true);
  r.predicted = pick(r.all_claims, spec.predict.claims, false);
  return r;
}

void write_calibration_outputs(const CalibrationSpec& spec, const OptimizerTrace& trace,
                               const std::vector<JournalEntry>& entries,
                               const std::vector<std::string>& terms, const CalibrationResult& r,
                               const std::string& out_dir) {
  render_figure(convergence_figure(entries, spec.optimizer.population), out_dir + "/figures");
  // Only a claims objective has claim margins as its terms.
  std::optional<ClaimFront> front;
  if (spec.objective.kind == ObjectiveKind::kClaims) front = claim_front(terms, entries);
  OutputSet out;
  out.add(out_dir + "/evaluations.csv") << evaluations_csv(spec, entries, terms);
  out.add(out_dir + "/best_scenario.toml")
      << fmt::format("# pneumachaos calibrate {}: evaluation {} of {}, objective {}\n",
                     spec.path, r.best, r.evaluations, exact_text(r.best_objective))
      << scenario_to_toml(spec.scenario_at(trace.u[trace.best]));
  out.add(out_dir + "/claims.json") << claims_json(r.all_claims);
  out.add(out_dir + "/calibration.json") << calibration_json(spec, r, terms, front);
  out.add(out_dir + "/summary.md") << summary_md(spec, r, front);
  out.commit();
}

}  // namespace pneumachaos::detail
