// `pneumachaos reproduce`: the paper's figures and claims from built-in defaults (or a rig of
// the user's), as a report.

#include <fmt/format.h>

#include <filesystem>

#include "commands.hpp"
#include "interrupt_hint.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/report/reproduce.hpp"

namespace pneumachaos::cli {

// How the page names a rig given on the command line.
std::string rig_source(const ScenarioArgs& a) {
  std::string s = a.file.empty() ? std::string("the built-in scenario") : "the scenario " + a.file;
  for (std::size_t i = 0; i < a.sets.size(); ++i) s += (i == 0 ? " with " : ", ") + a.sets[i];
  return s;
}

Action add_reproduce(CLI::App& app) {
  auto o = std::make_shared<ReproduceOptions>();
  auto rig = std::make_shared<ScenarioArgs>();
  CLI::App* cmd = app.add_subcommand(
      "reproduce",
      "Reproduce the paper's Figs. 2-7 and claims from the built-in virtual rig, or from a rig "
      "given as a scenario file: an HTML report with every figure's data and gnuplot script "
      "(resumes its sweeps when run again)");
  add_scenario_options(cmd, *rig);
  cmd->add_option("--out", o->out_dir, "report directory (default: report)")
      ->check(output_directory_check());
  cmd->add_flag("--quick", o->quick,
                "coarse grid and short records: the whole report in under a minute");
  cmd->add_flag("--full-maps", o->full_maps,
                "simulate every point of every map (about twice the runs) instead of refining "
                "the maps adaptively at their borders");
  cmd->add_option("--threads", o->threads, "worker threads for the sweeps (default: all cores)");
  return [o, rig]() {
    if (!rig->file.empty() || !rig->sets.empty()) {
      o->rig = build_scenario(rig->file, rig->sets);
      o->rig_source = rig_source(*rig);
    }
    // Its sweeps keep their finished runs: running the command again resumes them.
    const InterruptHint hint(fmt::format(
        "\nreproduce: interrupted; the finished sweep runs are kept in {}: run the same command "
        "again to continue the report from them\n",
        (std::filesystem::path(o->out_dir) / "sweeps").string()));
    const ReproduceResult r = reproduce(*o);
    fmt::print("reproduce: {} figures; {}; {}; report: {}\n", r.figures.size(),
               claims_headline(count_claims(r.claims)),
               both_judges_headline(count_claims(r.claims), count_claims(r.paper_claims)),
               r.index_html);
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
