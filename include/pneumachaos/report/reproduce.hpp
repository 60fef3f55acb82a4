#pragma once
// `reproduce`: the paper's figures and claims from built-in defaults (or a rig of the user's),
// as a self-contained HTML report with every figure's data and gnuplot script beside it.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/claims/claims.hpp"
#include "pneumachaos/plot/figure.hpp"

namespace pneumachaos {

struct ReproduceOptions {
  std::string out_dir = "report";
  /// The rig the maps, Figs. 3 and 7 and the linear trends run on, under the paper's
  /// conditions (Ps and the total moving mass set per figure); none: the built-in virtual rig.
  /// Fig. 2 always runs the paper's own model.
  std::optional<Scenario> rig;
  /// How the page names that rig (a file and its overrides); used only with `rig`.
  std::string rig_source;
  /// A coarse grid (6 x 7 points, 2 repeats, 5 s records) and shorter averages: the whole
  /// report in well under a minute. Full: the paper's grids, 5 repeats, 10 s records.
  bool quick = false;
  /// Every point of every map simulated (about twice the runs); by default the maps are
  /// refined adaptively (docs/sweep.md, "Adaptive maps") and the uniform cells inferred.
  bool full_maps = false;
  std::size_t threads = 0;
  bool progress = true;  ///< stage lines on a terminal only
  /// Called as on_progress(done, total) with the sweep runs of the whole report done so far
  /// (total: an upper bound with adaptive maps), from the sweeps' worker threads; for a
  /// caller that shows progress its own way (the Python module). Empty: not called.
  std::function<void(std::size_t done, std::size_t total)> on_progress;
  /// Throws Error naming the field that is out of range (an empty out_dir).
  void validate() const;
};

struct ReproduceResult {
  std::vector<FigureFiles> figures;
  std::vector<Claim> claims;
  /// The same rows with the paper's judge deciding which runs are chaotic (under_paper_judge).
  std::vector<Claim> paper_claims;
  std::string index_html;  ///< path of the report
};

/// Builds the report; sweeps live in out_dir/sweeps and are resumed when the command is run
/// again after an interruption. Throws Error for an unusable out_dir or a failed figure.
ReproduceResult reproduce(const ReproduceOptions& options);

/// The HTML page for a set of figures and claims (relative links into figures/).
/// `rig_source`: empty for the built-in virtual rig (the page explains it), else how the
/// user's rig was given. `paper_claims` (when given): the rows under the paper's judge, whose
/// count joins the headline and whose chaos rows get a table of their own.
std::string report_html(const std::vector<FigureFiles>& figures, const std::vector<Claim>& claims,
                        const std::string& scenario_toml, const std::string& settings,
                        const std::string& rig_source = "",
                        const std::vector<Claim>& paper_claims = {});

}  // namespace pneumachaos
