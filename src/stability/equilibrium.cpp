#include "pneumachaos/stability/equilibrium.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

template <typename F>
double root(F&& f, double lo, double hi) {
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
  const double Pa = plant.ambient_pressure_Pa();
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

// Steady forward motion at one piston position, held in a full plant state. Every balance
// below is a component of the plant's own derivative set to zero, so the equilibrium solves
// the same equations the simulation integrates (docs/architecture.md), not a copy of them.
class SteadyMotion {
 public:
  SteadyMotion(const Plant& plant, double position_m)
      : plant_(plant),
        L_(plant.layout()),
        mode_(plant.sliding_mode(+1)),
        x0_(position_m),
        state_(plant.initial_state()),
        rates_(state_.size()) {
    state_[L_.x] = x0_;
    if (L_.has_load_body()) state_[L_.load_x] = x0_;
    if (L_.has_valve_opening()) state_[L_.S1_open] = 1.0;  // steady motion: S1 fully open
  }

  // Speed at which chamber 2's outflow through S2 balances its shrinking volume, eq. (3) = 0.
  // Eq. (3) is affine in v, so two evaluations give the root exactly.
  double exhaust_speed(double P2) {
    state_[L_.P2] = P2;
    state_[L_.v] = 0.0;
    const double at_rest = plant_.rod_pressure_rate(state_);
    state_[L_.v] = 1.0;
    return at_rest / (at_rest - plant_.rod_pressure_rate(state_));
  }

  // Chamber 1's pressure at which the supply through S1 fills the growing volume, eq. (2) = 0.
  // The inflow is positive down to vacuum (S1 > 0), so (0, Ps] always brackets the root
  // unless the supply keeps chamber 1 at Ps.
  double chamber1_pressure(double v) {
    state_[L_.v] = v;
    const auto balance = [&](double P1) {
      state_[L_.P1] = P1;
      return plant_.head_pressure_rate(state_);
    };
    const double Ps = plant_.supply_pressure_Pa();
    return balance(Ps) >= 0.0 ? Ps : root(balance, 0.0, Ps);
  }

  // Places the steady motion with rod-side pressure P2 (the search's parameter).
  void place_at(double P2) {
    const double v = exhaust_speed(P2);
    const double P1 = chamber1_pressure(v);
    place(v, P1, P2);
    if (L_.has_load_body()) settle_load();
  }

  // Net force on the piston, eq. (1) times its mass: the residual of the search.
  [[nodiscard]] double net_force_N() { return plant_.piston_mass_kg() * rate(L_.v); }

  [[nodiscard]] const std::vector<double>& state() const { return state_; }
  [[nodiscard]] double v() const { return state_[L_.v]; }
  [[nodiscard]] double P1() const { return state_[L_.P1]; }
  [[nodiscard]] double P2() const { return state_[L_.P2]; }
  [[nodiscard]] double position_m() const { return x0_; }

 private:
  // Sets v, P1 and P2, and the friction internal states at their steady values.
  void place(double v, double P1, double P2) {
    state_[L_.v] = v;
    state_[L_.P1] = P1;
    state_[L_.P2] = P2;
    if (L_.seal_z_count > 0) {
      plant_.seal_friction().steady_state(
          {v, P1 + P2 - 2.0 * plant_.ambient_pressure_Pa(), x0_},
          std::span<double>(state_).subspan(L_.seal_z, L_.seal_z_count));
    }
    if (!L_.has_load_body()) return;
    state_[L_.load_v] = v;
    if (L_.guide_z_count > 0) {
      plant_.guide_friction()->steady_state(
          {v, 0.0, x0_}, std::span<double>(state_).subspan(L_.guide_z, L_.guide_z_count));
    }
  }

  // The spring deflection at which the load's own equation of motion balances (the spring
  // carries the guide's friction and the external force). The load's acceleration is affine
  // in the deflection (a texture on the guide aside), so one secant step finds it.
  void settle_load() {
    constexpr double kProbe_m = 1e-3;  // of the order of the deflection itself
    state_[L_.load_x] = x0_;
    const double undeflected = rate(L_.load_v);
    state_[L_.load_x] = x0_ - kProbe_m;
    const double probed = rate(L_.load_v);
    state_[L_.load_x] = x0_ - kProbe_m * undeflected / (undeflected - probed);
  }

  double rate(std::size_t i) {
    plant_.derivative(mode_, state_, rates_, 0.0);
    return rates_[i];
  }

  const Plant& plant_;
  const StateLayout& L_;
  Mode mode_;
  double x0_;
  std::vector<double> state_;
  std::vector<double> rates_;
};

double checked_position(const Plant& plant, const EquilibriumOptions& options) {
  const double stroke = plant.geometry().stroke_m;
  const double x0 = options.position_m < 0.0 ? 0.5 * stroke : options.position_m;
  if (x0 > stroke) {
    throw Error("position_m", fmt::format("{} m lies beyond the stroke {} m", x0, stroke));
  }
  return x0;
}

// The rod-side overpressures scanned: log-spaced, since low speeds live just above ambient,
// up to where the rod force alone exceeds any drive (friction >= 0).
std::vector<double> scanned_overpressures(const Plant& plant, int n) {
  const double Pa = plant.ambient_pressure_Pa();
  const double Ps = plant.supply_pressure_Pa();
  const double dP_max =
      1.01 * (plant.A1() * (Ps - Pa) + std::max(0.0, -plant.load().external_force_N)) / plant.A2() +
      1.0;
  const double lo = 1e-7 * dP_max;
  std::vector<double> dP(static_cast<std::size_t>(n) + 1);
  for (std::size_t i = 0; i < dP.size(); ++i) {
    dP[i] = lo * std::pow(dP_max / lo, static_cast<double>(i) / n);
  }
  return dP;
}

Equilibrium equilibrium_at(const Plant& plant, SteadyMotion& motion, double P2) {
  motion.place_at(P2);
  const SteadyFriction fr = steady_friction(plant, motion.v(), motion.P1(), motion.P2());
  return {motion.v(), motion.P1(),       motion.P2(),   motion.position_m(),
          fr.force_N, fr.slope_Ns_per_m, motion.state()};
}

// Why the scan found no sign change, judged at its lowest rod-side pressure.
std::string no_equilibrium_reason(const Plant& plant, SteadyMotion& creeping, double force_N) {
  if (creeping.P1() <= plant.ambient_pressure_Pa()) {
    return fmt::format(
        "the exhaust is too wide for the supply (circuit.S2_mm2 against circuit.S1_mm2): even at "
        "the smallest rod-side overpressure scanned ({:.3g} Pa) the piston would run at {:.3g} "
        "m/s, faster than the supply can fill chamber 1 (P1 = {:.3g} Pa abs, not above "
        "ambient); a steady motion, if any, has chamber 2 at ambient, which this search does not "
        "resolve",
        creeping.P2() - plant.ambient_pressure_Pa(), creeping.v(), creeping.P1());
  }
  if (force_N <= 0.0) {
    return fmt::format(
        "the drive cannot overcome friction and load: at creeping speed the net force is {:.3g} N",
        force_N);
  }
  return "no rod-side pressure balances the forces";
}

}  // namespace

void EquilibriumOptions::validate() const {
  if (scan_points < 8) throw Error("scan_points", "must be at least 8");
}

EquilibriumResult find_equilibria(const Plant& plant, const EquilibriumOptions& options) {
  options.validate();
  const double x0 = checked_position(plant, options);
  EquilibriumResult result;
  if (plant.valve2().choked_coefficient() <= 0.0 || plant.valve1().choked_coefficient() <= 0.0) {
    result.reason = "a valve is shut (S1 or S2 = 0): no steady motion";
    return result;
  }
  // Parametrised by P2, not by v0: with a choked exhaust every P2 above Pa/b passes the same
  // flow per pascal, so v0 is pinned while P2 is set by the force balance. From P2 the
  // steady speed follows from chamber 2's balance, P1 from chamber 1's, and the piston's
  // force balance is the residual whose sign changes are bracketed.
  SteadyMotion motion(plant, x0);
  const double Pa = plant.ambient_pressure_Pa();
  const auto residual = [&](double P2) {
    motion.place_at(P2);
    return motion.net_force_N();
  };
  const std::vector<double> dP = scanned_overpressures(plant, options.scan_points);
  double f_prev = residual(Pa + dP.front());
  const double f_first = f_prev;
  SteadyMotion creeping = motion;
  for (std::size_t i = 1; i < dP.size(); ++i) {
    const double f = residual(Pa + dP[i]);
    if ((f_prev > 0.0) != (f > 0.0)) {
      const double P2 = root(residual, Pa + dP[i - 1], Pa + dP[i]);
      result.equilibria.push_back(equilibrium_at(plant, motion, P2));
    }
    f_prev = f;
  }
  if (result.equilibria.empty()) result.reason = no_equilibrium_reason(plant, creeping, f_first);
  return result;
}

}  // namespace pneumachaos
