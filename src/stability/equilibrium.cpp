#include "pneumachaos/stability/equilibrium.hpp"

#include <fmt/format.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <functional>
#include <limits>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

double root(const std::function<double(double)>& f, double lo, double hi) {
  std::uintmax_t iterations = 100;
  const auto r = boost::math::tools::toms748_solve(
      f, lo, hi, boost::math::tools::eps_tolerance<double>(48), iterations);
  return 0.5 * (r.first + r.second);
}

// Friction on every contact at steady velocity v (seal sees the chamber pressures).
struct SteadyFriction {
  double force_N;
  double slope_Ns_per_m;
};
SteadyFriction steady_friction(const Plant& plant, double v, double P1, double P2) {
  const double Pa = plant.scenario().ambient_pressure_Pa;
  const FrictionInput seal_in{v, P1 + P2 - 2.0 * Pa, 0.0};
  SteadyFriction f{plant.seal_friction().steady_force_N(seal_in),
                   plant.seal_friction().steady_slope_Ns_per_m(seal_in)};
  if (const FrictionModel* guide = plant.guide_friction()) {
    const FrictionInput guide_in{v, 0.0, 0.0};
    f.force_N += guide->steady_force_N(guide_in);
    f.slope_Ns_per_m += guide->steady_slope_Ns_per_m(guide_in);
  }
  return f;
}

}  // namespace

void EquilibriumOptions::validate() const {
  if (scan_points < 8) throw Error("scan_points", "must be at least 8");
}

EquilibriumResult find_equilibria(const Plant& plant, const EquilibriumOptions& options) {
  options.validate();
  const Scenario& s = plant.scenario();
  const double Pa = s.ambient_pressure_Pa;
  const double Ps = s.supply_pressure_Pa();
  const double RT = s.gas.R_J_per_kgK * s.temperature_K;
  const double x0 = options.position_m < 0.0 ? 0.5 * s.cylinder.stroke_m : options.position_m;
  if (x0 > s.cylinder.stroke_m) {
    throw Error("position_m",
                fmt::format("{} m lies beyond the stroke {} m", x0, s.cylinder.stroke_m));
  }
  EquilibriumResult result;
  if (plant.valve2().choked_coefficient() <= 0.0 || plant.valve1().choked_coefficient() <= 0.0) {
    result.reason = "a valve is shut (S1 or S2 = 0): no steady motion";
    return result;
  }
  // Parametrised by P2, not by v0: with a choked exhaust every P2 above Pa/b passes the same
  // flow per pascal, so v0 is pinned while P2 is set by the force balance. From P2 the
  // steady speed follows explicitly (exhaust balance W2 = P2 A2 v / (R T)), P1 from the
  // supply balance (one root in (0, Ps)), and the force balance is the residual.
  struct Point {
    double v, P1, P2;
  };
  const auto point = [&](double P2) {
    const double v = RT * plant.valve2().mass_flow(P2, Pa) / (P2 * plant.A2());
    const auto r1 = [&](double P1) {
      return plant.valve1().mass_flow(Ps, P1) - P1 * plant.A1() * v / RT;
    };
    const double P1 = r1(Ps) >= 0.0 ? Ps : root(r1, 1e-9 * Ps, Ps);
    return Point{v, P1, P2};
  };
  const auto residual = [&](double P2) {
    const Point p = point(P2);
    return plant.A1() * (p.P1 - Pa) - plant.A2() * (p.P2 - Pa) - s.load.external_force_N -
           steady_friction(plant, p.v, p.P1, p.P2).force_N;
  };
  // Beyond this rod-side pressure the rod force alone exceeds any drive (friction >= 0).
  const double dP_max =
      1.01 * (plant.A1() * (Ps - Pa) + std::max(0.0, -s.load.external_force_N)) / plant.A2() + 1.0;
  const int n = options.scan_points;
  const double lo = 1e-7 * dP_max;  // log-spaced: low speeds live just above ambient
  double dP_prev = lo;
  double f_prev = residual(Pa + lo);
  const double f_first = f_prev;
  for (int i = 1; i <= n; ++i) {
    const double dP = lo * std::pow(dP_max / lo, static_cast<double>(i) / n);
    const double f = residual(Pa + dP);
    if ((f_prev > 0.0) != (f > 0.0)) {
      const double P2 = root([&](double P) { return residual(P); }, Pa + dP_prev, Pa + dP);
      const Point p = point(P2);
      const SteadyFriction fr = steady_friction(plant, p.v, p.P1, p.P2);
      Equilibrium e{p.v, p.P1, p.P2, x0, fr.force_N, fr.slope_Ns_per_m, {}};
      e.state = plant.initial_state();
      const StateLayout& L = plant.layout();
      e.state[L.x] = x0;
      e.state[L.v] = p.v;
      e.state[L.P1] = p.P1;
      e.state[L.P2] = p.P2;
      if (L.seal_z_count > 0) {
        plant.seal_friction().steady_state(
            {p.v, p.P1 + p.P2 - 2.0 * Pa, x0},
            std::span<double>(e.state).subspan(L.seal_z, L.seal_z_count));
      }
      if (const FrictionModel* guide = plant.guide_friction()) {
        const FrictionInput guide_in{p.v, 0.0, x0};
        // The coupling spring carries the load's friction and the external force.
        e.state[L.load_x] = x0 - (s.load.external_force_N + guide->steady_force_N(guide_in)) /
                                     s.load.coupling_stiffness_N_per_m;
        e.state[L.load_v] = p.v;
        if (L.guide_z_count > 0) {
          guide->steady_state(guide_in,
                              std::span<double>(e.state).subspan(L.guide_z, L.guide_z_count));
        }
      }
      result.equilibria.push_back(std::move(e));
    }
    dP_prev = dP;
    f_prev = f;
  }
  if (result.equilibria.empty()) {
    result.reason = f_first <= 0.0 ? fmt::format(
                                         "the drive cannot overcome friction and load: at creeping "
                                         "speed the net force is {:.3g} N",
                                         f_first)
                                   : "no rod-side pressure balances the forces";
  }
  return result;
}

}  // namespace pneumachaos
