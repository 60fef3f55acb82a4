// The paper's judge beside the verdict in a sweep: each run judged by both, each point's two
// incidences, the map under the paper's judge.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/paper_judge.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"
#include "support/sweep_test_files.hpp"

namespace pneumachaos {
namespace {

// Two points of the default rig, 5 s records: long enough for the ACF's 1 s lag.
SweepSpec judged_spec(bool paper) {
  SweepSpec spec;
  spec.base = build_scenario("", {"run.duration_s=5"});
  spec.axes = {parse_grid_axis("circuit.S2_mm2=0.35:0.50:0.15")};
  spec.repeats = 1;
  spec.paper_judge = paper;
  return spec;
}

TEST(SweepPaperJudge, EachRunCarriesBothJudgementsOfTheSameRecord) {
  const SweepSpec spec = judged_spec(true);
  const auto [run, record] = replay_run(spec, 0, 0, "test");
  AnalysisOptions o;
  o.wolf = true;
  const PaperJudgement j = paper_judge(analyze_series(run.measured_v, run.sim.series.rate_Hz(), o));
  ASSERT_TRUE(j.evaluated) << j.why;
  ASSERT_TRUE(record.paper_chaotic.has_value());
  EXPECT_EQ(*record.paper_chaotic, j.chaotic);
  // The judge reads Wolf's exponent, so the record has it without --wolf.
  EXPECT_EQ(record.wolf, j.wolf_per_s);
  // The strict verdict is the same as without the paper's judge: judged twice, not changed.
  const RunRecord strict = run_one(judged_spec(false), 0, 0);
  EXPECT_FALSE(strict.paper_chaotic.has_value());
  EXPECT_TRUE(std::isnan(strict.wolf));
  EXPECT_EQ(strict.regime, record.regime);
  EXPECT_EQ(strict.chaotic, record.chaotic);
  EXPECT_EQ(strict.lambda, record.lambda);
  // Beside --wolf alone, the only difference is the added last column.
  SweepSpec wolf = judged_spec(false);
  wolf.wolf = true;
  const std::string with_wolf = run_one(wolf, 0, 0).encode(), both = record.encode();
  EXPECT_EQ(with_wolf, both.substr(0, both.rfind(',') + 1));
}

TEST(SweepPaperJudge, AFingerprintChangesOnlyWithTheJudge) {
  EXPECT_NE(judged_spec(true).fingerprint(), judged_spec(false).fingerprint());
  SweepSpec wolf = judged_spec(false);
  wolf.wolf = true;
  EXPECT_NE(judged_spec(true).fingerprint(), wolf.fingerprint());
}

RunRecord verdicts(std::size_t point, std::size_t repeat, bool chaotic, std::optional<bool> paper) {
  RunRecord r;
  r.point = point;
  r.repeat = repeat;
  r.chaotic = chaotic;
  r.regime = chaotic ? "chaotic" : "stochastic";
  r.paper_chaotic = paper;
  return r;
}

// White-noise-like runs: the verdict calls them stochastic, the paper's indices chaotic.
std::vector<RunRecord> noise_and_chaos() {
  std::vector<RunRecord> rs;
  for (std::size_t k = 0; k < 4; ++k) rs.push_back(verdicts(0, k, false, true));
  // Point 1: 2 of 4 chaotic by the verdict; the paper's judge: 1 chaotic, 1 not judged.
  rs.push_back(verdicts(1, 0, true, true));
  rs.push_back(verdicts(1, 1, true, false));
  rs.push_back(verdicts(1, 2, false, std::nullopt));
  rs.push_back(verdicts(1, 3, false, false));
  return rs;
}

TEST(SweepPaperJudge, APointHasTheIncidenceOfEachJudge) {
  SweepSpec spec = judged_spec(true);
  spec.repeats = 4;
  const SweepSummary s = summarize(spec, noise_and_chaos());
  EXPECT_DOUBLE_EQ(s.per_point[0].chaos_incidence, 0.0);
  EXPECT_DOUBLE_EQ(s.per_point[0].paper_chaos_incidence, 1.0);
  EXPECT_DOUBLE_EQ(s.per_point[1].chaos_incidence, 0.5);
  EXPECT_DOUBLE_EQ(s.per_point[1].paper_chaos_incidence, 0.25);  // not judged: not chaotic
  EXPECT_EQ(s.chaos_full_points, 0u);
  EXPECT_EQ(s.chaos_any_points, 1u);
  EXPECT_EQ(s.paper_chaos_full_points, 1u);
  EXPECT_EQ(s.paper_chaos_any_points, 2u);
  // The map under the paper's judge: its chaos, the same stick-slip and regimes.
  const SweepSummary p = under_paper_judge(s);
  EXPECT_DOUBLE_EQ(p.per_point[0].chaos_incidence, 1.0);
  EXPECT_DOUBLE_EQ(p.per_point[1].chaos_incidence, 0.25);
  EXPECT_EQ(p.chaos_full_points, 1u);
  EXPECT_EQ(p.chaos_any_points, 2u);
  EXPECT_EQ(p.per_point[0].regime_incidence, s.per_point[0].regime_incidence);
  // A sweep without the judge has no such incidence, and no map under it.
  const SweepSummary strict = summarize(judged_spec(false), noise_and_chaos());
  EXPECT_TRUE(std::isnan(strict.per_point[0].paper_chaos_incidence));
  EXPECT_EQ(strict.paper_chaos_any_points, 0u);
  EXPECT_THROW(under_paper_judge(strict), Error);
}

TEST(SweepPaperJudge, TheFilesCarryBothJudgements) {
  const std::string dir = temp_dir("paperjudge");
  SweepOptions o;
  o.progress = false;
  o.out_dir = dir;
  const SweepSummary s = run_sweep(judged_spec(true), o);
  const std::string runs = slurp(dir + "/runs.csv");
  EXPECT_NE(runs.find(",reason,paper_chaotic\n"), std::string::npos);
  const std::string points = slurp(dir + "/points.csv");
  EXPECT_NE(points.find(",inferred,paper_chaos_incidence\n"), std::string::npos);
  const std::string last = fmt::format(",0,{}\n", s.per_point.back().paper_chaos_incidence);
  EXPECT_EQ(points.substr(points.size() - last.size()), last);
  EXPECT_NE(slurp(dir + "/summary.json").find("\"paper_chaos_any_points\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pneumachaos
