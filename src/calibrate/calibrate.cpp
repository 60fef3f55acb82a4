// calibrate's driver: the optimizer's loop over journalled evaluations, then the best point
// with the predictions, then the outputs (docs/guide/calibrate.md).
#include "pneumachaos/calibrate/calibrate.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "pneumachaos/sweep/distribution.hpp"
#include "calibration_outputs.hpp"
#include "claim_requirements.hpp"
#include "evaluation_journal.hpp"
#include "evaluator.hpp"
#include "calibrate/optimizer.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"
#include "pneumachaos/io/atomic_file.hpp"

namespace pneumachaos {
namespace {

namespace fs = std::filesystem;

// An --out that exists must be empty or hold this calibration (with --resume): anything else
// is refused rather than mixed with the calibration's files.
void check_out_dir(const CalibrateOptions& o) {
  std::error_code ec;
  if (!fs::exists(o.out_dir, ec) || fs::is_empty(o.out_dir, ec)) return;
  const fs::path dir(o.out_dir);
  if (!fs::exists(dir / "journal.csv", ec) && !fs::exists(dir / "sweeps", ec))
    throw Error(o.out_dir, "exists and is not a calibration directory (no journal.csv or "
                           "sweeps/); choose a new or empty directory");
  if (!o.resume)
    throw Error(o.out_dir, "holds a calibration already: pass --resume to continue it (its "
                           "evaluations are replayed), or choose a new directory");
}

// The working sweeps of the evaluations before `current`: finished and journalled. The caller
// has passed a barrier of all ranks first, so no rank still reads them.
void remove_old_work(const std::string& sweeps, std::size_t current) {
  std::error_code ec;
  for (const auto& d : fs::directory_iterator(sweeps, ec)) {
    const std::string name = d.path().filename().string();
    if (name.size() != 10 || name.rfind("eval_", 0) != 0 ||
        name.find_first_not_of("0123456789", 5) != std::string::npos)
      continue;
    if (std::stoul(name.substr(5)) < current) fs::remove_all(d.path(), ec);
  }
}

class Loop {
 public:
  Loop(const CalibrationSpec& spec, const CalibrateOptions& o, detail::Evaluator& ev,
       detail::EvaluationJournal& journal)
      : spec_(spec), o_(o), ev_(ev), journal_(journal),
        show_(o.progress && ::isatty(STDERR_FILENO) != 0 && detail::is_writer_rank()) {}

  double operator()(const std::vector<double>& u) {
    const std::size_t k = asked_++;
    const auto& done = journal_.entries();
    if (k < done.size()) {
      for (std::size_t i = 0; i < u.size(); ++i)
        if (detail::exact_text(u[i]) != detail::exact_text(done[k].u[i]))
          throw Error(o_.out_dir + "/journal.csv",
                      fmt::format("evaluation {} was journalled at another point: the journal "
                                  "was not written by this spec and seed", k));
      best_ = std::min(best_, done[k].objective);
      if (k + 1 == done.size()) note(fmt::format("replayed {} journalled evaluations", done.size()));
      return done[k].objective;
    }
    const std::string sweeps = o_.out_dir + "/sweeps";
    detail::Distribution::instance().barrier();  // every rank has finished evaluation k - 1
    if (detail::is_writer_rank()) remove_old_work(sweeps, k);
    const detail::Evaluation e = ev_.evaluate(u, fmt::format("{}/eval_{:05}", sweeps, k));
    journal_.append({u, e.objective, e.terms});
    best_ = std::min(best_, e.objective);
    note(fmt::format("evaluation {} of {}: objective {:.4f} (best so far {:.4f})", k + 1,
                     spec_.optimizer.evaluations(), e.objective, best_));
    return e.objective;
  }

 private:
  void note(const std::string& line) const {
    if (show_) fmt::print(stderr, "calibrate: {}\n", line);
  }
  const CalibrationSpec& spec_;
  const CalibrateOptions& o_;
  detail::Evaluator& ev_;
  detail::EvaluationJournal& journal_;
  bool show_;
  std::size_t asked_ = 0;
  double best_ = 1e300;
};

std::string measured_text_hash(const std::string& path) {
  if (path.empty()) return "";
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return detail::stable_hash(ss.str());
}

// The measured records of a records objective, read once (their errors name file:line), in
// the units and absolute pressures the fit uses; the [fixed] scenario gives the ambient
// pressure for gauge columns and the stroke for the travel check.
std::vector<identify::MeasuredRecord> read_records(const CalibrationSpec& spec) {
  std::vector<identify::MeasuredRecord> out;
  for (const RecordCondition& r : spec.objective.records) {
    std::error_code ec;
    if (!fs::is_regular_file(r.file, ec))
      throw Error(r.where, fmt::format("file = \"{}\": {}", r.file,
                                       fs::exists(r.file, ec) ? "not a regular file"
                                                              : "no such file (paths are relative "
                                                                "to the spec's folder)"));
    identify::RecordReadOptions read = identify::read_options_for(spec.base);
    if (r.Ps_MPa) read.plausible.supply_Pa = spec.base.ambient_pressure_Pa + *r.Ps_MPa * 1e6;
    read.units = r.units;
    out.push_back(identify::read_measured_record(r.file, identify::RecordColumns{}, read));
  }
  return out;
}

}  // namespace

void CalibrateOptions::validate() const {
  const ErrorField out = validation::field("calibrate.out_dir");
  if (out_dir.empty()) throw Error(out, "", "name the calibration's output directory");
  const std::string problem = output_directory_problem(out_dir);
  if (!problem.empty()) throw Error(out, " = " + out_dir, problem);
  validation::require_le(validation::field("calibrate.threads"), static_cast<double>(threads), 4096);
}

CalibrationResult calibrate(const CalibrationSpec& spec, const CalibrateOptions& o) {
  o.validate();
  spec.validate();
  check_out_dir(o);
  std::optional<MeasuredMap> measured;
  if (spec.objective.kind == ObjectiveKind::kIncidenceMap)
    measured = read_measured_map(spec.objective.measured_map);
  std::vector<identify::MeasuredRecord> records = read_records(spec);
  // Under MPI every rank has looked at --out before any rank creates something in it.
  detail::Distribution::instance().barrier();
  std::error_code ec;
  fs::create_directories(o.out_dir + "/sweeps", ec);
  if (ec) throw RunError(o.out_dir, "cannot create the calibration directory: " + ec.message());
  detail::Evaluator ev(spec, {o.threads, 1}, measured, std::move(records));
  const std::vector<std::string> terms = ev.term_names();
  std::string inputs = measured_text_hash(spec.objective.measured_map);
  for (const RecordCondition& r : spec.objective.records) inputs += measured_text_hash(r.file);
  detail::EvaluationJournal journal(o.out_dir + "/journal.csv", spec.fingerprint() + inputs,
                                    spec.free.size(), terms.size(), detail::is_writer_rank());
  // Every rank has read the journal before the writer appends to it.
  detail::Distribution::instance().barrier();
  Loop loop(spec, o, ev, journal);
  const OptimizerTrace trace = minimize(spec.optimizer, spec.free.size(), std::ref(loop));
  CalibrationResult r = detail::best_point_result(spec, trace, journal.entries(),
                                                  o.out_dir + "/sweeps/best", {o.threads, 1});
  detail::Distribution::instance().barrier();  // no rank still reads an evaluation's sweeps
  r.wrote_files = detail::is_writer_rank();
  if (r.wrote_files) {
    detail::write_calibration_outputs(spec, trace, journal.entries(), terms, r, o.out_dir);
    remove_old_work(o.out_dir + "/sweeps", trace.f.size());
  }
  return r;
}

}  // namespace pneumachaos
