#pragma once
// Automatic embedding parameters: the delay from the first minimum of the average mutual
// information (Fraser & Swinney 1986, Phys. Rev. A 33), the dimension by Cao's method
// (Cao 1997, Physica D 110), and a Theiler window (Theiler 1986, Phys. Rev. A 34).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace pneumachaos {

/// Average mutual information I(tau) [nats] for tau = 0..max_lag, with equiprobable
/// (rank-based) bins, `bins` per axis (0: about (N/10)^(1/2), clipped to [8, 64]). Equal-
/// probability bins keep the first minimum of a sine at a quarter period, which fixed-width
/// bins on a peaked density do not.
std::vector<double> mutual_information(std::span<const double> x, std::size_t max_lag,
                                       std::size_t bins = 0);

struct DelayChoice {
  std::size_t delay = 1;
  /// "mutual-information minimum", "autocorrelation 1/e" (fallback), or, from
  /// delay_within_an_orbit, "a quarter of the orbit (...)"
  std::string method;
  std::vector<double> ami;  ///< I(tau) as far as it was computed
};

/// First local minimum of I(tau) (searched up to N/10 lags); falls back to the lag where the
/// autocorrelation drops below 1/e when I(tau) has no minimum. With the record's white noise
/// of sd noise_sd (estimate_noise_floor), no bin of I is narrower than kNoiseBinWidth x
/// noise_sd: finer bins would measure the noise, not the motion.
DelayChoice choose_delay(std::span<const double> x, std::size_t max_lag = 0, double noise_sd = 0.0);
inline constexpr double kNoiseBinWidth = 2.0;

/// `c`, unless its delay is an orbit (`orbit_samples`, e.g. the mean spacing of the maxima)
/// or more: then kDelayShareOfOrbit of the orbit, where the first minimum of an oscillation's
/// I lies, with `method` saying so. Orbits under 8 samples (maps, noise) leave `c` as it is.
DelayChoice delay_within_an_orbit(DelayChoice c, double orbit_samples);
/// A quarter of the orbit: where a sine's I(tau) has its first minimum (mutual_information
/// above). The analysis's evidence scale caps the delay at the same share
/// (docs/notes/analysis.md "Evidence scale").
inline constexpr double kDelayShareOfOrbit = 0.25;

struct DimensionChoice {
  std::size_t dimension = 2;
  std::vector<double> E1;  ///< Cao's E1(d), d = 1..
  std::vector<double> E2;  ///< Cao's E2(d): stays near 1 for stochastic data
};

/// Smallest d whose E1(d) reaches `saturation` times E1's plateau (E1 -> ~1 once the
/// attractor is unfolded), searched up to max_dimension; nearest neighbours by k-d tree
/// outside the Theiler window, rounding-level repeats skipped.
DimensionChoice choose_dimension(std::span<const double> x, std::size_t delay, std::size_t theiler,
                                 std::size_t max_dimension = 8, double saturation = 0.85);

}  // namespace pneumachaos
