#pragma once
// Every chaos index of one record with automatic parameters, and its regime verdict.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/analysis/lyapunov_divergence.hpp"
#include "pneumachaos/analysis/lyapunov_wolf.hpp"
#include "pneumachaos/analysis/poincare.hpp"
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/analysis/spectrum.hpp"

namespace pneumachaos {

struct AnalysisOptions {
  SpectrumOptions spectrum;
  std::size_t delay = 0;      ///< 0: automatic (mutual information)
  std::size_t dimension = 0;  ///< 0: automatic (Cao)
  std::size_t theiler = 0;    ///< 0: max(delay, first zero of the autocorrelation)
  bool wolf = true;           ///< also run Wolf's estimator (the paper's method)
  VerdictOptions verdict;
};

struct AnalysisResult {
  std::size_t samples = 0;
  double rate_Hz = 0.0;
  double mean = 0.0, standard_deviation = 0.0;
  double period_samples = 0.0;  ///< mean spacing of maxima
  Spectrum spectrum;
  Autocorrelation acf;
  DelayChoice delay;
  DimensionChoice dimension;
  std::size_t theiler = 0;
  DivergenceResult divergence;
  bool wolf_run = false;
  WolfResult wolf;
  PoincareSection poincare;
  std::vector<std::array<double, 2>> maxima_map;
  RegimeEvidence evidence;
  Verdict verdict;
};

/// Throws Error for a series too short to analyse (fewer than 200 samples), non-finite
/// values, or a constant series.
AnalysisResult analyze_series(std::span<const double> x, double rate_Hz,
                              const AnalysisOptions& options = {});

}  // namespace pneumachaos
