#pragma once
// The Plant's equations, written once on a scalar type T: eqs. (1)-(3) of
// docs/model.md, the friction internal states and the optional second body.
// derivative() instantiates them on double, jacobian() on an automatic-differentiation scalar,
// and the equilibrium search solves their residual. Private to the model module.
//
// The double instantiation does the arithmetic of a hand-written double derivative, operation
// for operation, so that simulations are bit-identical to one.

#include <type_traits>

#include "friction_laws.hpp"
#include "pneumachaos/model/plant.hpp"

namespace pneumachaos {
namespace plant_detail {

inline constexpr std::size_t kSeal = 0;
inline constexpr std::size_t kGuide = 1;

inline ContactMode mode_of(const Mode& m, std::size_t contact) {
  return static_cast<ContactMode>(m.value[contact]);
}
inline bool moving(ContactMode m) { return m != ContactMode::kStuck && m != ContactMode::kAtStop; }
inline bool quasi_static(ContactMode m) {
  return m == ContactMode::kQuasiPos || m == ContactMode::kQuasiNeg;
}
inline int direction_of(ContactMode m) {
  if (m == ContactMode::kSlidePos || m == ContactMode::kSmoothPos || m == ContactMode::kQuasiPos)
    return 1;
  return m == ContactMode::kSlideNeg || m == ContactMode::kSmoothNeg || m == ContactMode::kQuasiNeg
             ? -1
             : 0;
}

}  // namespace plant_detail

template <typename T>
T Plant::drive_force(std::size_t contact, std::span<const T> x) const {
  const double Pa = ambient_Pa_;
  const auto& L = layout_;
  T coupling(0.0);
  if (contacts_ == 2) {
    coupling = load_.coupling_stiffness_N_per_m * (x[L.x] - x[L.load_x]) +
               load_.coupling_damping_Ns_per_m * (x[L.v] - x[L.load_v]);
  }
  if (contact == plant_detail::kGuide) return coupling - load_.external_force_N;
  const T pneumatic = A1_ * (x[L.P1] - Pa) - A2_ * (x[L.P2] - Pa);
  if (contacts_ == 2) return pneumatic - coupling;
  return pneumatic - load_.external_force_N;
}

template <typename T>
BasicFrictionInput<T> Plant::friction_input(std::size_t contact, std::span<const T> x) const {
  const auto& L = layout_;
  if (contact == plant_detail::kGuide) return {x[L.load_v], T(0.0), x[L.load_x]};
  return {x[L.v], x[L.P1] + x[L.P2] - 2.0 * ambient_Pa_, x[L.x]};
}

template <typename T>
T Plant::friction_force(std::size_t contact, ContactMode m, std::span<const T> x,
                        std::span<T> dz) const {
  using plant_detail::kSeal;
  const auto& L = layout_;
  const FrictionModel& f = contact == kSeal ? *seal_ : *guide_;
  const std::size_t z0 = contact == kSeal ? L.seal_z : L.guide_z;
  const std::size_t nz = contact == kSeal ? L.seal_z_count : L.guide_z_count;
  const T* z = nz == 0 ? nullptr : x.data() + z0;
  if (!plant_detail::moving(m)) {
    friction_law::resting_rates(f.params(), z, dz.data(), dz.size());
    return T(0.0);
  }
  return friction_law::moving_force_N(f.params(), friction_input(contact, x),
                                      plant_detail::direction_of(m), z, dz.data(),
                                      plant_detail::quasi_static(m));
}

// What S1 draws from: the supply line's pressure P0 when it has a volume, else the
// regulator's Ps itself (docs/model.md, "Supply line").
template <typename T>
T Plant::valve1_upstream(std::span<const T> x) const {
  return layout_.has_supply_line() ? x[layout_.P0] : T(supply_Pa_);
}

// Mass flow through S1 by the valve law, scaled by S1's opening fraction while the solenoid
// valve opens (valve.S1_opening = lag): the flow is proportional to the effective area.
template <typename T>
T Plant::valve1_flow(std::span<const T> x) const {
  const T W1 = valve1_->mass_flow(valve1_upstream(x), x[layout_.P1]);
  if (layout_.has_valve_opening()) return W1 * x[layout_.S1_open];
  return W1;
}

// Mass flow through S1 into chamber 1; with the energy equation, back-flow leaves chamber 1 at
// its own temperature T1 and passes sqrt(T_supply / T1) times the flow sized at T_supply.
template <typename T>
T Plant::valve1_inflow(std::span<const T> x) const {
  using std::sqrt;
  T W1 = valve1_flow(x);
  if (layout_.has_temperatures() && W1 < 0.0) W1 = W1 * sqrt(T_supply_ / x[layout_.T1]);
  return W1;
}

template <typename T>
T Plant::head_chamber_rate(std::span<const T> x) const {
  const auto& L = layout_;
  const double k = polytropic_exponent_;
  const T V1 = geometry_.volume_head_m3(x[L.x]);
  const T W1 = valve1_flow(x);
  return k * RT_ / V1 * W1 - k * x[L.P1] * A1_ / V1 * x[L.v];  // eq. (2)
}

template <typename T>
T Plant::rod_chamber_rate(std::span<const T> x) const {
  const auto& L = layout_;
  const double k = polytropic_exponent_;
  const T V2 = geometry_.volume_rod_m3(x[L.x]);
  const T W2 = valve2_->mass_flow(x[L.P2], T(ambient_Pa_));
  return -k * RT_ / V2 * W2 + k * x[L.P2] * A2_ / V2 * x[L.v];  // eq. (3)
}

// The energy equation of one chamber (docs/model.md, "Chamber temperatures"): the first law
// for an open volume of ideal gas, with H_in = sum of W * T of what flows in (out: negative),
// W_in the net mass inflow and the wall heat h A_wall (T_wall - T). Writes dT/dt, returns dP/dt.
template <typename T>
T Plant::open_chamber_rates(const T& P, const T& Tc, const T& V, const T& dV, const T& W_in,
                            const T& H_in, const T& A_wall, T& dTc) const {
  const double kap = kappa_;
  const T Q = thermal_.heat_transfer_W_per_m2K * A_wall * (thermal_.wall_temperature_K - Tc);
  const T dP = kap * R_ / V * H_in + (kap - 1.0) / V * Q - kap * P / V * dV;
  dTc = Tc * (dP / P + dV / V - W_in * R_ * Tc / (P * V));
  return dP;
}

// Both chambers with the energy equation. The valves' flows were sized for supply-temperature
// air upstream; air leaving a chamber at T passes sqrt(T_supply / T) times as much (the
// 1/sqrt(R T_up) of the nozzle law), and carries its own temperature out.
template <typename T>
void Plant::chamber_energy_rates(std::span<const T> x, std::span<T> dxdt) const {
  using std::sqrt;
  const auto& L = layout_;
  const T& T1 = x[L.T1];
  const T& T2 = x[L.T2];
  const T W1 = valve1_inflow(x);
  const T H1 = W1 < 0.0 ? T(W1 * T1) : T(W1 * T_supply_);  // back-flow carries T1 out
  T W2 = valve2_->mass_flow(x[L.P2], T(ambient_Pa_));
  T H2 = -W2 * T_supply_;  // reversed: atmosphere (at the supply temperature) flows in
  if (W2 >= 0.0) {
    W2 = W2 * sqrt(T_supply_ / T2);
    H2 = -W2 * T2;
  }
  const T V1 = geometry_.volume_head_m3(x[L.x]);
  const T V2 = geometry_.volume_rod_m3(x[L.x]);
  dxdt[L.P1] = open_chamber_rates(x[L.P1], T1, V1, T(A1_ * x[L.v]), W1, H1,
                                  geometry_.wall_area_head_m2(V1), dxdt[L.T1]);
  dxdt[L.P2] = open_chamber_rates(x[L.P2], T2, V2, T(-A2_ * x[L.v]), T(-W2), H2,
                                  geometry_.wall_area_rod_m2(V2), dxdt[L.T2]);
}

template <typename T>
void Plant::evaluate(const Mode& mode, std::span<const T> x, std::span<T> dxdt) const {
  using namespace plant_detail;
  const auto& L = layout_;
  if (L.has_temperatures()) {
    chamber_energy_rates(x, dxdt);
  } else {
    dxdt[L.P1] = head_chamber_rate(x);
    dxdt[L.P2] = rod_chamber_rate(x);
  }
  // The line loses to chamber 1 exactly what chamber 1 gains (mass conservation).
  if (L.has_supply_line()) dxdt[L.P0] = line_->pressure_rate(x[L.P0], valve1_inflow(x));
  // First-order opening of S1 from the switch at t = 0: a = 1 - exp(-t / tau).
  if (L.has_valve_opening())
    dxdt[L.S1_open] = (1.0 - x[L.S1_open]) / valve1_time_constant_s_;

  const auto body = [&](std::size_t contact, std::size_t ix, std::size_t iv, std::size_t iz,
                        std::size_t nz, double mass) {
    const ContactMode m = mode_of(mode, contact);
    std::span<T> dz = nz == 0 ? std::span<T>{} : dxdt.subspan(iz, nz);
    const T friction = friction_force(contact, m, x, dz);
    if (moving(m)) {
      dxdt[ix] = x[iv];
      dxdt[iv] = (drive_force(contact, x) - friction) / mass;  // eq. (1)
      // GMS in its quasi-static limit: the elements track their shares, whose rate needs
      // dv/dt (the Jacobian keeps the full law: friction_laws.hpp, moving_force_N).
      if constexpr (std::is_same_v<T, double>) {
        if (quasi_static(m) && friction_of(contact).params().kind == FrictionKind::kGms)
          track_shares(contact, direction_of(m), mass, x, dxdt);
      }
    } else {
      // Stuck or at the stop: v held at exactly 0 and x frozen (docs/model.md "Friction").
      dxdt[ix] = T(0.0);
      dxdt[iv] = T(0.0);
    }
  };
  body(kSeal, L.x, L.v, L.seal_z, L.seal_z_count, piston_mass_);
  if (contacts_ == 2) {
    body(kGuide, L.load_x, L.load_v, L.guide_z, L.guide_z_count, load_.mass_kg);
  }
}

}  // namespace pneumachaos
