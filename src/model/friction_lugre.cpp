#include <cmath>

#include "friction_laws.hpp"
#include "friction_models.hpp"

namespace pneumachaos {

double LuGreFriction::force_N(const FrictionInput& in, int /*direction*/, std::span<const double> z,
                              std::span<double> dz) const {
  return friction_law::lugre_N(p_, in, z[0], dz[0]);
}

double LuGreFriction::holding_force_N(const FrictionInput& /*in*/,
                                      std::span<const double> z) const {
  return p_.lugre.sigma0_N_per_m * z[0];
}

double LuGreFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return sgn * friction_law::stribeck_level_N(p_, in, v) + p_.curve.viscous_Ns_per_m * v;
}

void LuGreFriction::steady_state(const FrictionInput& in, std::span<double> z) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  z[0] = sgn * friction_law::stribeck_level_N(p_, in, v) / p_.lugre.sigma0_N_per_m;
}

}  // namespace pneumachaos
