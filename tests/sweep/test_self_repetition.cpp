// The self-repetition veto (docs/notes/analysis.md "Self-repetition veto"): a record that repeats
// itself at one lag over most of its length has no exponential divergence. Known answers: a
// modulated tone repeats at the common period of carrier and modulation; published chaotic systems
// never repeat; an imposed exponential growth of the mismatch is measured at its rate.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/self_repetition.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/reference_series.hpp"
#include "support/variant_scenarios.hpp"
#include "support/validation_corpus.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;
constexpr double kRate = 1000.0;  // 1 kHz, like the rig
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kCarrier = 6.0;  // Hz
const double kCarrierPeriod = kRate / kCarrier;

// A 6 Hz carrier with amplitude (AM) or phase (FM) modulation at f_mod, noiseless.
std::vector<double> modulated(std::size_t n, double f_mod, bool frequency) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / kRate;
    const double m = std::sin(kTwoPi * f_mod * t);
    x[i] = frequency ? std::sin(kTwoPi * kCarrier * t + 2.0 * m)
                     : (1.0 + 0.5 * m) * std::sin(kTwoPi * kCarrier * t);
  }
  return x;
}

TEST(SelfRepetition, ModulatedToneRepeatsAtTheCommonPeriod) {
  for (bool fm : {false, true}) {
    const SelfRepetition s = self_repetition(modulated(10000, 0.5, fm), kRate, kCarrierPeriod);
    ASSERT_TRUE(s.run) << s.reason;
    EXPECT_TRUE(s.repeats) << (fm ? "FM" : "AM");
    // 6 Hz and 0.5 Hz share the period 2 s; within half the record that is the only lag.
    EXPECT_NEAR(s.lag_s, 2.0, 1e-3) << (fm ? "FM" : "AM");
    EXPECT_LT(s.mismatch, 1e-6);
    EXPECT_NEAR(s.share, 0.8, 0.02);  // the overlap: 8 s of 10, in whole carrier periods
  }
}

// A torus: modulation at 6 / (10 x golden ratio) Hz, never an exact repeat. Its closest
// return within half the record, 16 carrier periods (2.667 s, 0.989 modulation periods),
// misses by ~0.01 of a modulation cycle: a mismatch of ~0.02, constant along the record, so
// the veto fires. That is right: a torus has no positive exponent either.
TEST(SelfRepetition, TorusWithACloseReturnIsVetoedToo) {
  const double f_mod = kCarrier / (10.0 * std::numbers::phi);
  const SelfRepetition s = self_repetition(modulated(10000, f_mod, false), kRate, kCarrierPeriod);
  ASSERT_TRUE(s.run) << s.reason;
  EXPECT_TRUE(s.repeats);
  EXPECT_NEAR(s.lag_s, 16.0 / kCarrier, 2e-3);
  EXPECT_GT(s.mismatch, 1e-3);
  EXPECT_LT(s.mismatch, 0.05);
  EXPECT_NEAR(s.growth_per_s, 0.0, 0.05);
}

TEST(SelfRepetition, PublishedChaosNeverRepeats) {
  for (const CorpusRecord& c : validation_corpus()) {
    if (c.name != "lorenz" && c.name != "rossler" && c.name != "mackey-glass") continue;
    for (std::size_t n : {5000, 10000}) {
      const AnalysisResult r = analyze_series(c.make(n), c.rate_Hz);
      const SelfRepetition& s = r.evidence.repetition;
      ASSERT_TRUE(s.run) << c.name << ": " << s.reason;
      EXPECT_FALSE(s.repeats) << c.name << " " << n;
      EXPECT_LT(s.share, 0.5) << c.name << " " << n;  // measured: at most 0.29 (Rossler)
      EXPECT_GT(s.mismatch, 0.1) << c.name << " " << n;
      EXPECT_TRUE(r.verdict.chaotic) << c.name << " " << n;
    }
  }
}

// The veto can fail to fire on a periodic record: noise of std 0.2 on a unit sine (std 0.71)
// alone gives a mismatch of 0.2 / sqrt(0.5 + 0.04) = 0.27, above 0.1: it does not "repeat".
TEST(SelfRepetition, NoisyPeriodicRecordIsNotCaught) {
  const std::vector<double> x = sine(10000, 10.0, kRate, 0.2);
  const SelfRepetition s = self_repetition(x, kRate, 100.0);
  ASSERT_TRUE(s.run);
  EXPECT_FALSE(s.repeats);
  EXPECT_NEAR(s.mismatch, 0.2 / std::sqrt(0.5 + 0.2 * 0.2), 0.01);
  EXPECT_TRUE(self_repetition(sine(10000, 10.0, kRate, 0.05), kRate, 100.0).repeats);
}

TEST(SelfRepetition, TooShortARecordIsNotRun) {
  // 600 samples are 3.6 carrier periods; a repeat 2 periods later over half the record
  // needs 4.
  const SelfRepetition s = self_repetition(modulated(600, 0.5, false), kRate, kCarrierPeriod);
  EXPECT_FALSE(s.run);
  EXPECT_NE(s.reason.find("not run"), std::string::npos) << s.reason;
  EXPECT_FALSE(self_repetition(modulated(600, 0.5, false), kRate, 0.0).run);
  RegimeEvidence e;
  e.samples = 5000;
  e.range = 1.0;
  e.last_half_std = 0.3;
  e.repetition = s;
  const Verdict v = decide_regime(e);
  bool said = false;
  for (const std::string& line : v.evidence) said |= line.find("self-repetition: not run") == 5;
  EXPECT_TRUE(said);
}

TEST(SelfRepetition, BadOptionsAreNamed) {
  AnalysisOptions o;
  o.verdict.repetition.min_share = 1.0;
  try {
    (void)analyze_series(modulated(2000, 0.5, false), kRate, o);
    FAIL() << "min_share = 1 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("min_share"), std::string::npos) << e.what();
  }
}

// A mismatch growing as e^(g t): a carrier plus a second tone whose amplitude grows at g.
TEST(SelfRepetition, MeasuresTheMismatchGrowthRate) {
  const double g = 1.0;  // 1/s: e^10 over the record, 1e-6 .. 0.02 of the size
  std::vector<double> x(10000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / kRate;
    x[i] = std::sin(kTwoPi * kCarrier * t) + 1e-6 * std::exp(g * t) * std::sin(kTwoPi * 8.3 * t);
  }
  const SelfRepetition s = self_repetition(x, kRate, kCarrierPeriod);
  ASSERT_TRUE(s.repeats);
  EXPECT_NEAR(s.growth_per_s, g, 0.1 * g);
}

// The verdict: with a claimed exponent, the veto fires only if the mismatch grows slower than
// the slowest exponent the divergence test supports.
TEST(SelfRepetition, VetoComparesTheGrowthWithTheClaimedExponent) {
  RegimeEvidence e;
  e.samples = 10000;
  e.range = 1.0;
  e.last_half_std = 0.3;
  e.lyapunov_found = true;
  e.lyapunov_per_s = 3.0;
  e.lyapunov_slope_uncertainty_per_s = 0.2;  // slowest supported: 3 - 3 x 0.2 = 2.4 1/s
  e.prediction_computed = true;
  e.prediction_nonlinear = 0.1;
  e.prediction_linear = 1.0;
  e.zero_one_run = true;
  e.zero_one_K = e.zero_one_q25 = e.zero_one_q75 = 0.9;
  e.repetition.run = true;
  EXPECT_TRUE(decide_regime(e).chaotic);  // no repeat: the evidence says chaos
  e.repetition.repeats = true;
  e.repetition.share = 0.8;
  e.repetition.growth_per_s = 0.1;
  const Verdict vetoed = decide_regime(e);
  EXPECT_FALSE(vetoed.chaotic);
  // Repeating over 80 % of the record with no exponential divergence left: periodic whatever
  // the 0-1 test's K (here high), not undetermined.
  EXPECT_EQ(vetoed.regime, Regime::kPeriodic);
  e.repetition.growth_per_s = 2.5;  // grows as fast as a chaotic near-return would
  EXPECT_TRUE(decide_regime(e).chaotic);
}

// A record the divergence alone would call chaotic on the frozen light-piston rig
// (scenarios/variants/frozen_light_piston.toml): 3.0 kg, S1 3.60, S2 0.35 mm^2, whose velocity
// envelope repeats; the model's own exponent is 0 within its error.
TEST(SelfRepetition, RigFalsePositiveIsNoLongerChaotic) {
  const Scenario s = frozen_light_piston(
      {"load.mass_kg=3.0", "circuit.S1_mm2=3.60", "circuit.S2_mm2=0.35"});
  ModelLyapunovOptions m;
  m.transient_s = 1.0;
  m.measure_s = 40.0;
  const ModelLyapunovResult model = plant_lyapunov(Plant(s), s.run, m);
  ASSERT_TRUE(model.ok) << model.message;
  // The premise: the model is not chaotic here.
  ASSERT_LT(model.lambda_per_s, 3.0 * model.uncertainty_per_s)
      << "this point is no longer a non-chaotic example";
  const SimulationResult sim = simulate(Plant(s), s.run);
  const AnalysisResult r = analyze_series(sim.series.channel("v").values, sim.series.rate_Hz());
  EXPECT_TRUE(r.evidence.repetition.repeats);
  EXPECT_FALSE(r.verdict.chaotic);
}

}  // namespace
}  // namespace pneumachaos
