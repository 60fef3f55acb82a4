#include "pneumachaos/stability/equilibrium.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <Eigen/Dense>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// Fewest rod-side pressures scanned: a coarser scan can step over a Stribeck curve's roots.
constexpr int kFewestScanPoints = 8;

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
        state_(plant.state_at({position_m, 0.0, plant.ambient_pressure_Pa(),
                               plant.ambient_pressure_Pa()})),
        rates_(state_.size()) {}

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

  // With a supply line or the energy equation, the search holds P0 at Ps and the chambers at
  // the supply temperature; the steady motion has its own values of those, and of everything
  // they move. Newton's method finds them on the smooth states (v, both pressures, P0, T1,
  // T2), the friction internal states and the load kept on their steady values at each
  // iterate (a GMS element's law has a kink there). False when it does not converge.
  bool refine() {
    const std::vector<std::size_t> u = smooth_states();
    if (u.size() == 3) return true;  // nothing held fixed
    constexpr int kIterations = 30;
    constexpr double kConverged = 1e-10;  // the step against each state's typical magnitude
    for (int it = 0; it < kIterations; ++it) {
      const Eigen::VectorXd f = smooth_rates(u);
      Eigen::MatrixXd J(f.size(), f.size());
      for (Eigen::Index j = 0; j < J.cols(); ++j) J.col(j) = smooth_column(u, j, f);
      const Eigen::VectorXd step = J.colPivHouseholderQr().solve(-f);
      if (!step.allFinite()) return false;
      double largest = 0.0;
      for (Eigen::Index k = 0; k < step.size(); ++k) {
        const std::size_t i = u[static_cast<std::size_t>(k)];
        state_[i] += step[k];
        largest = std::max(largest, std::abs(step[k]) / L_.entries[i].scale);
      }
      if (largest < kConverged) {
        smooth_rates(u);  // the friction states and the load on the last iterate's
        return true;
      }
    }
    return false;
  }

  // Net force on the piston, eq. (1) times its mass: the residual of the search.
  [[nodiscard]] double net_force_N() { return plant_.piston_mass_kg() * rate(L_.v); }

  [[nodiscard]] const std::vector<double>& state() const { return state_; }
  [[nodiscard]] double v() const { return state_[L_.v]; }
  [[nodiscard]] double P1() const { return state_[L_.P1]; }
  [[nodiscard]] double P2() const { return state_[L_.P2]; }
  [[nodiscard]] double position_m() const { return x0_; }

 private:
  // Sets v, P1 and P2, and every other state consistent with them (friction internal states
  // on their steady values).
  void place(double v, double P1, double P2) { state_ = plant_.state_at({x0_, v, P1, P2}); }

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

  // v, P1, P2 and the states the search holds fixed.
  [[nodiscard]] std::vector<std::size_t> smooth_states() const {
    std::vector<std::size_t> u{L_.v, L_.P1, L_.P2};
    if (L_.has_supply_line()) u.push_back(L_.P0);
    if (L_.has_temperatures()) u.insert(u.end(), {L_.T1, L_.T2});
    return u;
  }

  // Their rates, with the friction states and the load put on their steady values first.
  Eigen::VectorXd smooth_rates(const std::vector<std::size_t>& u) {
    std::vector<double> held(u.size());
    for (std::size_t k = 0; k < u.size(); ++k) held[k] = state_[u[k]];
    place(held[0], held[1], held[2]);
    for (std::size_t k = 3; k < u.size(); ++k) state_[u[k]] = held[k];
    if (L_.has_load_body()) settle_load();
    plant_.derivative(mode_, state_, rates_, 0.0);
    Eigen::VectorXd f(static_cast<Eigen::Index>(u.size()));
    for (std::size_t k = 0; k < u.size(); ++k) f[static_cast<Eigen::Index>(k)] = rates_[u[k]];
    return f;
  }

  // Column j of their Jacobian by a forward difference (the states are smooth functions here).
  Eigen::VectorXd smooth_column(const std::vector<std::size_t>& u, Eigen::Index j,
                                const Eigen::VectorXd& f) {
    const std::size_t i = u[static_cast<std::size_t>(j)];
    const double base = state_[i];
    const double h = 1e-7 * std::max(std::abs(base), L_.entries[i].scale);
    state_[i] = base + h;
    Eigen::VectorXd column = (smooth_rates(u) - f) / h;
    state_[i] = base;
    smooth_rates(u);
    return column;
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
  // By default the piston sits where the scenario freezes the chamber volumes, else mid-stroke.
  const CylinderGeometry& g = plant.geometry();
  const double automatic = g.volumes_frozen() ? g.frozen_position_m : 0.5 * stroke;
  const double x0 = options.position_m < 0.0 ? automatic : options.position_m;
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

std::optional<Equilibrium> equilibrium_at(const Plant& plant, SteadyMotion& motion, double P2) {
  motion.place_at(P2);
  if (!motion.refine()) return std::nullopt;
  const SteadyFriction fr = steady_friction(plant, motion.v(), motion.P1(), motion.P2());
  return Equilibrium{motion.v(), motion.P1(),       motion.P2(),   motion.position_m(),
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
  validation::require_ge(validation::field("equilibrium.scan_points"), scan_points,
                         kFewestScanPoints);
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
  bool unrefined = false;
  for (std::size_t i = 1; i < dP.size(); ++i) {
    const double f = residual(Pa + dP[i]);
    if ((f_prev > 0.0) != (f > 0.0)) {
      const double P2 = root(residual, Pa + dP[i - 1], Pa + dP[i]);
      if (auto eq = equilibrium_at(plant, motion, P2)) {
        result.equilibria.push_back(std::move(*eq));
      } else {
        unrefined = true;
      }
    }
    f_prev = f;
  }
  if (result.equilibria.empty()) {
    result.reason = unrefined ? "the force balance has a root, but the supply line's pressure or "
                                "the chamber temperatures found no steady value beside it"
                              : no_equilibrium_reason(plant, creeping, f_first);
  }
  return result;
}

}  // namespace pneumachaos
