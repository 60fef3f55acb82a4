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

/// The random streams of a run's transducer noise, one per measured channel, each apart from
/// the others and from vary()'s.
enum class NoiseStream : std::uint64_t {
  kVelocity = 0x5eed0002ULL,
  kPressure1 = 0x5eed0003ULL,
  kPressure2 = 0x5eed0004ULL,
};

/// A channel's transducer noise in the run of this seed: n draws of N(0, sd^2) from its stream.
/// Boost's distributions, unlike the standard library's, give the same numbers with every
/// compiler and standard library, so a map is the same on every machine.
std::vector<double> sensor_noise(std::uint64_t seed, NoiseStream stream, std::size_t n, double sd);

}  // namespace pneumachaos
