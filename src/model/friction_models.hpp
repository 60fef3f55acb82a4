#pragma once
// The concrete friction models; private to the model module (use make_friction_model). Their
// laws are the templates of friction_laws.hpp, shared with the Plant's right-hand side.

#include "pneumachaos/model/friction.hpp"

namespace pneumachaos {

/// True stiction: v = 0 held while |drive| <= Fs. Sliding force: `classic`, paper eq. (4),
/// Fc sgn v + B v; `stribeck`, [Fc + (Fs - Fc) exp(-(|v|/vs)^delta)] sgn v + B v.
class StictionFriction final : public FrictionModel {
 public:
  using FrictionModel::FrictionModel;
  [[nodiscard]] bool has_stiction() const override { return true; }
  double force_N(const FrictionInput& in, int direction, std::span<const double> z,
                 std::span<double> dz) const override;
  [[nodiscard]] double holding_force_N(const FrictionInput& in,
                                       std::span<const double> z) const override;
  [[nodiscard]] double steady_force_N(const FrictionInput& in) const override;
};

/// Canudas de Wit, Olsson, Astrom & Lischinsky (1995), IEEE TAC 40(3): bristle model
/// dz/dt = v - sigma0 |v| z / g(v), F = sigma0 z + sigma1 dz/dt + sigma2 v.
class LuGreFriction final : public FrictionModel {
 public:
  using FrictionModel::FrictionModel;
  [[nodiscard]] std::size_t state_count() const override { return 1; }
  [[nodiscard]] bool has_stiction() const override { return false; }
  double force_N(const FrictionInput& in, int direction, std::span<const double> z,
                 std::span<double> dz) const override;
  [[nodiscard]] double holding_force_N(const FrictionInput& in,
                                       std::span<const double> z) const override;
  [[nodiscard]] double steady_force_N(const FrictionInput& in) const override;
  void steady_state(const FrictionInput& in, std::span<double> z) const override;
};

/// What the stribeck model's memories share: true stiction as StictionFriction, and states
/// that are weights of the Stribeck drop (0..1), all 1 after a long rest (the start of a run).
class StribeckMemoryFriction : public FrictionModel {
 public:
  using FrictionModel::FrictionModel;
  [[nodiscard]] const char* state_unit() const override { return "-"; }
  [[nodiscard]] double state_scale() const override { return 1e-2; }
  void rest_state(std::span<double> z) const override;
  [[nodiscard]] bool has_stiction() const override { return true; }
};

/// The stribeck model with memory = lag: while sliding the Stribeck drop's weight s follows
/// exp(-(|v|/vs)^delta) with a first-order lag: ds/dt = (exp(-(|v|/vs)^delta) - s) / tau,
/// F = [Fc + (Fs - Fc) s] sgn v + B v (Hess & Soom 1990; docs/model.md). At rest s -> 1.
class StribeckLagFriction final : public StribeckMemoryFriction {
 public:
  using StribeckMemoryFriction::StribeckMemoryFriction;
  [[nodiscard]] std::size_t state_count() const override { return 1; }
  [[nodiscard]] const char* state_name() const override { return "s_lag"; }
  double force_N(const FrictionInput& in, int direction, std::span<const double> z,
                 std::span<double> dz) const override;
  [[nodiscard]] double holding_force_N(const FrictionInput& in,
                                       std::span<const double> z) const override;
  [[nodiscard]] double steady_force_N(const FrictionInput& in) const override;
  void steady_state(const FrictionInput& in, std::span<double> z) const override;
};

/// The stribeck model with memory = rate_state: breakaway at the level the two states hold,
/// Fc + (Fs - Fc)(share theta_1 + (1 - share) theta_2); while sliding,
/// friction_law::stribeck_rate_state_N (Gu, Rice, Ruina & Tse 1984; docs/model.md). The
/// states move with the slip only, so they hold still while stuck.
class StribeckRateStateFriction final : public StribeckMemoryFriction {
 public:
  using StribeckMemoryFriction::StribeckMemoryFriction;
  [[nodiscard]] std::size_t state_count() const override { return 2; }
  [[nodiscard]] const char* state_name() const override { return "theta"; }
  double force_N(const FrictionInput& in, int direction, std::span<const double> z,
                 std::span<double> dz) const override;
  [[nodiscard]] double holding_force_N(const FrictionInput& in,
                                       std::span<const double> z) const override;
  [[nodiscard]] double steady_force_N(const FrictionInput& in) const override;
  void steady_state(const FrictionInput& in, std::span<double> z) const override;
};

/// Generalized Maxwell-slip (Al-Bender, Lampaert & Swevers 2005) in the smooth state-equation
/// form of docs/model.md: N elements with deflections z_i, F = sum k_i z_i + B v.
class GmsFriction final : public FrictionModel {
 public:
  using FrictionModel::FrictionModel;
  [[nodiscard]] std::size_t state_count() const override;
  [[nodiscard]] const char* state_name() const override { return "z_gms"; }
  [[nodiscard]] bool has_stiction() const override { return false; }
  double force_N(const FrictionInput& in, int direction, std::span<const double> z,
                 std::span<double> dz) const override;
  [[nodiscard]] double holding_force_N(const FrictionInput& in,
                                       std::span<const double> z) const override;
  [[nodiscard]] double steady_force_N(const FrictionInput& in) const override;
  void steady_state(const FrictionInput& in, std::span<double> z) const override;
};

}  // namespace pneumachaos
