#include "pneumachaos/model/variation.hpp"

#include "level_field.hpp"

#include <boost/random/normal_distribution.hpp>
#include <boost/random/uniform_real_distribution.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace pneumachaos {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// std::mt19937_64 is specified to the bit; the distributions come from Boost (portable).
void vary_friction(FrictionParams& f, const VariationParams& v, std::mt19937_64& rng) {
  boost::random::normal_distribution<double> normal(0.0, 1.0);
  boost::random::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (v.friction_rel_sd > 0.0) {
    const auto scale = [&](double& p) {
      p *= std::max(0.2, 1.0 + v.friction_rel_sd * normal(rng));
    };
    for (double* p :
         {&f.curve.coulomb_N, &f.curve.static_N, &f.curve.viscous_Ns_per_m,
          &f.curve.stribeck_velocity_m_per_s, &f.lugre.sigma0_N_per_m, &f.lugre.sigma1_Ns_per_m}) {
      scale(*p);
    }
    f.curve.static_N = std::max(f.curve.static_N, f.curve.coulomb_N);
  }
  if (v.texture_rel > 0.0) {
    f.texture.clear();
    // Four modes, wavelengths spread over half to twice the typical one; amplitudes share
    // the texture's variance.
    for (int i = 0; i < 4; ++i) {
      const double wavelength = v.texture_wavelength_m * std::pow(2.0, 2.0 * uniform(rng) - 1.0);
      f.texture.push_back({0.5 * v.texture_rel * normal(rng), 2.0 * std::numbers::pi / wavelength,
                           2.0 * std::numbers::pi * uniform(rng)});
    }
  }
}

}  // namespace

std::uint64_t run_seed(std::uint64_t seed, std::uint64_t point, std::uint64_t repeat) {
  return splitmix64(splitmix64(splitmix64(seed) ^ point) ^ repeat);
}

Scenario vary(const Scenario& base, std::uint64_t seed) {
  Scenario s = base;
  std::mt19937_64 rng(splitmix64(seed ^ 0x5eed0001ULL));
  vary_friction(s.friction, s.variation, rng);
  vary_friction(s.load.guide_friction, s.variation, rng);
  if (s.variation.seal_noise_rel > 0.0) {
    // A stream of its own: the scatter and the texture draw the same numbers with or without it.
    std::mt19937_64 field_rng(splitmix64(seed ^ 0x5eed0005ULL));
    s.friction.level_field =
        draw_level_field(s.variation.seal_noise_rel, s.variation.seal_noise_correlation_m,
                         s.cylinder.stroke_m + 2.0 * kBoreMargin_m, field_rng);
  }
  return s;
}

std::vector<double> sensor_noise(std::uint64_t seed, NoiseStream stream, std::size_t n, double sd) {
  std::mt19937_64 rng(splitmix64(seed ^ static_cast<std::uint64_t>(stream)));
  boost::random::normal_distribution<double> noise(0.0, sd);
  std::vector<double> out(n);
  for (double& x : out) x = noise(rng);
  return out;
}

}  // namespace pneumachaos
