// The claims table as JSON (the report's claims.json): what a reader or a calibration reads.
#include <cmath>
#include <nlohmann/json.hpp>

#include "pneumachaos/report/claims.hpp"

namespace pneumachaos {

std::string claims_json(const std::vector<Claim>& claims) {
  const ClaimCount n = count_claims(claims);
  nlohmann::ordered_json j;
  j["headline"] = claims_headline(n);
  j["count"] = {{"agrees", n.agrees},
                {"disagrees", n.disagrees},
                {"not_reproduced", n.not_reproduced},
                {"scored", n.scored()},
                {"identity", n.identity},
                {"contradictory", n.contradictory}};
  j["margin_convention"] =
      "signed and dimensionless: >= 0 passes the rule, < 0 fails it; null: not evaluated";
  auto& rows = j["claims"] = nlohmann::ordered_json::array();
  for (const Claim& c : claims) {
    rows.push_back({{"id", c.id},
                    {"paper", c.quote},
                    {"where", c.where},
                    {"reading", c.reading},
                    {"rule", c.rule},
                    {"ours", c.ours},
                    {"margin", std::isfinite(c.margin) ? nlohmann::ordered_json(c.margin)
                                                       : nlohmann::ordered_json(nullptr)},
                    {"verdict", c.verdict},
                    {"scored", c.scored()},
                    {"why", c.why},
                    {"figure", c.figure}});
  }
  return j.dump(2) + "\n";
}

}  // namespace pneumachaos
