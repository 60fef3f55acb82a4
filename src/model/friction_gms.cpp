#include "friction_laws.hpp"
#include "friction_models.hpp"

namespace pneumachaos {

std::size_t GmsFriction::state_count() const { return static_cast<std::size_t>(p_.gms.count); }

// As LuGre's: the interface's smooth models read sgn v from v itself (no branch).
double GmsFriction::force_N(const FrictionInput& in, int /*direction*/, std::span<const double> z,
                            std::span<double> dz) const {
  return friction_law::gms_N(p_, in, z.data(), dz.data());
}

// At v = 0 the elements hold their deflections: the force they carry is what holds the contact.
double GmsFriction::holding_force_N(const FrictionInput& /*in*/,
                                    std::span<const double> z) const {
  double sum = 0.0;
  for (const double zi : z) sum += zi;
  return friction_law::gms_element_stiffness(p_) * sum;
}

// In steady sliding every element has reached its share, and the shares sum to one.
double GmsFriction::steady_force_N(const FrictionInput& in) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  return sgn * friction_law::stribeck_level_N(p_, in, v) + p_.curve.viscous_Ns_per_m * v;
}

void GmsFriction::steady_state(const FrictionInput& in, std::span<double> z) const {
  const double v = in.v_m_per_s;
  const double sgn = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  const double g = friction_law::stribeck_level_N(p_, in, v);
  for (int i = 0; i < p_.gms.count; ++i)
    z[static_cast<std::size_t>(i)] = sgn * friction_law::gms_reach_m(p_, i, g);
}

}  // namespace pneumachaos
