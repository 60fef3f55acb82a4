#pragma once
// Reading scenarios from TOML files and applying command-line overrides.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos {

/// Where each key was set: "file:line:column", "--set" or a flag; for the cross-key checks'
/// errors, which run after all keys are applied.
using SettingOrigins = std::map<std::string, std::string>;

/// Applies every key of a TOML document to `scenario`. `origin` names the source in errors
/// (a file path). Throws Error with file:line:column for syntax errors, unknown keys, wrong
/// types and out-of-range values. Records where each key was set in `origins` if given.
void apply_toml(Scenario& scenario, const std::string& toml_text, const std::string& origin,
                SettingOrigins* origins = nullptr);

/// Reads a scenario file on top of the built-in defaults.
Scenario load_scenario_file(const std::string& path, SettingOrigins* origins = nullptr);

/// An override's text or key, in errors: "override friction.Fs_N" for a malformed
/// assignment, "override: friction.Fs_N" for a bad value (detail() is the rest).
inline constexpr ErrorField kOverrideField{"scenario.override", "override"};

/// Applies "key=value" overrides (from --set) in order; errors are about kOverrideField.
void apply_overrides(Scenario& scenario, const std::vector<std::string>& assignments,
                     SettingOrigins* origins = nullptr);

/// scenario.validate(), with an error about a key that was set somewhere naming that place
/// (e.g. "rig.toml:3:1: cylinder.rod_mm: ..." or "--set: cylinder.rod_mm: ...").
void validate_scenario(const Scenario& scenario, const SettingOrigins& origins);

/// The optional [sweep] table of a scenario file: grid = ["KEY=FROM:TO:STEP", ...],
/// repeats = N, seed = N. Other commands ignore the table.
struct SweepFileSpec {
  std::vector<std::string> grid;
  std::optional<std::size_t> repeats;
  std::optional<std::uint64_t> seed;
  /// Throws Error naming sweep.grid (an entry that is not KEY=FROM:TO:STEP over a scenario
  /// key) or sweep.repeats (below 1).
  void validate() const;
};
/// The [sweep] table of the file at `path` (empty when it has none); each entry checked where
/// it is written (path:line:column: sweep.KEY).
SweepFileSpec read_sweep_file_spec(const std::string& path);

/// Defaults, then the file (when path is not empty), then the overrides; validated.
Scenario build_scenario(const std::string& path, const std::vector<std::string>& assignments);

}  // namespace pneumachaos
