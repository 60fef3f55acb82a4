// The stick-slip flag through sensor noise on the rig itself (docs/notes/analysis.md "Noise
// floor"): the default rig at S2 = 0.2 mm^2 rests 5-19 samples at a time between slips that end
// in a ringing about zero. Judged on the running median, with every raw sample of a rest inside
// the raw band, its rests survive white noise from below to above the clean rest band.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {
namespace {

TEST(RigRestsInNoise, ShortRestsBetweenRingingSlipsKeepTheFlag) {
  const Scenario s = vary(build_scenario("", {"circuit.S2_mm2=0.2", "variation.friction_rel_sd=0.03",
                                              "variation.texture_rel=0.05", "run.duration_s=12"}),
                          run_seed(0, 0, 1));
  const SimulationResult sim = simulate(Plant(s), s.run);
  ASSERT_TRUE(sim.summary.ok());
  const std::vector<double>& all = sim.series.channel("v").values;
  ASSERT_GT(all.size(), 8000u);
  const std::vector<double> v(all.begin() + 2000, all.end());  // from 2 s, as the sweep judges
  AnalysisOptions o;
  o.wolf = false;
  o.verdict_seeds = 1;
  const double rate = sim.series.rate_Hz();
  ASSERT_TRUE(analyze_series(v, rate, o).verdict.stick_slip) << "the premise: stick-slip clean";
  // 0.3 mm/s is about a quarter of the clean rest band (1 % of max|v|, ~1.3 mm/s), 1 mm/s most
  // of it: both above the twelfth of the band where the noisy rule takes over.
  for (const double sd : {0.0003, 0.0005, 0.001}) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, sd);
    std::vector<double> x = v;
    for (double& value : x) value += noise(rng);
    const AnalysisResult r = analyze_series(x, rate, o);
    ASSERT_GT(r.evidence.rest_noise_sd, 0.0) << sd << ": the premise, the noisy rule applies";
    EXPECT_TRUE(r.verdict.stick_slip) << "noise sd " << sd << " m/s: " << r.evidence.rest_intervals
                                      << " rests, " << r.evidence.rest_share;
  }
}

}  // namespace
}  // namespace pneumachaos
