#include "pneumachaos/model/scenario_keys.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Range {
  double lo = -kInf;
  double hi = kInf;
  bool lo_open = false;
  bool hi_open = false;
  [[nodiscard]] bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  [[nodiscard]] std::string text() const {
    std::string out;
    if (lo > -kInf) out += fmt::format("{} {}", lo_open ? ">" : ">=", lo);
    if (hi < kInf)
      out += fmt::format("{}{} {}", out.empty() ? "" : " and ", hi_open ? "<" : "<=", hi);
    return out.empty() ? "any finite number" : out;
  }
};

const Range kPositive{0.0, kInf, true, false};
const Range kNonNegative{0.0, kInf, false, false};

struct KeySpec {
  KeyInfo info;
  bool is_word = false;
  bool whole = false;  // a count: only whole numbers
  double scale = 1.0;  // user unit -> SI
  Range range;
  std::string why;  // for a physical plausibility range: where its bounds come from
  std::function<void(Scenario&, double)> set_number;
  std::function<double(const Scenario&)> get_number;
  std::vector<std::string> words;
  std::function<void(Scenario&, std::size_t)> set_word;
  std::function<std::size_t(const Scenario&)> get_word;
};

// `ref` is a generic lambda returning a reference to the SI field, usable on const and
// non-const scenarios, so one line per key serves both the setter and the getter.
template <typename Ref>
KeySpec number(std::string key, std::string unit, std::string description, double scale,
               Range range, Ref ref) {
  KeySpec s;
  s.info = {std::move(key), std::move(unit), std::move(description), "", range.text()};
  s.scale = scale;
  s.range = range;
  s.set_number = [ref](Scenario& sc, double si) { ref(sc) = si; };
  s.get_number = [ref](const Scenario& sc) -> double {
    const auto& v = ref(sc);
    // Optional keys (S1, S2) override this getter with their resolved default.
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::optional<double>>) {
      return v.value_or(0.0);
    } else {
      return v;
    }
  };
  return s;
}

// A number key whose range is what a pneumatic drive can physically be, not only what the
// equations accept: a value beyond it is almost always a unit slip (250 MPa for 0.25 MPa, a
// bore in metres) and is refused with `why`, the source of the bounds.
template <typename Ref>
KeySpec plausible(std::string key, std::string unit, std::string description, double scale,
                  Range range, std::string why, Ref ref) {
  KeySpec s = number(std::move(key), std::move(unit), std::move(description), scale, range, ref);
  s.why = std::move(why);
  return s;
}

// A whole-number key held in an int field.
template <typename Ref>
KeySpec count(std::string key, std::string unit, std::string description, Range range, Ref ref) {
  KeySpec s = number(std::move(key), std::move(unit), std::move(description), 1.0, range, ref);
  s.whole = true;
  s.set_number = [ref](Scenario& sc, double n) { ref(sc) = static_cast<int>(n); };
  return s;
}

template <typename Enum, typename Ref>
KeySpec word(std::string key, std::string description, std::vector<std::string> words, Ref ref) {
  KeySpec s;
  std::string choices;
  for (const auto& w : words) choices += (choices.empty() ? "" : " | ") + w;
  s.info = {std::move(key), "", std::move(description), choices, ""};
  s.is_word = true;
  s.words = std::move(words);
  s.set_word = [ref](Scenario& sc, std::size_t i) { ref(sc) = static_cast<Enum>(i); };
  s.get_word = [ref](const Scenario& sc) { return static_cast<std::size_t>(ref(sc)); };
  return s;
}

// The generalized Maxwell-slip keys (docs/model.md, "Friction"); the element count must be whole.
template <typename Ref>
void add_gms_keys(std::vector<KeySpec>& keys, const std::string& prefix, Ref ref) {
  keys.push_back(count(
      prefix + "gms_elements", "-", "gms: number of Maxwell-slip elements (a whole number)",
      Range{1.0, static_cast<double>(kMaxGmsElements)}, [ref](auto& s) -> auto& {
        return ref(s).gms.count;
      }));
  keys.push_back(number(
      prefix + "gms_stiffness_N_per_m", "N/m",
      "gms: total presliding stiffness, in equal shares over the elements", 1.0,
      kPositive, [ref](auto& s) -> auto& { return ref(s).gms.stiffness_N_per_m; }));
  keys.push_back(number(
      prefix + "gms_attraction_length_um", "um",
      "gms: sliding distance over which a slipping element reaches its share of the level", 1e-6,
      kPositive, [ref](auto& s) -> auto& { return ref(s).gms.attraction_length_m; }));
  keys.push_back(number(
      prefix + "gms_quasi_static_rate", "1/s",
      "gms: loading rate 4 |v| / r of the slowest element above which the elements are taken "
      "on their shares' slow manifold (0: never; off by default, docs/notes/performance.md)",
      1.0, kNonNegative, [ref](auto& s) -> auto& { return ref(s).gms.quasi_static_rate_per_s; }));
}

// The two-state memory's keys (memory = rate_state; docs/model.md, "Friction").
template <typename Ref>
void add_rate_state_keys(std::vector<KeySpec>& keys, const std::string& prefix, Ref ref) {
  keys.push_back(number(
      prefix + "rate_state_slip_length_um", "um",
      "rate_state: slip length L1 over which the first state reaches the Stribeck weight", 1e-6,
      kPositive, [ref](auto& s) -> auto& { return ref(s).rate_state.slip_length_m; }));
  keys.push_back(number(
      prefix + "rate_state_slip_length2_um", "um", "rate_state: the second state's slip length L2",
      1e-6, kPositive, [ref](auto& s) -> auto& { return ref(s).rate_state.slip_length2_m; }));
  keys.push_back(number(
      prefix + "rate_state_share", "-", "rate_state: the first state's share of the Stribeck drop",
      1.0, Range{0.0, 1.0}, [ref](auto& s) -> auto& { return ref(s).rate_state.share; }));
  keys.push_back(number(
      prefix + "rate_state_direct_N", "N",
      "rate_state: direct effect A of A ln(1 + |v|/vA), the friction's instant rise with speed",
      1.0, kNonNegative, [ref](auto& s) -> auto& { return ref(s).rate_state.direct_N; }));
  keys.push_back(number(
      prefix + "rate_state_direct_velocity_mm_per_s", "mm/s",
      "rate_state: reference velocity vA of the direct effect", 1e-3, kPositive,
      [ref](auto& s) -> auto& { return ref(s).rate_state.direct_velocity_m_per_s; }));
}

// The same friction keys serve the piston seal ("friction.") and the load guide
// ("guide_friction."), so they are generated from one list.
template <typename Ref>
void add_friction_keys(std::vector<KeySpec>& keys, const std::string& prefix,
                       const std::string& what, Ref ref) {
  keys.push_back(word<FrictionKind>(
      prefix + "model", "friction model of the " + what,
      {"classic", "stribeck", "lugre", "gms"}, [ref](auto& s) -> auto& { return ref(s).kind; }));
  keys.push_back(number(
      prefix + "Fc_N", "N", "Coulomb (kinetic) friction Fc", 1.0,
      kNonNegative, [ref](auto& s) -> auto& { return ref(s).curve.coulomb_N; }));
  keys.push_back(number(
      prefix + "Fs_N", "N", "static (breakaway) friction Fs, >= Fc", 1.0,
      kNonNegative, [ref](auto& s) -> auto& { return ref(s).curve.static_N; }));
  keys.push_back(number(
      prefix + "B_Ns_per_m", "N*s/m", "viscous coefficient B (sigma2 for lugre)", 1.0,
      kNonNegative, [ref](auto& s) -> auto& { return ref(s).curve.viscous_Ns_per_m; }));
  keys.push_back(number(
      prefix + "vs_mm_per_s", "mm/s", "Stribeck velocity vs", 1e-3,
      kPositive, [ref](auto& s) -> auto& { return ref(s).curve.stribeck_velocity_m_per_s; }));
  keys.push_back(number(
      prefix + "stribeck_exponent", "-", "exponent delta of exp(-(|v|/vs)^delta)", 1.0,
      Range{0.1, 10.0}, [ref](auto& s) -> auto& { return ref(s).curve.stribeck_exponent; }));
  keys.push_back(number(
      prefix + "sigma0_N_per_m", "N/m", "LuGre bristle stiffness sigma0", 1.0,
      kPositive, [ref](auto& s) -> auto& { return ref(s).lugre.sigma0_N_per_m; }));
  keys.push_back(number(
      prefix + "sigma1_Ns_per_m", "N*s/m", "LuGre bristle damping sigma1", 1.0,
      kNonNegative, [ref](auto& s) -> auto& { return ref(s).lugre.sigma1_Ns_per_m; }));
  add_gms_keys(keys, prefix, ref);
  keys.push_back(word<FrictionMemory>(
      prefix + "memory",
      "stribeck only: lag makes the Stribeck drop lag the velocity by lag_time_ms; rate_state "
      "gives it two states that follow the slip (the rate_state_* keys)",
      {"none", "lag", "rate_state"}, [ref](auto& s) -> auto& { return ref(s).memory; }));
  keys.push_back(number(
      prefix + "quasi_static_rate", "1/s",
      "lugre only: bristle relaxation rate sigma0 |v| / g above which the bristle is taken "
      "on its steady state (0: never)",
      1.0, kNonNegative, [ref](auto& s) -> auto& { return ref(s).lugre.quasi_static_rate_per_s; }));
  keys.push_back(number(
      prefix + "lag_time_ms", "ms", "time constant of the Stribeck drop's lag (memory = lag)", 1e-3,
      kPositive, [ref](auto& s) -> auto& { return ref(s).lag.time_s; }));
  add_rate_state_keys(keys, prefix, ref);
  keys.push_back(number(
      prefix + "Fc_gain_N_per_MPa", "N/MPa",
      "pressure dependence: Fc grows by this per MPa of P1+P2-2Pa", 1e-6,
      kNonNegative, [ref](auto& s) -> auto& { return ref(s).pressure_gain.coulomb_N_per_Pa; }));
  keys.push_back(number(
      prefix + "Fs_gain_N_per_MPa", "N/MPa",
      "pressure dependence: Fs grows by this per MPa of P1+P2-2Pa", 1e-6,
      kNonNegative, [ref](auto& s) -> auto& { return ref(s).pressure_gain.static_N_per_Pa; }));
}

// A speed controller's effective area (ISO 6358 C converted to mm^2) is a few mm^2 for the
// M5-1/4" fittings of small cylinders and some 100-200 mm^2 for 1" valves; 1000 mm^2 (a 36 mm
// orifice) bounds any pneumatic valve.
constexpr double kMaxValveArea_mm2 = 1000.0;
const char* const kValveAreaWhy =
    "the largest pneumatic valves (1\" ports) have effective areas of some 100-200 mm^2; is "
    "the unit mm^2?";

// Keys of the circuit: valve openings, supply and ambient pressure.
void add_circuit_keys(std::vector<KeySpec>& k) {
  k.push_back(word<CircuitKind>(
      "circuit.kind",
      "meter-out: S2 is the exhaust speed controller (the paper's rig); "
      "meter-in: S1 is the supply speed controller. The circuit is the same either way (S1 "
      "feeds the head side, S2 vents the rod side): the kind picks S1's and S2's defaults and "
      "which one `stability` treats as the controller, so with both given the simulation is "
      "the same",
      {"meter-out", "meter-in"}, [](auto& s) -> auto& { return s.circuit.kind; }));
  {
    KeySpec s1 = number(
        "circuit.S1_mm2", "mm^2",
        "effective sectional area of the supply-side valve (default 2.70 "
        "meter-out, 0.35 meter-in)",
        1e-6, Range{0.0, kMaxValveArea_mm2}, [](auto& s) -> auto& { return s.circuit.S1_m2; });
    s1.why = kValveAreaWhy;
    s1.get_number = [](const Scenario& s) { return s.circuit.S1(); };
    k.push_back(std::move(s1));
    KeySpec s2 = number(
        "circuit.S2_mm2", "mm^2",
        "effective sectional area of the rod-side (exhaust) valve (default 0.35 "
        "meter-out, 20 meter-in)",
        1e-6, Range{0.0, kMaxValveArea_mm2}, [](auto& s) -> auto& { return s.circuit.S2_m2; });
    s2.why = kValveAreaWhy;
    s2.get_number = [](const Scenario& s) { return s.circuit.S2(); };
    k.push_back(std::move(s2));
  }
  // Industrial compressed-air networks run at 0.4-1 MPa gauge (ISO 8573 air, ISO 4414 safety
  // practice); cylinders (ISO 15552, ISO 6432) are rated to 1-1.6 MPa. 2 MPa leaves room for
  // boosters and high-pressure valves; above it a pneumatic cylinder is out of its rating.
  k.push_back(plausible(
      "supply.pressure_MPa", "MPa (gauge)", "supply pressure Ps above ambient", 1e6,
      Range{0.0, 2.0, true, false},
      "pneumatic cylinders are rated to 1-1.6 MPa gauge (ISO 15552, ISO 6432) and industrial "
      "supplies run at 0.4-1 MPa; is the unit MPa?",
      [](auto& s) -> auto& { return s.supply_gauge_Pa; }));
  // The standard atmosphere spans 101 kPa at sea level to 31 kPa at 9 km; 120 kPa allows a
  // deep mine or a pressurised room.
  k.push_back(plausible(
      "ambient.pressure_kPa", "kPa (absolute)", "atmospheric pressure Pa", 1e3,
      Range{30.0, 120.0},
      "the atmosphere is 101.3 kPa at sea level and 31 kPa at 9,000 m (ISO 2533); is the unit "
      "kPa?",
      [](auto& s) -> auto& { return s.ambient_pressure_Pa; }));
}

// Keys of the air: gas properties, chamber thermodynamics and the supply line.
void add_gas_keys(std::vector<KeySpec>& k) {
  // Pneumatic components are rated for about -20..+80 degC (manufacturers' data; ISO 8573
  // air); -73..+127 degC bounds any air a cylinder works with.
  k.push_back(plausible(
      "gas.temperature_K", "K", "temperature of supply air and chambers", 1.0,
      Range{200.0, 400.0},
      "pneumatic components work at about 253-353 K (-20..+80 degC); is the unit kelvin?",
      [](auto& s) -> auto& { return s.temperature_K; }));
  k.push_back(number(
      "gas.R_J_per_kgK", "J/(kg*K)", "specific gas constant", 1.0, kPositive,
      [](auto& s) -> auto& { return s.gas.R_J_per_kgK; }));
  k.push_back(number(
      "gas.heat_capacity_ratio", "-", "cp/cv of air, used by the valve flow law and the energy equation", 1.0,
      Range{1.0, 1.67, true, false}, [](auto& s) -> auto& { return s.gas.heat_capacity_ratio; }));
  k.push_back(number(
      "gas.polytropic_exponent", "-", "k of the chamber equations: 1.4 adiabatic, 1.0 isothermal",
      1.0, Range{1.0, 1.67}, [](auto& s) -> auto& { return s.polytropic_exponent; }));
  k.push_back(word<ChamberModel>(
      "thermal.chamber_model",
      "polytropic: eqs. (2)-(3) with gas.polytropic_exponent; energy: chamber temperatures as "
      "states with wall heat transfer",
      {"polytropic", "energy"}, [](auto& s) -> auto& { return s.thermal.chamber_model; }));
  k.push_back(number(
      "thermal.heat_transfer_W_per_m2K", "W/(m^2*K)",
      "wall heat-transfer coefficient h (chamber_model = energy)", 1.0, kNonNegative,
      [](auto& s) -> auto& { return s.thermal.heat_transfer_W_per_m2K; }));
  k.push_back(number(
      "thermal.wall_temperature_K", "K", "cylinder wall temperature (chamber_model = energy)",
      1.0, kPositive, [](auto& s) -> auto& { return s.thermal.wall_temperature_K; }));
  k.push_back(number(
      "supply_line.volume_cm3", "cm^3",
      "volume between the regulator and S1 (tube + manifold); 0: ideal supply, no state P0",
      1e-6, kNonNegative, [](auto& s) -> auto& { return s.supply_line.volume_m3; }));
  k.push_back(number(
      "supply_line.regulator_S_mm2", "mm^2",
      "effective sectional area of the regulator feeding the line (volume_cm3 > 0)", 1e-6,
      kPositive, [](auto& s) -> auto& { return s.supply_line.regulator_S_m2; }));
  k.push_back(number(
      "supply_line.polytropic_exponent", "-",
      "n of the line's pressure equation: 1.0 isothermal, 1.4 adiabatic (volume_cm3 > 0)", 1.0,
      Range{1.0, 1.67}, [](auto& s) -> auto& { return s.supply_line.polytropic_exponent; }));
}

// Keys of the cylinder and its valves.
void add_cylinder_keys(std::vector<KeySpec>& k) {
  // Standard bores run from 2.5 mm (miniature) through ISO 6432 (8-25 mm) and ISO 15552
  // (32-320 mm); 500 mm bounds the largest special cylinders.
  k.push_back(plausible(
      "cylinder.bore_mm", "mm", "piston diameter", 1e-3, Range{1.0, 500.0},
      "pneumatic bores run from 2.5 mm to 320 mm (ISO 6432, ISO 15552); is the unit mm?",
      [](auto& s) -> auto& { return s.cylinder.bore_m; }));
  k.push_back(number(
      "cylinder.rod_mm", "mm", "rod diameter, < bore", 1e-3, kNonNegative,
      [](auto& s) -> auto& { return s.cylinder.rod_m; }));
  k.push_back(number(
      "cylinder.stroke_mm", "mm", "stroke length", 1e-3, kPositive,
      [](auto& s) -> auto& { return s.cylinder.stroke_m; }));
  k.push_back(number(
      "cylinder.dead_volume_head_cm3", "cm^3", "head-side volume at x = 0, tubing included", 1e-6,
      kPositive, [](auto& s) -> auto& { return s.cylinder.dead_volume_head_m3; }));
  k.push_back(number(
      "cylinder.dead_volume_rod_cm3", "cm^3", "rod-side volume at full stroke, tubing included",
      1e-6, kPositive, [](auto& s) -> auto& { return s.cylinder.dead_volume_rod_m3; }));
  k.push_back(number(
      "cylinder.frozen_position_mm", "mm",
      "evaluate the chamber volumes at this position, stroke end ignored "
      "(-1: off, volumes follow the piston)",
      1e-3, Range{-1.0, 1e6}, [](auto& s) -> auto& { return s.cylinder.frozen_position_m; }));
  k.push_back(word<FlowLaw>(
      "valve.law", "valve flow law", {"iso6358", "isentropic"},
      [](auto& s) -> auto& { return s.valve.law; }));
  k.push_back(number(
      "valve.critical_ratio", "-", "critical pressure ratio b (iso6358)", 1.0,
      Range{0.0, 1.0, false, true}, [](auto& s) -> auto& { return s.valve.critical_ratio; }));
  k.push_back(number(
      "valve.laminar_ratio", "-",
      "pressure ratio above which the flow is linear in the pressure difference", 1.0,
      Range{0.9, 1.0, false, true}, [](auto& s) -> auto& { return s.valve.laminar_ratio; }));
  k.push_back(word<ValveOpening>(
      "valve.S1_opening",
      "instant: S1 fully open at the switch; lag: S1's area opens as 1 - exp(-t / "
      "S1_opening_time_ms) (the solenoid valve's response)",
      {"instant", "lag"}, [](auto& s) -> auto& { return s.valve_opening.kind; }));
  k.push_back(number(
      "valve.S1_opening_time_ms", "ms", "time constant of S1's opening (S1_opening = lag)", 1e-3,
      kPositive, [](auto& s) -> auto& { return s.valve_opening.time_constant_s; }));
}

// Keys of the seal, the load and its guide.
void add_moving_part_keys(std::vector<KeySpec>& k) {
  add_friction_keys(
      k, "friction.", "piston seal", [](auto& s) -> auto& { return s.friction; });
  k.push_back(number(
      "load.mass_kg", "kg", "moving mass m (rigid: piston, rod and load; spring: the load alone)",
      1.0, kPositive, [](auto& s) -> auto& { return s.load.mass_kg; }));
  k.push_back(number(
      "load.force_N", "N", "constant external force opposing extension", 1.0, Range{},
      [](auto& s) -> auto& { return s.load.external_force_N; }));
  k.push_back(word<LoadCoupling>(
      "load.coupling",
      "rigid: one moving mass; spring: the load on its own guide, "
      "coupled to the rod by a spring and damper",
      {"rigid", "spring"}, [](auto& s) -> auto& { return s.load.coupling; }));
  k.push_back(number(
      "load.piston_mass_kg", "kg", "piston + rod mass (spring coupling)", 1.0, kPositive,
      [](auto& s) -> auto& { return s.load.piston_mass_kg; }));
  k.push_back(number(
      "load.stiffness_N_per_m", "N/m", "rod-load coupling stiffness", 1.0, kPositive,
      [](auto& s) -> auto& { return s.load.coupling_stiffness_N_per_m; }));
  k.push_back(number(
      "load.damping_Ns_per_m", "N*s/m", "rod-load coupling damping", 1.0, kNonNegative,
      [](auto& s) -> auto& { return s.load.coupling_damping_Ns_per_m; }));
  add_friction_keys(
      k, "guide_friction.", "load guide (spring coupling)",
      [](auto& s) -> auto& { return s.load.guide_friction; });
}

// Keys of run-to-run variation and the integration.
void add_run_keys(std::vector<KeySpec>& k) {
  k.push_back(number(
      "variation.friction_rel_sd", "-",
      "relative sd of each friction parameter, drawn per run (sweeps)", 1.0, Range{0.0, 0.5},
      [](auto& s) -> auto& { return s.variation.friction_rel_sd; }));
  k.push_back(number(
      "variation.texture_rel", "-",
      "relative amplitude of a seeded friction texture along the bore", 1.0, Range{0.0, 0.5},
      [](auto& s) -> auto& { return s.variation.texture_rel; }));
  k.push_back(number(
      "variation.texture_wavelength_mm", "mm", "typical wavelength of the texture", 1e-3, kPositive,
      [](auto& s) -> auto& { return s.variation.texture_wavelength_m; }));
  k.push_back(number(
      "variation.seal_noise_rel", "-",
      "relative sd of a seeded random field of the seal's friction level along the bore", 1.0,
      Range{0.0, 0.25}, [](auto& s) -> auto& { return s.variation.seal_noise_rel; }));
  k.push_back(number(
      "variation.seal_noise_correlation_mm", "mm",
      "correlation length of the seal's random level along the bore", 1e-3, Range{0.2, 100.0},
      [](auto& s) -> auto& { return s.variation.seal_noise_correlation_m; }));
  k.push_back(number(
      "run.duration_s", "s", "simulated time (the run also ends at stroke end)", 1.0, kPositive,
      [](auto& s) -> auto& { return s.run.duration_s; }));
  k.push_back(number(
      "run.rate_Hz", "Hz", "output sample rate", 1.0, kPositive,
      [](auto& s) -> auto& { return s.run.sample_rate_Hz; }));
  k.push_back(number(
      "run.rtol", "-", "relative error tolerance of the integrator", 1.0, Range{1e-14, 1e-2},
      [](auto& s) -> auto& { return s.run.relative_tolerance; }));
  k.push_back(number(
      "run.atol", "-", "absolute error tolerance (SI state units)", 1.0, Range{1e-16, 1e-2},
      [](auto& s) -> auto& { return s.run.absolute_tolerance; }));
  k.push_back(number(
      "run.max_step_ms", "ms", "largest integration step", 1e-3, kPositive,
      [](auto& s) -> auto& { return s.run.max_step_s; }));
  k.push_back(word<StepperKind>(
      "run.stepper",
      "dopri5 (explicit, default) or rosenbrock4 (stiff, for stiff "
      "LuGre bristles)",
      {"dopri5", "rosenbrock4"}, [](auto& s) -> auto& { return s.run.stepper; }));
  k.push_back(word<RunStart>(
      "run.start",
      "rest (against the stop, the valve switching at t = 0; default) or sliding (on the "
      "steady motion the stability analysis finds, at its position)",
      {"rest", "sliding"}, [](auto& s) -> auto& { return s.run.start; }));
}

// Keys of the transducers (docs/model.md, "The transducer"); 0 is the ideal transducer.
void add_transducer_keys(std::vector<KeySpec>& k) {
  const Range bits{0.0, static_cast<double>(kMaxTransducerBits)};
  k.push_back(number(
      "transducer.velocity_noise_mm_per_s", "mm/s",
      "sd of white noise in the velocity record (seeded per run)", 1e-3, kNonNegative,
      [](auto& s) -> auto& { return s.transducer.velocity.noise_m_per_s; }));
  k.push_back(number(
      "transducer.velocity_bandwidth_Hz", "Hz",
      "corner frequency of the velocity transducer's first-order lag (0: unlimited)", 1.0,
      kNonNegative, [](auto& s) -> auto& { return s.transducer.velocity.bandwidth_Hz; }));
  k.push_back(count(
      "transducer.velocity_bits", "bits",
      "A/D resolution of the velocity record (0: not quantised; > 0 needs velocity_range_mm_per_s)",
      bits, [](auto& s) -> auto& { return s.transducer.velocity.bits; }));
  k.push_back(number(
      "transducer.velocity_range_mm_per_s", "mm/s",
      "full scale +-range of the velocity record, clipped beyond (0: none)", 1e-3, kNonNegative,
      [](auto& s) -> auto& { return s.transducer.velocity.range_m_per_s; }));
  k.push_back(number(
      "transducer.pressure_noise_kPa", "kPa", "sd of white noise in the P1 and P2 records", 1e3,
      kNonNegative, [](auto& s) -> auto& { return s.transducer.pressure.noise_Pa; }));
  k.push_back(number(
      "transducer.pressure_bandwidth_Hz", "Hz",
      "corner frequency of the pressure transducers' first-order lag (0: unlimited)", 1.0,
      kNonNegative, [](auto& s) -> auto& { return s.transducer.pressure.bandwidth_Hz; }));
  k.push_back(count(
      "transducer.pressure_bits", "bits",
      "A/D resolution of the P1 and P2 records (0: not quantised; > 0 needs pressure_range_MPa)",
      bits, [](auto& s) -> auto& { return s.transducer.pressure.bits; }));
  k.push_back(number(
      "transducer.pressure_range_MPa", "MPa (gauge)",
      "full scale 0..range above ambient of the P1 and P2 records, clipped beyond (0: none)", 1e6,
      kNonNegative, [](auto& s) -> auto& { return s.transducer.pressure.range_Pa; }));
}

// Every key, in the order `pneumachaos scenario` lists them.
std::vector<KeySpec> build_keys() {
  std::vector<KeySpec> k;
  add_circuit_keys(k);
  add_gas_keys(k);
  add_cylinder_keys(k);
  add_moving_part_keys(k);
  add_run_keys(k);
  add_transducer_keys(k);
  return k;
}

const std::vector<KeySpec>& keys() {
  static const std::vector<KeySpec> table = build_keys();
  return table;
}

const KeySpec& find(const std::string& key, const std::string& where) {
  for (const auto& k : keys()) {
    if (k.info.key == key) return k;
  }
  const auto dot = key.find('.');
  std::string hint;
  for (const auto& k : keys()) {
    if (dot != std::string::npos && k.info.key.compare(0, dot + 1, key, 0, dot + 1) == 0) {
      hint += (hint.empty() ? "" : ", ") + k.info.key;
    }
  }
  throw Error(
      where.empty() ? key : where + ": " + key,
      "unknown scenario key" + (hint.empty() ? std::string("; see `pneumachaos scenario --keys`")
                                             : "; keys of that section are: " + hint));
}

// Values are stored in SI and shown in the key's unit: the division leaves conversion noise
// in the last bits (20 cm^3 shows as 20.000000000000004). Fifteen significant digits, the
// most a double always carries, remove it; the shortest form of that is printed.
std::string format_number(double v) {
  return fmt::format("{}", std::strtod(fmt::format("{:.15g}", v).c_str(), nullptr));
}

}  // namespace

std::vector<KeyInfo> scenario_key_infos() {
  std::vector<KeyInfo> out;
  for (const auto& k : keys()) out.push_back(k.info);
  return out;
}

void apply_setting(Scenario& scenario, const std::string& key, const SettingValue& value,
                   const std::string& where) {
  const KeySpec& spec = find(key, where);
  const std::string place = where.empty() ? key : where + ": " + key;
  if (spec.is_word) {
    const auto* text = std::get_if<std::string>(&value);
    if (text == nullptr) {
      throw Error(place, fmt::format("expected one of {}, got the number {}", spec.info.choices,
                                     std::get<double>(value)));
    }
    for (std::size_t i = 0; i < spec.words.size(); ++i) {
      if (spec.words[i] == *text) {
        spec.set_word(scenario, i);
        return;
      }
    }
    throw Error(place, fmt::format("expected one of {}, got \"{}\"", spec.info.choices, *text));
  }
  const auto* number = std::get_if<double>(&value);
  if (number == nullptr) {
    throw Error(place, fmt::format("expected a number in {}, got \"{}\"", spec.info.unit,
                                   std::get<std::string>(value)));
  }
  if (!std::isfinite(*number)) {
    throw Error(place,
                fmt::format("expected a finite number in {}, got {}", spec.info.unit, *number));
  }
  if (!spec.range.contains(*number)) {
    throw Error(place, fmt::format("{} {} is out of range: expected {}{}", *number, spec.info.unit,
                                   spec.info.range, spec.why.empty() ? "" : " (" + spec.why + ")"));
  }
  if (spec.whole && *number != std::floor(*number)) {
    throw Error(place, fmt::format("expected a whole number, got {}", *number));
  }
  spec.set_number(scenario, *number * spec.scale);
}

SettingValue parse_setting_text(const std::string& key, const std::string& text,
                                const std::string& where) {
  const KeySpec& spec = find(key, where);
  if (spec.is_word) return text;
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || text.empty()) {
    throw Error(where.empty() ? key : where + ": " + key,
                fmt::format("expected a number in {}, got \"{}\"", spec.info.unit, text));
  }
  return v;
}

std::string setting_text(const Scenario& scenario, const std::string& key) {
  const KeySpec& spec = find(key, "");
  if (spec.is_word) return "\"" + spec.words.at(spec.get_word(scenario)) + "\"";
  return format_number(spec.get_number(scenario) / spec.scale);
}

// Written line by line rather than through toml++: the file is meant to be read and edited by
// a person, with each key's unit, meaning and range as a comment beside it, and toml++ (3.x)
// writes no comments. The reader is toml++; a test reads every printed key back.
std::string scenario_to_toml(const Scenario& scenario) {
  std::string out =
      "# pneumachaos scenario. Units are in the key names; pressures in MPa are gauge.\n"
      "#\n"
      "# The defaults are the virtual rig (docs/notes/virtual_rig.md), not a generic cylinder:\n"
      "# the paper's one rigid moving mass with a generalized Maxwell-slip seal, a supply line\n"
      "# and chamber end volumes calibrated to the paper's claims (scenarios/calibrations/\n"
      "# paper.toml's best point). For your own cylinder give its seal (friction.*), bore,\n"
      "# stroke, mass, volumes and valves; docs/scenario.md says how. The load keys of\n"
      "# load.coupling = \"spring\" hold the compliant mount of scenarios/variants/\n"
      "# compliant_mount.toml (two bodies); starting from that file for your\n"
      "# own cylinder, set load.coupling = \"rigid\" unless its mount is compliant.\n";
  std::string section;
  for (const auto& k : keys()) {
    const auto dot = k.info.key.find('.');
    const std::string sec = k.info.key.substr(0, dot);
    if (sec != section) {
      out += "\n[" + sec + "]\n";
      section = sec;
    }
    const std::string comment =
        k.is_word ? k.info.choices
                  : k.info.unit + (k.info.range.empty() ? "" : ", " + k.info.range);
    out += fmt::format("{} = {}  # {} ({})\n", k.info.key.substr(dot + 1),
                       setting_text(scenario, k.info.key), k.info.description, comment);
  }
  return out;
}

}  // namespace pneumachaos
