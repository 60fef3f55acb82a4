#pragma once
// Reading scenarios from TOML files and applying command-line overrides.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos {

/// Applies every key of a TOML document to `scenario`. `origin` names the source in errors
/// (a file path). Throws Error with file:line:column for syntax errors, unknown keys, wrong
/// types and out-of-range values.
void apply_toml(Scenario& scenario, const std::string& toml_text, const std::string& origin);

/// Reads a scenario file on top of the built-in defaults.
Scenario load_scenario_file(const std::string& path);

/// Applies "key=value" overrides (from --set) in order.
void apply_overrides(Scenario& scenario, const std::vector<std::string>& assignments);

/// The optional [sweep] table of a scenario file: grid = ["KEY=FROM:TO:STEP", ...],
/// repeats = N, seed = N. Other commands ignore the table.
struct SweepSettings {
  std::vector<std::string> grid;
  std::optional<std::size_t> repeats;
  std::optional<std::uint64_t> seed;
};
SweepSettings read_sweep_settings(const std::string& path);

/// Defaults, then the file (when path is not empty), then the overrides; validated.
Scenario build_scenario(const std::string& path, const std::vector<std::string>& assignments);

}  // namespace pneumachaos
