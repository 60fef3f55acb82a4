// `pneumachaos analyze`: chaos indices and the regime verdict of a recorded series.

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <optional>
#include <regex>

#include "commands.hpp"
#include "flag_names.hpp"
#include "pneumachaos/analysis/analysis_output.hpp"
#include "pneumachaos/analysis/paper_judge.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/io/csv_reader.hpp"
#include "stage_progress.hpp"

namespace pneumachaos::cli {
namespace {

// The analysis knows only a series; its errors gain the file and column they concern.
AnalysisResult analyzed(const Channel& channel, double rate_Hz, const AnalysisOptions& options,
                        const std::string& file) {
  try {
    return analyze_series(channel.values, rate_Hz, options);
  } catch (const Error& e) {
    throw Error(fmt::format("{}, column {}", file, channel.name), e.what());
  }
}

struct AnalyzeArgs {
  std::string file;
  std::string column = "v";
  std::string quantity;  ///< velocity, other, or empty: from the column (record_is_velocity)
  std::optional<double> rate_Hz, from_s, to_s;
  std::vector<std::string> units;
  std::string json;
  std::string series_out;
  bool no_wolf = false;
  std::string judge = "strict";
  bool jacobian = false;
  bool explain = false;
  bool quiet = false;
  bool no_embedding_spread = false;
  std::optional<std::string> surrogates, seed, verdict_seeds, dimension, delay, theiler;
};

// The command line's analysis settings, each checked and named by its flag.
AnalysisOptions analysis_options(const AnalyzeArgs& a) {
  AnalysisOptions options;
  options.wolf = !a.no_wolf;
  options.paper_judge = a.judge == "paper";
  if (options.paper_judge && a.no_wolf)
    throw Error("--judge", "paper reads Wolf's exponent, which --no-wolf skips");
  options.jacobian = a.jacobian;
  options.embedding_spread = !a.no_embedding_spread;
  options.surrogates.count = surrogate_count_option(a.surrogates, 39);
  if (a.seed) {
    const long long seed = integer_option("--seed", *a.seed, LLONG_MIN);
    options.seed = static_cast<std::uint64_t>(seed);  // negative seeds wrap: any integer
  }
  options.verdict_seeds = option_or(a.verdict_seeds, "--verdict-seeds", 0, 5);
  options.dimension = option_or(a.dimension, "--dimension", 1, 0);
  options.delay = option_or(a.delay, "--delay", 1, 0);
  options.theiler_given = a.theiler.has_value();
  options.theiler = option_or(a.theiler, "--theiler", 0, 0);
  // Checked before the record is read, naming the flag rather than the library's field.
  with_flag_names(FlagNames{{AnalysisOptions::kVerdictSeedsField.id, "--verdict-seeds"}},
                  [&] { options.validate(); });
  return options;
}

// A rest is zero velocity, so stick-slip is judged only on a velocity: as --quantity says,
// else a column named v, vel, velocity or speed (before any "_suffix") or whose unit is a length
// per second; another named column is not; a file without a header is taken as the product's
// records are, a velocity (the verdict's evidence says whether rests were judged).
bool record_is_velocity(const std::string& quantity, const Channel& c) {
  if (!quantity.empty()) return quantity == "velocity";
  static const std::regex unnamed(R"(column [0-9]+)");  // read_csv_series, no header
  if (c.unit.empty() && std::regex_match(c.name, unnamed)) return true;
  std::string name = c.name.substr(0, c.name.find('_'));
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  static const std::regex speed_unit(R"((m|mm|um|µm|cm|km|in|ft)/s)");
  return name == "v" || name == "vel" || name == "velocity" || name == "speed" ||
         std::regex_match(c.unit, speed_unit);
}

// Reads the record, analyses it (with progress on a terminal) and writes the summary, and the
// JSON and the curves together or not at all.
int run_analyze(const AnalyzeArgs& a) {
  const AnalysisOptions options = analysis_options(a);
  CsvSeriesOptions input;
  input.column = a.column;
  input.rate_Hz = a.rate_Hz;
  input.units = parse_unit_overrides(a.units, "--units");
  const TimeSeries series = with_flag_names(
      FlagNames{{kWindowFromField.id, "--from"}, {kWindowToField.id, "--to"}},
      [&] { return time_window(read_csv_series(a.file, input), a.from_s, a.to_s); });
  const Channel& channel = series.channels().front();
  AnalysisOptions chosen = options;
  chosen.velocity = record_is_velocity(a.quantity, channel);
  AnalysisResult r;
  {
    StageProgress progress("analyze", !a.quiet);
    chosen.on_stage = [&progress](const char* stage) { progress.stage(stage); };
    r = analyzed(channel, series.rate_Hz(), chosen, a.file);
  }
  if (chosen.paper_judge) fmt::print("the paper's judge: {}\n", describe(paper_judge(r)));
  fmt::print("{}", analysis_summary(r, channel.name, channel.unit, a.explain));
  // The JSON and the curves appear together or not at all.
  OutputSet outputs;
  if (!a.json.empty()) {
    outputs.add(a.json) << analysis_json(r, a.file, channel.name, channel.unit) << '\n';
  }
  if (!a.series_out.empty()) {
    write_analysis_series(r, channel.values, a.series_out, channel.unit, outputs);
  }
  outputs.commit();
  return kExitOk;
}

}  // namespace

Action add_analyze(CLI::App& app) {
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Chaos indices of a uniformly sampled record (measured or simulated): spectrum, "
      "autocorrelation, embedding, Lyapunov exponents (divergence curve and Wolf 1985), "
      "Poincare section, regime verdict");
  cmd->add_option("file", args->file,
                  "record: CSV with a header, or blank-separated columns with or without one; "
                  "- reads standard input")
      ->required()
      ->check(input_record_check());
  cmd->add_option("--column", args->column,
                  "column to analyse: header name (default v), or its number in a file "
                  "without a header (default 1, unless that column looks like a clock)");
  cmd->add_option("--quantity", args->quantity,
                  "what the column measures: velocity (stick-slip is judged from its rests at "
                  "zero) or other (not judged); default: velocity for a column named v, vel, "
                  "velocity or speed or with a unit of length/s, or in a file without a header; "
                  "other for any other named column")
      ->check(CLI::IsMember({"velocity", "other"}));
  cmd->add_option("--rate", args->rate_Hz,
                  "sample rate [Hz] of a file without a time column (with one, the two must "
                  "agree)");
  add_units_option(cmd, args->units);
  cmd->add_option("--from", args->from_s,
                  "analyse from this time [s] on the record's clock (e.g. 2 to skip a start-up "
                  "transient, as `reproduce` does; default: the first sample)");
  cmd->add_option("--to", args->to_s, "analyse up to this time [s] (default: the last sample)");
  cmd->add_option("--json", args->json, "write every number with its unit as JSON to this file")
      ->check(output_file_check());
  cmd->add_option("--series-out", args->series_out,
                  "directory for the curves as CSV (spectrum, autocorrelation, divergence, "
                  "Wolf running estimate, embedded trajectory, Poincare points, maxima map)")
      ->check(output_directory_check());
  cmd->add_flag("--no-wolf", args->no_wolf, "skip Wolf's estimator");
  cmd->add_option("--judge", args->judge,
                  "strict (default): the regime verdict leads; paper: the paper's three "
                  "indices (spectrum without a dominant line, autocorrelation converging to "
                  "zero, Wolf's exponent positive) lead, Wolf running on every record as the "
                  "paper's did; both are reported either way when Wolf ran")
      ->check(CLI::IsMember({"strict", "paper"}));
  cmd->add_flag("--jacobian-exponents", args->jacobian,
                "also estimate the exponents from local Jacobians (Eckmann & Ruelle 1985), a "
                "second estimate of the largest shown beside the divergence curve's with their "
                "disagreement, and the next exponents (off by default: more work)");
  add_quiet_flag(cmd, args->quiet);
  cmd->add_flag("--explain", args->explain,
                "print the rule that combines the evidence into the verdict (a paragraph)");
  cmd->add_flag("--no-embedding-spread", args->no_embedding_spread,
                "leave out of the divergence exponent's uncertainty its values at embedding "
                "dimensions m - 1 and m + 1 (two fewer divergence curves, about 15 % less work on "
                "a chaotic record)");
  cmd->add_option("--surrogates", args->surrogates,
                  "IAAFT surrogates for the test against linear noise (default 39: a two-sided "
                  "95 % rank test, about 0.5 s for 1e4 samples, up to five times that where "
                  "its outcome could turn the verdict (--verdict-seeds); 0 = off, else 19 to "
                  "999)");
  cmd->add_option("--seed", args->seed,
                  "seed of the surrogates and the 0-1 test's frequencies (any integer; default 1)");
  cmd->add_option("--verdict-seeds", args->verdict_seeds,
                  "seeds the verdict is decided on when the 0-1 test or the surrogates could "
                  "turn it: --seed and the next ones; the majority's regime is reported, with "
                  "the tally (odd, 1 to 99; default 5; 1: the first seed alone)");
  cmd->add_option("--dimension", args->dimension, "embedding dimension (>= 1; default: Cao)");
  cmd->add_option("--delay", args->delay,
                  "embedding delay in samples (>= 1; default: mutual information)");
  cmd->add_option("--theiler", args->theiler,
                  "Theiler window in samples (>= 0; default: max(delay, first ACF zero))");
  return [args]() { return run_analyze(*args); };
}

}  // namespace pneumachaos::cli
