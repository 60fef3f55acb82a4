// The spec's cross-checks, its scenarios and its fingerprint.
#include <fmt/format.h>

#include <set>

#include "claim_requirements.hpp"
#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {
namespace {

// The map conditions set Ps and the total moving mass; the grid sets S1 and S2.
const std::set<std::string> kSetByConditions = {"supply.pressure_MPa", "load.mass_kg",
                                                "circuit.S1_mm2", "circuit.S2_mm2"};

// Whether a record sets the scenario key `key` (one of kSetByConditions).
bool a_record_sets(const std::vector<RecordCondition>& records, const std::string& key) {
  for (const RecordCondition& r : records) {
    if ((key == "circuit.S1_mm2" && r.S1_mm2) || (key == "circuit.S2_mm2" && r.S2_mm2) ||
        (key == "supply.pressure_MPa" && r.Ps_MPa) || (key == "load.mass_kg" && r.m_kg))
      return true;
  }
  return false;
}

// The conditions' keys cannot be free where the conditions set them: the maps always do
// (Ps, m and the grid's S1, S2); a records objective only where a record names them, so the
// valve areas of a rig can be fitted to its records.
bool set_by_conditions(const CalibrationSpec& spec, const std::string& key) {
  if (kSetByConditions.count(key) == 0) return false;
  if (spec.objective.kind != ObjectiveKind::kRecords || !spec.predict.maps.empty()) return true;
  return a_record_sets(spec.objective.records, key);
}

void check_roles(const ConditionSet& c, std::set<std::string>& roles) {
  for (const MapCondition& m : c.maps)
    if (!roles.insert(m.role).second)
      throw Error(m.where, "role \"" + m.role + "\" is given twice (objective and predict together)");
}

void check_claims(const std::vector<ClaimWeight>& claims, const ConditionSet& available,
                  const char* set_name) {
  for (const ClaimWeight& c : claims) {
    const std::string missing = detail::missing_for_claim(c.id, available);
    if (!missing.empty())
      throw Error(c.where, fmt::format("the {} cannot score this claim: {}", set_name, missing));
  }
}

std::string conditions_text(const ConditionSet& c) {
  std::string s = fmt::format("example={};", c.example);
  for (const MapCondition& m : c.maps) s += fmt::format("map {} {} {};", m.role, m.Ps_MPa, m.m_kg);
  for (const ClaimWeight& w : c.claims) s += fmt::format("claim {} {};", w.id, w.weight);
  return s;
}

}  // namespace

std::vector<std::string> known_claim_ids() {
  std::vector<std::string> ids;
  for (const Claim& c : evaluate_claims(ClaimInputs{})) ids.push_back(c.id);
  return ids;
}

void CalibrationSpec::validate() const {
  if (free.empty()) throw Error(path + ": free", "name at least one [[free]] parameter");
  std::set<std::string> keys;
  for (const FreeParameter& p : free) {
    if (!keys.insert(p.key).second) throw Error(p.where + " " + p.key, "this key is free twice");
    if (set_by_conditions(*this, p.key))
      throw Error(p.where + " " + p.key,
                  "this key is set by the conditions (the maps' Ps and m, the grid's S1 and "
                  "S2, or a record's)");
  }
  optimizer.validate();
  objective.validate();
  std::set<std::string> roles;
  check_roles(objective.fit, roles);
  check_roles(predict, roles);
  check_claims(objective.fit.claims, objective.fit, "objective's conditions");
  ConditionSet all = objective.fit;
  all.example = all.example || predict.example;
  all.maps.insert(all.maps.end(), predict.maps.begin(), predict.maps.end());
  check_claims(predict.claims, all, "objective's and predict's conditions together");
  for (const ClaimWeight& p : predict.claims)
    for (const ClaimWeight& f : objective.fit.claims)
      if (p.id == f.id)
        throw Error(p.where, "this claim is fitted: a prediction must be out of sample");
  if (!all.maps.empty() && objective.maps.axes.empty())
    throw Error(path + ": objective.grid", "the maps need grid = [\"circuit.S1_mm2=...\", "
                                           "\"circuit.S2_mm2=...\"]");
  for (const auto* claims : {&objective.fit.claims, &predict.claims})
    for (const ClaimWeight& c : *claims) {
      const std::string problem = detail::grid_problem_for_claim(c.id, objective.maps.axes);
      if (!problem.empty()) throw Error(c.where, "the maps' grid cannot score this claim: " + problem);
    }
  try {
    scenario_at(std::vector<double>(free.size(), 0.5)).validate();
  } catch (const Error& e) {
    throw Error(path + ": fixed", std::string("the scenario at the middle of the free box is "
                                              "invalid: ") + e.what());
  }
}

Scenario CalibrationSpec::scenario_at(const std::vector<double>& u) const {
  Scenario s = base;
  for (std::size_t i = 0; i < free.size(); ++i) apply_setting(s, free[i].key, free[i].value(u[i]), free[i].where);
  return s;
}

std::string CalibrationSpec::fingerprint() const {
  std::string s = "calibration 1;";
  for (const FreeParameter& p : free)
    s += fmt::format("free {} {} {} {};", p.key, p.lower, p.upper, p.log_scale);
  s += scenario_to_toml(base);
  const ObjectiveSpec& o = objective;
  s += fmt::format("objective {} {} {} {} {} {} {} {};", static_cast<int>(o.kind), o.maps.repeats,
                   o.maps.duration_s, o.maps.adaptive, o.example_record_s,
                   o.example_model_exponent, o.stick_slip_weight, o.chaos_weight);
  for (const GridAxis& a : o.maps.axes) {
    s += a.key;
    for (double v : a.values) s += fmt::format(" {}", v);
    s += ";";
  }
  s += o.measured_map + ";" + conditions_text(o.fit) + "predict;" + conditions_text(predict);
  const auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{}", *v) : "-"; };
  for (const RecordCondition& r : o.records) {
    s += fmt::format("record {} {} {} {} {} {};", r.file, opt(r.S1_mm2), opt(r.S2_mm2),
                     opt(r.Ps_MPa), opt(r.m_kg), opt(r.x0_mm));
    for (const auto& [column, unit] : r.units) s += fmt::format("unit {}={};", column, unit);
  }
  if (o.kind == ObjectiveKind::kRecords)
    s += fmt::format("records {} {} {};", o.segment_s, o.pressure_scale_kPa,
                     o.velocity_scale_mm_per_s);
  s += fmt::format("optimizer {} {} {} {} {};", optimizer.algorithm, optimizer.population,
                   optimizer.max_evaluations, optimizer.seed, optimizer.sigma0);
  return detail::stable_hash(s);
}

}  // namespace pneumachaos
