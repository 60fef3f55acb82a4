#include "friction_laws.hpp"
#include "friction_models.hpp"

namespace pneumachaos {

double StribeckLagFriction::force_N(const FrictionInput& in, int direction,
                                    std::span<const double> z, std::span<double> dz) const {
  return friction_law::stribeck_lag_N(p_, in, direction, z[0], dz[0]);
}

// Breakaway at Fs, as the stiction model: the lag acts while sliding (docs/model.md).
double StribeckLagFriction::holding_force_N(const FrictionInput& in,
                                            std::span<const double> /*z*/) const {
  return friction_law::static_N(p_, in);
}

// In steady sliding the lag has caught up: the static Stribeck curve.
double StribeckLagFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return sgn * friction_law::stribeck_level_N(p_, in, v) + p_.curve.viscous_Ns_per_m * v;
}

void StribeckLagFriction::steady_state(const FrictionInput& in, std::span<double> z) const {
  z[0] = friction_law::stribeck_weight(p_, in.v_m_per_s);
}

}  // namespace pneumachaos
