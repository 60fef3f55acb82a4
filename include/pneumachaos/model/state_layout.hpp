#pragma once
// Where each quantity sits in the ODE state vector. Options append blocks (friction internal
// states, a second body for the load on its own guide) so that new states never fork the model.

#include <cstddef>
#include <string>
#include <vector>

namespace pneumachaos {

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
  };
  std::vector<Entry> entries{{"x", "m"}, {"v", "m/s"}, {"P1", "Pa"}, {"P2", "Pa"}};

  /// Appends `count` states named name, name2, ...; returns the index of the first.
  std::size_t append(const std::string& name, const std::string& unit, std::size_t count = 1);
  [[nodiscard]] bool has_load_body() const { return load_x != kNone; }
  [[nodiscard]] bool has_temperatures() const { return T1 != kNone; }
  [[nodiscard]] bool has_supply_line() const { return P0 != kNone; }
  [[nodiscard]] bool has_valve_opening() const { return S1_open != kNone; }
};

}  // namespace pneumachaos
