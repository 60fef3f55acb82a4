#pragma once
// One evaluation of the objective at a scenario (private to the calibrate module).

#include <optional>
#include <string>
#include <vector>

#include "condition_runs.hpp"
#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "calibrate/measured_map.hpp"
#include "pneumachaos/identify/fit.hpp"
#include "pneumachaos/identify/measured_record.hpp"

namespace pneumachaos::detail {

struct Evaluation {
  double objective = 1.0;
  std::vector<double> terms;
};

class Evaluator {
 public:
  Evaluator(const CalibrationSpec& spec, ConditionRunOptions settings,
            std::optional<MeasuredMap> measured,
            std::vector<identify::MeasuredRecord> records = {});
  /// The names of the terms, in order: the fitted claims' ids, the map errors, or one error
  /// per measured record.
  [[nodiscard]] std::vector<std::string> term_names() const;
  /// Runs the objective's conditions at point u into dir.
  [[nodiscard]] Evaluation evaluate(const std::vector<double>& u, const std::string& dir) const;
  /// The model's incidences on the measured map's grid.
  [[nodiscard]] Evaluation map_errors(const Scenario& s, const std::string& dir) const;
  /// The segment-wise simulation of every measured record at s under its conditions.
  [[nodiscard]] Evaluation record_errors(const Scenario& s) const;

 private:
  const CalibrationSpec& spec_;
  ConditionRunOptions settings_;
  std::optional<MeasuredMap> measured_;
  std::vector<identify::MeasuredRecord> records_;
};

/// A record's error at a scenario: the RMS over its samples and its three signals of the
/// segment-wise simulation's residuals, each divided by its noise scale (docs/notes/model_fit.md).
double scaled_record_error(const identify::ValidationSeries& v, double pressure_scale_Pa,
                           double velocity_scale_m_per_s);

}  // namespace pneumachaos::detail
