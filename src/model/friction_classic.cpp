#include <algorithm>
#include <cmath>

#include "friction_models.hpp"

namespace pneumachaos {

double ClassicFriction::force_N(const FrictionInput& in, int direction,
                                std::span<const double> /*z*/, std::span<double> /*dz*/) const {
  // The mode fixes the sign, so the force is smooth within a sliding segment.
  const double speed = std::max(direction * in.v_m_per_s, 0.0);
  return direction * (coulomb_N(in) + p_.viscous_Ns_per_m * speed);
}

double ClassicFriction::holding_force_N(const FrictionInput& in,
                                        std::span<const double> /*z*/) const {
  return static_N(in);
}

double ClassicFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  return (v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0)) * coulomb_N(in) + p_.viscous_Ns_per_m * v;
}

}  // namespace pneumachaos
