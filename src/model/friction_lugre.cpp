#include <cmath>

#include "friction_models.hpp"

namespace pneumachaos {

double LuGreFriction::force_N(const FrictionInput& in, int /*direction*/, std::span<const double> z,
                              std::span<double> dz) const {
  const double v = in.v_m_per_s;
  const double g = stribeck_level_N(in, v);
  const double dzdt = v - p_.sigma0_N_per_m * std::abs(v) * z[0] / g;
  dz[0] = dzdt;
  return p_.sigma0_N_per_m * z[0] + p_.sigma1_Ns_per_m * dzdt + p_.viscous_Ns_per_m * v;
}

double LuGreFriction::holding_force_N(const FrictionInput& /*in*/,
                                      std::span<const double> z) const {
  return p_.sigma0_N_per_m * z[0];
}

double LuGreFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return sgn * stribeck_level_N(in, v) + p_.viscous_Ns_per_m * v;
}

void LuGreFriction::steady_state(const FrictionInput& in, std::span<double> z) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  z[0] = sgn * stribeck_level_N(in, v) / p_.sigma0_N_per_m;
}

}  // namespace pneumachaos
