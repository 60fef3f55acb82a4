#pragma once
// The 0-1 test for chaos (Gottwald & Melbourne 2004, Proc. R. Soc. A 460; 2009, SIAM J. Appl.
// Dyn. Syst. 8, "On the implementation of the 0-1 test for chaos"), correlation method:
// the record drives a planar walk p_c, q_c; its mean square displacement grows linearly for
// chaotic (or stochastic) dynamics and stays bounded for regular dynamics. K_c is the
// correlation of the regularised displacement with time; K is the median over random
// frequencies c in (pi/5, 4pi/5): near 1 for chaos (and noise), near 0 for regular motion.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace pneumachaos {

struct ZeroOneOptions {
  std::size_t frequencies = 100;  ///< random c values (Gottwald & Melbourne 2009 use 100)
  std::uint64_t seed = 1;
  std::size_t min_points = 200;   ///< after down-sampling; fewer: not run
  /// Longer down-sampled records are cut to this many points: K converges well before, and
  /// the cost grows as points x points / 10 per frequency.
  std::size_t max_points = 2000;
  void validate() const;
};

struct ZeroOneResult {
  bool run = false;
  std::string reason;      ///< why not run, when not
  std::size_t step = 1;    ///< down-sampling step [samples]
  std::size_t points = 0;  ///< samples used after down-sampling
  double K = 0.0;          ///< median over the frequencies c
  double K_q25 = 0.0, K_q75 = 0.0;  ///< its spread (quartiles over c)
};

/// The test on every `step`-th sample of x. An oversampled flow must be down-sampled (its
/// walk is smooth at the sample scale and reads K ~ 0 even when chaotic); analyze_series uses
/// the embedding delay, the first minimum of the mutual information, as the step.
ZeroOneResult zero_one_test(std::span<const double> x, std::size_t step,
                            const ZeroOneOptions& options = {});

}  // namespace pneumachaos
