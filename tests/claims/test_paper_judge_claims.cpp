// The chaos claims under the paper's judge: the same rules, fed the same runs, with the
// paper's three indices deciding which runs are chaotic.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "support/claim_test_maps.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {
namespace {

// Every run judged stochastic by the verdict, which calls none chaotic; the paper's judge
// calls `paper_chaotic` of them chaotic.
SweepSummary noisy_map(std::size_t paper_chaotic) {
  SweepSummary s =
      spread_map(paper_chaotic, {0, 0, 0, 0, 0, 1, 0}, &PointSummary::paper_chaos_incidence);
  for (const PointSummary& p : s.per_point) {
    s.paper_chaos_full_points += p.paper_chaos_incidence >= 1.0 ? 1 : 0;
    s.paper_chaos_any_points += p.paper_chaos_incidence > 0.0 ? 1 : 0;
  }
  return s;
}

// White-noise-like records everywhere: the verdict says stochastic, the paper chaotic.
ClaimInputs noise_everywhere() {
  ClaimInputs in;
  in.base = noisy_map(1000);
  in.high_ps = noisy_map(900);
  in.double_m = noisy_map(1200);
  in.triple_m = noisy_map(800);
  in.example_chaotic = false;
  in.example_regime = "stochastic";
  in.example_paper_chaotic = true;
  return in;
}

TEST(PaperJudgeClaims, NoiseIsChaosByThePapersIndicesAndNotByTheVerdict) {
  const ClaimInputs in = noise_everywhere();
  const std::vector<Claim> strict = evaluate_claims(in);
  const std::vector<Claim> paper = evaluate_claims(under_paper_judge(in));
  // "A tripled load completely prevents chaotic behavior": no chaotic run by the verdict,
  // 800 of 3900 by the paper's indices, far beyond the false-positive allowance.
  EXPECT_EQ(row(strict, "fig6_triple_no_chaos").verdict, kAgrees);
  EXPECT_EQ(row(paper, "fig6_triple_no_chaos").verdict, kDisagrees);
  EXPECT_NE(row(paper, "fig6_triple_no_chaos").ours.find("800 chaotic runs"), std::string::npos);
  // Chaos to place exists only under the paper's judge; the reduction is measured there.
  EXPECT_EQ(row(strict, "fig5_chaos_reduced").verdict, kNotReproduced);
  EXPECT_EQ(row(paper, "fig5_chaos_reduced").verdict, kAgrees);  // 1000 -> 900 runs
  EXPECT_EQ(row(strict, "fig7_verdict").verdict, kDisagrees);
  EXPECT_EQ(row(paper, "fig7_verdict").verdict, kAgrees);
  EXPECT_NE(row(paper, "fig7_verdict").ours.find("paper's three indices"), std::string::npos);
  // A rule that does not read chaos gives the same row under both judges.
  ASSERT_EQ(strict.size(), paper.size());
  for (std::size_t i = 0; i < strict.size(); ++i) {
    if (reads_chaos_judge(strict[i].id)) continue;
    EXPECT_EQ(strict[i].verdict, paper[i].verdict) << strict[i].id;
    EXPECT_EQ(strict[i].ours, paper[i].ours) << strict[i].id;
  }
  const ClaimCount p = count_claims(paper), s = count_claims(strict);
  EXPECT_EQ(both_judges_headline(s, p),
            fmt::format("{} of {} claims agree by the strict verdict; {} of {} by the paper's "
                        "criterion",
                        s.agrees, s.scored(), p.agrees, p.scored()));
}

TEST(PaperJudgeClaims, AMapSweptWithoutThePapersJudgeCannotBeReadUnderIt) {
  ClaimInputs in = noise_everywhere();
  in.base->per_point[0].paper_chaos_incidence = kNaN;
  EXPECT_NO_THROW(under_paper_judge(in));  // one point without a successful run
  for (PointSummary& p : in.base->per_point) p.paper_chaos_incidence = kNaN;
  EXPECT_THROW(under_paper_judge(in), Error);
}

// claims.json keeps the strict table as it was and adds the paper's outcome of each chaos row.
TEST(PaperJudgeClaims, ClaimsJsonCarriesBothOutcomesAndTheStrictTableUnchanged) {
  const ClaimInputs in = noise_everywhere();
  const std::vector<Claim> strict = evaluate_claims(in);
  const std::vector<Claim> paper = evaluate_claims(under_paper_judge(in));
  const std::string alone = claims_json(strict), both = claims_json(strict, paper);
  EXPECT_EQ(both.substr(0, alone.rfind("\n}")), alone.substr(0, alone.rfind("\n}")));
  const auto j = nlohmann::json::parse(both);
  const auto& rows = j["paper_judge"]["claims"];
  ASSERT_EQ(rows.size(), 8u);
  for (const auto& r : rows) {
    EXPECT_TRUE(reads_chaos_judge(r["id"].get<std::string>()));
    EXPECT_EQ(r["verdict"], row(paper, r["id"].get<std::string>()).verdict);
  }
  EXPECT_EQ(j["paper_judge"]["count"]["agrees"], count_claims(paper).agrees);
  EXPECT_EQ(j["count"]["agrees"], count_claims(strict).agrees);
}

}  // namespace
}  // namespace pneumachaos
