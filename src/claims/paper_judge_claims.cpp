// The claims under the paper's own judge of chaos: the same rules fed the same runs, with the
// paper's three indices deciding which runs are chaotic instead of the regime verdict.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {
namespace {

// Every rule that counts chaotic runs or points, or reads the example's verdict.
constexpr std::array<std::string_view, 8> kChaosClaims = {"fig4_border",
                                                          "fig4_s1_above_s2",
                                                          "figs4to6_small_areas",
                                                          "fig5_chaos_reduced",
                                                          "fig5_full_chaos_halved",
                                                          "fig6_few_always_chaotic",
                                                          "fig6_triple_no_chaos",
                                                          "fig7_verdict"};

void judge_map(std::optional<SweepSummary>& map) {
  if (map) map = under_paper_judge(*map);
}

}  // namespace

bool reads_chaos_judge(const std::string& claim_id) {
  return std::find(kChaosClaims.begin(), kChaosClaims.end(), claim_id) != kChaosClaims.end();
}

ClaimInputs under_paper_judge(const ClaimInputs& in) {
  ClaimInputs out = in;
  for (auto* map : {&out.base, &out.high_ps, &out.double_m, &out.triple_m}) judge_map(*map);
  out.example_chaotic = in.example_paper_chaotic;
  // The row names the judgement where it names a regime.
  out.example_regime = in.example_paper_chaotic.value_or(false)
                           ? "chaotic by the paper's three indices"
                           : "not chaotic by the paper's three indices";
  return out;
}

std::string both_judges_headline(const ClaimCount& strict, const ClaimCount& paper) {
  return fmt::format(
      "{} of {} claims agree by the strict verdict; {} of {} by the paper's "
      "criterion",
      strict.agrees, strict.scored(), paper.agrees, paper.scored());
}

}  // namespace pneumachaos
