#pragma once
// The pneumatic cylinder with its valves, seal friction and load, as a hybrid system
// (docs/model.md, equations (1)-(3)). Immutable: parameters and the derivative rule only; time,
// state and mode belong to the integrator (docs/architecture.md).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/core/hybrid_system.hpp"
#include "pneumachaos/model/friction.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/model/state_layout.hpp"

namespace pneumachaos {

/// Per friction contact (index 0: piston seal, 1: load guide), stored in Mode::value.
enum class ContactMode : std::int8_t {
  kSmooth = 0,    ///< smooth friction model (LuGre), moving or not
  kStuck = 1,     ///< true stiction: v = 0 held exactly, position frozen
  kSlidePos = 2,  ///< sliding with v > 0
  kSlideNeg = 3,  ///< sliding with v < 0
  kAtStop = 4,    ///< piston held against the stop at x = 0
  /// Smooth friction model moving with v >= 0 (v <= 0): |v| is integrated as +v (-v), its
  /// smooth continuation, and the crossing of v = 0 is an event that flips the branch, so no
  /// step straddles the kink of |v| (docs/model.md, "Friction"; docs/notes/performance.md).
  kSmoothPos = 5,
  kSmoothNeg = 6,
  /// LuGre or GMS moving with v > 0 (v < 0) fast enough that its bristle (its elements)
  /// relaxes far quicker than anything else moves: the bristle is taken on its steady state,
  /// the elements that reached their shares on them (quasi-static limit,
  /// FrictionParams::quasi_static_threshold(); docs/model.md, "Friction").
  kQuasiPos = 7,
  kQuasiNeg = 8,
};

/// Quantities derived from a state, for output and analysis.
struct PlantOutputs {
  double seal_friction_N = 0.0;   ///< force the seal exerts against +x motion
  double guide_friction_N = 0.0;  ///< same for the load guide (spring coupling)
  double drive_force_N = 0.0;     ///< net non-friction force on the piston
  double W1_kg_per_s = 0.0;       ///< mass flow into chamber 1
  double W2_kg_per_s = 0.0;       ///< mass flow out of chamber 2
  bool piston_stuck = false;      ///< stuck or held at the stop
};

/// Where a motion is at one moment, as a user or a record states it: the rest of the state
/// (friction internal states, load body, temperatures, supply line, valve) follows from it.
struct OperatingPoint {
  double position_m = 0.0;
  double velocity_m_per_s = 0.0;
  double P1_Pa = 0.0;  ///< absolute
  double P2_Pa = 0.0;  ///< absolute
};

/// One sampled output column: a state, or a force or flag derived from the state.
struct OutputChannel {
  enum class Source : std::uint8_t { kState, kSealFriction, kGuideFriction, kStuck };
  std::string name;
  std::string unit;
  Source source = Source::kState;
  std::size_t state = 0;  ///< the state's index (Source::kState)
};

class Plant final : public HybridSystem {
 public:
  /// Validates the scenario (throws Error naming the key) and builds the plant.
  explicit Plant(const Scenario& scenario);

  [[nodiscard]] std::size_t state_size() const override { return layout_.size; }
  void derivative(const Mode& mode, std::span<const double> x, std::span<double> dxdt,
                  double t) const override;
  [[nodiscard]] std::size_t event_count(const Mode& mode) const override;
  void event_functions(const Mode& mode, std::span<const double> x, double t,
                       std::span<double> g) const override;
  EventOutcome apply_event(std::size_t which, Mode& mode, std::span<double> x,
                           double t) const override;
  [[nodiscard]] Mode initial_mode(std::span<const double> x, double t) const override;
  /// The exact Jacobian of derivative() in `mode`, by automatic differentiation of the same
  /// templated equations (Eigen's AutoDiff); the plant is autonomous, so dfdt = 0.
  bool jacobian(const Mode& mode, std::span<const double> x, double t, std::span<double> dfdx,
                std::span<double> dfdt) const override;

  /// The start of a run (docs/model.md): chamber 1 at Pa, chamber 2 at Ps, at rest at x = 0.
  [[nodiscard]] std::vector<double> initial_state() const;
  /// A full state at `op`, every block consistent with it: friction internal states at rest
  /// (v = 0) or on their steady state, the load riding with the piston on a spring deflected by
  /// what holds it back, the chambers at supply temperature, the supply line charged, S1 open.
  [[nodiscard]] std::vector<double> state_at(const OperatingPoint& op) const;
  /// The sampled output columns, in order (simulate's CSV and TimeSeries).
  [[nodiscard]] const std::vector<OutputChannel>& channels() const { return channels_; }
  /// One sample of every channel into `row` (cleared first).
  void sample(const Mode& mode, std::span<const double> x, std::vector<double>& row) const;
  [[nodiscard]] PlantOutputs outputs(const Mode& mode, std::span<const double> x) const;

  /// Typical magnitudes of the state variables (1 mm, 10 mm/s, 10 kPa, 1 um of bristle),
  /// for norms that weigh positions, speeds and pressures alike (model Lyapunov exponent).
  [[nodiscard]] std::vector<double> state_scales() const;

  // What the plant integrates, and nothing else of the Scenario it was built from (the run's
  // settings and the variation stay with the caller).
  [[nodiscard]] const StateLayout& layout() const { return layout_; }
  [[nodiscard]] double ambient_pressure_Pa() const { return ambient_Pa_; }
  [[nodiscard]] double supply_pressure_Pa() const { return supply_Pa_; }  ///< absolute
  [[nodiscard]] double polytropic_exponent() const { return polytropic_exponent_; }
  /// R T of the supply air [J/kg]; the chambers' too unless the energy equation is on.
  [[nodiscard]] double RT_J_per_kg() const { return RT_; }
  [[nodiscard]] const CylinderGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const LoadParams& load() const { return load_; }
  /// Meter-out or meter-in: which of the two valves is the speed controller.
  [[nodiscard]] CircuitKind circuit() const { return circuit_; }
  [[nodiscard]] const FrictionModel& seal_friction() const { return *seal_; }
  /// The load guide's friction model; nullptr for rigid coupling.
  [[nodiscard]] const FrictionModel* guide_friction() const { return guide_.get(); }
  [[nodiscard]] const Orifice& valve1() const { return *valve1_; }  ///< supply -> chamber 1
  [[nodiscard]] const Orifice& valve2() const { return *valve2_; }  ///< chamber 2 -> atmosphere
  /// The mode in which every contact slides in `direction` (+1/-1): steady motion.
  [[nodiscard]] Mode sliding_mode(int direction) const;
  [[nodiscard]] double A1() const { return A1_; }
  [[nodiscard]] double A2() const { return A2_; }
  /// Mass whose motion carries the seal friction: total mass (rigid) or piston + rod (spring).
  [[nodiscard]] double piston_mass_kg() const { return piston_mass_; }

  /// dP1/dt (eq. 2) and dP2/dt (eq. 3) alone: the parts of derivative() that no mode changes,
  /// for balances that need only one chamber.
  [[nodiscard]] double head_pressure_rate(std::span<const double> x) const;
  [[nodiscard]] double rod_pressure_rate(std::span<const double> x) const;

  /// Mass flows W1 (into chamber 1) and W2 (out of chamber 2) at these pressures.
  [[nodiscard]] std::array<double, 2> mass_flows(double P1_Pa, double P2_Pa) const;

 private:
  enum class EventType : std::uint8_t {
    kVelocityZero,
    kBreakaway,
    kStopRelease,
    kStopHit,
    kStrokeEnd,
    kQuasiEnter,  ///< a LuGre (GMS) contact's relaxation (loading) rate rises to its threshold
    kQuasiExit    ///< ... falls to its exit fraction of it (FrictionParams)
  };
  struct ActiveEvent {
    EventType type;
    std::uint8_t contact;
  };
  struct EventList {
    std::array<ActiveEvent, 8> items{};
    std::size_t count = 0;
  };

  [[nodiscard]] EventList active_events(const Mode& mode) const;

  // The model's equations, written once on a scalar type T (double, or an automatic-
  // differentiation scalar for the Jacobian); defined in src/model/plant_equations.hpp.
  template <typename T>
  void evaluate(const Mode& mode, std::span<const T> x, std::span<T> dxdt) const;
  template <typename T>
  [[nodiscard]] T head_chamber_rate(std::span<const T> x) const;
  template <typename T>
  [[nodiscard]] T rod_chamber_rate(std::span<const T> x) const;
  template <typename T>
  void chamber_energy_rates(std::span<const T> x, std::span<T> dxdt) const;
  template <typename T>
  [[nodiscard]] T open_chamber_rates(const T& P, const T& Tc, const T& V, const T& dV,
                                     const T& W_in, const T& H_in, const T& A_wall,
                                     T& dTc) const;
  template <typename T>
  [[nodiscard]] T valve1_upstream(std::span<const T> x) const;
  template <typename T>
  [[nodiscard]] T valve1_flow(std::span<const T> x) const;
  template <typename T>
  [[nodiscard]] T valve1_inflow(std::span<const T> x) const;
  template <typename T>
  [[nodiscard]] T drive_force(std::size_t contact, std::span<const T> x) const;
  template <typename T>
  [[nodiscard]] BasicFrictionInput<T> friction_input(std::size_t contact,
                                                     std::span<const T> x) const;
  template <typename T>
  [[nodiscard]] T friction_force(std::size_t contact, ContactMode m, std::span<const T> x,
                                 std::span<T> dz) const;

  [[nodiscard]] double holding_force(std::size_t contact, std::span<const double> x) const;
  /// The mode of a contact at rest (v = 0) consistent with its forces.
  [[nodiscard]] ContactMode rest_mode(std::size_t contact, std::span<const double> x,
                                      bool at_stop) const;
  /// The quasi-static limit's switching function of a LuGre or GMS contact on its branch,
  /// negative where it switches: while off, when its rate is above the threshold and its
  /// bristle (elements) has settled; while on, when the rate falls below the threshold's exit
  /// fraction (FrictionParams::quasi_static_exit_fraction).
  [[nodiscard]] double quasi_static_switch(std::size_t contact, const Mode& mode,
                                           std::span<const double> x) const;
  /// Puts a LuGre contact's bristle on its steady state; a GMS contact's elements below their
  /// shares on them when `entering`, else at their deflections in the limit's mode `quasi`.
  void settle_bristle(std::size_t contact, const Mode& quasi, bool entering,
                      std::span<double> x) const;
  // The GMS quasi-static limit (src/model/plant_gms_limit.cpp, docs/model.md "Friction").
  /// Writes the elements' rates to dxdt and adds their lag to dv/dt, where the rates of
  /// everything else (the pressures', dv/dt with every element on max(m, r)) are written.
  void track_shares(std::size_t contact, int direction, double mass, std::span<const double> x,
                    std::span<double> dxdt) const;
  /// The elements' deflections in the limit (signed) in `mode`, where the contact is in it.
  void limit_deflections(std::size_t contact, const Mode& mode, std::span<const double> x,
                         double* out) const;
  /// The contact's friction force in the limit, lag included: drive - mass dv/dt.
  [[nodiscard]] double limit_force(std::size_t contact, const Mode& mode,
                                   std::span<const double> x) const;
  /// The output columns: piston and chambers, each contact's friction force beside its
  /// internal states, then the optional blocks, then the stuck flag.
  [[nodiscard]] std::vector<OutputChannel> build_channels() const;
  /// A friction model's internal states at rest (v = 0) or on their steady state at `in`.
  static void settle_internal_states(const FrictionModel& f, const FrictionInput& in,
                                     std::span<double> z);
  [[nodiscard]] const FrictionModel& friction_of(std::size_t contact) const {
    return contact == 0 ? *seal_ : *guide_;
  }

  CylinderGeometry geometry_;
  LoadParams load_;
  CircuitKind circuit_ = CircuitKind::kMeterOut;
  double ambient_Pa_ = 0.0;
  double supply_Pa_ = 0.0;
  double polytropic_exponent_ = 0.0;
  double RT_ = 0.0;
  ThermalParams thermal_;
  double kappa_ = 1.4;     // cp/cv, the energy equation's exponent
  double R_ = 287.0;       // specific gas constant
  double T_supply_ = 0.0;  // supply and atmosphere temperature: what flows in
  StateLayout layout_;
  std::unique_ptr<FrictionModel> seal_;
  std::unique_ptr<FrictionModel> guide_;
  std::optional<Orifice> valve1_;  // supply -> chamber 1 (S1)
  std::optional<Orifice> valve2_;  // chamber 2 -> atmosphere (S2)
  double valve1_time_constant_s_ = 0.0;  // S1's opening lag tau (valve.S1_opening = lag)
  std::optional<SupplyLine> line_;  // regulator -> line volume -> S1 (supply_line.volume_cm3 > 0)
  double A1_ = 0.0;
  double A2_ = 0.0;
  double piston_mass_ = 0.0;
  std::size_t contacts_ = 1;
  std::vector<OutputChannel> channels_;
};

}  // namespace pneumachaos
