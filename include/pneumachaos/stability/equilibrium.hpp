#pragma once
// Steady motion of the cylinder (paper §3.2-3.3): constant velocity v0 with the chamber
// pressures balanced by the valve flows and the force balance closed by friction.

#include <string>
#include <vector>

#include "pneumachaos/model/plant.hpp"

namespace pneumachaos {

struct EquilibriumOptions {
  /// Piston position at which the volumes are evaluated [m]; negative: where the scenario
  /// freezes the chamber volumes (cylinder.frozen_position_mm), else mid-stroke.
  double position_m = -1.0;
  /// Rod-side pressures scanned for sign changes of the force balance before bracketing each
  /// root (a Stribeck curve can give several equilibria).
  int scan_points = 96;
  void validate() const;
};

struct Equilibrium {
  double v0_m_per_s = 0.0;
  double P10_Pa = 0.0;
  double P20_Pa = 0.0;
  double position_m = 0.0;
  double friction_N = 0.0;      ///< seal (+ guide) friction at v0
  double slope_Ns_per_m = 0.0;  ///< d(friction)/dv of the steady curves at v0: the paper's B
  std::vector<double> state;    ///< full plant state at the equilibrium (x = position)
};

struct EquilibriumResult {
  std::vector<Equilibrium> equilibria;  ///< ascending in v0; empty when none exists
  std::string reason;                   ///< why none exists, when empty
  /// The steady motion the paper linearises about: the fastest equilibrium.
  [[nodiscard]] const Equilibrium& primary() const { return equilibria.back(); }
  [[nodiscard]] bool exists() const { return !equilibria.empty(); }
};

/// Steady forward motion (v0 > 0) of the plant. Never throws for "no equilibrium": that is a
/// result with a reason (e.g. the drive cannot overcome friction).
EquilibriumResult find_equilibria(const Plant& plant, const EquilibriumOptions& options = {});

}  // namespace pneumachaos
