// The rules read from the maps (docs/report.md): chaos location, region changes, the "no
// chaos" tolerance and the sign rule, with misreadings of the paper shown failing.
#include <gtest/gtest.h>

#include "pneumachaos/claims/claim_rules.hpp"

namespace pneumachaos {
namespace {

// A map on a grid of n1 S1 values (2.45 ...) and n2 S2 values (0.05 ... by 0.15), stick-slip
// in the first `stick_rows` S2 rows, chaos where chaos(i, j) says.
struct TestMap {
  MapGrid grid;
  std::vector<PointSummary> pts;
};
template <class Chaos>
TestMap make_map(std::size_t n1, std::size_t n2, std::size_t stick_rows, Chaos chaos) {
  TestMap m;
  for (std::size_t i = 0; i < n1; ++i) m.grid.s1.push_back(2.45 + 0.05 * i);
  for (std::size_t j = 0; j < n2; ++j) m.grid.s2.push_back(0.05 + 0.15 * j);
  for (std::size_t i = 0; i < n1; ++i)
    for (std::size_t j = 0; j < n2; ++j) {
      PointSummary p;
      p.point = m.pts.size();
      p.runs = 5;
      p.stick_slip_incidence = j < stick_rows ? 1.0 : 0.0;
      p.chaos_incidence = chaos(i, j);
      m.pts.push_back(p);
    }
  return m;
}

TEST(MapRules, ChaosNextToTheBorderAgreesAndFarFromItFails) {
  // Stick-slip in rows 0-1; chaos in row 2 (next to the border).
  auto near = make_map(10, 30, 2, [](auto, auto j) { return j == 2 ? 0.6 : 0.0; });
  EXPECT_TRUE(chaos_highest_near_border(near.pts, near.grid).passes());
  auto far = make_map(10, 30, 2, [](auto, auto j) { return j == 8 ? 0.6 : 0.0; });
  EXPECT_FALSE(chaos_highest_near_border(far.pts, far.grid).passes());
}

// The cells the report marks for the border rule: rows 1 and 2 of every column (either side of
// a border between rows 1 and 2), no others; and the points a count rule counted.
TEST(MapRules, TheBorderPointsAreBothSidesOfTheBorder) {
  const auto m = make_map(3, 5, 2, [](auto i, auto j) { return i == 0 && j == 4 ? 1.0 : 0.0; });
  EXPECT_EQ(stick_slip_border_points(m.pts, m.grid),
            (std::vector<std::size_t>{1, 2, 6, 7, 11, 12}));
  SweepSummary s;
  s.per_point = m.pts;
  EXPECT_EQ(points_where(s, [](const PointSummary& p) { return p.chaos_incidence > 0; }),
            (std::vector<std::size_t>{4}));
  EXPECT_TRUE(stick_slip_border_points(m.pts, MapGrid{}).empty());  // no grid, no cells
}

// Misreading: a "near" that reaches two S2 rows from a border; two steps away is not the
// neighbourhood of one grid step.
TEST(MapRules, TwoStepsFromTheBorderIsNotNearIt) {
  auto two_away = make_map(10, 30, 2, [](auto, auto j) { return j == 3 ? 0.6 : 0.0; });
  const RuleResult r = chaos_highest_near_border(two_away.pts, two_away.grid);
  EXPECT_FALSE(r.passes());
  EXPECT_DOUBLE_EQ(r.margin, -1.0);  // none of the chaos within one step
}

// Misreading: "S1 > S2 holds on every point of the paper's grid" is false (S2 reaches 4.40,
// S1 3.70); "S1 relatively small" is a claim of its own, tested here too.
TEST(MapRules, S1AboveS2AndSmallAreasAreTested) {
  auto low = make_map(26, 30, 2, [](auto i, auto j) { return j == 2 && i < 8 ? 1.0 : 0.0; });
  EXPECT_TRUE(chaos_highest_where_s1_above_s2(low.pts, low.grid).passes());
  EXPECT_TRUE(chaos_where_s1_and_s2_small(low.pts, low.grid).passes());
  // Chaos high up the S2 axis, where S2 > S1: fails S1 > S2.
  auto high = make_map(26, 30, 2, [](auto, auto j) { return j >= 25 ? 1.0 : 0.0; });
  EXPECT_FALSE(chaos_highest_where_s1_above_s2(high.pts, high.grid).passes());
  // Chaos at small S2 but at the largest S1: S1 is not relatively small.
  auto big_s1 = make_map(26, 30, 2, [](auto i, auto j) { return j == 2 && i > 18 ? 1.0 : 0.0; });
  const RuleResult r = chaos_where_s1_and_s2_small(big_s1.pts, big_s1.grid);
  EXPECT_FALSE(r.passes());
  EXPECT_NE(r.why.find("lower half of S1"), std::string::npos);
  // Chaos over most of the map: not a limited region.
  auto wide = make_map(26, 30, 2, [](auto, auto) { return 0.2; });
  EXPECT_FALSE(chaos_where_s1_and_s2_small(wide.pts, wide.grid).passes());
  // A grid without a point where S1 <= S2 cannot test the comparison.
  auto small_grid = make_map(6, 7, 2, [](auto, auto j) { return j == 2 ? 1.0 : 0.0; });
  EXPECT_FALSE(chaos_highest_where_s1_above_s2(small_grid.pts, small_grid.grid).evaluated());
}

TEST(MapRules, RegionChanges) {
  EXPECT_TRUE(region_shrinks(32, 26).passes());
  EXPECT_FALSE(region_shrinks(32, 32).passes());
  EXPECT_TRUE(region_grows(32, 37).passes());
  EXPECT_FALSE(region_grows(32, 31).passes());
  EXPECT_EQ(min_region_for_change(0.5), 24u);
  EXPECT_EQ(min_region_for_change(0.2), 180u);
  EXPECT_TRUE(region_more_than_halved(40, 19).passes());
  EXPECT_FALSE(region_more_than_halved(40, 20).passes());  // exactly half is not more
}

// Misreading: scoring the 100 %-chaos contraction on base regions of 0-4 points of 780.
TEST(MapRules, AHalvingOfAFewPointsIsNotReproduced) {
  EXPECT_FALSE(region_more_than_halved(1, 0).evaluated());  // the misreading: "agrees"
  EXPECT_FALSE(region_more_than_halved(23, 2).evaluated());
  EXPECT_TRUE(region_more_than_halved(24, 2).evaluated());
}

TEST(MapRules, AFewPoints) {
  EXPECT_FALSE(a_few_points(0, 780).passes());
  EXPECT_TRUE(a_few_points(1, 780).passes());
  EXPECT_TRUE(a_few_points(10, 780).passes());
  EXPECT_FALSE(a_few_points(11, 780).passes());
  EXPECT_TRUE(a_few_points(3, 42).passes());
}

// Misreading: scoring "completely prevents" as zero chaotic runs of 3,900, stricter than the
// verdict's own false-positive rate (14 of 197 judged non-chaotic rig records) allows.
TEST(MapRules, NoChaosAllowsTheVerdictsFalsePositives) {
  const std::size_t allow = false_positive_allowance(3900);
  // Binomial(3900, 0.071): mean 277, sd 16; the 95 % quantile lies near mean + 1.645 sd.
  EXPECT_GT(allow, 295u);
  EXPECT_LT(allow, 312u);
  EXPECT_TRUE(no_chaos_beyond_false_positives(1, 3900).passes());  // the misreading: "disagrees"
  EXPECT_TRUE(no_chaos_beyond_false_positives(allow, 3900).passes());
  EXPECT_FALSE(no_chaos_beyond_false_positives(allow + 1, 3900).passes());
  EXPECT_FALSE(no_chaos_beyond_false_positives(900, 3900).passes());
}

PointSummary point_with(double steady, double undetermined) {
  PointSummary p;
  p.runs = 5;
  p.regime_incidence = {steady, 0, 0, 1 - steady - undetermined, 0, 0, undetermined};
  return p;
}

// Misreading: counting runs judged "undetermined" (short records) as not steady.
TEST(MapRules, SignRuleCountsUndecidedPointsApart) {
  SweepSummary s;
  s.per_point = {point_with(0.0, 1.0), point_with(0.8, 0.2), point_with(0.0, 0.0),
                 point_with(0.2, 0.6)};
  const SignRuleCounts c = count_sign_rule({true, true, false, false}, s);
  EXPECT_EQ(c.undecided, 2u);  // points 0 and 3: mostly undetermined
  EXPECT_EQ(c.damped, 1u);
  EXPECT_EQ(c.damped_steady, 1u);
  EXPECT_EQ(c.excited_moving, 1u);
  EXPECT_TRUE(sign_rule_holds(c).passes());
  EXPECT_FALSE(sign_rule_holds({10, 5, 10, 10, 0}).passes());
  // A class with no decided point leaves half of the rule untested.
  EXPECT_FALSE(sign_rule_holds({0, 0, 24, 24, 18}).evaluated());
  EXPECT_EQ(oscillating_points(s), 1u);
}

// An adaptive map infers a point's motion from a cell uniform in other classes: the motion
// counts read the coarse lattice only, which every map runs.
TEST(MapRules, MotionIsCountedOnTheLatticeOnly) {
  SweepSummary s;
  s.per_point = {point_with(0.0, 0.0), point_with(0.0, 0.0), point_with(1.0, 0.0)};
  s.per_point[1].on_lattice = false;
  EXPECT_EQ(oscillating_points(s), 1u);
  EXPECT_EQ(lattice_points(s), 2u);
  const SignRuleCounts c = count_sign_rule({false, false, true}, s);
  EXPECT_EQ(c.excited, 1u);  // point 1, off the lattice, is not counted
  EXPECT_EQ(c.damped, 1u);
  s.per_point[1].on_lattice = true;
  EXPECT_EQ(oscillating_points(s), 2u);
  EXPECT_EQ(count_sign_rule({false, false, true}, s).excited, 2u);
}

// Runs judged steady or undetermined cannot be false positives: the allowance counts the rest,
// and a map whose chaos stays within it has no chaos to locate.
TEST(MapRules, FalsePositivesCountOnlyJudgedRuns) {
  SweepSummary s;
  for (int i = 0; i < 100; ++i) s.per_point.push_back(point_with(0.2, 0.6));  // 1 of 5 judged
  EXPECT_EQ(judged_runs(s), 100u);
  s.per_point[0].chaos_incidence = 0.2;  // one chaotic run: within what false positives give
  EXPECT_FALSE(chaos_beyond_false_positives(s));
  for (int i = 0; i < 30; ++i) s.per_point[i].chaos_incidence = 0.2;  // 30 of 100 judged
  EXPECT_TRUE(chaos_beyond_false_positives(s));
  // A point an adaptive map inferred from its cell stands for as many runs as an evaluated one.
  PointSummary inferred = point_with(0.2, 0.6);
  inferred.runs = 0;
  inferred.inferred = true;
  inferred.chaos_incidence = 0.2;
  s.per_point.push_back(inferred);
  EXPECT_EQ(judged_runs(s), 101u);
  EXPECT_EQ(chaotic_runs(s), 31u);
}

}  // namespace
}  // namespace pneumachaos
