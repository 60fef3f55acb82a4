// The exponent and the verdict on the dysts database's flows (docs/notes/exponent_validation.md;
// data: tests/data/dysts/README.md), none of which the analysis was tuned on. The truth is the
// exponent from the equations by the two-trajectory method, computed here; dysts's own estimate
// is printed beside it (they disagree on several systems: the page lists them). Prints the
// table; asserts floors at the measured accuracy, so that a change that loses ground fails. The whole table
// takes a few minutes (label `long`); the two-flow check below runs by default.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdlib>

#include "support/dysts_runner.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing::dysts;

// What the analysis reaches on the 54 chaotic records at 10,000 samples (docs/notes/
// exponent_validation.md: 24 within 10 %, 47 covered, 51 called chaotic), a little below, as
// floors: a change may raise them, not lower them. A segment's window never lies on the
// divergence curve's saturated top (the page, "window on the rise"), so an interval cannot
// cover its truth through that top.
constexpr double kWithin10Floor = 0.42, kCoveredFloor = 0.87, kChaoticFloor = 0.93;

bool long_tests() { return std::getenv("PNEUMACHAOS_LONG_TESTS") != nullptr; }

// The two-trajectory method itself against published exponents (Sprott, Chaos and Time-Series
// Analysis, 2003, table A.1: Lorenz 0.9056, Rossler 0.0714), with dysts's parameters (its
// Lorenz has beta = 2.667 rather than 8/3, which moves the exponent by well under 1 %).
TEST(Dysts, TwoTrajectoryMethodMatchesPublishedExponents) {
  for (const System& s : load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    if (s.name == "Lorenz") EXPECT_NEAR(benettin(s).lambda, 0.9056, 0.02);
    if (s.name == "Rossler") EXPECT_NEAR(benettin(s).lambda, 0.0714, 0.003);
  }
}

// Classes of records (dysts_runner.hpp truth_class): the chaotic ones are scored for the exponent
// and the verdict, the regular ones (dysts's HenonHeiles and SprottA start on invariant tori,
// PanXuZhou settles to a fixed point) must never be called chaotic.
// A flow whose divergence curve rises all along without one straight stretch (BurkeShaw: its
// slope falls from 3.5 to 0 /time) is chaotic by the 0-1 test's support; a torus's curve also
// rises (HenonHeiles, from dysts's start on an invariant torus), and its record repeats itself.
TEST(Dysts, ARiseWithoutAStraightStretchIsChaoticButNotOnATorus) {
  for (const System& s : load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    if (s.name != "BurkeShaw" && s.name != "HenonHeiles") continue;
    const std::vector<double> x = record(s, 10000);
    AnalysisOptions o;
    o.surrogates.count = 39;
    const AnalysisResult r = analyze_series(x, kPointsPerPeriod / s.period, o);
    EXPECT_FALSE(r.divergence.found_linear_region) << s.name;
    EXPECT_TRUE(r.evidence.rises_throughout()) << s.name;
    const Regime expected = s.name == "BurkeShaw" ? Regime::kChaotic : Regime::kQuasiPeriodic;
    EXPECT_EQ(r.verdict.regime, expected) << s.name;
  }
}

TEST(Dysts, ExponentAndVerdictOnEveryFlow) {
  if (!long_tests()) GTEST_SKIP() << "long: run with PNEUMACHAOS_LONG_TESTS=1 (ctest -L long)";
  std::vector<Row> chaotic5, chaotic10;
  std::size_t regular = 0, regular_called_chaotic = 0;
  fmt::print("{}\n", table_header());
  for (const System& s : load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    const Benettin long_run = benettin(s);
    for (const std::size_t n : {5000u, 10000u}) {
      const Row r = analyse(s, n, long_run);
      fmt::print("{}\n", format_row(r));
      const Truth t = truth_class(r);
      if (t == Truth::kChaotic) (n == 5000 ? chaotic5 : chaotic10).push_back(r);
      if (t == Truth::kRegular) {
        ++regular;
        regular_called_chaotic += r.regime == Regime::kChaotic ? 1 : 0;
      }
    }
  }
  const Summary s5 = summarise(chaotic5), s10 = summarise(chaotic10);
  fmt::print("chaotic flows, 5,000 samples: {}\nchaotic flows, 10,000 samples: {}\n"
             "regular records: {}, called chaotic {}\n",
             s5.text(), s10.text(), regular, regular_called_chaotic);
  EXPECT_GT(regular, 0u);
  // The goal is none. At most two, both DequanLi's: its record catches a chaotic transient
  // of dysts's start (its two trajectories separate by e^5.8 over the whole record, as little
  // as a torus's do) and the divergence curve's first 100 samples read as a rise (the page).
  EXPECT_LE(regular_called_chaotic, 2u);
  // Floors below the goals of 90 % within 10 % and 90 % covered (not met: the page says why).
  const double n10 = static_cast<double>(s10.records);
  EXPECT_GE(s10.within10 / n10, kWithin10Floor);
  EXPECT_GE(s10.covered / n10, kCoveredFloor);
  EXPECT_GE(s10.chaotic / n10, kChaoticFloor);
}

}  // namespace
}  // namespace pneumachaos
