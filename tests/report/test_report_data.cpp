// The explorable report's data (src/report/report_data.cpp): the replay command of a map's
// run reaches the scenario its sweep ran, to the last bit of the load's mass.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "pneumachaos/model/scenario_keys.hpp"
#include "report/report_data.hpp"
#include "support/variant_scenarios.hpp"

namespace pneumachaos {
namespace {

// On the compliant-mount rig, whose load is the total less its 1.05 kg piston + rod.
TEST(ReportData, SetArgumentsNameEveryChangedKeyAndTheMassInFull) {
  const Scenario rig = compliant_mount();
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
  // The report's maps are judged by both judges: the replay judges its run the same way, so
  // its runs.csv line has the same Wolf exponent and paper_chaotic.
  m.spec.paper_judge = true;
  EXPECT_NE(replay_arguments(m).find(" --judge paper "), std::string::npos);
}

// A map swept before the paper's judge has a runs.csv without its last column: the explorer
// reads it by its own header, as it reads the new one.
TEST(ReportData, ARunsCsvWrittenBeforeThePaperJudgeIsReadByItsHeader) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("pneumachaos_old_runs_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "sweeps" / "m");
  MapData m;
  m.sweep_dir = "sweeps/m";
  m.spec.axes = {parse_grid_axis("circuit.S1_mm2=2.45:2.45:0.25"),
                 parse_grid_axis("circuit.S2_mm2=0.05:0.05:0.15")};
  PointSummary p;
  p.coordinates = {2.45, 0.05};
  m.summary.per_point = {p};
  const std::string header = "circuit.S1_mm2,circuit.S2_mm2," + RunRecord::csv_header();
  const std::string old_header = header.substr(0, header.rfind(','));
  ASSERT_EQ(old_header.substr(old_header.size() - 7), ",reason");
  RunRecord r;
  r.paper_chaotic = true;
  const std::string line = "2.45,0.05," + r.encode();
  for (const auto& [head, row] : {std::pair{old_header, line.substr(0, line.rfind(','))},
                                  std::pair{header, line}}) {
    std::ofstream(dir / "sweeps" / "m" / "runs.csv") << head << "\n" << row << "\n";
    const std::string js = report_data_js({m}, {}, dir.string());
    EXPECT_NE(js.find("\"stick_slip\",\"zero_one_K\""), std::string::npos);
    EXPECT_EQ(js.find("\"paper_chaotic\"") != std::string::npos, head == header) << js;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pneumachaos
