#include "claim_requirements.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

namespace pneumachaos::detail {
namespace {

constexpr const char* kExample = "example";
constexpr const char* kUnsupported = "unsupported";

// The inputs each claim reads (src/claims/claims.cpp and claims_example.cpp): its rule is
// not evaluated without them.
const std::map<std::string, std::vector<std::string>>& requirements() {
  static const std::map<std::string, std::vector<std::string>> table = {
      {"fig4_border", {"base"}},
      {"fig4_s1_above_s2", {"base"}},
      {"figs4to6_small_areas", {"base"}},
      {"fig5_stick_slip", {kUnsupported}},  // not scored: the paper contradicts itself
      {"fig5_chaos_reduced", {"base", "high_ps"}},
      {"fig5_full_chaos_halved", {"base", "high_ps"}},
      {"fig5_whole_system_damping", {"base", "high_ps"}},
      {"fig6_stick_slip_grows", {"base", "double_m"}},
      {"fig6_few_always_chaotic", {"base", "double_m"}},
      {"fig6_triple_no_chaos", {"triple_m"}},
      {"fig7_exponent", {kExample}},
      {"fig7_verdict", {kExample}},
      {"fig7_spectrum", {kExample}},
      {"fig7_acf", {kExample}},
      {"fig7_fold_stretch", {kExample}},
      {"sec34_negative_slope", {kExample}},
      {"sec4_loop", {kExample}},
  };
  return table;
}

}  // namespace

bool is_map_role(const std::string& role) {
  return role == "base" || role == "high_ps" || role == "double_m" || role == "triple_m";
}

std::string missing_for_claim(const std::string& id, const ConditionSet& c) {
  const auto it = requirements().find(id);
  if (it == requirements().end())
    return "its inputs (Fig. 2's transients, the stability map or the linearized trends) are "
           "not computed by calibrate; use reproduce for it";
  for (const std::string& need : it->second) {
    if (need == kUnsupported) return "the report does not score it (the paper's sentences contradict each other)";
    if (need == kExample) {
      if (!c.example) return "it needs example = true";
      continue;
    }
    const bool have = std::any_of(c.maps.begin(), c.maps.end(),
                                  [&](const MapCondition& m) { return m.role == need; });
    if (!have) return fmt::format("it needs a map with role = \"{}\"", need);
  }
  return "";
}

std::string grid_problem_for_claim(const std::string& id, const std::vector<GridAxis>& axes) {
  if (id != "fig4_s1_above_s2") return "";
  const auto axis = [&](const char* key) {
    const auto it = std::find_if(axes.begin(), axes.end(),
                                 [&](const GridAxis& a) { return a.key == key; });
    return it == axes.end() ? nullptr : &*it;
  };
  const GridAxis* s1 = axis("circuit.S1_mm2");
  const GridAxis* s2 = axis("circuit.S2_mm2");
  if (s1 == nullptr || s2 == nullptr || s1->values.empty() || s2->values.empty()) return "";
  const auto [s1_lo, s1_hi] = std::minmax_element(s1->values.begin(), s1->values.end());
  const auto [s2_lo, s2_hi] = std::minmax_element(s2->values.begin(), s2->values.end());
  if (*s2_hi < *s1_lo)
    return fmt::format("it compares S1 > S2 with S1 <= S2, and every point of the grid has S1 > "
                       "S2 (S2 up to {:g}, S1 from {:g} mm^2): extend circuit.S2_mm2 to S1's "
                       "values, or leave the claim out",
                       *s2_hi, *s1_lo);
  if (*s1_hi <= *s2_lo)
    return fmt::format("it compares S1 > S2 with S1 <= S2, and no point of the grid has S1 > S2 "
                       "(S1 up to {:g}, S2 from {:g} mm^2)",
                       *s1_hi, *s2_lo);
  return "";
}

std::string stable_hash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 1099511628211ULL;
  }
  return fmt::format("{:016x}", h);
}

}  // namespace pneumachaos::detail
