// `pneumachaos reproduce`: the paper's figures and claims from built-in defaults, as a report.

#include <fmt/format.h>

#include "commands.hpp"
#include "pneumachaos/report/reproduce.hpp"

namespace pneumachaos::cli {

Action add_reproduce(CLI::App& app) {
  auto o = std::make_shared<ReproduceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reproduce",
      "Reproduce the paper's Figs. 2-7 and claims from the built-in virtual rig: an HTML report "
      "with every figure's data and gnuplot script (resumes its sweeps when run again)");
  cmd->add_option("--out", o->out_dir, "report directory (default: report)")
      ->check(output_directory_check());
  cmd->add_flag("--quick", o->quick,
                "coarse grid and short records: the whole report in under a minute");
  cmd->add_flag("--full-maps", o->full_maps,
                "simulate every point of every map (about twice the runs) instead of refining "
                "the maps adaptively at their borders");
  cmd->add_option("--threads", o->threads, "worker threads for the sweeps (default: all cores)");
  return [o]() {
    const ReproduceResult r = reproduce(*o);
    fmt::print("reproduce: {} figures; {}; report: {}\n", r.figures.size(),
               claims_headline(count_claims(r.claims)), r.index_html);
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
