#include "friction_laws.hpp"
#include "friction_models.hpp"

namespace pneumachaos {

double StictionFriction::force_N(const FrictionInput& in, int direction,
                                 std::span<const double> /*z*/, std::span<double> /*dz*/) const {
  return friction_law::stiction_sliding_N(p_, in, direction);
}

double StictionFriction::holding_force_N(const FrictionInput& in,
                                         std::span<const double> /*z*/) const {
  return friction_law::static_N(p_, in);
}

double StictionFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  const double level = p_.kind == FrictionKind::kClassic
                           ? friction_law::coulomb_N(p_, in)
                           : friction_law::stribeck_level_N(p_, in, v);
  return sgn * level + p_.curve.viscous_Ns_per_m * v;
}

}  // namespace pneumachaos
