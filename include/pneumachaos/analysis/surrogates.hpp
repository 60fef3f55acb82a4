#pragma once
// Surrogate-data test against the linear-stochastic null (Theiler, Eubank, Longtin, Galdrikian
// & Farmer 1992, Physica D 58): iterative amplitude-adjusted Fourier-transform (IAAFT)
// surrogates (Schreiber & Schmitz 1996, Phys. Rev. Lett. 77) keep the record's values exactly
// and its power spectrum closely, and are otherwise random. If the record's nonlinear
// prediction error lies outside all N surrogates' (a rank test), the null hypothesis "a
// static monotonic transform of a linear Gaussian process" is rejected.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pneumachaos/analysis/prediction_error.hpp"

namespace pneumachaos {

/// A surrogate count is 0 (the test off) or kMinSurrogates..kMaxSurrogates. "Below every
/// surrogate" happens by chance with probability 1/(N+1), so 19 is the least count for a test
/// at 5 %; past 999 (0.1 %) only the time grows, by ~13 s per 1e4 samples.
inline constexpr std::size_t kMinSurrogates = 19, kMaxSurrogates = 999;
/// Throws an Error at `where` (a key, or the option the user typed) for any other count.
void check_surrogate_count(std::size_t count, const std::string& where);

struct SurrogateOptions {
  /// 39 surrogates: the record is outside all of them with probability 2/40 = 0.05 under the
  /// null, a two-sided test at 95 % (Theiler et al. 1992). 0: the test is off.
  std::size_t count = 39;
  std::uint64_t seed = 1;
  /// IAAFT stops when the surrogate's amplitude spectrum is within this relative RMS of the
  /// record's (1 %: Lorenz x, 1e4 samples, ~8 iterations; 1e-3 needs 20 to > 50, depending on
  /// the segment), at a fixed point of the rank order, or after max_iterations.
  double spectral_tolerance = 1e-2;
  std::size_t max_iterations = 50;
  std::size_t min_samples = 500;     ///< shorter records: the test is not run (said so)
  void validate() const;
};

struct SurrogateTest {
  bool run = false;
  std::string reason;           ///< why not run, when not
  std::size_t samples = 0;      ///< length of the end-matched segment tested
  std::size_t offset = 0;       ///< its first sample in the record
  double statistic = 0.0;       ///< the record's nonlinear prediction error (normalised)
  std::vector<double> surrogate_statistics;
  std::size_t rank = 0;         ///< surrogates with a smaller statistic than the record
  double p_value = 1.0;         ///< two-sided rank p-value
  bool rejected = false;        ///< the record lies outside every surrogate
  bool more_predictable = false;  ///< rejected with a smaller error than every surrogate
};

/// One IAAFT surrogate of x (its length should have small prime factors for speed).
std::vector<double> iaaft_surrogate(std::span<const double> x, std::uint64_t seed,
                                    std::size_t max_iterations = 50, double tolerance = 1e-2);

/// The test on the longest segment of x whose length factors into 2, 3, 5 and whose ends
/// match best (a jump between the last and first sample leaks power to all frequencies of the
/// surrogates); the statistic uses the embedding and horizon in `prediction`.
SurrogateTest surrogate_test(std::span<const double> x, const PredictionOptions& prediction,
                             const SurrogateOptions& options);

}  // namespace pneumachaos
