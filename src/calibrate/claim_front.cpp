#include "claim_front.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A claim agrees where its margin is >= 0 (the rule of include/pneumachaos/claims/claims.hpp).
bool agrees(double margin) { return margin >= 0.0; }

bool judged_anything(const std::vector<double>& terms) {
  return std::any_of(terms.begin(), terms.end(), [](double t) { return !std::isnan(t); });
}

void count_reach(const JournalEntry& e, std::size_t k, std::vector<ClaimReach>& reach) {
  for (std::size_t i = 0; i < reach.size(); ++i) {
    const double m = e.terms[i];
    if (std::isnan(m)) continue;
    ClaimReach& r = reach[i];
    ++r.evaluated;
    if (agrees(m)) ++r.agreed;
    if (std::isnan(r.best_margin) || m > r.best_margin) {
      r.best_margin = m;
      r.best_evaluation = k;
    }
  }
}

std::vector<std::size_t> agreed_claims(const JournalEntry& e) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < e.terms.size(); ++i)
    if (agrees(e.terms[i])) out.push_back(i);
  return out;
}

// The sets no other set contains (sorted vectors), largest first, then the most visited.
std::vector<AgreedSet> maximal_sets(const std::map<std::vector<std::size_t>, AgreedSet>& sets) {
  std::vector<AgreedSet> front;
  for (const auto& entry : sets) {
    // Named, not a structured binding: clang before 16 cannot capture those in a lambda.
    const std::vector<std::size_t>& claims = entry.first;
    const bool contained = std::any_of(sets.begin(), sets.end(), [&](const auto& other) {
      return other.first.size() > claims.size() &&
             std::includes(other.first.begin(), other.first.end(), claims.begin(), claims.end());
    });
    if (!contained) front.push_back(entry.second);
  }
  std::stable_sort(front.begin(), front.end(), [](const AgreedSet& a, const AgreedSet& b) {
    if (a.claims.size() != b.claims.size()) return a.claims.size() > b.claims.size();
    return a.evaluations > b.evaluations;
  });
  return front;
}

double margin_correlation(const std::vector<JournalEntry>& entries, std::size_t a, std::size_t b) {
  std::vector<std::pair<double, double>> xy;
  for (const JournalEntry& e : entries)
    if (!std::isnan(e.terms[a]) && !std::isnan(e.terms[b])) xy.emplace_back(e.terms[a], e.terms[b]);
  if (xy.size() < 3) return kNaN;
  double mx = 0.0, my = 0.0;
  for (const auto& [x, y] : xy) mx += x, my += y;
  mx /= static_cast<double>(xy.size());
  my /= static_cast<double>(xy.size());
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (const auto& [x, y] : xy) {
    sxy += (x - mx) * (y - my);
    sxx += (x - mx) * (x - mx);
    syy += (y - my) * (y - my);
  }
  return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : kNaN;
}

std::vector<ClaimConflict> conflicts(const ClaimFront& f, const std::vector<JournalEntry>& entries,
                                     const std::vector<std::vector<bool>>& together) {
  std::vector<ClaimConflict> out;
  for (std::size_t a = 0; a < f.ids.size(); ++a)
    for (std::size_t b = a + 1; b < f.ids.size(); ++b)
      if (f.reach[a].agreed > 0 && f.reach[b].agreed > 0 && !together[a][b])
        out.push_back({a, b, margin_correlation(entries, a, b)});
  return out;
}

}  // namespace

ClaimFront claim_front(const std::vector<std::string>& ids,
                       const std::vector<JournalEntry>& entries) {
  ClaimFront f;
  f.ids = ids;
  for (const std::string& id : ids) f.reach.push_back({id, 0, 0, kNaN, 0});
  std::map<std::vector<std::size_t>, AgreedSet> sets;
  std::vector<std::vector<bool>> together(ids.size(), std::vector<bool>(ids.size(), false));
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const JournalEntry& e = entries[k];
    if (e.terms.size() != ids.size())
      throw Error("calibration front", fmt::format("evaluation {} has {} margins for {} claims",
                                                   k, e.terms.size(), ids.size()));
    if (!judged_anything(e.terms)) continue;
    ++f.accepted;
    count_reach(e, k, f.reach);
    const std::vector<std::size_t> agreed = agreed_claims(e);
    for (const std::size_t a : agreed)
      for (const std::size_t b : agreed) together[a][b] = true;
    AgreedSet& s = sets[agreed];
    if (s.evaluations == 0 || e.objective < entries[s.example].objective) s.example = k;
    s.claims = agreed;
    ++s.evaluations;
  }
  f.front = maximal_sets(sets);
  f.conflicts = conflicts(f, entries, together);
  return f;
}

std::string claim_front_md(const ClaimFront& f) {
  std::string out = fmt::format(
      "## What the evaluations say together\n\nOver the {} evaluations the model accepted.\n\n"
      "| claim | agreed at | judged at | best margin | at evaluation |\n|---|---|---|---|---|\n",
      f.accepted);
  for (const ClaimReach& r : f.reach)
    out += std::isnan(r.best_margin)
               ? fmt::format("| {} | 0 | 0 | - | - |\n", r.id)
               : fmt::format("| {} | {} | {} | {:.3f} | {} |\n", r.id, r.agreed, r.evaluated,
                             r.best_margin, r.best_evaluation);
  out += "\nThe front: the sets of claims agreed at one evaluation that no evaluation extends.\n\n"
         "| claims agreed together | how many | evaluations | best of them |\n|---|---|---|---|\n";
  for (const AgreedSet& s : f.front) {
    std::string names;
    for (const std::size_t i : s.claims) names += (names.empty() ? "" : ", ") + f.ids[i];
    out += fmt::format("| {} | {} | {} | {} |\n", names.empty() ? "(none)" : names,
                       s.claims.size(), s.evaluations, s.example);
  }
  out += "\nConflicts: claims each agreed somewhere, never at the same evaluation";
  if (f.conflicts.empty()) return out + ": none.\n";
  out += " (r: correlation of their margins).\n\n| claim | claim | r |\n|---|---|---|\n";
  for (const ClaimConflict& c : f.conflicts)
    out += fmt::format("| {} | {} | {} |\n", f.ids[c.a], f.ids[c.b],
                       std::isnan(c.correlation) ? std::string("-")
                                                 : fmt::format("{:+.2f}", c.correlation));
  return out;
}

}  // namespace pneumachaos::detail
