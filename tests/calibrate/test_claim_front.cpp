// calibrate's account of its evaluations together (src/calibrate/claim_front.hpp): on
// journals made up so that the answer is known, the claims reached, the front (the sets of
// claims agreed at one point that no point extends) and the pairs reached only apart.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "calibrate/claim_front.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

JournalEntry entry(double objective, std::vector<double> margins) {
  return {{0.5}, objective, std::move(margins)};
}

const std::vector<std::string> kIds = {"a", "b", "c"};

// a and b trade against each other (never both >= 0; margins anti-correlated); c agrees with
// either; one point refused by the model (no margin at all) counts for nothing.
std::vector<JournalEntry> trading_journal() {
  return {entry(0.2, {0.5, -0.5, 0.1}),  entry(0.1, {0.8, -0.9, 0.2}),
          entry(0.3, {-0.4, 0.4, 0.3}),  entry(1.0, {kNaN, kNaN, kNaN}),
          entry(0.4, {-0.1, 0.05, -0.2}), entry(0.6, {-0.7, -0.2, -0.1})};
}

TEST(ClaimFront, ReachCountsOnlyAcceptedPointsAndFindsEachClaimsBest) {
  const ClaimFront f = claim_front(kIds, trading_journal());
  EXPECT_EQ(f.accepted, 5u);
  EXPECT_EQ(f.reach[0].agreed, 2u);
  EXPECT_EQ(f.reach[0].evaluated, 5u);
  EXPECT_DOUBLE_EQ(f.reach[0].best_margin, 0.8);
  EXPECT_EQ(f.reach[0].best_evaluation, 1u);
  EXPECT_EQ(f.reach[1].agreed, 2u);
  EXPECT_DOUBLE_EQ(f.reach[1].best_margin, 0.4);
  EXPECT_EQ(f.reach[2].agreed, 3u);
}

TEST(ClaimFront, TheFrontHoldsTheMaximalSetsAndTheirBestPoint) {
  const ClaimFront f = claim_front(kIds, trading_journal());
  // {a, c} (evaluations 0 and 1) and {b, c} (2) are maximal; {b} (4) and {} (5) are inside them.
  ASSERT_EQ(f.front.size(), 2u);
  EXPECT_EQ(f.front[0].claims, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(f.front[0].evaluations, 2u);
  EXPECT_EQ(f.front[0].example, 1u);  // the lower objective of the two
  EXPECT_EQ(f.front[1].claims, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(f.front[1].example, 2u);
}

TEST(ClaimFront, ClaimsReachedOnlyApartAreAConflictWithTheirCorrelation) {
  const ClaimFront f = claim_front(kIds, trading_journal());
  ASSERT_EQ(f.conflicts.size(), 1u);
  EXPECT_EQ(f.conflicts[0].a, 0u);
  EXPECT_EQ(f.conflicts[0].b, 1u);
  EXPECT_LT(f.conflicts[0].correlation, -0.5);
  // One point agreeing with a and b together removes the conflict: the check can fail.
  std::vector<JournalEntry> j = trading_journal();
  j.push_back(entry(0.0, {0.1, 0.1, -0.3}));
  EXPECT_TRUE(claim_front(kIds, j).conflicts.empty());
}

TEST(ClaimFront, NothingAgreedLeavesOneEmptySetAndNoConflict) {
  const ClaimFront f = claim_front(kIds, {entry(0.9, {-1.0, -2.0, kNaN})});
  ASSERT_EQ(f.front.size(), 1u);
  EXPECT_TRUE(f.front[0].claims.empty());
  EXPECT_TRUE(f.conflicts.empty());
  EXPECT_TRUE(std::isnan(f.reach[2].best_margin));
  EXPECT_NE(claim_front_md(f).find("| (none) | 0 | 1 | 0 |"), std::string::npos);
}

TEST(ClaimFront, AJournalOfAnotherWidthIsRefused) {
  EXPECT_THROW(claim_front(kIds, {entry(0.0, {0.1, 0.2})}), Error);
}

}  // namespace
}  // namespace pneumachaos::detail
