// `pneumachaos calibrate SPEC.toml --out DIR`: fits a spec's free scenario keys with pagmo2's
// CMA-ES or xNES (docs/guide/calibrate.md).

#include <fmt/format.h>

#include "commands.hpp"
#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos::cli {
namespace {

struct CalibrateArgs {
  std::string spec;
  CalibrateOptions options;
};

void print_result(const CalibrationResult& r, const std::string& out) {
  const auto agreeing = [](const std::vector<ScoredClaim>& rows) {
    std::size_t n = 0;
    for (const ScoredClaim& s : rows) n += s.claim.verdict == kAgrees ? 1 : 0;
    return n;
  };
  std::string fitted = fmt::format("fitted claims agreeing {} of {}", agreeing(r.fitted), r.fitted.size());
  if (!r.record_errors.empty()) {
    fitted = "record errors";
    for (const double e : r.record_errors) fitted += fmt::format(" {:.4g}", e);
  }
  fmt::print("calibrate: {} evaluations; best: evaluation {}, objective {:.4f}; {}, predicted {} "
             "of {}; results in {}\n",
             r.evaluations, r.best, r.best_objective, fitted, agreeing(r.predicted),
             r.predicted.size(), out);
}

}  // namespace

Action add_calibrate(CLI::App& app) {
  auto a = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate",
      "Fit a spec's free scenario keys (each bound with its source) to the paper's claims, a "
      "measured incidence map or measured records with pagmo2's CMA-ES; journalled and "
      "resumable");
  cmd->add_option("spec", a->spec, "the calibration spec (TOML; docs/guide/calibrate.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", a->options.out_dir, "directory for the journal and the results")
      ->required()
      ->check(output_directory_check());
  cmd->add_option("--threads", a->options.threads, "worker threads of the sweeps (default 0: all cores)")
      ->check(CLI::Range(0, 4096));
  cmd->add_flag("--resume", a->options.resume,
                "continue the calibration in --out (journalled evaluations are replayed)");
  return [a]() {
    const CalibrationSpec spec = read_calibration_spec(a->spec);
    const CalibrationResult r = calibrate(spec, a->options);
    if (r.wrote_files) print_result(r, a->options.out_dir);  // else another MPI rank reports
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
