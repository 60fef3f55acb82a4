#pragma once
// Each subcommand registers its options on the CLI11 app and returns the action to run after
// parsing. Commands only translate arguments into library calls; no physics here.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"

namespace pneumachaos::cli {

/// The action returns the process exit code.
using Action = std::function<int()>;

/// The options every scenario-driven command takes: a positional TOML file (default: the
/// built-in scenario) and repeatable --set key=value overrides.
struct ScenarioArgs {
  std::string file;
  std::vector<std::string> sets;
};
void add_scenario_options(CLI::App* cmd, ScenarioArgs& args);

/// A number > 0 (CLI::PositiveNumber prints its range as 0 to 1.8e308 in full).
CLI::Validator positive_number_check();
/// A record to read: an existing file, or "-" for standard input.
CLI::Validator input_record_check();

/// Checks of output paths at parse time, before any work (one policy: output_file_problem,
/// output_directory_problem): a bad path is a usage error (exit 2) naming the option.
CLI::Validator output_file_check();
CLI::Validator output_directory_check();

/// --column-t/-v/-P1/-P2/-x/-a: the header names of a measured record's columns.
void add_record_column_options(CLI::App* cmd, identify::RecordColumns& columns);

/// --quiet: no progress line (StageProgress shows one on a terminal after 2 s of work).
void add_quiet_flag(CLI::App* cmd, bool& quiet);

/// --units COLUMN=UNIT (repeatable): the unit of a column whose header has no brackets.
void add_units_option(CLI::App* cmd, std::vector<std::string>& entries);

/// How a measured record is read for a scenario-driven command: the scenario's ambient pressure
/// and stroke, the --units entries, and the supply as a plausibility bound only when the user
/// named the rig (a scenario file or --set): the built-in scenario's supply is not theirs.
identify::RecordReadOptions record_read_options(const Scenario& scenario, const ScenarioArgs& args,
                                                const std::vector<std::string>& units);

/// An integer option read as text, so that a bad value is an Error naming the option `name`
/// (exit code 2): "expected an integer" or "out of range: must be >= min".
long long integer_option(const std::string& name, const std::string& text, long long min);
/// The option's value checked as above, or `automatic` when it was not given.
std::size_t option_or(const std::optional<std::string>& text, const std::string& name,
                      long long min, std::size_t automatic);

/// --surrogates of `analyze` and `sweep`, checked by check_surrogate_count (an Error naming
/// the option); `automatic` when not given.
std::size_t surrogate_count_option(const std::optional<std::string>& text, std::size_t automatic);

/// Writes the series as CSV to `path`, whole or not at all, or to standard output when `path`
/// is empty (main checks that standard output took it all); returns kExitOk.
int write_series_csv(const TimeSeries& series, const std::string& path);

Action add_simulate(CLI::App& app);
Action add_scenario(CLI::App& app);
Action add_stability(CLI::App& app);
Action add_analyze(CLI::App& app);
Action add_sweep(CLI::App& app);
Action add_lyapunov(CLI::App& app);
Action add_reproduce(CLI::App& app);
Action add_friction(CLI::App& app);
Action add_fit(CLI::App& app);
Action add_calibrate(CLI::App& app);

/// Exit codes shared by all commands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitRunFailed = 3;

}  // namespace pneumachaos::cli
