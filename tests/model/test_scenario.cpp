// Scenario keys, TOML reading and overrides.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/error_text.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"

namespace pneumachaos {
namespace {

TEST(Scenario, KeysConvertEngineeringUnitsOnce) {
  Scenario s = default_scenario();
  apply_overrides(s, {"circuit.S1_mm2=3.1", "supply.pressure_MPa=0.3", "cylinder.bore_mm=32",
                      "friction.vs_mm_per_s=4", "friction.Fc_gain_N_per_MPa=10",
                      "run.max_step_ms=0.5", "friction.model=lugre"});
  EXPECT_DOUBLE_EQ(s.circuit.S1(), 3.1e-6);
  EXPECT_DOUBLE_EQ(s.supply_pressure_Pa(), 101325.0 + 0.3e6);
  EXPECT_DOUBLE_EQ(s.cylinder.bore_m, 0.032);
  EXPECT_DOUBLE_EQ(s.friction.curve.stribeck_velocity_m_per_s, 0.004);
  EXPECT_DOUBLE_EQ(s.friction.pressure_gain.coulomb_N_per_Pa, 10e-6);
  EXPECT_DOUBLE_EQ(s.run.max_step_s, 0.5e-3);
  EXPECT_EQ(s.friction.kind, FrictionKind::kLuGre);
}

TEST(Scenario, RequiredKeysExistAsWritten) {
  std::vector<std::string> names;
  for (const auto& k : scenario_key_infos()) names.push_back(k.key);
  for (const char* required :
       {"circuit.kind", "circuit.S1_mm2", "circuit.S2_mm2", "supply.pressure_MPa", "load.mass_kg",
        "cylinder.bore_mm", "cylinder.rod_mm", "cylinder.stroke_mm", "friction.model"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
  }
}

TEST(Scenario, ValveDefaultsFollowTheCircuit) {
  Scenario s = default_scenario();
  EXPECT_DOUBLE_EQ(s.circuit.S1(), 2.70e-6);
  EXPECT_DOUBLE_EQ(s.circuit.S2(), 0.35e-6);
  apply_overrides(s, {"circuit.kind=meter-in"});
  EXPECT_DOUBLE_EQ(s.circuit.S1(), 0.35e-6);
  EXPECT_DOUBLE_EQ(s.circuit.S2(), 20e-6);
  apply_overrides(s, {"circuit.S2_mm2=5"});
  EXPECT_DOUBLE_EQ(s.circuit.S2(), 5e-6);
}

TEST(Scenario, TomlRoundTripsEveryKey) {
  Scenario a = default_scenario();
  apply_overrides(a, {"friction.model=lugre", "load.coupling=spring", "circuit.S2_mm2=0.123456789",
                      "gas.polytropic_exponent=1.2"});
  Scenario b = default_scenario();
  apply_toml(b, scenario_to_toml(a), "roundtrip.toml");
  for (const auto& k : scenario_key_infos()) {
    EXPECT_EQ(setting_text(a, k.key), setting_text(b, k.key)) << k.key;
  }
}

TEST(Scenario, ErrorsNameFileLineAndKey) {
  Scenario s = default_scenario();
  EXPECT_EQ(error_of([&] { apply_toml(s, "[load]\nmass_kg = -1\n", "my.toml"); }),
            "my.toml:2:11: load.mass_kg: -1 kg is out of range: expected > 0");
  EXPECT_EQ(error_of([&] { apply_toml(s, "[friction]\nmodel = 3\n", "f.toml"); }),
            "f.toml:2:9: friction.model: expected one of classic | stribeck | lugre | gms, got the "
            "number 3");
  EXPECT_EQ(
      error_of([&] { apply_toml(s, "[cylinder]\nbore = 40\n", "c.toml"); }).rfind("c.toml:2:", 0),
      0u);
  EXPECT_NE(error_of([&] { apply_toml(s, "[cylinder]\nbore = 40\n", "c.toml"); })
                .find("cylinder.bore: unknown scenario key; keys of that section are: "
                      "cylinder.bore_mm"),
            std::string::npos);
  EXPECT_NE(error_of([&] { apply_toml(s, "flag = true\n", "b.toml"); }).find("b.toml:1:"),
            std::string::npos);
  EXPECT_NE(error_of([&] { apply_overrides(s, {"friction.Fs_N"}); }).find("expected key=value"),
            std::string::npos);
}

// A [sweep] table's entries are checked where they are written, and the same checks hold for
// a table built in code.
TEST(Scenario, SweepTableEntriesAreCheckedWhereWritten) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("pneumachaos_sweep_table_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << "[sweep]\nrepeats = 2\ngrid = [\"circuit.S2_mm2=0.1:0.3:0.1\", \"circuit.S1_mm2=2:1\"]\n";
  const std::string message = error_of([&] { (void)read_sweep_file_spec(file.string()); });
  std::filesystem::remove(file);
  EXPECT_NE(message.find(file.string() + ":3:"), std::string::npos) << message;
  EXPECT_NE(message.find("sweep.grid"), std::string::npos) << message;
  SweepFileSpec s;
  s.grid = {"circuit.S2_mm2=0.1:0.3:0.1"};
  s.repeats = 3;
  EXPECT_EQ(error_of([&] { s.validate(); }), "(no error)");
  s.repeats = 0;
  EXPECT_NE(error_of([&] { s.validate(); }).find("sweep.repeats = 0: must be >= 1"), std::string::npos);
  s.repeats.reset();
  s.grid.push_back("circuit.S1_mm2=2:1");
  EXPECT_NE(error_of([&] { s.validate(); }).find("sweep.grid"), std::string::npos);
}

TEST(Scenario, CrossKeyChecksNameTheKey) {
  EXPECT_NE(error_of([] {
              build_scenario("", {"friction.Fs_N=10", "friction.Fc_N=20"});
            }).find("friction.Fs_N"),
            std::string::npos);
  // The bore given too: the built-in rig's (45.5 mm) is a calibrated value, not the point here.
  EXPECT_NE(error_of([] {
              build_scenario("", {"cylinder.bore_mm=40", "cylinder.rod_mm=40"});
            }).find("cylinder.rod_mm"),
            std::string::npos);
}

TEST(Scenario, DefaultsPrintAsWrittenWithoutConversionNoise) {
  // Stored in SI, shown in the key's unit: 20 cm^3 must not print as 20.000000000000004.
  const Scenario d = default_scenario();
  for (const auto& k : scenario_key_infos()) {
    const std::string text = setting_text(d, k.key);
    EXPECT_EQ(text.find("0000000"), std::string::npos) << k.key << " = " << text;
    EXPECT_EQ(text.find("9999999"), std::string::npos) << k.key << " = " << text;
  }
  // As written in default_scenario() (the calibrated text times the key's unit), and the
  // simple rig's round 20 cm^3.
  EXPECT_EQ(setting_text(d, "cylinder.dead_volume_head_cm3"), "27.9582580267986");
  EXPECT_EQ(setting_text(simple_rig_scenario(), "cylinder.dead_volume_head_cm3"), "20");
}

}  // namespace
}  // namespace pneumachaos
