#pragma once
// Small statistics of a scalar series used to set analysis scales automatically.

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

double mean_of(std::span<const double> x);
double standard_deviation(std::span<const double> x);

/// Indices of the maxima of x, each followed by a fall of at least a quarter standard
/// deviation, or 6 x noise_sd where a white noise of that sd is known, before the next counts
/// (hysteresis against noise riding on an oscillation).
std::vector<std::size_t> maxima_indices(std::span<const double> x, double noise_sd = 0.0);

/// Mean number of samples between successive maxima (as maxima_indices counts them): the orbital period of an oscillating flow (Lorenz: one
/// turn around a lobe), ~2-3 for maps and noise. Robust where the spectral peak is not
/// (Lorenz x peaks at its slow lobe switching).
double mean_maxima_spacing(std::span<const double> x, double noise_sd = 0.0);

/// x smoothed by a centred moving average of `width` samples (shorter at the ends).
std::vector<double> moving_average(std::span<const double> x, std::size_t width);

/// x smoothed by a centred moving median over the same windows as moving_average: a run
/// shorter than the window still sets the median while it fills more than half the window.
std::vector<double> moving_median(std::span<const double> x, std::size_t width);

/// The orbital period [samples] as the mean maxima spacing of x smoothed over `width` samples
/// (the embedding delay, about a quarter period): measurement noise and a faster superposed
/// ripple do not count as extra maxima (a sine with 20 % noise: 4.7 samples unsmoothed,
/// its true 100 smoothed; docs/notes/analysis.md "Evidence scale").
double smoothed_period(std::span<const double> x, std::size_t width);

}  // namespace pneumachaos
