#pragma once
// Small statistics of a scalar series used to set analysis scales automatically.

#include <cstddef>
#include <span>

namespace pneumachaos {

double mean_of(std::span<const double> x);
double standard_deviation(std::span<const double> x);

/// Mean number of samples between successive maxima (each followed by a fall of at least
/// a quarter standard deviation): the orbital period of an oscillating flow (Lorenz: one
/// turn around a lobe), ~2-3 for maps and noise. Robust where the spectral peak is not
/// (Lorenz x peaks at its slow lobe switching).
double mean_maxima_spacing(std::span<const double> x);

}  // namespace pneumachaos
