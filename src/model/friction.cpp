#include "pneumachaos/model/friction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "friction_models.hpp"

namespace pneumachaos {

double FrictionModel::texture_factor(const FrictionInput& in) const {
  double f = 1.0;
  for (const TextureMode& m : p_.texture) {
    f += m.amplitude * std::sin(m.wavenumber_per_m * in.position_m + m.phase);
  }
  return f;
}

double FrictionModel::stribeck_weight(double speed) const {
  const double u = std::abs(speed) / p_.stribeck_velocity_m_per_s;
  const double delta = p_.stribeck_exponent;
  // The common exponents avoid pow(), which dominated the derivative's cost.
  const double w = delta == 2.0   ? u * u
                   : delta == 1.0 ? u
                   : delta == 0.5 ? std::sqrt(u)
                                  : std::pow(u, delta);
  return std::exp(-w);
}

double FrictionModel::stribeck_level_N(const FrictionInput& in, double speed) const {
  const double fc = coulomb_N(in);
  return fc + (static_N(in) - fc) * stribeck_weight(speed);
}

double FrictionModel::stribeck_dspeed(const FrictionInput& in, double speed) const {
  const double vs = p_.stribeck_velocity_m_per_s;
  const double u = std::abs(speed) / vs;
  const double delta = p_.stribeck_exponent;
  if (u == 0.0) return delta > 1.0 ? 0.0 : -std::numeric_limits<double>::infinity();
  return -(static_N(in) - coulomb_N(in)) * stribeck_weight(speed) * delta *
         std::pow(u, delta - 1.0) / vs;
}

double FrictionModel::stribeck_dp(double speed) const {
  const double w = stribeck_weight(speed);
  return p_.coulomb_gain_N_per_Pa + (p_.static_gain_N_per_Pa - p_.coulomb_gain_N_per_Pa) * w;
}

double FrictionModel::steady_slope_Ns_per_m(const FrictionInput& in) const {
  // Central difference with a step small against vs but far above rounding.
  const double h = std::max(1e-7, 1e-4 * std::abs(in.v_m_per_s));
  FrictionInput lo = in;
  FrictionInput hi = in;
  lo.v_m_per_s -= h;
  hi.v_m_per_s += h;
  return (steady_force_N(hi) - steady_force_N(lo)) / (2.0 * h);
}

void FrictionModel::steady_state(const FrictionInput& /*in*/, std::span<double> z) const {
  std::fill(z.begin(), z.end(), 0.0);
}

std::unique_ptr<FrictionModel> make_friction_model(const FrictionParams& params) {
  switch (params.kind) {
    case FrictionKind::kClassic:
    case FrictionKind::kStribeck:
      return std::make_unique<StictionFriction>(params);
    case FrictionKind::kLuGre:
      return std::make_unique<LuGreFriction>(params);
  }
  return nullptr;
}

const char* friction_kind_name(FrictionKind kind) {
  switch (kind) {
    case FrictionKind::kClassic:
      return "classic";
    case FrictionKind::kStribeck:
      return "stribeck";
    case FrictionKind::kLuGre:
      return "lugre";
  }
  return "?";
}

}  // namespace pneumachaos
