// Reading SPEC.toml (docs/guide/calibrate.md): every problem is an Error naming
// file:line:column and the key, so a user can find what to fix.
#include "pneumachaos/calibrate/calibration_spec.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "claim_requirements.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/claims/example_run.hpp"

namespace pneumachaos {
namespace {

std::string at(const std::string& origin, const toml::node& n, const std::string& key) {
  const auto& b = n.source().begin;
  return fmt::format("{}:{}:{}: {}", origin, b.line, b.column, key);
}

// The reader of one table: typed look-ups that name the place of every problem, and a check
// that no key was left unread (a misspelt optional key would otherwise be ignored).
class Table {
 public:
  Table(const toml::table& t, std::string origin, std::string name)
      : t_(t), origin_(std::move(origin)), name_(std::move(name)) {}
  [[nodiscard]] std::string where(const std::string& key) const {
    const toml::node* n = t_.get(key);
    return at(origin_, n != nullptr ? *n : static_cast<const toml::node&>(t_), name_ + key);
  }
  const toml::node* get(const std::string& key) {
    read_.push_back(key);
    return t_.get(key);
  }
  std::optional<double> number(const std::string& key) {
    const toml::node* n = get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
    if (const auto* f = n->as_floating_point()) return f->get();
    throw Error(where(key), "expected a number");
  }
  double number_or(const std::string& key, double fallback) {
    return number(key).value_or(fallback);
  }
  std::size_t count_or(const std::string& key, std::size_t fallback, double lo, double hi) {
    const auto v = number(key);
    if (!v) return fallback;
    if (*v != std::floor(*v) || *v < lo || *v > hi)
      throw Error(where(key), fmt::format("expected a whole number from {} to {}, got {}", lo, hi, *v));
    return static_cast<std::size_t>(*v);
  }
  std::optional<std::string> text(const std::string& key) {
    const toml::node* n = get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* s = n->as_string()) return s->get();
    throw Error(where(key), "expected a string");
  }
  bool flag_or(const std::string& key, bool fallback) {
    const toml::node* n = get(key);
    if (n == nullptr) return fallback;
    if (const auto* b = n->as_boolean()) return b->get();
    throw Error(where(key), "expected true or false");
  }
  void no_other_keys() const {
    for (const auto& [k, node] : t_) {
      const std::string key(k.str());
      if (std::find(read_.begin(), read_.end(), key) == read_.end())
        throw Error(at(origin_, node, name_ + key), "unknown key here (docs/guide/calibrate.md lists them)");
    }
  }
  [[nodiscard]] const std::string& origin() const { return origin_; }

 private:
  const toml::table& t_;
  std::string origin_, name_;
  std::vector<std::string> read_;
};

const toml::table* sub_table(const toml::table& doc, const std::string& name,
                             const std::string& origin) {
  const toml::node* n = doc.get(name);
  if (n == nullptr) return nullptr;
  if (const auto* t = n->as_table()) return t;
  throw Error(at(origin, *n, name), "expected a table [" + name + "]");
}

// The key must be a number key of the table; its own error lists the section's keys.
void check_free_key(Scenario& scratch, const std::string& key, const std::string& where) {
  for (const KeyInfo& k : scenario_key_infos()) {
    if (k.key != key) continue;
    if (!k.choices.empty())
      throw Error(where + " (" + key + ")", "a word key (" + k.choices + ") cannot be free; set it in [fixed]");
    return;
  }
  apply_setting(scratch, key, 0.0, where);  // throws: unknown key, with the keys near it
}

FreeParameter read_free(const toml::table& t, const std::string& origin) {
  Table r(t, origin, "free.");
  FreeParameter p;
  p.where = at(origin, t, "[[free]]");
  const auto key = r.text("key");
  if (!key) throw Error(p.where, "every [[free]] entry needs key = \"a scenario key\"");
  p.key = *key;
  const auto lo = r.number("lower"), hi = r.number("upper");
  if (!lo || !hi) throw Error(p.where + " " + p.key, "needs both lower and upper");
  p.lower = *lo;
  p.upper = *hi;
  const auto source = r.text("source");
  if (!source || source->find_first_not_of(" \t") == std::string::npos)
    throw Error(r.where(source ? "source" : "key") + " (" + p.key + ")",
                "needs source = \"...\": the paper, catalogue or measurement that bounds it; a "
                "parameter without a citable bound belongs in [fixed]");
  p.source = *source;
  const auto scale = r.text("scale");
  if (scale && *scale != "log" && *scale != "linear")
    throw Error(r.where("scale"), "expected \"linear\" or \"log\", got \"" + *scale + "\"");
  p.log_scale = scale && *scale == "log";
  r.no_other_keys();
  // Each bound goes through the key table: an unknown key, a word key or a bound outside the
  // key's plausible range is refused with the table's own reason.
  Scenario scratch = default_scenario();
  check_free_key(scratch, p.key, r.where("key"));
  apply_setting(scratch, p.key, p.lower, r.where("lower") + " (" + p.key + ")");
  apply_setting(scratch, p.key, p.upper, r.where("upper") + " (" + p.key + ")");
  if (!(p.lower < p.upper))
    throw Error(r.where("lower") + " (" + p.key + ")",
                fmt::format("lower ({}) must be below upper ({})", p.lower, p.upper));
  if (p.log_scale && p.lower <= 0.0)
    throw Error(r.where("scale") + " (" + p.key + ")", "a log scale needs lower > 0");
  return p;
}

void apply_fixed(Scenario& s, const toml::table& t, const std::string& prefix,
                 const std::string& origin) {
  for (const auto& [name, node] : t) {
    const std::string key = prefix + std::string(name.str());
    const std::string where = at(origin, node, "fixed." + key);
    if (const auto* sub = node.as_table()) {
      apply_fixed(s, *sub, key + ".", origin);
    } else if (const auto* i = node.as_integer()) {
      apply_setting(s, key, static_cast<double>(i->get()), where);
    } else if (const auto* f = node.as_floating_point()) {
      apply_setting(s, key, f->get(), where);
    } else if (const auto* w = node.as_string()) {
      apply_setting(s, key, w->get(), where);
    } else {
      throw Error(where, "expected a number or a word");
    }
  }
}

std::vector<ClaimWeight> read_claims(Table& r) {
  std::vector<ClaimWeight> out;
  const toml::node* n = r.get("claims");
  if (n == nullptr) return out;
  const auto* t = n->as_table();
  if (t == nullptr) throw Error(r.where("claims"), "expected a table { claim_id = weight, ... }");
  const std::vector<std::string> known = known_claim_ids();
  for (const auto& [k, node] : *t) {
    ClaimWeight c;
    c.id = std::string(k.str());
    c.where = at(r.origin(), node, "claims." + c.id);
    if (std::find(known.begin(), known.end(), c.id) == known.end())
      throw Error(c.where, "unknown claim id (docs/report.md lists the claims)");
    const auto w = node.value<double>();
    if (!w || !(*w > 0.0) || !std::isfinite(*w)) throw Error(c.where, "expected a weight > 0");
    c.weight = *w;
    out.push_back(c);
  }
  return out;
}

// Each inline table of the array `key` (nothing when it is absent), read by `read(table,
// where)`; the item's unknown keys are refused. `shape` says what an item looks like.
template <class Read>
void for_each_item(Table& r, const std::string& key, const char* shape, Read read) {
  const toml::node* n = r.get(key);
  if (n == nullptr) return;
  const auto* a = n->as_array();
  if (a == nullptr) throw Error(r.where(key), fmt::format("expected an array of {}", shape));
  for (const toml::node& item : *a) {
    const auto* t = item.as_table();
    const std::string where = at(r.origin(), item, key);
    if (t == nullptr) throw Error(where, fmt::format("expected {}", shape));
    Table m(*t, r.origin(), key + ".");
    read(m, where);
    m.no_other_keys();
  }
}

std::vector<MapCondition> read_maps(Table& r) {
  std::vector<MapCondition> out;
  for_each_item(r, "maps", "{ role, Ps_MPa, m_kg }", [&](Table& m, const std::string& where) {
    MapCondition c;
    c.where = where;
    c.role = m.text("role").value_or("");
    if (!is_map_role(c.role))
      throw Error(m.where("role"), "expected role = \"base\" | \"high_ps\" | \"double_m\" | \"triple_m\"");
    c.Ps_MPa = m.number_or("Ps_MPa", c.Ps_MPa);
    c.m_kg = m.number_or("m_kg", c.m_kg);
    Scenario scratch = default_scenario();
    apply_setting(scratch, "supply.pressure_MPa", c.Ps_MPa, m.where("Ps_MPa"));
    if (!(c.m_kg > 0.0) || c.m_kg > 1000.0) throw Error(m.where("m_kg"), "expected 0 < m_kg <= 1000");
    out.push_back(c);
  });
  return out;
}

ConditionSet read_conditions(Table& r) {
  ConditionSet c;
  c.maps = read_maps(r);
  c.example = r.flag_or("example", false);
  c.claims = read_claims(r);
  return c;
}

// spec.validate(), a refusal naming the key's place in the file (the field's id is
// SECTION.KEY; the table's keys are KEY).
template <typename Spec>
void validate_in_file(Table& r, const Spec& spec) {
  try {
    spec.validate();
  } catch (const Error& e) {
    throw Error(r.where(e.field().substr(e.field().find('.') + 1)), e.message());
  }
}

MapSpec read_map_spec(Table& r) {
  MapSpec m;
  const toml::node* g = r.get("grid");
  if (g != nullptr) {
    const auto* a = g->as_array();
    if (a == nullptr || a->size() != 2)
      throw Error(r.where("grid"), "expected [\"circuit.S1_mm2=FROM:TO:STEP\", "
                                   "\"circuit.S2_mm2=FROM:TO:STEP\"]");
    for (const toml::node& item : *a) {
      const auto axis = item.value<std::string>();
      if (!axis) throw Error(r.where("grid"), "expected strings KEY=FROM:TO:STEP");
      try {
        m.axes.push_back(parse_grid_axis(*axis));
      } catch (const Error& e) {
        throw Error(r.where("grid"), e.what());
      }
    }
  }
  m.repeats = r.count_or("repeats", m.repeats, 1, 1000);
  m.duration_s = r.number_or("duration_s", m.duration_s);
  m.adaptive = r.flag_or("adaptive", true);
  return m;  // checked with the objective (ObjectiveSpec::validate)
}

std::string relative_to(const std::string& dir, const std::string& file) {
  return (file.front() == '/' || dir.empty()) ? file : dir + "/" + file;
}

// A condition of a record, checked as the scenario key it sets.
std::optional<double> record_setting(Table& m, const char* name, const char* key) {
  const std::optional<double> v = m.number(name);
  if (v && key != nullptr) {
    Scenario scratch = default_scenario();
    apply_setting(scratch, key, *v, m.where(name));
  }
  return v;
}

// A record's `units = { t = "ms", P1 = "kPa g" }`: the units of columns without brackets.
UnitOverrides record_units(Table& m) {
  const toml::node* n = m.get("units");
  if (n == nullptr) return {};
  const char* shape = "a table of column units, e.g. units = { t = \"ms\", P1 = \"kPa g\" }";
  const auto* t = n->as_table();
  if (t == nullptr) throw Error(m.where("units"), fmt::format("expected {}", shape));
  UnitOverrides out;
  for (const auto& [column, unit] : *t) {
    const auto* text = unit.as_string();
    if (text == nullptr) throw Error(m.where("units"), fmt::format("expected {}", shape));
    out.emplace(std::string(column.str()), text->get());
  }
  return out;
}

std::vector<RecordCondition> read_records(Table& r, const std::string& dir) {
  std::vector<RecordCondition> out;
  const char* shape = "{ file = \"run.csv\", S1_mm2, S2_mm2, Ps_MPa, m_kg }";
  for_each_item(r, "records", shape, [&](Table& m, const std::string& where) {
    RecordCondition c;
    c.where = where;
    const auto file = m.text("file");
    if (!file || file->empty()) throw Error(m.where("file"), "needs file = \"run.csv\"");
    c.file = relative_to(dir, *file);
    c.S1_mm2 = record_setting(m, "S1_mm2", "circuit.S1_mm2");
    c.S2_mm2 = record_setting(m, "S2_mm2", "circuit.S2_mm2");
    c.Ps_MPa = record_setting(m, "Ps_MPa", "supply.pressure_MPa");
    c.m_kg = record_setting(m, "m_kg", nullptr);
    if (c.m_kg && (!(*c.m_kg > 0.0) || *c.m_kg > 1000.0))
      throw Error(m.where("m_kg"), "expected 0 < m_kg <= 1000");
    c.units = record_units(m);
    c.x0_mm = record_setting(m, "x0_mm", nullptr);
    if (c.x0_mm && !(*c.x0_mm >= 0.0 && *c.x0_mm <= 10000.0))
      throw Error(m.where("x0_mm"), "expected 0 <= x0_mm <= 10000");
    out.push_back(c);
  });
  if (out.empty())
    throw Error(r.where("records"), fmt::format("needs records = [ {}, ... ]", shape));
  return out;
}

void read_record_settings(Table& r, ObjectiveSpec& o, const std::string& dir) {
  o.records = read_records(r, dir);
  o.segment_s = r.number_or("segment_s", o.segment_s);
  o.pressure_scale_kPa = r.number_or("pressure_scale_kPa", o.pressure_scale_kPa);
  o.velocity_scale_mm_per_s = r.number_or("velocity_scale_mm_per_s", o.velocity_scale_mm_per_s);
}

// judge = "strict" (the default: the regime verdict) or "paper" (the paper's three indices).
bool read_judge(Table& r) {
  const std::string judge = r.text("judge").value_or("strict");
  if (judge != "strict" && judge != "paper")
    throw Error(r.where("judge"), fmt::format("expected judge = \"strict\" or \"paper\", not \"{}\"", judge));
  return judge == "paper";
}

ObjectiveSpec read_objective(const toml::table& t, const std::string& origin, const std::string& dir) {
  Table r(t, origin, "objective.");
  ObjectiveSpec o;
  const std::string kind = r.text("kind").value_or("");
  if (kind != "claims" && kind != "incidence_map" && kind != "records")
    throw Error(r.where("kind"), "expected kind = \"claims\", \"incidence_map\" or \"records\"");
  o.kind = kind == "claims"          ? ObjectiveKind::kClaims
           : kind == "incidence_map" ? ObjectiveKind::kIncidenceMap
                                     : ObjectiveKind::kRecords;
  o.maps = read_map_spec(r);
  if (o.kind != ObjectiveKind::kRecords) o.paper_judge = read_judge(r);
  if (o.kind == ObjectiveKind::kRecords) {
    read_record_settings(r, o, dir);
  } else if (o.kind == ObjectiveKind::kClaims) {
    o.fit = read_conditions(r);
    o.example_record_s = r.number_or("example_record_s", o.example_record_s);
    o.example_model_exponent = r.flag_or("example_model_exponent", false);
  } else {
    const auto file = r.text("file");
    if (file && !file->empty()) o.measured_map = relative_to(dir, *file);
    o.stick_slip_weight = r.number_or("stick_slip_weight", 1.0);
    o.chaos_weight = r.number_or("chaos_weight", 1.0);
  }
  r.no_other_keys();
  validate_in_file(r, o);
  return o;
}

OptimizerSpec read_optimizer(const toml::table& t, const std::string& origin) {
  Table r(t, origin, "optimizer.");
  OptimizerSpec o;
  o.algorithm = r.text("algorithm").value_or(o.algorithm);
  o.population = r.count_or("population", o.population, 0, 1e6);
  o.max_evaluations = r.count_or("max_evaluations", o.max_evaluations, 0, 1e7);
  o.seed = r.count_or("seed", o.seed, 0, 4294967295.0);
  o.sigma0 = r.number_or("sigma0", o.sigma0);
  r.no_other_keys();
  validate_in_file(r, o);
  return o;
}

}  // namespace

double FreeParameter::value(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  if (log_scale) return std::exp(std::log(lower) + u * (std::log(upper) - std::log(lower)));
  return lower + u * (upper - lower);
}

void MapSpec::validate() const {
  using namespace validation;
  if (!axes.empty() && (axes.size() != 2 || axes[0].key != "circuit.S1_mm2" ||
                        axes[1].key != "circuit.S2_mm2"))
    throw Error(field("objective.grid"),
                "the maps are S1 x S2: circuit.S1_mm2 first, then circuit.S2_mm2");
  require_between(field("objective.repeats"), static_cast<double>(repeats), 1, 1000);
  require_gt_le(field("objective.duration_s"), duration_s, 0.0, 3600.0);
}

void ObjectiveSpec::validate() const {
  using namespace validation;
  maps.validate();
  switch (kind) {
    case ObjectiveKind::kClaims:
      require_gt_le(field("objective.example_record_s"), example_record_s, kExampleSettle_s, 3600.0,
                    "the first 2 s settle");
      if (fit.claims.empty()) throw Error(field("objective.claims"), "name at least one claim to fit");
      break;
    case ObjectiveKind::kIncidenceMap:
      if (measured_map.empty())
        throw Error(field("objective.file"), "needs file = \"measured_map.csv\"");
      require_ge(field("objective.stick_slip_weight"), stick_slip_weight, 0.0);
      require_ge(field("objective.chaos_weight"), chaos_weight, 0.0);
      require_gt(field("objective.chaos_weight"), stick_slip_weight + chaos_weight, 0.0,
                 "the weights must not both be 0");
      break;
    case ObjectiveKind::kRecords:
      if (records.empty()) throw Error(field("objective.records"), "name at least one record");
      require_between(field("objective.segment_s"), segment_s, 0.005, 10.0);
      require_gt_le(field("objective.pressure_scale_kPa"), pressure_scale_kPa, 0.0, 1000.0);
      require_gt_le(field("objective.velocity_scale_mm_per_s"), velocity_scale_mm_per_s, 0.0, 10000.0);
      break;
  }
}

void OptimizerSpec::validate() const {
  using namespace validation;
  if (algorithm != "cmaes" && algorithm != "xnes")
    throw Error(field("optimizer.algorithm"),
                "expected \"cmaes\" or \"xnes\" (pagmo2), got \"" + algorithm + "\"");
  require_between(field("optimizer.population"), static_cast<double>(population), 5, 10000,
                  "pagmo's CMA-ES and xNES need at least 5 individuals");
  require_ge(field("optimizer.max_evaluations"), static_cast<double>(max_evaluations),
             2.0 * static_cast<double>(population), "two populations");
  require_le(field("optimizer.seed"), static_cast<double>(seed), 4294967295.0);
  require_gt_le(field("optimizer.sigma0"), sigma0, 0.0, 1.0);
}

std::size_t OptimizerSpec::generations() const { return max_evaluations / population - 1; }

CalibrationSpec parse_calibration_spec(const std::string& text, const std::string& origin) {
  toml::table doc;
  try {
    doc = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw Error(fmt::format("{}:{}:{}", origin, b.line, b.column), std::string(e.description()));
  }
  CalibrationSpec s;
  s.path = origin;
  const auto slash = origin.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : origin.substr(0, slash);
  for (const auto& [k, node] : doc) {
    const std::string key(k.str());
    if (key != "free" && key != "fixed" && key != "objective" && key != "predict" && key != "optimizer")
      throw Error(at(origin, node, key), "unknown table; expected [[free]], [fixed], [objective], "
                                         "[predict] or [optimizer]");
  }
  s.base = default_scenario();
  if (const auto* fixed = sub_table(doc, "fixed", origin)) apply_fixed(s.base, *fixed, "", origin);
  if (const toml::node* free = doc.get("free")) {
    const auto* a = free->as_array();
    if (a == nullptr || !a->is_array_of_tables())
      throw Error(at(origin, *free, "free"), "expected [[free]] entries");
    for (const toml::node& item : *a) s.free.push_back(read_free(*item.as_table(), origin));
  }
  const auto* objective = sub_table(doc, "objective", origin);
  if (objective == nullptr) throw Error(origin + ": objective", "the spec needs an [objective] table");
  s.objective = read_objective(*objective, origin, dir);
  if (const auto* predict = sub_table(doc, "predict", origin)) {
    Table r(*predict, origin, "predict.");
    s.predict = read_conditions(r);
    r.no_other_keys();
  }
  if (const auto* opt = sub_table(doc, "optimizer", origin)) s.optimizer = read_optimizer(*opt, origin);
  s.validate();
  return s;
}

CalibrationSpec read_calibration_spec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open the calibration spec");
  std::stringstream text;
  text << in.rdbuf();
  return parse_calibration_spec(text.str(), path);
}

}  // namespace pneumachaos
