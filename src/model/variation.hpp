#pragma once
// Seeded run-to-run variation: every random stream is derived from (seed, point, repeat), so a
// run's draw does not depend on which thread or rank computes it, or in which order.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos {

/// A 64-bit seed for one run, mixed from the sweep seed, the grid point and the repeat with
/// SplitMix64 (Steele, Lea & Flood 2014), so neighbouring runs get unrelated streams.
std::uint64_t run_seed(std::uint64_t seed, std::uint64_t point, std::uint64_t repeat);

/// The scenario of one run: friction parameters of the seal (and guide) each scaled by
/// 1 + friction_rel_sd * N(0,1) (clipped to >= 0.2, Fs kept >= Fc) and, when texture_rel > 0,
/// a texture of four modes with wavelengths around texture_wavelength. With zero variation the
/// scenario comes back unchanged.
Scenario vary(const Scenario& base, std::uint64_t seed);

/// The run's sensor noise: n draws of N(0, sd^2) from a stream apart from vary()'s. Boost's
/// distributions, unlike the standard library's, give the same numbers with every compiler
/// and standard library, so a map is the same on every machine.
std::vector<double> sensor_noise(std::uint64_t seed, std::size_t n, double sd);

}  // namespace pneumachaos
