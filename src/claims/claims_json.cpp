// The claims table as JSON (the report's claims.json): what a reader or a calibration reads.
#include <cmath>
#include <nlohmann/json.hpp>

#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {

namespace {

using Json = nlohmann::ordered_json;

Json count_json(const ClaimCount& n) {
  return {{"agrees", n.agrees},   {"disagrees", n.disagrees}, {"not_reproduced", n.not_reproduced},
          {"scored", n.scored()}, {"identity", n.identity},   {"contradictory", n.contradictory}};
}

Json margin_json(double margin) { return std::isfinite(margin) ? Json(margin) : Json(nullptr); }

Json table_json(const std::vector<Claim>& claims) {
  const ClaimCount n = count_claims(claims);
  Json j;
  j["headline"] = claims_headline(n);
  j["count"] = count_json(n);
  j["margin_convention"] =
      "signed and dimensionless: >= 0 passes the rule, < 0 fails it; null: not evaluated";
  auto& rows = j["claims"] = Json::array();
  for (const Claim& c : claims) {
    rows.push_back({{"id", c.id},
                    {"paper", c.quote},
                    {"where", c.where},
                    {"reading", c.reading},
                    {"rule", c.rule},
                    {"ours", c.ours},
                    {"margin", margin_json(c.margin)},
                    {"verdict", c.verdict},
                    {"scored", c.scored()},
                    {"why", c.why},
                    {"figure", c.figure}});
  }
  return j;
}

}  // namespace

std::string claims_json(const std::vector<Claim>& claims) {
  return table_json(claims).dump(2) + "\n";
}

std::string claims_json(const std::vector<Claim>& claims, const std::vector<Claim>& paper) {
  Json j = table_json(claims);
  const ClaimCount n = count_claims(paper);
  Json& p = j["paper_judge"];
  p["headline"] = both_judges_headline(count_claims(claims), n);
  p["judge"] =
      "the paper's three indices decide which runs are chaotic (spectrum without a dominant "
      "line, autocorrelation converging to zero, Wolf's exponent positive); the rules are the "
      "same, read on the same runs";
  p["count"] = count_json(n);
  auto& rows = p["claims"] = Json::array();
  for (const Claim& c : paper) {
    if (!reads_chaos_judge(c.id)) continue;
    rows.push_back({{"id", c.id},
                    {"ours", c.ours},
                    {"margin", margin_json(c.margin)},
                    {"verdict", c.verdict},
                    {"why", c.why}});
  }
  return j.dump(2) + "\n";
}

}  // namespace pneumachaos
