#pragma once
// The generalized Maxwell-slip law in its smooth state-equation form (docs/model.md,
// "Friction"), written once on the scalar types of friction_laws.hpp, which includes this file
// after the Stribeck curve it builds on. Private to the model module.

#include <algorithm>
#include <array>
#include <cmath>

#include "pneumachaos/model/friction.hpp"

namespace pneumachaos::friction_law {

/// Share of the Stribeck level carried by element i (0-based) of n: proportional to i + 1, so
/// the elements (of equal stiffness) slip one after another as the deflection grows.
/// Tabulated when compiled (the same rounded quotients): the division sat on the element
/// loop's critical path in every friction evaluation.
inline constexpr auto kGmsForceShares = [] {
  std::array<std::array<double, kMaxGmsElements>, kMaxGmsElements + 1> t{};
  for (int n = 1; n <= kMaxGmsElements; ++n)
    for (int i = 0; i < n; ++i) t[n][i] = 2.0 * (i + 1) / (n * (n + 1.0));
  return t;
}();
inline double gms_force_share(int i, int n) { return kGmsForceShares[n][i]; }

/// Stiffness of one element: the total presliding stiffness in equal shares.
template <typename P>
double gms_element_stiffness(const P& p) {
  return p.gms.stiffness_N_per_m / p.gms.count;
}

/// Deflection at which element i of n, of stiffness k, carries its share of the level g.
template <typename T>
T gms_reach_m(int i, int n, const T& g, double k) {
  return gms_force_share(i, n) * g / k;
}

/// Deflection at which element i carries its share of the level g: where it slips.
template <typename T, typename P>
T gms_reach_m(const P& p, int i, const T& g) {
  return gms_reach_m(i, p.gms.count, g, gms_element_stiffness(p));
}

/// Rate of that slip deflection while the level changes at dg/dt.
template <typename P>
double gms_share_rate(const P& p, int i, double dg_dt) {
  return gms_force_share(i, p.gms.count) * dg_dt / gms_element_stiffness(p);
}

/// Slip weight of an element at utilisation q (its deflection over its slip deflection, in
/// the direction of motion): 0 while it is unloaded or loaded against the motion, q^4 on the
/// way up (nearly elastic until close to breakaway), 1 at its share of the level.
template <typename T>
T gms_slip_weight(T q) {
  if (q < 0.0) q = T(0.0);
  if (q > 1.0) q = T(1.0);
  const T q2 = q * q;
  return q2 * q2;
}

/// An element above its share (the level fell below it) is attracted back to it over the
/// attraction length L: dz/dt = (v r - |v| z) / L.
template <typename T, typename P>
T gms_attraction_rate(const P& p, const T& v, const T& speed, const T& z, const T& r) {
  return (v * r - speed * z) / p.gms.attraction_length_m;
}

/// Rate of one element's deflection z at slip deflection r: (1 - w) v while it loads up to
/// its share (the contact's motion, less the slip); above it (the level fell) it is attracted
/// back by (v r - |v| z) / L over the attraction length L. Both vanish at z = r sgn v and at
/// v = 0, and the element never deflects faster than the contact while loading, so it only
/// dissipates (docs/model.md). `sgn` and `speed` stand for sgn v and |v| (or their branch's
/// continuation, as in lugre_N).
template <typename T, typename P>
T gms_element_rate(const P& p, const T& v, const T& speed, double sgn, const T& z, const T& r) {
  const T q = sgn * z / r;
  if (q > 1.0) return gms_attraction_rate(p, v, speed, z, r);
  return (1.0 - gms_slip_weight(q)) * v;
}

/// Writes each element's dz_i/dt to dz[i]; returns F = sum k z_i + B v, with the slip
/// deflections at the present Stribeck level g(v). `branch` as in lugre_N: +1/-1 the contact
/// moves with v >= 0 / v <= 0 and |v| is continued as branch * v past 0; 0: |v| itself.
template <typename T, typename P>
T gms_N(const P& p, const BasicFrictionInput<T>& in, const T* z, T* dz, int branch = 0) {
  using std::abs;
  const T& v = in.v_m_per_s;
  const double sgn = branch != 0 ? branch : (v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0));
  const T speed = branch == 0 ? T(abs(v)) : T(sgn * v);
  const T g = stribeck_level_N(p, in, speed, branch != 0);
  // Read once: the writes to dz could alias p's members, so the compiler would reload them
  // and divide for the stiffness on every element.
  const int n = p.gms.count;
  const double k = gms_element_stiffness(p);
  T elastic(0.0);
  for (int i = 0; i < n; ++i) {
    dz[i] = gms_element_rate(p, v, speed, sgn, z[i], gms_reach_m(i, n, g, k));
    elastic += z[i];
  }
  return k * elastic + p.curve.viscous_Ns_per_m * v;
}

// ---- The quasi-static limit of the elements' loading (docs/model.md, "Friction") ----------
// On a branch (direction d = sgn v) with m_i = d z_i, an element below its share loads at the
// rate (1 - (m/r)^4) |v|, whose slope at the kink m = r is -4 |v| / r: stiff at speed. In the
// limit of an infinite loading rate an element at or below its share sits on it, and one above
// it relaxes exactly as in the full law.

/// The loading rate of the slowest element (the largest share), 4 |v| / r_N, is this
/// coefficient times |v| / g: the quasi-static switch compares it with its threshold.
template <typename P>
double gms_loading_rate_per_speed_over_level(const P& p) {
  const double last_share = gms_force_share(p.gms.count - 1, p.gms.count);
  return 4.0 * gms_element_stiffness(p) / last_share;
}

/// How far the elements z are from their deflections `on` in the limit (gms_limit_deflections)
/// at level g: the largest |z_i - on_i| / r_i, what entering the limit would move them.
template <typename P>
double gms_distance_from_limit(const P& p, double g, const double* z, const double* on) {
  double worst = 0.0;
  for (int i = 0; i < p.gms.count; ++i)
    worst = std::max(worst, std::abs(z[i] - on[i]) / gms_reach_m(p, i, g));
  return worst;
}

/// An element's deflection in the direction of motion, held at least at its share: d max(m, r)
/// with m = d z (the limit's force before the elements' lag).
template <typename P>
double gms_held_m(const P& p, int i, double g, double z, int direction) {
  return std::max(direction * z, gms_reach_m(p, i, g));
}

/// Deflection, in the direction of motion, of an element in the limit, with m its state, r its
/// share's deflection and dr/dt the share's rate: above its share its own m (the attraction
/// branch, exact); at or below it the loading branch's slow manifold, where the element loads
/// as fast as its share rises, (1 - (m/r)^4) |v| = max(dr/dt, 0): it lags a rising share by
/// about r (dr/dt) / (4 |v|) and sits on a falling one.
inline double gms_limit_deflection(double m, double r, double dr_dt, double speed) {
  if (m > r) return m;
  if (dr_dt <= 0.0) return r;
  return r * std::sqrt(std::sqrt(std::max(1.0 - dr_dt / speed, 0.0)));
}

/// Every element's deflection in the limit (as gms_limit_deflection) at level g rising at
/// dg/dt, on branch `direction`, written signed to `out`.
template <typename P>
void gms_limit_deflections(const P& p, double v, double g, double dg_dt, const double* z,
                           double* out, int direction) {
  const double d = direction;
  for (int i = 0; i < p.gms.count; ++i) {
    const double r = gms_reach_m(p, i, g);
    const double dr_dt = gms_share_rate(p, i, dg_dt);
    out[i] = d * gms_limit_deflection(d * z[i], r, dr_dt, d * v);
  }
}

/// How much less than the force with every element at d max(m_i, r_i) (gms_quasi_static_N)
/// the elements carry in the direction of motion: their lag behind rising shares.
template <typename P>
double gms_lag_force_N(const P& p, double v, double g, double dg_dt, const double* z,
                       int direction) {
  std::array<double, kMaxGmsElements> on{};
  gms_limit_deflections(p, v, g, dg_dt, z, on.data(), direction);
  double lag = 0.0;
  for (int i = 0; i < p.gms.count; ++i)
    lag += gms_held_m(p, i, g, z[i], direction) - direction * on[i];
  return gms_element_stiffness(p) * lag;
}

/// Puts every element below its share on it (entering the limit): the state then holds the
/// share it tracks; the force is unchanged to within the settled condition's bound.
template <typename P>
void gms_settle_on_shares(const P& p, double g, double* z, int direction) {
  for (int i = 0; i < p.gms.count; ++i) z[i] = direction * gms_held_m(p, i, g, z[i], direction);
}

/// The force with every element at d max(m_i, r_i), F = k sum d max(m_i, r_i) + B v: the
/// limit's force before the elements' lag (gms_lag_force_N), which needs dv/dt and is the
/// Plant's to subtract (Plant::track_shares).
template <typename P>
double gms_quasi_static_N(const P& p, const FrictionInput& in, const double* z, int direction) {
  const double d = direction;
  const double g = stribeck_level_N(p, in, d * in.v_m_per_s, true);
  double deflection = 0.0;
  for (int i = 0; i < p.gms.count; ++i) deflection += d * gms_held_m(p, i, g, z[i], direction);
  return gms_element_stiffness(p) * deflection + p.curve.viscous_Ns_per_m * in.v_m_per_s;
}

/// The elements' rates in the limit, given the level g and its rate of change dg/dt: above
/// its share an element relaxes by the attraction law; at (or, by rounding, below) it, the
/// state follows a rising share, dm/dt = dr/dt = share dg/dt / k, and stays put while the
/// share falls (the element is then above it, on the attraction branch). While it tracks, the
/// state holds its share and the deflection is gms_limit_deflection's.
template <typename P>
void gms_quasi_static_rates(const P& p, double v, double g, double dg_dt, const double* z,
                            double* dz, int direction) {
  const double d = direction;
  for (int i = 0; i < p.gms.count; ++i) {
    const double r = gms_reach_m(p, i, g);
    if (d * z[i] > r) {
      dz[i] = gms_attraction_rate(p, v, d * v, z[i], r);
    } else {
      dz[i] = d * std::max(gms_share_rate(p, i, dg_dt), 0.0);
    }
  }
}

}  // namespace pneumachaos::friction_law
