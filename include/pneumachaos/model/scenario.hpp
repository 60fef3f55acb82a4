#pragma once
// Every parameter of a run, in SI units with absolute pressures (docs/model.md). The scenario
// keys users write (TOML, --set) speak engineering units; scenario_keys.hpp converts once.

#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/core/hybrid_system.hpp"
#include "pneumachaos/core/run_params.hpp"
#include "pneumachaos/model/cylinder.hpp"
#include "pneumachaos/model/friction.hpp"
#include "pneumachaos/model/supply_line.hpp"
#include "pneumachaos/model/transducer.hpp"
#include "pneumachaos/model/valve_flow.hpp"

namespace pneumachaos {

enum class CircuitKind {
  kMeterOut,  ///< S1 = supply (solenoid) valve, S2 = exhaust speed controller (the paper's rig)
  kMeterIn,   ///< S1 = supply speed controller, S2 = free exhaust (large unless set)
};

enum class LoadCoupling {
  kRigid,   ///< piston, rod and load move as one mass (the paper's model)
  kSpring,  ///< the load rides its own guide, coupled to the rod by a spring and damper
};

struct CircuitParams {
  CircuitKind kind = CircuitKind::kMeterOut;
  std::optional<double> S1_m2;  ///< unset: 2.70 mm^2 (meter-out) / 0.35 mm^2 (meter-in)
  std::optional<double> S2_m2;  ///< unset: 0.35 mm^2 (meter-out) / 20 mm^2 (meter-in)
  [[nodiscard]] double S1() const;
  [[nodiscard]] double S2() const;
};

struct LoadParams {
  double mass_kg = 1.5;           ///< total moving mass m (rigid) / load mass (spring)
  double external_force_N = 0.0;  ///< constant force opposing extension
  LoadCoupling coupling = LoadCoupling::kRigid;
  double piston_mass_kg = 0.5;  ///< piston + rod, spring coupling only
  double coupling_stiffness_N_per_m = 8.0e3;
  double coupling_damping_Ns_per_m = 7.0;
  FrictionParams guide_friction = [] {
    FrictionParams f;  // stribeck, every field not named here at its default
    f.curve = {.coulomb_N = 10.0,
               .static_N = 12.0,
               .viscous_Ns_per_m = 10.0,
               .stribeck_velocity_m_per_s = 0.004,
               .stribeck_exponent = 1.0};
    f.lugre.sigma0_N_per_m = 1.0e5;
    f.lugre.sigma1_Ns_per_m = 50.0;
    return f;
  }();
};

/// Run-to-run and seal-to-seal variation (docs/model.md, "Friction"; docs/sweep.md): what makes repeated runs of a
/// virtual rig differ as the paper's five measurements per point did. All zero: no variation
/// (the transducers' noise, Scenario::transducer, also differs from run to run).
struct VariationParams {
  double friction_rel_sd = 0.0;  ///< relative sd of Fc, Fs, B, vs, sigma0, sigma1 per run
  double texture_rel = 0.0;      ///< relative amplitude of the friction texture along the bore
  double texture_wavelength_m = 0.02;  ///< typical wavelength of the texture
  /// The random seal (docs/model.md, "Friction"): relative standard deviation of the seal's
  /// friction level along the bore, a Gaussian field drawn per run; 0: none.
  double seal_noise_rel = 0.0;
  double seal_noise_correlation_m = 0.005;  ///< its correlation length along the bore
};

enum class ChamberModel {
  kPolytropic,  ///< eqs. (2)-(3) with exponent k, one temperature everywhere (the paper's model)
  kEnergy,      ///< temperatures T1, T2 as states, wall heat transfer (docs/model.md)
};

/// The chamber energy equation (docs/model.md, "Chamber temperatures"). Off by default, so
/// that the paper's eqs. (2)-(3) stay the model unless asked for.
struct ThermalParams {
  ChamberModel chamber_model = ChamberModel::kPolytropic;
  /// h of the wall heat flow h A_wall (T_wall - T): free to forced convection of a gas,
  /// order 2-250 W/(m^2 K) (docs/model.md gives the range and why 20).
  double heat_transfer_W_per_m2K = 20.0;
  double wall_temperature_K = 293.15;  ///< cylinder wall, taken constant (large heat capacity)
};

enum class ValveOpening {
  kInstant,  ///< S1 fully open from the switch at t = 0 (the paper's model)
  kLag,      ///< S1's area follows a first-order lag after the switch
};

/// The solenoid valve S1's own opening (docs/model.md, "Valves"): its effective area grows as
/// S1 (1 - exp(-t / tau)) after the switch, through a state a = opening fraction. Off by default.
struct ValveOpeningParams {
  ValveOpening kind = ValveOpening::kInstant;
  double time_constant_s = 0.010;  ///< tau; catalogue response times of 5-30 ms
  [[nodiscard]] bool lagged() const { return kind == ValveOpening::kLag; }
};

struct Scenario {
  GasConstants gas;
  double polytropic_exponent = 1.4;  ///< k of eqs. (2)-(3): 1.4 adiabatic, 1.0 isothermal
  double temperature_K = 293.15;     ///< chambers and supply
  double ambient_pressure_Pa = 101325.0;
  double supply_gauge_Pa = 0.25e6;  ///< Ps above ambient (key supply.pressure_MPa)
  CylinderGeometry cylinder;
  CircuitParams circuit;
  ValveLaw valve;
  ValveOpeningParams valve_opening;
  FrictionParams friction;
  LoadParams load;
  VariationParams variation;
  ThermalParams thermal;
  SupplyLineParams supply_line;  ///< off in Scenario{} (eqs. (2)-(3)); the built-in rig has one
  TransducerParams transducer;   ///< ideal by default: the records are the sampled signals
  RunParams run;

  [[nodiscard]] double supply_pressure_Pa() const { return ambient_pressure_Pa + supply_gauge_Pa; }

  /// Cross-key checks (rod < bore, Fs >= Fc, ...); throws Error naming the key(s).
  void validate() const;

  /// The paper's m, its notation list's "total mass": piston, rod and load together (rigid:
  /// load.mass_kg; spring: load.piston_mass_kg + load.mass_kg).
  [[nodiscard]] double total_moving_mass_kg() const;
  /// Sets the total moving mass; a spring-coupled rig keeps its piston + rod and changes the
  /// load. Throws Error (naming load.mass_kg) when kg is not above the piston + rod.
  void set_total_moving_mass(double kg);
};

/// The built-in default scenario: the virtual rig (the paper's one rigid moving mass of 1.5 kg,
/// a generalized Maxwell-slip seal on a wide, pressure-dependent Stribeck curve, a supply line,
/// chamber volumes following the piston over a 500 mm stroke, calibrated by
/// scenarios/calibrations/paper.toml), at the paper's chaotic point S1 = 2.70, S2 = 0.35 mm^2.
/// Its spring-coupling keys hold the compliant mount of scenarios/variants/compliant_mount.toml.
/// Every value and its reasoning: docs/notes/virtual_rig.md and docs/scenario.md.
Scenario default_scenario();

/// What a user should know about a valid scenario, one sentence each (commands print them as
/// notes): a cylinder other than the compliant-mount rig's (another bore) that still carries
/// that rig's load mount, whose mode then dominates its record.
std::vector<std::string> scenario_notes(const Scenario& scenario);

/// The simple rig: one rigid moving mass, Stribeck seal friction with true stiction, volumes
/// following the piston (the paper's own model with a Stribeck curve). Scenario{} is this.
Scenario simple_rig_scenario();

}  // namespace pneumachaos
