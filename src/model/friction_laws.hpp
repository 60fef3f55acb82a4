#pragma once
// The friction laws, written once on a scalar type T: double when the plant is integrated, an
// automatic-differentiation scalar when its Jacobian is taken (docs/architecture.md). The
// FrictionModel classes and the Plant's right-hand side both call these; private to the
// model module.
//
// The laws are also templated on the parameter type P: FrictionParams (or the models'
// TabulatedFriction) for the plant, or a struct with the same members holding
// automatic-differentiation scalars when the friction parameters themselves are fitted
// (src/identify/friction_fits.cpp).
//
// The double instantiation does the arithmetic of hand-written double laws, operation for
// operation; a textured bore's factor is read from the Plant's table (texture_table.hpp),
// within the table's stated bound of the sines.

#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <type_traits>

#include "pneumachaos/model/friction.hpp"
#include "texture_table.hpp"

namespace pneumachaos::friction_law {

/// The bore texture's factor 1 + sum(amplitude sin(wavenumber x + phase)) (docs/model.md).
template <typename T, typename P>
T bore_texture(const P& p, const T& position_m) {
  using std::sin;
  // The Plant's table serves the double evaluations; the automatic-differentiation ones (the
  // Jacobian, the friction fits) take the sines, which differ by the table's bound at most.
  if constexpr (std::is_same_v<T, double> && std::is_same_v<P, TabulatedFriction>) {
    if (p.texture_table) {
      if (const std::optional<double> f = p.texture_table->at(position_m)) return *f;
    }
  }
  T f(1.0);
  for (const TextureMode& m : p.texture)
    f += m.amplitude * sin(m.wavenumber_per_m * position_m + m.phase);
  return f;
}

/// The seal's random level field at x (docs/model.md, "Friction"). Where the Plant tabulated
/// it, the table is the field for every evaluation: the automatic-differentiation ones take its
/// value and slope at x, so the Jacobian is the derivative of what the integrator sees.
template <typename T, typename P>
T random_level(const P& p, const T& position_m) {
  if constexpr (std::is_same_v<P, TabulatedFriction>) {
    if (p.level_table) {
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      if constexpr (std::is_same_v<T, double>) {
        return p.level_table->at(position_m).value_or(kNaN);
      } else {
        const double x0 = position_m.value();
        const auto vs = p.level_table->value_and_slope(x0).value_or(std::pair{kNaN, kNaN});
        return T(vs.first) + vs.second * (position_m - x0);
      }
    }
  }
  using std::sin;
  T f(0.0);
  for (const TextureMode& m : p.level_field.modes)
    f += m.amplitude * sin(m.wavenumber_per_m * position_m + m.phase);
  return f;
}

/// Friction levels times the bore's factor: the texture's and, on a seal with a random level
/// field, the field added.
template <typename T, typename P>
T texture_factor(const P& p, const T& position_m) {
  T f = bore_texture(p, position_m);
  if constexpr (requires { p.level_field; }) {
    if (!p.level_field.modes.empty()) f += random_level(p, position_m);
  }
  return f;
}

/// A friction level with its pressure dependence, times the texture factor `texture`.
template <typename T, typename Q>
T textured_level_N(const Q& level_N, const Q& gain_N_per_Pa, const T& gauge_sum_Pa,
                   const T& texture) {
  return (level_N + gain_N_per_Pa * gauge_sum_Pa) * texture;
}

/// Fc with its pressure dependence and texture (docs/model.md).
template <typename T, typename P>
T coulomb_N(const P& p, const BasicFrictionInput<T>& in) {
  return textured_level_N(p.curve.coulomb_N, p.pressure_gain.coulomb_N_per_Pa, in.gauge_sum_Pa,
                          texture_factor(p, in.position_m));
}

/// Fs, likewise.
template <typename T, typename P>
T static_N(const P& p, const BasicFrictionInput<T>& in) {
  return textured_level_N(p.curve.static_N, p.pressure_gain.static_N_per_Pa, in.gauge_sum_Pa,
                          texture_factor(p, in.position_m));
}

/// Fc and Fs together: the texture's sines, the bulk of a friction evaluation on a textured
/// bore (docs/notes/performance.md), are summed once for both.
template <typename T>
struct Levels {
  T coulomb_N;
  T static_N;
};
template <typename T, typename P>
Levels<T> levels_N(const P& p, const BasicFrictionInput<T>& in) {
  const T texture = texture_factor(p, in.position_m);
  return {textured_level_N(p.curve.coulomb_N, p.pressure_gain.coulomb_N_per_Pa, in.gauge_sum_Pa,
                           texture),
          textured_level_N(p.curve.static_N, p.pressure_gain.static_N_per_Pa, in.gauge_sum_Pa,
                           texture)};
}

/// exp(-(|speed|/vs)^delta), the Stribeck drop's weight. `continued`: speed is a branch's
/// signed continuation of |v| (lugre_N), taken as it is where the law has a smooth
/// continuation past 0 (delta = 1: exp(-speed/vs)); equal to |speed| wherever speed >= 0.
template <typename T, typename P>
T stribeck_weight(const P& p, const T& speed, bool continued = false) {
  using std::abs;
  using std::exp;
  using std::pow;
  using std::sqrt;
  const auto& delta = p.curve.stribeck_exponent;  // double, or a fitted Jet
  const T u =
      (continued && delta == 1.0 ? speed : T(abs(speed))) / p.curve.stribeck_velocity_m_per_s;
  // The common exponents avoid pow(), which dominated the derivative's cost.
  T w;
  if (delta == 2.0) {
    w = u * u;
  } else if (delta == 1.0) {
    w = u;
  } else if (delta == 0.5) {
    w = sqrt(u);
  } else {
    w = pow(u, delta);
  }
  return exp(-w);
}

/// Stribeck curve magnitude g(v) = Fc + (Fs - Fc) exp(-(|v|/vs)^delta).
template <typename T, typename P>
T stribeck_level_N(const P& p, const BasicFrictionInput<T>& in, const T& speed,
                   bool continued = false) {
  const Levels<T> f = levels_N(p, in);
  return f.coulomb_N + (f.static_N - f.coulomb_N) * stribeck_weight(p, speed, continued);
}

/// Sliding force of the stiction models in `direction` (+1/-1): `classic`, paper eq. (4),
/// Fc sgn v + B v; `stribeck`, [Fc + (Fs - Fc) exp(-(|v|/vs)^delta)] sgn v + B v.
template <typename T, typename P>
T stiction_sliding_N(const P& p, const BasicFrictionInput<T>& in, int direction) {
  // The mode fixes the sign, so the force is smooth within a sliding segment.
  const double d = direction;
  T speed = d * in.v_m_per_s;
  if (speed < 0.0) speed = T(0.0);
  const T level =
      p.kind == FrictionKind::kClassic ? coulomb_N(p, in) : stribeck_level_N(p, in, speed);
  return d * (level + p.curve.viscous_Ns_per_m * speed);
}

/// LuGre (Canudas de Wit et al. 1995): dz/dt = v - sigma0 |v| z / g(v),
/// F = sigma0 z + sigma1 dz/dt + sigma2 v. Writes dz/dt to dz. `branch` +1/-1: the contact
/// moves with v >= 0 / v <= 0 and |v| is taken as branch * v, its smooth continuation past
/// v = 0 (the Plant flips the branch at the crossing, docs/model.md); 0: |v| itself.
template <typename T, typename P>
T lugre_N(const P& p, const BasicFrictionInput<T>& in, const T& z, T& dz, int branch = 0) {
  using std::abs;
  const T& v = in.v_m_per_s;
  const T speed = branch == 0 ? T(abs(v)) : T(static_cast<double>(branch) * v);
  const T g = stribeck_level_N(p, in, speed, branch != 0);
  dz = v - p.lugre.sigma0_N_per_m * speed * z / g;
  return p.lugre.sigma0_N_per_m * z + p.lugre.sigma1_Ns_per_m * dz + p.curve.viscous_Ns_per_m * v;
}

/// LuGre's quasi-static limit on a branch (docs/model.md, "Friction"): the bristle on its
/// steady state z = g(v) sgn v / sigma0, where dz/dt = 0 and the force is the steady
/// g(v) sgn v + sigma2 v. The state z is held (dz = 0); the Plant sets it on the steady
/// state when the contact enters and leaves this limit.
template <typename T, typename P>
T lugre_quasi_static_N(const P& p, const BasicFrictionInput<T>& in, T& dz, int branch) {
  const double d = branch;
  const T speed = d * in.v_m_per_s;
  dz = T(0.0);
  return d * stribeck_level_N(p, in, speed, true) + p.curve.viscous_Ns_per_m * in.v_m_per_s;
}

/// Hess-Soom lag (docs/model.md): the Stribeck weight s lags the velocity by tau, writes
/// ds/dt = (exp(-(|v|/vs)^delta) - s) / tau; F = [Fc + (Fs - Fc) s] sgn v + B v while
/// sliding in `direction`.
template <typename T, typename P>
T stribeck_lag_N(const P& p, const BasicFrictionInput<T>& in, int direction,
                 const T& s, T& ds) {
  const double d = direction;
  T speed = d * in.v_m_per_s;
  if (speed < 0.0) speed = T(0.0);
  ds = (stribeck_weight(p, speed) - s) / p.lag.time_s;
  const Levels<T> f = levels_N(p, in);
  return d * (f.coulomb_N + (f.static_N - f.coulomb_N) * s + p.curve.viscous_Ns_per_m * speed);
}

/// The two-state memory's weight of the Stribeck drop, share theta_1 + (1 - share) theta_2.
template <typename T>
T rate_state_weight(const RateStateMemory& m, const T* theta) {
  return m.share * theta[0] + (1.0 - m.share) * theta[1];
}

/// Its direct effect A ln(1 + speed / v_A) (speed >= 0).
template <typename T>
T rate_state_direct_N(const RateStateMemory& m, const T& speed) {
  using std::log;
  return m.direct_N * log(1.0 + speed / m.direct_velocity_m_per_s);
}

/// The two-state memory (docs/model.md, "Friction"), after the two-state law of Gu, Rice,
/// Ruina & Tse (1984) with the Stribeck weight as the states' steady value: writes
/// d theta_i/dt = -(|v| / L_i)(theta_i - w(v)) (Ruina's slip law: the states move with the
/// slip, not with time); F = [Fc + (Fs - Fc)(share theta_1 + (1 - share) theta_2)
/// + A ln(1 + |v|/v_A)] sgn v + B v while sliding in `direction`.
template <typename T, typename P>
T stribeck_rate_state_N(const P& p, const BasicFrictionInput<T>& in, int direction,
                        const T* theta, T* dtheta) {
  const double d = direction;
  T speed = d * in.v_m_per_s;
  if (speed < 0.0) speed = T(0.0);
  const RateStateMemory& m = p.rate_state;
  const T w = stribeck_weight(p, speed);
  dtheta[0] = -speed / m.slip_length_m * (theta[0] - w);
  dtheta[1] = -speed / m.slip_length2_m * (theta[1] - w);
  const Levels<T> f = levels_N(p, in);
  return d * (f.coulomb_N + (f.static_N - f.coulomb_N) * rate_state_weight(m, theta) +
              rate_state_direct_N(m, speed) +
              p.curve.viscous_Ns_per_m * speed);
}

}  // namespace pneumachaos::friction_law

#include "friction_gms_law.hpp"

namespace pneumachaos::friction_law {

/// Rates of the internal states while the contact rests: LuGre's bristles, the GMS elements
/// and the two-state memory (whose states move with the slip) hold still; the lagged
/// Stribeck weight recovers towards its value at v = 0, which is 1.
template <typename T, typename P>
void resting_rates(const P& p, const T* z, T* dz, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) dz[i] = T(0.0);
  if (p.lagged()) dz[0] = (1.0 - z[0]) / p.lag.time_s;
}

/// The force of whichever model `p.kind` names, while the contact moves; z and dz point to
/// the model's internal states (none for the stiction models). `quasi_static`: LuGre or GMS
/// in its quasi-static limit. GMS's rates there need dv/dt and so are the Plant's to write
/// (Plant::track_shares); the automatic-differentiation instantiation (the Jacobian) keeps
/// the full law, whose stiff slopes the linearization and Rosenbrock's stepper want.
template <typename T, typename P>
T moving_force_N(const P& p, const BasicFrictionInput<T>& in, int direction, const T* z, T* dz,
                 bool quasi_static = false) {
  if (quasi_static && p.kind == FrictionKind::kLuGre)
    return lugre_quasi_static_N(p, in, dz[0], direction);
  if constexpr (std::is_same_v<T, double>) {
    if (quasi_static && p.kind == FrictionKind::kGms)
      return gms_quasi_static_N(p, in, z, direction);
  }
  if (p.kind == FrictionKind::kLuGre) return lugre_N(p, in, z[0], dz[0], direction);
  if (p.kind == FrictionKind::kGms) return gms_N(p, in, z, dz, direction);
  if (p.lagged()) return stribeck_lag_N(p, in, direction, z[0], dz[0]);
  if (p.rate_and_state()) return stribeck_rate_state_N(p, in, direction, z, dz);
  return stiction_sliding_N(p, in, direction);
}

}  // namespace pneumachaos::friction_law
