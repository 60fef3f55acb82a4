// The explorable report's data (src/report/report_data.cpp): the replay command of a map's
// run reaches the scenario its sweep ran, to the last bit of the load's mass.
#include <gtest/gtest.h>

#include "pneumachaos/model/scenario_keys.hpp"
#include "report/report_data.hpp"

namespace pneumachaos {
namespace {

TEST(ReportData, SetArgumentsNameEveryChangedKeyAndTheMassInFull) {
  const Scenario rig = default_scenario();
  Scenario map = rig;
  apply_setting(map, "supply.pressure_MPa", 0.30, "test");
  map.set_total_moving_mass(1.5);  // 1.5 - 1.05: not 0.45 to the last bit
  map.variation.texture_rel = 0.02;
  const std::string args = set_arguments(rig, map);
  EXPECT_NE(args.find("--set supply.pressure_MPa=0.3"), std::string::npos) << args;
  EXPECT_NE(args.find("--set variation.texture_rel=0.02"), std::string::npos) << args;
  EXPECT_NE(args.find("--set load.mass_kg=0.44999999999999996"), std::string::npos) << args;
  EXPECT_EQ(args.find("circuit."), std::string::npos) << args;  // unchanged keys stay out
  EXPECT_EQ(set_arguments(rig, rig), "");
}

TEST(ReportData, ReplayArgumentsNameTheGridRepeatsAndSeed) {
  MapData m;
  m.scenario_args = "--set run.duration_s=5";
  m.spec.axes = {parse_grid_axis("circuit.S1_mm2=2.45:3.70:0.25"),
                 parse_grid_axis("circuit.S2_mm2=0.05:0.95:0.15")};
  m.spec.repeats = 2;
  m.spec.seed = 7;
  EXPECT_EQ(replay_arguments(m),
            "--set run.duration_s=5 --grid circuit.S1_mm2=2.45:3.7:0.25 "
            "--grid circuit.S2_mm2=0.05:0.95:0.15 --repeats 2 --seed 7");
}

}  // namespace
}  // namespace pneumachaos
