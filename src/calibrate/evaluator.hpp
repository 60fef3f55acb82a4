#pragma once
// One evaluation of the objective at a scenario (private to the calibrate module).

#include <optional>
#include <string>
#include <vector>

#include "condition_runs.hpp"
#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "calibrate/measured_map.hpp"

namespace pneumachaos::detail {

struct Evaluation {
  double objective = 1.0;
  std::vector<double> terms;
};

class Evaluator {
 public:
  Evaluator(const CalibrationSpec& spec, RunSettings settings,
            std::optional<MeasuredMap> measured);
  /// The names of the terms, in order: the fitted claims' ids, or the map errors.
  [[nodiscard]] std::vector<std::string> term_names() const;
  /// Runs the objective's conditions at point u into dir.
  [[nodiscard]] Evaluation evaluate(const std::vector<double>& u, const std::string& dir) const;
  /// The model's incidences on the measured map's grid.
  [[nodiscard]] Evaluation map_errors(const Scenario& s, const std::string& dir) const;

 private:
  const CalibrationSpec& spec_;
  RunSettings settings_;
  std::optional<MeasuredMap> measured_;
};

}  // namespace pneumachaos::detail
