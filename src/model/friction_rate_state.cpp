#include <cmath>

#include "friction_laws.hpp"
#include "friction_models.hpp"

namespace pneumachaos {

double StribeckRateStateFriction::force_N(const FrictionInput& in, int direction,
                                          std::span<const double> z,
                                          std::span<double> dz) const {
  return friction_law::stribeck_rate_state_N(p_, in, direction, z.data(), dz.data());
}

// The sliding force at v = 0 with the states as they are: breakaway continues into sliding
// without a jump, and a slip that ended on a weakened state leaves a lower breakaway.
double StribeckRateStateFriction::holding_force_N(const FrictionInput& in,
                                                  std::span<const double> z) const {
  const friction_law::Levels<double> f = friction_law::levels_N(p_, in);
  return f.coulomb_N +
         (f.static_N - f.coulomb_N) * friction_law::rate_state_weight(p_.rate_state, z.data());
}

// In steady sliding both states sit on the Stribeck weight: the stribeck curve plus the
// direct effect.
double StribeckRateStateFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  const double direct = friction_law::rate_state_direct_N(p_.rate_state, std::abs(v));
  return sgn * (friction_law::stribeck_level_N(p_, in, v) + direct) +
         p_.curve.viscous_Ns_per_m * v;
}

void StribeckRateStateFriction::steady_state(const FrictionInput& in, std::span<double> z) const {
  z[0] = z[1] = friction_law::stribeck_weight(p_, in.v_m_per_s);
}

}  // namespace pneumachaos
