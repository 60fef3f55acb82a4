// A record with a clear deterministic signature whose divergence curve bends all the way gets a
// wide estimate from its local slopes rather than nothing (docs/notes/exponent_validation.md),
// and only such a record: noise gets none.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/dysts_runner.hpp"
#include "pneumachaos/analysis/analysis_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "support/reference_series.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

dysts::System dysts_system(const std::string& name) {
  for (const dysts::System& s : dysts::load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    if (s.name == name) return s;
  }
  throw std::runtime_error("no dysts system " + name);
}

// dysts's BurkeShaw at 10,000 samples: its curve's slope falls from ~3.5 to 0 /time with no
// three half-orbit segments agreeing, so no linear region; the flow's exponent (two
// trajectories from the equations, 2.33 /time over 2000 periods) lies inside the estimate.
TEST(DivergenceShape, CurvedCurveOfADeterministicRecordGetsAWideEstimate) {
  const dysts::System s = dysts_system("BurkeShaw");
  const double rate = dysts::kPointsPerPeriod / s.period;
  AnalysisOptions o;
  o.wolf = false;
  const AnalysisResult r = analyze_series(dysts::record(s, 10000), rate, o);
  ASSERT_FALSE(r.divergence.found_linear_region) << "the premise: no linear region";
  ASSERT_TRUE(r.divergence_estimate) << r.divergence_status;
  const double truth = dysts::benettin(s, 500.0).lambda;
  const SlopeSpread& ls = r.divergence.local_slopes;
  EXPECT_LE(ls.low * rate, truth);
  EXPECT_GE(ls.high * rate, truth);
  EXPECT_NEAR(ls.median * rate, truth, 0.25 * truth);
  EXPECT_NE(r.divergence_status.find("a wide estimate"), std::string::npos);
  const auto j = nlohmann::json::parse(analysis_json(r, "burke.csv", "x", "1"));
  const auto& est = j["lyapunov"]["divergence"]["without_linear_region"];
  ASSERT_TRUE(est.is_object()) << j["lyapunov"].dump();
  EXPECT_TRUE(j["lyapunov"]["divergence"]["value"].is_null());  // the fitted value stays null
  EXPECT_TRUE(j["lyapunov"]["divergence"]["uncertainty"].is_null());
  // No window of the record's: no fit, and a segment without a window of its own has no value
  // (it read 0, a number nothing measured); one with its own keeps its slope.
  EXPECT_TRUE(j["lyapunov"]["divergence"]["fit"].is_null());
  const auto& segments = j["lyapunov"]["divergence"]["segments"];
  std::size_t nulls = 0;
  for (const auto& v : segments["values"]) {
    if (v.is_null()) ++nulls;
    else EXPECT_GT(v.get<double>(), 0.0) << segments.dump();
  }
  EXPECT_EQ(nulls, segments["without_own_linear_region"].get<std::size_t>()) << segments.dump();
}

TEST(DivergenceShape, NoiseAndFittedRecordsGetNoShapeEstimate) {
  const AnalysisResult n = analyze_series(white_noise(10000), 1000.0);
  EXPECT_FALSE(n.divergence_estimate);
  const auto j = nlohmann::json::parse(analysis_json(n, "noise.csv", "x", "1"));
  EXPECT_TRUE(j["lyapunov"]["divergence"]["without_linear_region"].is_null());
  const AnalysisResult l = analyze_series(lorenz_x(10000), 100.0);
  ASSERT_TRUE(l.divergence.found_linear_region);
  EXPECT_FALSE(l.divergence_estimate);
}

}  // namespace
}  // namespace pneumachaos
