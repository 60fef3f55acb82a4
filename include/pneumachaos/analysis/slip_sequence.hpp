#pragma once
// Stick-slip reduced to one number per slip, and whether that sequence is chaotic
// (docs/analysis.md "Slip sequence"). On a stick-slip record the rests fill the delay
// embedding with identical vectors, so the divergence curve of the raw record can find no
// linear region even where the dynamics is chaotic; the slips' own sequence is where chaos
// shows: a return map s(n) -> s(n+1) that is deterministic (predicts the next slip far better
// than a linear-stochastic sequence with the same spectrum and values could) and irregular
// (the slips differ, and the sequence does not repeat itself at any lag).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pneumachaos {

/// Samples [first, last) at rest.
struct RestInterval {
  std::size_t first = 0, last = 0;
};

/// The rest intervals of a record and the band |x| <= level they were found in.
struct Rests {
  double level = 0.0;
  std::vector<RestInterval> intervals;
};

/// Rests: runs of at least min_samples samples with |x| <= level whose spread stays within
/// level / 2 (a smooth passage through zero spreads over the whole band and is no rest).
/// The one rest detection of the analysis: the stick-slip flag and the slip sequence read it.
Rests find_rests(std::span<const double> x, double level, std::size_t min_samples);

/// The slips: each run of samples between two rests whose peak |x| exceeds min_peak
/// (the partial slips before the first rest and after the last are left out), reduced to its
/// displacement, the sum of x over the slip divided by the sample rate (x a velocity: the
/// distance slid). Rests parted by less (touching, a creep inside the rest band, a creep
/// burst) are one stick: no slip between them. min_peak below the rest level counts as it.
std::vector<double> slip_displacements(std::span<const double> x, double rate_Hz,
                                       const Rests& rests, double min_peak = 0.0);

struct SlipSequenceOptions {
  /// Fewer slips: not run. A return map needs its range covered: with 20 slips the two nearest
  /// neighbours of a slip lie ~1/10 of the range away, still far finer than a chaotic map's
  /// spread of its images.
  std::size_t min_slips = 20;
  /// A slip reaches at least this fraction of the record's max |x|, ten times the rest band
  /// (1 %): a release of the stick, not a creep burst a little above the band (a frozen-rig
  /// record creeps at 1.5-3 % of its peak speed 3-4 times per stick, irregularly;
  /// docs/analysis.md "Slip sequence").
  double min_peak_fraction = 0.1;
  /// IAAFT surrogates of the sequence (39: a one-sided rank test at p = 1/40 = 0.025).
  std::size_t surrogates = 39;
  std::uint64_t seed = 1;
  /// Deterministic: the sequence's prediction error below every surrogate's AND at most this
  /// fraction of their median (a size of effect, not only a rank: the rank alone is passed
  /// by 1 linear-stochastic sequence in 40).
  double max_error_ratio = 0.5;
  /// Slips alike: their displacements' std at most this fraction of their mean |value| (a
  /// periodic stick-slip; sampling the slip boundaries alone varies them far less).
  double min_variation = 0.02;
  /// Repeats: at some lag of 1 .. half the sequence, the RMS of s(n + L) - s(n) at most this
  /// fraction of sqrt(2) std (0 for an exact repeat, ~1 for unrelated slips). Noise of
  /// relative std r on a repeating sequence reads ~r, so a period-2 stick-slip with up to
  /// ~30 % slip-to-slip noise still repeats.
  double max_repeat_mismatch = 0.3;
  /// Local-constant predictor: neighbours averaged, return-map dimensions tried (1 .. this).
  std::size_t neighbours = 2;
  std::size_t max_dimension = 2;
  void validate() const;  ///< throws Error naming the option
};

struct SlipSequenceTest {
  bool run = false;
  std::string reason;  ///< why not run, when not
  std::size_t slips = 0;
  double mean = 0.0, variation = 0.0;  ///< mean displacement and std / |mean|
  /// Normalised leave-one-out error of the local-constant return-map predictor (best over
  /// dimensions 1 .. max_dimension), and the same statistic on the surrogates.
  double prediction_error = 0.0;
  std::size_t dimension = 0;
  double surrogate_median = 0.0, surrogate_min = 0.0;
  std::size_t surrogates_below = 0;  ///< surrogates at least as predictable as the sequence
  std::size_t repeat_lag = 0;  ///< the lag of the smallest mismatch (in slips)
  double repeat_mismatch = 0.0;
  bool varies = false, deterministic = false, repeats = false;
  bool chaotic = false;  ///< varies AND deterministic AND NOT repeats
};

/// The test on the displacement sequence of the slips between `rests`.
SlipSequenceTest slip_sequence_test(std::span<const double> x, double rate_Hz,
                                    const Rests& rests,
                                    const SlipSequenceOptions& options = {});

/// The same test on a sequence already reduced to one number per slip.
SlipSequenceTest slip_sequence_test(std::span<const double> slips,
                                    const SlipSequenceOptions& options = {});

}  // namespace pneumachaos
