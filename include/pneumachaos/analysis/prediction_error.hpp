#pragma once
// How well a record predicts itself a short time ahead, by a local-constant (zeroth-order)
// predictor in the delay embedding (Farmer & Sidorowich 1987, Phys. Rev. Lett. 59) and by the
// best linear predictor on the same delay coordinates. A deterministic nonlinear record is
// predicted far better by its neighbours in the embedding than by any linear rule; for a
// linear Gaussian process the linear predictor is optimal (docs/notes/analysis.md "Determinism").

#include <cstddef>
#include <span>

namespace pneumachaos {

struct PredictionOptions {
  std::size_t dimension = 3;
  std::size_t delay = 1;
  std::size_t theiler = 1;
  std::size_t horizon = 0;         ///< steps ahead; 0: the delay
  std::size_t neighbours = 4;      ///< averaged by the local-constant predictor
  std::size_t max_references = 500;  ///< predicted points, spread over the record
  /// Throws Error naming the field that is out of range.
  void validate() const;
};

struct PredictionErrors {
  bool computed = false;
  std::size_t horizon = 0;
  double nonlinear = 0.0;  ///< RMS error of the local-constant predictor / std of the record
  double linear = 0.0;     ///< RMS error of the least-squares linear predictor / std
  /// nonlinear / linear: well below 1 for deterministic nonlinear dynamics, >= ~1 for noise.
  [[nodiscard]] double ratio() const { return linear > 0.0 ? nonlinear / linear : 1.0; }
};

/// The local-constant predictor's normalised RMS error alone (the surrogate test's statistic).
/// Returns a negative value when the record is too short for the embedding and horizon.
double nonlinear_prediction_error(std::span<const double> x, const PredictionOptions& o);

/// Both errors; computed == false when the record is too short.
PredictionErrors prediction_errors(std::span<const double> x, const PredictionOptions& o);

}  // namespace pneumachaos
