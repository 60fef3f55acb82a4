#pragma once
// Sweeps (paper Figs. 4-6): repeated runs over a grid of scenario parameters, each run
// simulated and then judged by the analysis exactly as a measured record would be.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

/// The model's own finite-time exponent per run (plant_lyapunov, docs/notes/virtual_rig.md): after
/// the start-up transient, over the rest of the run (to its stroke end or its duration).
struct ModelExponentSpec {
  bool enabled = false;
  double transient_s = 1.0;  ///< discarded first (the start-up from rest)
  double measure_s = 0.0;    ///< at most this long; 0: the rest of the run
  double renormalize_s = 0.02;
  static constexpr ErrorField kTransientField{"sweep.model_exponent.transient_s",
                                              "model exponent transient"};
  static constexpr ErrorField kMeasureField{"sweep.model_exponent.measure_s",
                                            "model exponent measure"};
  static constexpr ErrorField kRenormalizeField{"sweep.model_exponent.renormalize_s",
                                                "model exponent renormalize"};
  /// Checks the settings against a run of `duration_s`, naming the fields above.
  void validate(double duration_s) const;
  /// The options of plant_lyapunov for a run of `duration_s`.
  [[nodiscard]] ModelLyapunovOptions options(double duration_s) const;
};

/// Adaptive refinement of a two-axis map (sweep --adaptive, GridRefinement, docs/sweep.md
/// "Adaptive maps"): the coarse lattice first, then only the cells whose points differ in what
/// the map shows, down to the grid's own step; every other point is inferred from its cell.
struct AdaptiveSpec {
  bool enabled = false;
  std::size_t coarse_step = 4;  ///< grid steps between the first lattice's lines, >= 1
  /// Also refine where the motion changes between settling and oscillating (point_motion):
  /// needed where a point's regime is read, not only its stick-slip and chaos classes (the
  /// report's sign rule); about twice the runs on the paper's maps.
  bool follow_motion = false;
  static constexpr ErrorField kEnabledField{"sweep.adaptive", "adaptive"};
  static constexpr ErrorField kCoarseStepField{"sweep.adaptive.coarse_step", "adaptive step"};
  /// When enabled: throws Error naming the field unless the map has exactly two axes and
  /// coarse_step >= 1.
  void validate(std::size_t axes) const;
};

struct SweepSpec {
  Scenario base;
  std::vector<GridAxis> axes;  ///< default: the paper's S1 x S2 grid
  std::size_t repeats = 5;
  std::uint64_t seed = 1;
  bool wolf = false;  ///< also run Wolf's estimator per run (slower; the verdict does not use it)
  /// Also judge every run by the paper's three indices (paper_judge.hpp) beside the verdict;
  /// they read Wolf's exponent, so this runs Wolf's estimator whatever `wolf` says.
  bool paper_judge = false;
  /// IAAFT surrogates per run for the verdict's determinism test (0 = off, as in the library:
  /// 39 cost about 1.2 s of CPU per 10 s rig run); seeded as `analyze`'s default, so
  /// `analyze --surrogates N` on a replayed record gives the run's verdict.
  std::size_t surrogates = 0;
  ModelExponentSpec model_exponent;  ///< two more trajectories per run at tight tolerances
  AdaptiveSpec adaptive;  ///< needs exactly two axes; part of the fingerprint when enabled
  static constexpr ErrorField kRepeatsField{"sweep.repeats", "repeats"};
  /// Throws Error naming the field (the fields above, kGridField, ModelExponentSpec's).
  void validate() const;
  /// What a user should know before the runs start, one sentence each: repeats that are
  /// identical copies (no run-to-run variation set or gridded), so every incidence is 0 or 1.
  [[nodiscard]] std::vector<std::string> warnings() const;
  [[nodiscard]] std::size_t points() const { return grid_size(axes); }
  [[nodiscard]] std::size_t runs() const { return points() * repeats; }
  /// Whether each run gets Wolf's estimator: asked for, or read by the paper's judge.
  [[nodiscard]] bool runs_wolf() const { return wolf || paper_judge; }
  /// Identifies the spec: a resume with another spec is refused.
  [[nodiscard]] std::string fingerprint() const;
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// One finished run, as stored (no wall times: result files are identical on every machine).
struct RunRecord {
  std::size_t point = 0, repeat = 0;
  std::uint64_t seed = 0;
  bool ok = true;      ///< false: the run failed (invalid parameters, solver failure)
  std::string reason;  ///< why it failed, or why the analysis could not judge it
  std::string termination;
  double t_final_s = kNaN;
  std::size_t steps = 0, sticks = 0;
  double mean_v = kNaN, std_v = kNaN;                            ///< [m/s]
  double lambda = kNaN, lambda_uncertainty = kNaN, wolf = kNaN;  ///< [1/s]
  double broadband = kNaN, late_acf = kNaN;
  std::string regime = "undetermined";
  bool chaotic = false, stick_slip = false;
  double zero_one_K = kNaN;        ///< the 0-1 test's median K (NaN: not run)
  double prediction_ratio = kNaN;  ///< local-constant / linear prediction error
  double repeat_share = kNaN;  ///< share of the record over which it repeats itself (veto)
  /// The model's own exponent and its standard error (NaN: not asked for, or not measurable;
  /// `reason` then says why) and the time it spans.
  double lambda_model = kNaN, lambda_model_uncertainty = kNaN, lambda_model_span_s = kNaN;
  /// The paper's judge (SweepSpec::paper_judge): chaotic or not; none when not asked for or
  /// when an index could not be computed (no ACF lag of 1 s, no Wolf exponent).
  std::optional<bool> paper_chaotic;

  [[nodiscard]] std::size_t index(std::size_t repeats) const { return point * repeats + repeat; }
  /// Fields of an encoded record (one table in run_record.cpp gives the header, the writer and
  /// the reader); part of the journal's header, so a journal written in another record format
  /// is refused as such.
  static const std::size_t kFields;
  [[nodiscard]] std::string encode() const;          ///< one CSV line, doubles round-trip exactly
  static RunRecord decode(const std::string& line);  ///< throws Error for a malformed line
  static std::string csv_header();
  /// Each column of runs.csv with this run's value as encode() writes it, in the file's order.
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> named_fields() const;
};

/// Simulates and analyses run `repeat` of grid point `point`. Never throws for a bad point or
/// a failed run: that is a record with ok = false and the reason.
RunRecord run_one(const SweepSpec& spec, std::size_t point, std::size_t repeat);

/// One run as the sweep sees it: the point's scenario with the run's seeded variation, its
/// simulation with the measured channels (v_measured, P1_measured, P2_measured: through the
/// scenario's transducers, noise seeded by the run's seed), and the velocity the analysis
/// judges, v_measured. Throws Error for a point whose parameters are invalid.
struct SweepRun {
  std::size_t point = 0, repeat = 0;
  std::uint64_t seed = 0;
  Scenario scenario;
  SimulationResult sim;
  std::vector<double> measured_v;  ///< [m/s], v_measured; empty when the simulation failed
};
SweepRun simulate_run(const SweepSpec& spec, std::size_t point, std::size_t repeat);

/// The record of a simulated run: what run_one stores for it.
RunRecord judge_run(const SweepSpec& spec, const SweepRun& run);

/// run_one, handing each simulated run to `observe` before it is judged (not called when the
/// simulation throws): for a caller that keeps what runs.csv does not, such as the record.
/// Runs on the caller's thread; observe must not throw.
RunRecord run_one(const SweepSpec& spec, std::size_t point, std::size_t repeat,
                  const std::function<void(const SweepRun&)>& observe);

/// One run of the sweep again, bit for bit (`sweep --replay`, the Python module's replay): the
/// spec validated, the run simulated and judged. Throws Error named `name` (what the user
/// typed) for a run outside the sweep's points and repeats.
std::pair<SweepRun, RunRecord> replay_run(const SweepSpec& spec, std::size_t point,
                                          std::size_t repeat, const std::string& name);

struct PointSummary {
  std::size_t point = 0;
  std::vector<double> coordinates;
  std::size_t runs = 0, failed = 0;
  double stick_slip_incidence = 0.0;  ///< fraction of the successful runs
  double chaos_incidence = 0.0;
  /// Fraction of the successful runs with each regime, in the order of sweep_regime_names().
  std::vector<double> regime_incidence;
  double mean_v = kNaN, mean_lambda = kNaN;
  /// The model's exponent (--model-exponent): the mean over the runs that measured it, the
  /// standard error of that mean from the runs' own uncertainties, and the fraction of the
  /// successful runs whose exponent is positive beyond 3 of its standard errors.
  double mean_lambda_model = kNaN, lambda_model_uncertainty = kNaN;
  double model_chaos_incidence = kNaN;
  /// The paper's judge: the fraction of the successful runs it calls chaotic (a run it could
  /// not judge counts as not chaotic, as an undetermined verdict does); NaN when no run of the
  /// sweep was judged by it.
  double paper_chaos_incidence = kNaN;
  /// Adaptive maps: not evaluated (runs 0, NaN means) but filled from the evaluated point of
  /// its cell named by GridRefinement::sources(): its incidences, hence its classes.
  bool inferred = false;
  /// On the coarse lattice: every `SweepSpec::adaptive.coarse_step`-th value of each of two
  /// axes and its last (every point of a sweep over another number of axes), run by the full
  /// grid and by every adaptive map alike. What a map's refinement does not follow — a point's motion — is
  /// counted on these points (the report's sign rule and damping rows).
  bool on_lattice = true;
};

/// What a map shows at a point (also for an inferred one): stick-slip in at least half of its
/// successful runs (the stick-slip region); chaos in none, some or all of them.
enum class ChaosClass { kNone = 0, kSome = 1, kAll = 2 };
bool in_stick_slip_region(const PointSummary& p);
ChaosClass chaos_class(const PointSummary& p);
/// Whether the motion settles at a point: undecided when fewer than half of its successful
/// runs got a determined regime (short or irregular records), else steady when most of its
/// determined runs are steady, oscillating otherwise (the paper's damped / self-excited).
enum class Motion { kUndecided = 0, kSteady = 1, kOscillating = 2 };
Motion point_motion(const PointSummary& p);

/// Every regime name a run can carry (columns of points.csv).
const std::vector<std::string>& sweep_regime_names();

struct SweepSummary {
  std::size_t runs = 0, failed = 0, points = 0;
  std::size_t stick_slip_points = 0;  ///< points with stick-slip in at least half of the runs
  std::size_t chaos_full_points = 0;  ///< points chaotic in every run (the paper's black)
  std::size_t chaos_any_points = 0;   ///< points chaotic in at least one run
  /// With the model's exponent: points where it is beyond 3 sigma in every / in some run.
  std::size_t model_chaos_full_points = 0, model_chaos_any_points = 0;
  /// With the paper's judge: points it calls chaotic in every / in some run.
  std::size_t paper_chaos_full_points = 0, paper_chaos_any_points = 0;
  /// Adaptive maps: points filled from their cell, not evaluated (runs counts only evaluated
  /// runs; the region counts above include the inferred points).
  std::size_t inferred_points = 0;
  std::vector<PointSummary> per_point;
  bool wrote_files = true;  ///< false on the MPI ranks other than 0
};

/// Incidence per point and the map's region areas, from records sorted by (point, repeat).
SweepSummary summarize(const SweepSpec& spec, const std::vector<RunRecord>& records);

/// An adaptive map's summary: `summarize` of the evaluated points' records, with every point p
/// whose source[p] != p (GridRefinement::sources) filled from that point and marked inferred.
SweepSummary summarize_adaptive(const SweepSpec& spec, const std::vector<RunRecord>& records,
                                const std::vector<std::size_t>& source);

/// The same map with the paper's judge in the verdict's place: every point's chaos incidence
/// is its paper_chaos_incidence and the chaos regions are counted from it; stick-slip, the
/// regimes and everything else stay as they are (the same runs, judged twice). Throws Error
/// when the sweep did not run the paper's judge.
SweepSummary under_paper_judge(const SweepSummary& s);

}  // namespace pneumachaos
