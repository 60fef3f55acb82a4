#pragma once
// Lyapunov exponents from local linear maps of the reconstructed dynamics (Eckmann & Ruelle
// 1985, Rev. Mod. Phys. 57; Sano & Sawada 1985, Phys. Rev. Lett. 55; Eckmann, Kamphorst,
// Ruelle & Ciliberto 1986, Phys. Rev. A 34).
//
// Why a second estimator: the divergence curve (lyapunov_divergence.hpp) reads one slope off
// one averaged curve, so a wrong linear region, a curve that saturates early or a bad
// alignment moves the value with nothing to show it. This one never looks at a curve: it fits
// a least-squares Jacobian on each reference point's neighbourhood (the neighbours' images
// `evolve` steps later against the neighbours themselves), multiplies the Jacobians along the
// trajectory and re-orthonormalises with Householder QR; the averaged logarithms of R's
// diagonal are the exponents, the next ones included (their sum is negative for a
// dissipative system). Its failure modes are different ones (docs/notes/analysis.md
// "Exponents from local Jacobians"): spurious exponents when the embedding has more
// dimensions than the dynamics, and noise, which the local fits report as unexplained
// variance.

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

struct JacobianOptions {
  std::size_t dimension = 3;
  std::size_t delay = 1;
  std::size_t theiler = 1;  ///< neighbours closer in time than this are not used
  /// Samples per orbit; when given (> 0), the delay is capped so that a delay vector spans at
  /// most half an orbit: a longer window folds the reconstruction so that a neighbourhood of
  /// a 1e4-sample record is no longer mapped linearly (docs/notes/analysis.md).
  std::size_t typical_period = 0;
  /// Coordinates the local maps are fitted in, spread over the delay vector's window (the
  /// neighbours are still found in all `dimension`); 0: min(dimension, 3), what a chaotic
  /// flow needs. Coordinates beyond the attractor's own fill no neighbourhood and make
  /// spurious stretching (docs/notes/analysis.md); raise it for hyperchaotic records.
  std::size_t local_dimension = 0;
  /// Steps each local map spans; 0: one delay of the local coordinates, so that the map's
  /// image repeats all but one of the point's coordinates and only that one is fitted.
  std::size_t evolve = 0;
  /// Neighbours per local fit; 0: max(12, 4 x dimension), enough that an affine fit in
  /// `dimension` coordinates is over-determined about four times.
  std::size_t neighbours = 0;
  std::size_t batches = 10;  ///< contiguous stretches of the trajectory for the uncertainty
  /// The estimate is called reliable when the median unexplained share of the local fits (see
  /// JacobianResult::unexplained) is at most this.
  double max_unexplained = 0.2;
  /// Throws Error for zero dimension/delay/evolve-derived values, too few neighbours for an
  /// affine fit, or a record too short for the embedding, the window and the batches.
  void validate(std::size_t n_samples) const;
};

struct JacobianResult {
  /// All exponents of the local coordinates (JacobianOptions::local_dimension), largest
  /// first, per second; those beyond the dynamics' own dimension are spurious
  /// (docs/notes/analysis.md).
  std::vector<double> exponents_per_s;
  double lambda_per_s = 0.0;       ///< exponents_per_s[0]
  double sum_per_s = 0.0;          ///< sum of the exponents: negative when dissipative
  /// The largest's uncertainty: the two below in quadrature; +-1.96 of it is meant as a 95 %
  /// interval.
  double uncertainty_per_s = 0.0;
  /// Standard error of the largest from batch means: its value on `batches` contiguous
  /// stretches of the trajectory.
  double statistical_uncertainty_per_s = 0.0;
  /// Largest change of the largest when the neighbourhoods hold twice the neighbours or the
  /// maps span twice the steps: what the fits' choices move.
  double choice_spread_per_s = 0.0;
  std::size_t maps = 0;            ///< local maps fitted and multiplied
  std::size_t skipped = 0;  ///< reference points without a fit: too few neighbours, or flat
  std::size_t neighbours = 0;      ///< per fit, as used
  std::size_t evolve = 0;          ///< steps per map, as used
  std::size_t delay = 0;           ///< delay of the reconstruction, as used
  /// Median over the fits of the worst image coordinate's unexplained share of variance
  /// (1 - R^2): near 0 where the neighbourhood's images are a linear function of the
  /// neighbours (deterministic, smooth), near 1 for noise, where no map exists.
  double unexplained = 0.0;
  bool reliable = false;  ///< unexplained <= JacobianOptions::max_unexplained
};

JacobianResult jacobian_exponents(std::span<const double> x, double rate_Hz,
                                  const JacobianOptions& options);

}  // namespace pneumachaos
