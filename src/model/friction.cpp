#include "pneumachaos/model/friction.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "friction_models.hpp"

namespace pneumachaos {

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

void FrictionModel::rest_state(std::span<double> z) const { std::fill(z.begin(), z.end(), 0.0); }

// A long rest has restored the whole Stribeck drop.
void StribeckMemoryFriction::rest_state(std::span<double> z) const {
  std::fill(z.begin(), z.end(), 1.0);
}

std::unique_ptr<FrictionModel> make_friction_model(
    const FrictionParams& params, std::shared_ptr<const TextureTable> texture_table,
    std::shared_ptr<const TextureTable> level_table) {
  std::shared_ptr<const TextureTable>& t = texture_table;
  std::shared_ptr<const TextureTable>& f = level_table;
  switch (params.kind) {
    case FrictionKind::kClassic:
    case FrictionKind::kStribeck:
      if (params.lagged()) return std::make_unique<StribeckLagFriction>(params, std::move(t), std::move(f));
      if (params.rate_and_state())
        return std::make_unique<StribeckRateStateFriction>(params, std::move(t), std::move(f));
      return std::make_unique<StictionFriction>(params, std::move(t), std::move(f));
    case FrictionKind::kLuGre:
      return std::make_unique<LuGreFriction>(params, std::move(t), std::move(f));
    case FrictionKind::kGms:
      return std::make_unique<GmsFriction>(params, std::move(t), std::move(f));
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
    case FrictionKind::kGms:
      return "gms";
  }
  return "?";
}

}  // namespace pneumachaos
