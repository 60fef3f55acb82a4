#include <algorithm>
#include <cmath>

#include "friction_models.hpp"

namespace pneumachaos {

double StribeckFriction::force_N(const FrictionInput& in, int direction,
                                 std::span<const double> /*z*/, std::span<double> /*dz*/) const {
  const double speed = std::max(direction * in.v_m_per_s, 0.0);
  return direction * (stribeck_level_N(in, speed) + p_.viscous_Ns_per_m * speed);
}

double StribeckFriction::holding_force_N(const FrictionInput& in,
                                         std::span<const double> /*z*/) const {
  return static_N(in);
}

double StribeckFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return sgn * stribeck_level_N(in, v) + p_.viscous_Ns_per_m * v;
}

}  // namespace pneumachaos
