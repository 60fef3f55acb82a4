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

FrictionPartials LuGreFriction::partials(const FrictionInput& in, int /*direction*/,
                                         std::span<const double> z) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  const double g = stribeck_level_N(in, v);
  const double g_v = sgn * stribeck_dspeed(in, v);
  const double g_p = stribeck_dp(v);
  const double s0 = p_.sigma0_N_per_m;
  // zdot = v - s0 |v| z / g(v, p).
  FrictionPartials d;
  d.dzdot_dv = 1.0 - s0 * z[0] * (sgn * g - std::abs(v) * g_v) / (g * g);
  d.dzdot_dz = -s0 * std::abs(v) / g;
  d.dzdot_dp = s0 * std::abs(v) * z[0] * g_p / (g * g);
  // F = s0 z + s1 zdot + s2 v.
  d.dF_dv = p_.sigma1_Ns_per_m * d.dzdot_dv + p_.viscous_Ns_per_m;
  d.dF_dz = s0 + p_.sigma1_Ns_per_m * d.dzdot_dz;
  d.dF_dp = p_.sigma1_Ns_per_m * d.dzdot_dp;
  return d;
}

void LuGreFriction::steady_state(const FrictionInput& in, std::span<double> z) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  z[0] = sgn * stribeck_level_N(in, v) / p_.sigma0_N_per_m;
}

}  // namespace pneumachaos
