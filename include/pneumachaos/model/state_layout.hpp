#pragma once
// Where each quantity sits in the ODE state vector. The Plant declares its state here once, as
// named blocks (docs/architecture.md, "Adding a state"): each entry carries its name, unit,
// typical magnitude and block, so that output channels, norms, the equilibrium and the
// linearization reach every state through this table and never by position.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pneumachaos {

/// The kinds of state the Plant can hold; a scenario's options decide which are present.
enum class StateBlock : std::uint8_t {
  kPiston,          ///< x, v
  kChambers,        ///< P1, P2
  kValveOpening,    ///< S1's opening fraction (valve.S1_opening = lag)
  kSupplyLine,      ///< the supply line's pressure P0 (supply_line.volume_cm3 > 0)
  kTemperatures,    ///< T1, T2 (thermal.chamber_model = energy)
  kSealFriction,    ///< the seal friction model's internal states
  kLoadBody,        ///< x_load, v_load (load.coupling = spring)
  kGuideFriction,   ///< the load guide friction model's internal states
};

struct StateLayout {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  std::size_t x = 0;           ///< piston position [m]
  std::size_t v = 1;           ///< piston velocity [m/s]
  std::size_t P1 = 2;          ///< head-side pressure [Pa abs]
  std::size_t P2 = 3;          ///< rod-side pressure [Pa abs]
  std::size_t seal_z = kNone;  ///< first internal state of the seal friction model
  std::size_t seal_z_count = 0;
  std::size_t load_x = kNone;   ///< load position [m] (spring coupling only)
  std::size_t load_v = kNone;   ///< load velocity [m/s]
  std::size_t guide_z = kNone;  ///< first internal state of the guide friction model
  std::size_t guide_z_count = 0;
  std::size_t T1 = kNone;  ///< head-side temperature [K] (energy equation only)
  std::size_t T2 = kNone;  ///< rod-side temperature [K]
  std::size_t S1_open = kNone;  ///< opening fraction of S1, 0..1 (valve.S1_opening = lag only)
  std::size_t P0 = kNone;  ///< supply-line pressure [Pa abs] (supply_line.volume_cm3 > 0 only)
  std::size_t size = 4;

  struct Entry {
    std::string name;
    std::string unit;
    double scale = 1.0;  ///< typical magnitude, for norms that weigh states alike
    StateBlock block = StateBlock::kPiston;
  };
  std::vector<Entry> entries{{"x", "m", 1e-3, StateBlock::kPiston},
                             {"v", "m/s", 1e-2, StateBlock::kPiston},
                             {"P1", "Pa", 1e4, StateBlock::kChambers},
                             {"P2", "Pa", 1e4, StateBlock::kChambers}};

  /// Appends `count` states named name, name2, ...; returns the index of the first.
  std::size_t append(const std::string& name, const std::string& unit, double scale,
                     StateBlock block, std::size_t count = 1);
  [[nodiscard]] bool has(StateBlock block) const;
  [[nodiscard]] bool has_load_body() const { return load_x != kNone; }
  [[nodiscard]] bool has_temperatures() const { return T1 != kNone; }
  [[nodiscard]] bool has_supply_line() const { return P0 != kNone; }
  [[nodiscard]] bool has_valve_opening() const { return S1_open != kNone; }
};

}  // namespace pneumachaos
