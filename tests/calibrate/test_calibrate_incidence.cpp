// calibrate's incidence_map objective end to end: a map measured on the model itself (a sweep
// at Fc = 19.7 N on the compliant-mount rig, scenarios/variants/compliant_mount.toml) is matched exactly at
// the generating point and missed elsewhere.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <fmt/format.h>

#include "calibrate/condition_runs.hpp"
#include "calibrate/evaluator.hpp"
#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "calibrate/measured_map.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"
#include "support/variant_scenarios.hpp"

namespace pneumachaos {
namespace {

// The "measurement": the model's own map over `grid` at `base`, as an incidence_map objective
// runs it, written as the measured-map CSV in dir/measured.csv (chaos by the verdict, or by the
// paper's three indices); returns the CSV's path.
std::string measured_map_of(const Scenario& base, double duration_s, std::size_t repeats,
                            const std::string& s1_axis, bool paper, const std::string& dir) {
  SweepSpec truth;
  truth.base = base;
  truth.base.run.duration_s = duration_s;
  truth.axes = {parse_grid_axis(s1_axis), parse_grid_axis("circuit.S2_mm2=0.05:0.65:0.3")};
  truth.repeats = repeats;
  truth.paper_judge = paper;
  SweepOptions so;
  so.out_dir = dir + "/truth";
  so.progress = false;
  const SweepSummary t = run_sweep(truth, so);
  std::string csv = "S1_mm2,S2_mm2,stick_slip,chaos\n";
  for (const PointSummary& p : t.per_point)
    csv += fmt::format("{},{},{},{}\n", p.coordinates[0], p.coordinates[1], p.stick_slip_incidence,
                       paper ? p.paper_chaos_incidence : p.chaos_incidence);
  const std::string measured = dir + "/measured.csv";
  std::ofstream(measured) << csv;
  return measured;
}

TEST(CalibrationIncidenceMap, TheModelsOwnMapIsMatchedAtItsPoint) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           fmt::format("pneumachaos_incidence_{}", ::getpid())).string();
  std::filesystem::remove_all(dir);
  const std::string fixed = "[fixed]\nvariation.friction_rel_sd = 0.03\nload.coupling = "
                            "\"spring\"\n" + kCompliantMountFixed;
  // The "measurement": the model's own map at the generating point (Fc at the free key's lower
  // end, 19.7 N), as the objective runs it.
  Scenario base = parse_calibration_spec(
      "[[free]]\nkey = \"friction.Fc_N\"\nlower = 19.7\nupper = 40\nsource = \"x\"\n" + fixed +
          "[objective]\nkind = \"claims\"\nexample = true\nclaims = { fig7_acf = 1 }\n",
      "x.toml").base;
  apply_setting(base, "friction.Fc_N", 19.7, "test");
  const std::string measured =
      measured_map_of(base, 2.0, 2, "circuit.S1_mm2=2.7:3.0:0.3", false, dir);
  const CalibrationSpec spec = parse_calibration_spec(
      "[[free]]\nkey = \"friction.Fc_N\"\nlower = 19.7\nupper = 40\nsource = \"x\"\n" + fixed +
          "[objective]\nkind = \"incidence_map\"\nfile = \"" + measured +
          "\"\nrepeats = 2\nduration_s = 2\n",
      "spec.toml");
  const detail::Evaluator ev(spec, {1, 1}, read_measured_map(measured));
  const detail::Evaluation at_truth = ev.evaluate({0.0}, dir + "/a");
  EXPECT_EQ(at_truth.objective, 0.0);
  EXPECT_EQ(at_truth.terms, (std::vector<double>{0.0, 0.0}));
  // Twice the Coulomb friction moves the map (more stick-slip): the check can fail.
  EXPECT_GT(ev.evaluate({1.0}, dir + "/b").objective, 0.05);
  std::filesystem::remove_all(dir);
}

// Under judge = "paper" the objective's maps are judged by the paper's three indices: a map
// "measured" as the paper's incidence is matched exactly at its point, and the evaluation's
// runs carry the paper's judgement.
TEST(CalibrationIncidenceMap, UnderThePapersJudgeTheChaosIsThePapersIncidence) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           fmt::format("pneumachaos_incidence_paper_{}", ::getpid())).string();
  std::filesystem::remove_all(dir);
  const std::string free = "[[free]]\nkey = \"friction.Fc_N\"\nlower = 19.7\nupper = 40\nsource = \"x\"\n"
                           "[fixed]\nload.coupling = \"spring\"\n" + kCompliantMountFixed;
  Scenario base = parse_calibration_spec(free + "[objective]\nkind = \"claims\"\nexample = true\n"
                                         "claims = { fig7_acf = 1 }\n", "x.toml").base;
  apply_setting(base, "friction.Fc_N", 19.7, "test");  // the free key's lower end
  const std::string measured =
      measured_map_of(base, 6.0, 1, "circuit.S1_mm2=2.7:2.7:0.3", true, dir);
  const CalibrationSpec spec = parse_calibration_spec(
      free + "[objective]\nkind = \"incidence_map\"\njudge = \"paper\"\nfile = \"" + measured +
          "\"\nrepeats = 1\nduration_s = 6\n",
      "spec.toml");
  const detail::Evaluator ev(spec, {1, 1}, read_measured_map(measured));
  EXPECT_EQ(ev.evaluate({0.0}, dir + "/a").terms, (std::vector<double>{0.0, 0.0}));
  std::ifstream runs(dir + "/a/map/runs.csv");
  std::string header, line;
  std::getline(runs, header);
  EXPECT_NE(header.find(",paper_chaotic"), std::string::npos) << header;
  std::size_t judged = 0;  // paper_chaotic, the last column, is 0 or 1 where judged
  while (std::getline(runs, line)) judged += !line.empty() && line.back() != ',';
  EXPECT_GT(judged, 0u);
  std::filesystem::remove_all(dir);
}

// Under judge = "paper" a claims objective reads the example by the paper's three indices
// too: its verdict is the paper's judgement, and the row names it.
TEST(CalibrationClaims, UnderThePapersJudgeTheExampleIsJudgedByItsIndices) {
  const CalibrationSpec spec = parse_calibration_spec(
      "[[free]]\nkey = \"friction.Fc_N\"\nlower = 19.7\nupper = 40\nsource = \"x\"\n"
      "[objective]\nkind = \"claims\"\nexample = true\nexample_record_s = 6\njudge = \"paper\"\n"
      "claims = { fig7_verdict = 1 }\n",
      "spec.toml");
  ClaimInputs strict, paper;
  detail::add_example(spec.objective, spec.base, strict);
  detail::run_conditions(spec.objective, spec.base, spec.objective.fit, "", {1, 1}, paper);
  ASSERT_TRUE(strict.example_paper_chaotic.has_value());
  EXPECT_EQ(paper.example_chaotic, strict.example_paper_chaotic);
  EXPECT_NE(paper.example_regime.find("the paper's three indices"), std::string::npos)
      << paper.example_regime;
  EXPECT_EQ(strict.example_regime.find("the paper's"), std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
