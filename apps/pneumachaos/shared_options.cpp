#include "commands.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <fmt/format.h>

#include "pneumachaos/analysis/surrogates.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/io/csv_writer.hpp"

namespace pneumachaos::cli {

int write_series_csv(const TimeSeries& series, const std::string& path) {
  if (path.empty()) {
    write_csv(std::cout, series);
    return kExitOk;
  }
  AtomicFile file(path);
  write_csv(file.stream(), series);
  file.commit();
  return kExitOk;
}

void add_scenario_options(CLI::App* cmd, ScenarioArgs& args) {
  cmd->add_option("scenario", args.file, "scenario TOML file (default: built-in scenario)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", args.sets, "override a scenario key, e.g. --set circuit.S2_mm2=0.05");
}

CLI::Validator positive_number_check() {
  return CLI::Validator(
      [](std::string& text) {
        double v = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size() || !(v > 0.0) ||
            !std::isfinite(v))
          return fmt::format("must be a positive number, got {}", text);
        return std::string();
      },
      "POSITIVE");
}

CLI::Validator input_record_check() {
  return CLI::Validator(
      [](std::string& path) {
        if (path == "-") return std::string();
        std::error_code ec;
        if (std::filesystem::is_regular_file(path, ec) || std::filesystem::is_fifo(path, ec))
          return std::string();
        return fmt::format("{}: {}; give a record's path, or - for standard input", path,
                           std::filesystem::exists(path, ec) ? "not a file" : "no such file");
      },
      "FILE|-");
}

namespace {

// A CLI11 check from one of the library's output-path rules ("" = fine, else the problem).
CLI::Validator path_check(std::string (*problem_of)(const std::string&), const char* name) {
  return CLI::Validator(
      [problem_of](std::string& path) {
        const std::string problem = problem_of(path);
        return problem.empty() ? std::string() : path + " " + problem;
      },
      name);
}

}  // namespace

CLI::Validator output_file_check() { return path_check(&output_file_problem, "OUTPUT FILE"); }

CLI::Validator output_directory_check() {
  return path_check(&output_directory_problem, "OUTPUT DIR");
}

void add_record_column_options(CLI::App* cmd, identify::RecordColumns& columns) {
  cmd->add_option("--column-t", columns.t, "header name of the time column (default t, or time)");
  cmd->add_option("--column-v", columns.v, "header name of the velocity column (default v)");
  cmd->add_option("--column-P1", columns.P1, "header name of chamber 1's pressure (default P1)");
  cmd->add_option("--column-P2", columns.P2, "header name of chamber 2's pressure (default P2)");
  cmd->add_option("--column-x", columns.x, "header name of the position column (default x; optional)");
  cmd->add_option("--column-a", columns.a,
                  "header name of an acceleration column (default a; optional)");
}

void add_quiet_flag(CLI::App* cmd, bool& quiet) {
  cmd->add_flag("--quiet", quiet,
                "no progress line (shown on a terminal when the work runs longer than 2 s)");
}

void add_units_option(CLI::App* cmd, std::vector<std::string>& entries) {
  cmd->add_option("--units", entries,
                  "unit of a column whose header has no brackets (repeatable), e.g. --units t=ms "
                  "--units \"P1=kPa g\"; a header's own brackets, e.g. t[ms] or P1[kPa g], say "
                  "the same (docs/reference)");
}

// The integer options are read as text and checked here, so that a bad value is a
// pneumachaos::Error naming the option (exit code 2) like every other bad input.
long long integer_option(const std::string& name, const std::string& text, long long min) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) {
    throw Error(name, fmt::format("expected an integer, got \"{}\"", text));
  }
  if (v < min) throw Error(name, fmt::format("{} is out of range: must be >= {}", v, min));
  return v;
}

std::size_t option_or(const std::optional<std::string>& text, const std::string& name,
                      long long min, std::size_t automatic) {
  return text ? static_cast<std::size_t>(integer_option(name, *text, min)) : automatic;
}

std::size_t surrogate_count_option(const std::optional<std::string>& text,
                                   std::size_t automatic) {
  const std::size_t n = option_or(text, "--surrogates", 0, automatic);
  check_surrogate_count(n, "--surrogates");
  return n;
}

}  // namespace pneumachaos::cli
