#pragma once
// The seal's random friction level along the bore (docs/model.md, "Friction"): drawn per run
// from the variation's stream, tabulated once per Plant. Private to the model module.

#include <memory>
#include <random>

#include "pneumachaos/model/friction.hpp"
#include "texture_table.hpp"

namespace pneumachaos {

/// The field's spectrum is kept up to the wavenumber kFieldCutoff / correlation length: an
/// exponential correlation's spectrum 1 / (1 + (k l)^2) holds 96 % of its variance below it
/// (2/pi atan 16), and the rest, the field's finest roughness, is what the table could not
/// resolve at a sensible size. The amplitudes are scaled to give the stated variance exactly.
inline constexpr double kFieldCutoff = 16.0;

/// One realisation: relative standard deviation `rel_sd`, correlation exp(-|dx| / correlation_m)
/// (to the cutoff above), repeating every `period_m`; amplitudes from the spectrum, phases
/// uniform (the spectral representation of Shinozuka & Deodatis 1991, Appl. Mech. Rev. 44(4)).
RandomLevelField draw_level_field(double rel_sd, double correlation_m, double period_m,
                                  std::mt19937_64& rng);

/// The covariance of the relative level at `lag_m` that the field's modes give, sum a^2/2 cos(k lag).
double level_field_covariance(const RandomLevelField& field, double lag_m);

/// The Plant's table of the field over one period from from_m, 32 nodes per shortest
/// wavelength; null when there is no field.
std::shared_ptr<const TextureTable> tabulate_level_field(const RandomLevelField& field,
                                                         double from_m);

}  // namespace pneumachaos
