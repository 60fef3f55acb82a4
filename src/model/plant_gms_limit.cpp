// The GMS seal's quasi-static limit in the Plant (docs/model.md, "Friction"): the elements'
// rates and their lag need dv/dt and the rate of the Stribeck level, which the friction law
// alone cannot know. The level's rate is the derivative of the same level function along
// dx/dt (a dual number), so the level's physics is not written a second time.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "plant_equations.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

using plant_detail::direction_of;
using plant_detail::kSeal;
using plant_detail::mode_of;

// Two directions: along dx/dt (the level's rate) and along v alone (its slope in v).
using Dual2 = Eigen::AutoDiffScalar<Eigen::Vector2d>;
constexpr std::size_t kMaxStates = 24;

struct LevelRates {
  double g;      // the Stribeck level on the branch
  double dg_dt;  // its rate along dx/dt
  double dg_dv;  // its slope in v
};

// `input` maps a dual state to the contact's friction input (Plant::friction_input).
template <typename Input>
LevelRates level_rates(const TabulatedFriction& p, int direction, std::span<const double> x,
                       std::span<const double> dxdt, std::size_t iv, Input input) {
  const std::size_t n = x.size();
  if (n > kMaxStates) throw Error("friction.model", "too many states for the GMS limit");
  std::array<Dual2, kMaxStates> xd;
  for (std::size_t i = 0; i < n; ++i)
    xd[i] = Dual2(x[i], Eigen::Vector2d(dxdt[i], i == iv ? 1.0 : 0.0));
  const BasicFrictionInput<Dual2> in = input(std::span<const Dual2>(xd.data(), n));
  const Dual2 g = friction_law::stribeck_level_N(p, in, Dual2(direction * in.v_m_per_s), true);
  return {g.value(), g.derivatives()[0], g.derivatives()[1]};
}

}  // namespace

// dv/dt arrives computed with every element on max(m, r); the elements' lag lowers the force
// by L(dg/dt) and so raises dv/dt, which raises dg/dt by dg/dv times as much: a fixed point
// whose contraction factor is (dL/d(dg/dt)) (dg/dv) / mass, 1e-2 to 1e-1 on the default rig
// where the limit is on (docs/model.md): the passes stop once one moves dv/dt by less than
// 1e-13 of its size, at most four (1e-4 of the lag, a few uN, at the slowest contraction:
// far below the limit's own neglected term; eight passes cost 20 % more CPU).
void Plant::track_shares(std::size_t contact, int direction, double mass,
                         std::span<const double> x, std::span<double> dxdt) const {
  const TabulatedFriction& p = friction_of(contact).params();
  const std::size_t z0 = contact == kSeal ? layout_.seal_z : layout_.guide_z;
  const std::size_t iv = contact == kSeal ? layout_.v : layout_.load_v;
  const LevelRates l = level_rates(p, direction, x, dxdt, iv, [&](std::span<const Dual2> xd) {
    return friction_input<Dual2>(contact, xd);
  });
  const double* z = x.data() + z0;
  const double base = dxdt[iv];
  double dg_dt = l.dg_dt;
  for (int pass = 0; pass < 4; ++pass) {
    const double before = dxdt[iv];
    dxdt[iv] = base + direction * friction_law::gms_lag_force_N(p, x[iv], l.g, dg_dt, z,
                                                                 direction) / mass;
    dg_dt = l.dg_dt + l.dg_dv * (dxdt[iv] - base);
    if (std::abs(dxdt[iv] - before) <= 1e-13 * std::abs(dxdt[iv])) break;
  }
  friction_law::gms_quasi_static_rates(p, x[iv], l.g, dg_dt, z, dxdt.data() + z0, direction);
}

void Plant::limit_deflections(std::size_t contact, const Mode& mode, std::span<const double> x,
                              double* out) const {
  const int d = direction_of(mode_of(mode, contact));
  Mode quasi = mode;
  quasi.value[contact] =
      static_cast<std::int8_t>(d > 0 ? ContactMode::kQuasiPos : ContactMode::kQuasiNeg);
  std::vector<double> dxdt(layout_.size);
  evaluate<double>(quasi, x, std::span<double>(dxdt));
  const TabulatedFriction& p = friction_of(contact).params();
  const std::size_t z0 = contact == kSeal ? layout_.seal_z : layout_.guide_z;
  const std::size_t iv = contact == kSeal ? layout_.v : layout_.load_v;
  const LevelRates l = level_rates(p, d, x, dxdt, iv, [&](std::span<const Dual2> xd) {
    return friction_input<Dual2>(contact, xd);
  });
  friction_law::gms_limit_deflections(p, x[iv], l.g, l.dg_dt, x.data() + z0, out, d);
}

double Plant::limit_force(std::size_t contact, const Mode& mode, std::span<const double> x) const {
  std::vector<double> dxdt(layout_.size);
  evaluate<double>(mode, x, std::span<double>(dxdt));
  const bool seal = contact == kSeal;
  const double mass = seal ? piston_mass_ : load_.mass_kg;
  return drive_force<double>(contact, x) - mass * dxdt[seal ? layout_.v : layout_.load_v];
}

}  // namespace pneumachaos
