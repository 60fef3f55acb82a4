#pragma once
// The generalized Maxwell-slip law in its smooth state-equation form (docs/model.md,
// "Friction"), written once on the scalar types of friction_laws.hpp, which includes this file
// after the Stribeck curve it builds on. Private to the model module.

#include <cmath>

#include "pneumachaos/model/friction.hpp"

namespace pneumachaos::friction_law {

/// Share of the Stribeck level carried by element i (0-based) of n: proportional to i + 1, so
/// the elements (of equal stiffness) slip one after another as the deflection grows.
inline double gms_force_share(int i, int n) { return 2.0 * (i + 1) / (n * (n + 1.0)); }

/// Stiffness of one element: the total presliding stiffness in equal shares.
template <typename P>
double gms_element_stiffness(const P& p) {
  return p.gms_stiffness_N_per_m / p.gms_elements;
}

/// Deflection at which element i carries its share of the level g: where it slips.
template <typename T, typename P>
T gms_reach_m(const P& p, int i, const T& g) {
  return gms_force_share(i, p.gms_elements) * g / gms_element_stiffness(p);
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

/// Rate of one element's deflection z at slip deflection r: (1 - w) v while it loads up to
/// its share (the contact's motion, less the slip); above it (the level fell) it is attracted
/// back by (v r - |v| z) / L over the attraction length L. Both vanish at z = r sgn v and at
/// v = 0, and the element never deflects faster than the contact while loading, so it only
/// dissipates (docs/model.md). `sgn` and `speed` stand for sgn v and |v| (or their branch's
/// continuation, as in lugre_N).
template <typename T, typename P>
T gms_element_rate(const P& p, const T& v, const T& speed, double sgn, const T& z, const T& r) {
  const T q = sgn * z / r;
  if (q > 1.0) return (v * r - speed * z) / p.gms_attraction_length_m;
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
  T elastic(0.0);
  for (int i = 0; i < p.gms_elements; ++i) {
    dz[i] = gms_element_rate(p, v, speed, sgn, z[i], gms_reach_m(p, i, g));
    elastic += z[i];
  }
  return gms_element_stiffness(p) * elastic + p.viscous_Ns_per_m * v;
}

}  // namespace pneumachaos::friction_law
