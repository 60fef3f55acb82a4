#pragma once
// Every chaos index of one record with automatic parameters, and its regime verdict.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/analysis/jacobian_exponents.hpp"
#include "pneumachaos/analysis/lyapunov_divergence.hpp"
#include "pneumachaos/analysis/lyapunov_wolf.hpp"
#include "pneumachaos/analysis/noise_floor.hpp"
#include "pneumachaos/analysis/poincare.hpp"
#include "pneumachaos/analysis/prediction_error.hpp"
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/analysis/spectral_lines.hpp"
#include "pneumachaos/analysis/spectrum.hpp"
#include "pneumachaos/analysis/surrogates.hpp"
#include "pneumachaos/analysis/zero_one_test.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

struct AnalysisOptions {
  SpectrumOptions spectrum;
  std::size_t delay = 0;      ///< 0: automatic (mutual information)
  std::size_t dimension = 0;  ///< 0: automatic (Cao)
  std::size_t theiler = 0;    ///< 0: max(delay, first zero of the autocorrelation)...
  bool theiler_given = false;  ///< ...unless set: then `theiler` as given, 0 included
  bool wolf = true;           ///< also run Wolf's estimator (the paper's method)
  /// Judge by the paper's three indices as the paper did (paper_judge.hpp): Wolf's estimator
  /// then runs on every record, linear noise included, where it is otherwise skipped.
  bool paper_judge = false;
  /// Also estimate the exponents from local Jacobians (jacobian_exponents.hpp), a second
  /// estimate of the largest beside the divergence curve's, compared with it. Off by default:
  /// it adds work to every analysis (`analyze --jacobian-exponents` turns it on).
  bool jacobian = false;
  /// Also measure the divergence exponent at embedding dimensions m - 1 and m + 1, and widen
  /// its uncertainty to reach them (AnalysisResult::exponent_spread): two more divergence
  /// curves on a quarter of the reference pairs, 20 % more work on a chaotic record. `analyze`
  /// and the Python module turn it on;
  /// off here, where sweeps analyse thousands of records and no map reads the uncertainty.
  bool embedding_spread = false;
  /// The record is a velocity, where zero means rest: stick-slip is judged from its rests.
  /// false for any other signal (a position, a pressure, a model's coordinate): not judged.
  bool velocity = true;
  /// Seeds the 0-1 test's random frequencies and the surrogates (each result is a function of
  /// the record, the options and this seed alone).
  std::uint64_t seed = 1;
  ZeroOneOptions zero_one;
  /// Off in the library (the sweep analyses thousands of records); `analyze` runs 39.
  SurrogateOptions surrogates{.count = 0};
  VerdictOptions verdict;
  /// Seeds the verdict is decided on when a random test (the 0-1 test, the surrogates) could
  /// turn it: seed, seed + 1, ...; the regime a majority gives is reported, with the tally
  /// (AnalysisResult::seed_agreement). Odd, 1 to 99; 1: the first seed alone.
  std::size_t verdict_seeds = 5;
  static constexpr ErrorField kVerdictSeedsField{"analysis.verdict_seeds", "verdict_seeds"};
  /// Called as each stage of the analysis begins, with its name (e.g. "divergence curve"), for
  /// a progress display on a long record; empty: not called.
  std::function<void(const char* stage)> on_stage;
  void validate() const;
};

/// How the verdict held across the seeds of its random tests.
struct SeedAgreement {
  std::size_t seeds = 1;     ///< seeds decided on (1: no random test could turn the verdict)
  std::size_t agreeing = 1;  ///< of them, those giving the reported regime
  std::vector<Regime> regimes;  ///< the regime on each seed: seed, seed + 1, ...
  bool zero_one_rerun = false;    ///< the 0-1 test was pivotal, able to turn, run on every seed
  bool surrogates_rerun = false;  ///< likewise the surrogates (pivotal and able to turn)
  /// The chances that each test's outcome turns on another seed (0: not run).
  double zero_one_flip_probability = 0.0;
  double surrogate_flip_probability = 0.0;
};

/// What the divergence exponent depends on beyond its own curve, which its uncertainty
/// includes: the window (each half of it fitted alone, and the other stretches the window rule
/// accepts) and the embedding dimension (m - 1 and m + 1, those with a linear region;
/// AnalysisOptions::embedding_spread).
struct ExponentSpread {
  double window_per_s = 0.0;  ///< largest change of the value when half the window is fitted
  /// The values on the curve's other agreeing runs (the windows the rule passed over for a
  /// longer one), and the largest |value there - value|.
  std::vector<double> other_windows_per_s;
  double window_choice_per_s = 0.0;
  std::vector<std::size_t> dimensions;
  std::vector<double> lambda_per_s;  ///< the value at each of `dimensions`
  double embedding_per_s = 0.0;      ///< largest |lambda(m') - lambda(m)|
};

struct AnalysisResult {
  std::size_t samples = 0;
  double rate_Hz = 0.0;
  double mean = 0.0, standard_deviation = 0.0;
  NoiseFloor noise;                     ///< the record's white noise, estimated from the record
  double maxima_spacing_samples = 0.0;  ///< mean spacing of maxima
  /// Orbital period: the maxima spacing, or the fundamental's period when the maxima follow
  /// a harmonic (orbital_period, docs/notes/analysis.md "Orbital period").
  double period_samples = 0.0;
  Spectrum spectrum;
  Autocorrelation acf;
  DelayChoice delay;
  DimensionChoice dimension;
  std::size_t theiler = 0;
  DivergenceResult divergence;
  ZeroOneResult zero_one;
  PredictionErrors prediction;
  SurrogateTest surrogate;
  SpectralLines lines;
  std::string divergence_status;  ///< what the divergence curve measured, or why nothing
  /// No linear region, but a deterministic record (the prediction test) whose curve rises:
  /// divergence.local_slopes is reported as a wide estimate (the verdict reads only whether
  /// they stay positive: RegimeEvidence::rises_throughout).
  bool divergence_estimate = false;
  bool wolf_run = false;
  WolfResult wolf;
  std::string wolf_status;  ///< empty: Wolf not requested; else what it measured or why not
  bool jacobian_run = false;  ///< the local-Jacobian estimate exists (requested and computed)
  JacobianResult jacobian;
  /// Empty: not requested; else what the local Jacobians measured, or why nothing.
  std::string jacobian_status;
  PoincareSection poincare;
  std::vector<std::array<double, 2>> maxima_map;
  RegimeEvidence evidence;
  Verdict verdict;
  SeedAgreement seed_agreement;
  ExponentSpread exponent_spread;
};

/// Throws Error for a series too short to analyse (fewer than 200 samples), non-finite
/// values, or a constant series.
AnalysisResult analyze_series(std::span<const double> x, double rate_Hz,
                              const AnalysisOptions& options = {});

}  // namespace pneumachaos
