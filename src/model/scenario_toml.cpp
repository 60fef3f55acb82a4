#include "pneumachaos/model/scenario_toml.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <fstream>
#include <sstream>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/model/scenario_keys.hpp"

namespace pneumachaos {
namespace {

std::string location(const std::string& origin, const toml::source_region& src) {
  return fmt::format("{}:{}:{}", origin, src.begin.line, src.begin.column);
}

void apply_table(Scenario& scenario, const toml::table& table, const std::string& prefix,
                 const std::string& origin, SettingOrigins* origins) {
  for (const auto& [name, node] : table) {
    const std::string key = prefix + std::string(name.str());
    const std::string where = location(origin, node.source());
    if (prefix.empty() && key == "sweep") continue;  // read by read_sweep_file_spec
    if (const auto* sub = node.as_table()) {
      apply_table(scenario, *sub, key + ".", origin, origins);
      continue;
    } else if (const auto* i = node.as_integer()) {
      apply_setting(scenario, key, static_cast<double>(i->get()), where);
    } else if (const auto* f = node.as_floating_point()) {
      apply_setting(scenario, key, f->get(), where);
    } else if (const auto* s = node.as_string()) {
      apply_setting(scenario, key, s->get(), where);
    } else {
      throw Error(
          fmt::format("{}: {}", where, key),
          "expected a number or a word; arrays, booleans and dates are not scenario values");
    }
    if (origins != nullptr) (*origins)[key] = where;
  }
}

// One grid entry of a [sweep] table, as the sweep will read it.
void check_grid_entry(const std::string& where, const std::string& entry) {
  try {
    (void)parse_grid_axis(entry);
  } catch (const Error& e) {
    throw Error(where, e.what());
  }
}

}  // namespace

void apply_toml(Scenario& scenario, const std::string& toml_text, const std::string& origin,
                SettingOrigins* origins) {
  toml::table doc;
  try {
    doc = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    throw Error(location(origin, e.source()),
                std::string("TOML syntax error: ") + std::string(e.description()));
  }
  apply_table(scenario, doc, "", origin, origins);
}

void SweepFileSpec::validate() const {
  for (const std::string& entry : grid) check_grid_entry("sweep.grid", entry);
  if (repeats) validation::require_ge(validation::field("sweep.repeats"), static_cast<double>(*repeats), 1.0);
}

SweepFileSpec read_sweep_file_spec(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  toml::table doc;
  try {
    doc = toml::parse(text.str(), path);
  } catch (const toml::parse_error& e) {
    throw Error(location(path, e.source()),
                std::string("TOML syntax error: ") + std::string(e.description()));
  }
  SweepFileSpec s;
  const toml::table* sweep = doc["sweep"].as_table();
  if (sweep == nullptr) return s;
  for (const auto& [name, node] : *sweep) {
    const std::string key = "sweep." + std::string(name.str());
    const std::string where = location(path, node.source()) + ": " + key;
    if (key == "sweep.grid") {
      const auto* list = node.as_array();
      if (list == nullptr) throw Error(where, "expected a list of \"KEY=FROM:TO:STEP\" strings");
      for (const auto& item : *list) {
        const auto* str = item.as_string();
        if (str == nullptr) throw Error(where, "expected a list of \"KEY=FROM:TO:STEP\" strings");
        check_grid_entry(where, str->get());
        s.grid.push_back(str->get());
      }
    } else if (key == "sweep.repeats" || key == "sweep.seed") {
      const auto* i = node.as_integer();
      if (i == nullptr || i->get() < (key == "sweep.repeats" ? 1 : 0)) {
        throw Error(where, key == "sweep.repeats" ? "expected a whole number >= 1"
                                                  : "expected a whole number >= 0");
      }
      if (key == "sweep.repeats") {
        s.repeats = static_cast<std::size_t>(i->get());
      } else {
        s.seed = static_cast<std::uint64_t>(i->get());
      }
    } else {
      throw Error(where, "unknown key; [sweep] takes grid, repeats and seed");
    }
  }
  return s;
}

Scenario load_scenario_file(const std::string& path, SettingOrigins* origins) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  Scenario s = default_scenario();
  apply_toml(s, text.str(), path, origins);
  return s;
}

void apply_overrides(Scenario& scenario, const std::vector<std::string>& assignments,
                     SettingOrigins* origins) {
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw Error(kOverrideField, " " + a, "expected key=value, e.g. friction.Fs_N=30");
    }
    const std::string key = a.substr(0, eq);
    try {
      apply_setting(scenario, key, parse_setting_text(key, a.substr(eq + 1), ""), "");
    } catch (const Error& e) {
      throw Error(kOverrideField, ": " + e.where(), e.message());  // e.where() is the key
    }
    if (origins != nullptr) (*origins)[key] = kOverrideField.label;
  }
}

void validate_scenario(const Scenario& scenario, const SettingOrigins& origins) {
  try {
    scenario.validate();
  } catch (const Error& e) {
    // A field's error (core/validation.hpp) is found by its id; where() adds its value.
    const auto it = origins.find(e.field().empty() ? e.where() : e.field());
    if (it == origins.end()) throw;
    // Overrides are recorded under the field's label (apply_overrides).
    if (it->second == kOverrideField.label) {
      throw Error(kOverrideField, ": " + e.where(), e.message());
    }
    throw Error(it->second + ": " + e.where(), e.message());
  }
}

Scenario build_scenario(const std::string& path, const std::vector<std::string>& assignments) {
  SettingOrigins origins;
  Scenario s = path.empty() ? default_scenario() : load_scenario_file(path, &origins);
  apply_overrides(s, assignments, &origins);
  validate_scenario(s, origins);
  return s;
}

}  // namespace pneumachaos
