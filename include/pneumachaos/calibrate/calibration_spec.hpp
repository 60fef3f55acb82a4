#pragma once
// A calibration as the user writes it (SPEC.toml, docs/guide/calibrate.md): the free scenario
// keys with their bounds and each bound's source, the fixed settings, the objective, the
// conditions predicted out of sample at the best point, and the optimizer's settings.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/io/column_units.hpp"
#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos {

/// One free scenario key, searched within [lower, upper] (user units, as the key table).
struct FreeParameter {
  std::string key;
  double lower = 0.0, upper = 0.0;
  bool log_scale = false;  ///< searched uniformly in log(value); needs lower > 0
  std::string source;      ///< the paper, catalogue or measurement that bounds it
  std::string where;       ///< file:line of its entry, for errors
  /// The value at position u in [0, 1] of the searched interval.
  [[nodiscard]] double value(double u) const;
};

/// A map condition: the S1 x S2 map at supply pressure Ps and total moving mass m, in the
/// role the claims read it (the paper's Fig. 4 = base, Fig. 5 = high_ps, Fig. 6 = double_m,
/// 4.5 kg = triple_m).
struct MapCondition {
  std::string role;
  double Ps_MPa = 0.25, m_kg = 1.5;
  std::string where;
};

struct ClaimWeight {
  std::string id;  ///< a claim of the paper (the claims module; docs/report.md), e.g. "fig7_spectrum"
  double weight = 1.0;
  std::string where;
};

/// A set of conditions and the claims judged on them.
struct ConditionSet {
  std::vector<MapCondition> maps;
  bool example = false;  ///< the chaotic example (Figs. 3 and 7) at the fixed S1, S2
  std::vector<ClaimWeight> claims;
};

enum class ObjectiveKind { kClaims, kIncidenceMap, kRecords };

/// A measured record (P1, P2, v; docs/guide/record-fits.md "The record") and the conditions it was taken at; a
/// condition not given keeps the [fixed] scenario's value.
struct RecordCondition {
  std::string file;  ///< the CSV's path (relative to the spec's folder)
  std::optional<double> S1_mm2, S2_mm2, Ps_MPa, m_kg;  ///< m_kg: the total moving mass
  std::optional<double> x0_mm;  ///< the piston's position at the first sample, without an x column
  /// Units of columns whose header has no brackets, e.g. {"t", "ms"}
  /// (docs/reference/record-units.md).
  UnitOverrides units;
  std::string where;
};

/// The maps' grid and runs (objective and predictions alike).
struct MapSpec {
  std::vector<GridAxis> axes;  ///< circuit.S1_mm2 then circuit.S2_mm2
  std::size_t repeats = 2;
  double duration_s = 5.0;
  /// Refine the maps adaptively (docs/sweep.md, "Adaptive maps": validated on the paper's maps).
  bool adaptive = true;
  /// Throws Error naming objective.grid, objective.repeats or objective.duration_s.
  void validate() const;
};

struct ObjectiveSpec {
  ObjectiveKind kind = ObjectiveKind::kClaims;
  ConditionSet fit;            ///< kClaims: the conditions and claims fitted
  MapSpec maps;            ///< kClaims: the maps' grid; kIncidenceMap: repeats, duration
  double example_record_s = 10.0;
  bool example_model_exponent = false;  ///< the model's own exponent (shown, never scored)
  std::string measured_map;    ///< kIncidenceMap: the CSV's path (relative to the spec's folder)
  double stick_slip_weight = 1.0, chaos_weight = 1.0;  ///< kIncidenceMap
  /// kClaims, kIncidenceMap (`judge = "paper"`): which runs count as chaotic is decided by the
  /// paper's three indices instead of the regime verdict (pneumachaos/analysis/paper_judge.hpp);
  /// the claims' rules and the measured map are the same.
  bool paper_judge = false;
  std::vector<RecordCondition> records;  ///< kRecords
  /// kRecords: the segment-wise simulation's segment and the noise scales of its residuals,
  /// as `fit` uses them (docs/notes/model_fit.md, "Method").
  double segment_s = 0.2, pressure_scale_kPa = 1.0, velocity_scale_mm_per_s = 30.0;
  /// Throws Error naming the objective's field (objective.example_record_s, objective.claims,
  /// objective.file, objective.chaos_weight, objective.segment_s, ...) whose value its kind
  /// cannot use; the maps' fields through MapSpec::validate().
  void validate() const;
};

struct OptimizerSpec {
  std::string algorithm = "cmaes";  ///< pagmo2's "cmaes" or "xnes"
  std::size_t population = 8;
  std::size_t max_evaluations = 40;
  std::uint64_t seed = 1;
  double sigma0 = 0.3;  ///< initial step, as a fraction of each (normalized) interval
  /// Throws Error naming the [optimizer] key that is out of range.
  void validate() const;
  /// Generations after the initial population, so that population x (generations + 1) does
  /// not exceed max_evaluations.
  [[nodiscard]] std::size_t generations() const;
  [[nodiscard]] std::size_t evaluations() const { return population * (generations() + 1); }
};

struct CalibrationSpec {
  std::string path;
  std::vector<FreeParameter> free;
  Scenario base;  ///< the defaults with [fixed] applied
  ObjectiveSpec objective;
  ConditionSet predict;  ///< evaluated only at the best point
  OptimizerSpec optimizer;
  /// Cross-checks (claims the conditions cannot score, duplicate keys); Error names the place.
  void validate() const;
  /// The scenario at the free parameters' positions u (each in [0, 1]).
  [[nodiscard]] Scenario scenario_at(const std::vector<double>& u) const;
  /// Identifies the calibration: a journal written for another spec is refused.
  [[nodiscard]] std::string fingerprint() const;
};

/// Reads SPEC.toml. Throws Error naming file:line:column and the key for every problem: a
/// syntax error, an unknown scenario key or claim id, a missing or empty source, lower >=
/// upper, a bound outside the key's plausible range, an unknown optimizer or objective kind.
CalibrationSpec read_calibration_spec(const std::string& path);
/// The same from text; `origin` names the source in errors.
CalibrationSpec parse_calibration_spec(const std::string& text, const std::string& origin);

/// The claim ids the claims module knows, in its table's order.
std::vector<std::string> known_claim_ids();

}  // namespace pneumachaos
