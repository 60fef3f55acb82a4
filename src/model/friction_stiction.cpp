#include <algorithm>
#include <cmath>

#include "friction_models.hpp"

namespace pneumachaos {

double StictionFriction::sliding_level_N(const FrictionInput& in, double speed) const {
  return p_.kind == FrictionKind::kClassic ? coulomb_N(in) : stribeck_level_N(in, speed);
}

double StictionFriction::force_N(const FrictionInput& in, int direction,
                                 std::span<const double> /*z*/, std::span<double> /*dz*/) const {
  // The mode fixes the sign, so the force is smooth within a sliding segment.
  const double speed = std::max(direction * in.v_m_per_s, 0.0);
  return direction * (sliding_level_N(in, speed) + p_.viscous_Ns_per_m * speed);
}

double StictionFriction::holding_force_N(const FrictionInput& in,
                                         std::span<const double> /*z*/) const {
  return static_N(in);
}

double StictionFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return sgn * sliding_level_N(in, v) + p_.viscous_Ns_per_m * v;
}

FrictionPartials StictionFriction::partials(const FrictionInput& in, int direction,
                                            std::span<const double> /*z*/) const {
  // F = d * level(d v, p) + B v with d = direction, so dF/dv = level' + B.
  const double speed = std::max(direction * in.v_m_per_s, 0.0);
  FrictionPartials d;
  const bool classic = p_.kind == FrictionKind::kClassic;
  d.dF_dv = (classic ? 0.0 : stribeck_dspeed(in, speed)) + p_.viscous_Ns_per_m;
  d.dF_dp = direction * (classic ? p_.coulomb_gain_N_per_Pa : stribeck_dp(speed));
  return d;
}

}  // namespace pneumachaos
