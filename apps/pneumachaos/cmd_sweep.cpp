// `pneumachaos sweep`: repeated runs over a grid, each judged by the analysis; resumable.

#include <fmt/format.h>
#include <unistd.h>

#include <charconv>
#include <csignal>
#include <optional>

#include "commands.hpp"
#include "interrupt_hint.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

namespace pneumachaos::cli {
namespace {

std::size_t replay_index(const std::string& text, std::size_t pos, std::size_t end) {
  std::size_t v = 0;
  const auto [p, ec] = std::from_chars(text.data() + pos, text.data() + end, v);
  if (ec != std::errc() || p != text.data() + end || pos == end) {
    throw Error("--replay", fmt::format("expected POINT:REPEAT (whole numbers), got \"{}\"", text));
  }
  return v;
}

// One run of the sweep again, bit for bit: the record the analysis judged (the simulated
// channels plus the measured ones, v_measured, P1_measured and P2_measured, through the
// transducers) and its runs.csv line.
int replay(const SweepSpec& spec, const std::string& which, const std::string& path) {
  spec.validate();
  const auto colon = which.find(':');
  if (colon == std::string::npos) replay_index(which, 0, 0);  // throws the usage message
  const std::size_t point = replay_index(which, 0, colon);
  const std::size_t repeat = replay_index(which, colon + 1, which.size());
  const auto [run, r] = replay_run(spec, point, repeat, "--replay");
  fmt::print(stderr, "sweep: run {}:{} replayed; as runs.csv records it:\n", point, repeat);
  for (const auto& [name, value] : r.named_fields())
    fmt::print(stderr, "  {:<22} {}\n", name, value);
  if (!run.sim.summary.ok()) return kExitRunFailed;
  return write_series_csv(run.sim.series, path);
}

struct SweepArgs {
  ScenarioArgs scenario;
  std::vector<std::string> grids;
  std::optional<std::size_t> repeats;
  std::optional<std::uint64_t> seed;
  std::size_t threads = 0;
  std::string out;
  bool resume = false;
  bool wolf = false;
  std::string judge = "strict";
  std::optional<std::string> surrogates;
  ModelExponentSpec model;
  AdaptiveSpec adaptive;
  std::string replay;
  std::string record;
};

void add_model_exponent_options(CLI::App* cmd, ModelExponentSpec& model) {
  CLI::Option* flag =
      cmd->add_flag("--model-exponent", model.enabled,
                    "also store each run's model exponent (as `lyapunov`) over the rest of its "
                    "stroke, with its uncertainty (about 1.5x the time per run)");
  cmd->add_option("--model-transient", model.transient_s,
                  "with --model-exponent: seconds of start-up discarded (default 1)")
      ->needs(flag);
  cmd->add_option("--model-measure", model.measure_s,
                  "with --model-exponent: at most this many seconds measured (default 0: the "
                  "rest of the run, to its stroke end)")
      ->needs(flag);
  cmd->add_option("--model-renormalize", model.renormalize_s,
                  "with --model-exponent: renormalisation interval [s] (default 0.02)")
      ->needs(flag);
}

void add_sweep_options(CLI::App* cmd, SweepArgs& a) {
  add_scenario_options(cmd, a.scenario);
  cmd->add_option("--grid", a.grids, "grid axis KEY=FROM:TO:STEP in the key's unit (repeatable)");
  cmd->add_option(
      "--repeats", a.repeats,
      "runs per grid point (default: the file's [sweep] repeats, else 5 as in the paper)");
  cmd->add_option("--seed", a.seed, "seed of the run-to-run variation (default 1)");
  cmd->add_option("--threads", a.threads, "worker threads (default 0: all cores)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--out", a.out, "directory for the journal and the results")
      ->check(output_directory_check());
  cmd->add_flag("--resume", a.resume, "finish an interrupted sweep in --out");
  cmd->add_flag("--wolf", a.wolf, "also run Wolf's estimator on every record (slower)");
  cmd->add_option("--judge", a.judge,
                  "strict (default): the regime verdict alone; paper: every run also judged by "
                  "the paper's three indices (spectrum without a dominant line, autocorrelation "
                  "converging to zero, Wolf's exponent positive; implies --wolf): runs.csv "
                  "paper_chaotic, points.csv paper_chaos_incidence")
      ->check(CLI::IsMember({"strict", "paper"}));
  cmd->add_option("--surrogates", a.surrogates,
                  "IAAFT surrogates per record for the verdict's test against linear noise, as "
                  "in `analyze`: 0 (default, off) or 19 to 999; 39 add about 1.2 s of CPU per 10 s "
                  "run");
  add_model_exponent_options(cmd, a.model);
  CLI::Option* adaptive = cmd->add_flag(
      "--adaptive", a.adaptive.enabled,
      "for a map over two axes: run a coarse lattice of the grid, then refine only the cells "
      "whose points differ (stick-slip, chaos in none / some / all runs, failed runs) down to "
      "the grid's step; the other points are inferred from their cell (points.csv: inferred)");
  cmd->add_flag("--adaptive-motion", a.adaptive.follow_motion,
                "with --adaptive: also refine where the motion changes between settling and "
                "oscillating, so an inferred point's regime can be read (about twice the runs)")
      ->needs(adaptive);
  cmd->add_option("--adaptive-step", a.adaptive.coarse_step,
                  "with --adaptive: grid steps between the coarse lattice's lines (default 4); "
                  "a region narrower than this between the lattice's points can be missed")
      ->needs(adaptive);
  cmd->add_option("--replay", a.replay,
                  "POINT:REPEAT: run only that run of this sweep again (same grid, repeats, seed "
                  "and analysis options such as --surrogates) and write its record; its "
                  "runs.csv line goes to standard error");
  cmd->add_option("-o,--record", a.record,
                  "with --replay: CSV file for the record (default: standard output)")
      ->check(output_file_check());
}

// The command line wins over the scenario file's [sweep] table, which wins over defaults.
SweepSpec sweep_spec_from(const SweepArgs& a) {
  SweepSpec spec;
  spec.base = build_scenario(a.scenario.file, a.scenario.sets);
  const SweepFileSpec file =
      a.scenario.file.empty() ? SweepFileSpec{} : read_sweep_file_spec(a.scenario.file);
  for (const auto& g : a.grids.empty() ? file.grid : a.grids) spec.axes.push_back(parse_grid_axis(g));
  if (spec.axes.empty()) spec.axes = paper_valve_grid();
  spec.repeats = a.repeats.value_or(file.repeats.value_or(5));
  spec.seed = a.seed.value_or(file.seed.value_or(1));
  spec.wolf = a.wolf;
  spec.paper_judge = a.judge == "paper";
  spec.surrogates = surrogate_count_option(a.surrogates, 0);
  spec.model_exponent = a.model;
  spec.adaptive = a.adaptive;
  return spec;
}

void print_sweep_summary(const SweepSpec& spec, const SweepSummary& s, const std::string& out) {
  fmt::print(
      "sweep: {} points x {} repeats = {} runs ({} failed); stick-slip region {} points, "
      "100 %-chaos region {} points, chaos anywhere {} points; results in {}\n",
      s.points, spec.repeats, s.runs, s.failed, s.stick_slip_points, s.chaos_full_points,
      s.chaos_any_points, out);
  if (spec.adaptive.enabled) {
    fmt::print("adaptive: {} of {} points evaluated, {} inferred; {} of the full grid's {} runs\n",
               s.points - s.inferred_points, s.points, s.inferred_points, s.runs, spec.runs());
  }
  if (spec.paper_judge) {
    fmt::print("the paper's judge: 100 %-chaos region {} points, chaos anywhere {} points\n",
               s.paper_chaos_full_points, s.paper_chaos_any_points);
  }
  if (spec.model_exponent.enabled) {
    fmt::print(
        "model exponent beyond 3 sigma: in every run at {} points, in some run at {} "
        "points\n",
        s.model_chaos_full_points, s.model_chaos_any_points);
  }
}

}  // namespace

Action add_sweep(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Repeated runs over a parameter grid (default: the paper's S1 x S2 grid, 5 repeats), "
      "each simulated and judged stick-slip / chaotic from its velocity record; resumable");
  add_sweep_options(cmd, *args);
  return [args]() {
    const SweepSpec spec = sweep_spec_from(*args);
    if (!args->replay.empty()) return replay(spec, args->replay, args->record);
    if (!args->record.empty()) throw Error("--record", "needs --replay");
    for (const auto& w : spec.warnings()) fmt::print(stderr, "sweep: warning: {}\n", w);
    SweepOptions options;
    options.out_dir = args->out;
    options.resume = args->resume;
    options.threads = args->threads;
    std::optional<InterruptHint> hint;
    if (!args->out.empty())
      hint.emplace(
          fmt::format("\nsweep: interrupted; the finished runs are kept in {}: run the same "
                      "command with --resume to finish the sweep\n",
                      args->out));
    const SweepSummary s = run_sweep(spec, options);
    if (!s.wrote_files) return kExitOk;  // another MPI rank reports
    print_sweep_summary(spec, s, args->out);
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
