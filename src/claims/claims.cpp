// The claims about the maps (Figs. 4-6), the verdict count and the headline.
#include "pneumachaos/claims/claims.hpp"

#include <fmt/format.h>

#include <cmath>

namespace pneumachaos {
namespace {

const char* kFig4Location =
    "As Fig. 4 indicates, the rate is highest in the range of S1 > S2 and the neighborhood of "
    "the boundary between the stick-slip region and the non-stick-slip region.";
const char* kFig5First =
    "In comparison with Fig. 4, the stick-slip region indicated by the oblique lines decreases "
    "by about 20%, and the region in which the chaotic oscillation happens at a rate of 100% "
    "also contracts by more than half.";
const char* kFig5Second =
    "Contrary to this, increased supply pressure extends the stick-slip region and "
    "simultaneously reduces the chaotic oscillation region.";
const char* kFig6 =
    "A doubled load promotes stick-slip occurrence, and there are a few points where chaotic "
    "oscillation always happens, as seen in Fig. 6.";
const char* kWholeSystem =
    "Moreover, from Fig. 5 and (11), increased supply pressure improves damping capacity of the "
    "whole system.";

// "N chaotic runs of J judged (false positives alone: at most A)".
std::string beyond_false_positives(const SweepSummary& m) {
  const std::size_t judged = judged_runs(m);
  return fmt::format("{} chaotic runs of {} judged (false positives alone: at most {})",
                     chaotic_runs(m), judged, false_positive_allowance(judged));
}

std::string pct(std::size_t from, std::size_t to) {
  return from == 0 ? std::string("from none")
                   : fmt::format("{:+.0f} %", 100.0 * (static_cast<double>(to) -
                                                       static_cast<double>(from)) /
                                                  static_cast<double>(from));
}

Claim not_reproduced(Claim c, const char* why) {
  c.ours = "maps missing";
  judge(c, {kNaN, why});
  return c;
}

std::vector<Claim> location(const ClaimInputs& in) {
  Claim border{"fig4_border", kFig4Location, "Section 4.2, Fig. 4",
               "chaos is most frequent next to the stick-slip border",
               "the mean chaos incidence of the points within one grid step of the border (a "
               "4-neighbour of the other stick-slip class) is above that of the other points; "
               "evaluated when the map's chaos exceeds what false positives give",
               "fig4_map_ps025_m15"};
  Claim s1{"fig4_s1_above_s2", kFig4Location, "Section 4.2, Fig. 4",
           "chaos is more frequent where S1 > S2 than where S1 <= S2",
           "the mean chaos incidence where S1 > S2 is above that where S1 <= S2; evaluated "
           "when the map's chaos exceeds what false positives give",
           "fig4_map_ps025_m15"};
  Claim small{"figs4to6_small_areas",
              "In Figs. 4 ~ 6, chaotic oscillation occurs in the limited region in which S1 and "
              "S2 are relatively small.",
              "Section 4.2, Figs. 4-6",
              "on every map the chaos sits at the small end of both valve axes and covers a "
              "limited part of the map",
              "on each of Figs. 4-6 with chaos beyond false positives: the incidence-weighted "
              "mean S1 and mean S2 "
              "below the middle of their axis, and fewer than half of the points ever chaotic",
              "fig4_map_ps025_m15"};
  if (!in.base) return {not_reproduced(border, "no map"), not_reproduced(s1, "no map"),
                        not_reproduced(small, "no map")};
  const auto& pts = in.base->per_point;
  border.ours = beyond_false_positives(*in.base);
  s1.ours = border.ours;
  // Where the chaos lies means nothing when all of it could be false positives.
  const RuleResult within{kNaN, "the map's chaotic runs are within what the verdict's false "
                                "positives give: where they lie says nothing of the chaos"};
  const bool real = chaos_beyond_false_positives(*in.base);
  judge(border, real ? chaos_highest_near_border(pts, in.grid) : within);
  border.cells = stick_slip_border_points(pts, in.grid);
  judge(s1, real ? chaos_highest_where_s1_above_s2(pts, in.grid) : within);
  RuleResult r{kNaN, "no map has chaos beyond what the verdict's false positives give"};
  std::string ours;
  const std::pair<const char*, const std::optional<SweepSummary>*> maps[] = {
      {"Fig. 4", &in.base}, {"Fig. 5", &in.high_ps}, {"Fig. 6", &in.double_m}};
  for (const auto& [name, m] : maps) {
    if (!*m) continue;
    if (!chaos_beyond_false_positives(**m)) {
      ours += fmt::format("{}{}: chaos within false positives", ours.empty() ? "" : "; ", name);
      continue;
    }
    const RuleResult one = chaos_where_s1_and_s2_small((*m)->per_point, in.grid);
    if (!one.evaluated()) continue;
    r = r.evaluated() ? both(r, one) : one;
    ours += fmt::format("{}{}: margin {:.2f}", ours.empty() ? "" : "; ", name, one.margin);
  }
  small.ours = ours;
  judge(small, r);
  return {border, s1, small};
}

std::vector<Claim> supply_pressure(const ClaimInputs& in) {
  Claim ss{"fig5_stick_slip", std::string(kFig5First) + " / " + kFig5Second,
           "Section 4.2, Fig. 5",
           "the paper says both that the stick-slip region decreases by about 20 % and that it "
           "is extended",
           "not scored: the two sentences contradict each other; our change is shown",
           "fig5_map_ps030_m15"};
  Claim chaos{"fig5_chaos_reduced", std::string(kFig5First) + " / " + kFig5Second,
              "Section 4.2, Fig. 5",
              "what both sentences agree on: raising Ps from 0.25 to 0.30 MPa reduces the chaos",
              "the chaotic runs on the map fall by at least one, from a base map whose chaotic "
              "runs exceed what the verdict's false-positive rate gives (else not reproduced)",
              "fig5_map_ps030_m15"};
  Claim full{"fig5_full_chaos_halved", kFig5First, "Section 4.2, Fig. 5",
             "the region chaotic in every run keeps fewer than half of its points at 0.30 MPa",
             fmt::format("fewer than half of the base points, on a base region of at least {} "
                         "points (a halving of fewer is counting noise)",
                         min_region_for_change(0.5)),
             "fig5_map_ps030_m15"};
  Claim whole{"fig5_whole_system_damping", kWholeSystem, "Section 4.2, Fig. 5",
              "on the maps: fewer points oscillate at 0.30 MPa than at 0.25 MPa",
              "the points whose determined runs are mostly not steady (undetermined runs left "
              "out) lose at least one, counted on the maps' coarse lattice (every 4th grid "
              "line of each axis and the last: the points every map runs, adaptive or full)",
              "fig5_map_ps030_m15"};
  if (!in.base || !in.high_ps) {
    return {not_reproduced(ss, "maps missing"), not_reproduced(chaos, "maps missing"),
            not_reproduced(full, "maps missing"), not_reproduced(whole, "maps missing")};
  }
  const SweepSummary &b = *in.base, &h = *in.high_ps;
  ss.ours = fmt::format("stick-slip region {} -> {} points ({})", b.stick_slip_points,
                        h.stick_slip_points, pct(b.stick_slip_points, h.stick_slip_points));
  ss.verdict = kContradictory;
  ss.why = "the paper's own sentences disagree on the direction";
  chaos.ours = "0.25 MPa: " + beyond_false_positives(b) + "; 0.30 MPa: " +
               beyond_false_positives(h);
  judge(chaos, chaos_beyond_false_positives(b)
                   ? region_shrinks(chaotic_runs(b), chaotic_runs(h))
                   : RuleResult{kNaN, "the base map's chaos is within what false positives give"});
  full.ours = fmt::format("{} -> {} points chaotic in every run", b.chaos_full_points,
                          h.chaos_full_points);
  judge(full, region_more_than_halved(b.chaos_full_points, h.chaos_full_points));
  const std::size_t ob = oscillating_points(b), oh = oscillating_points(h);
  whole.ours = fmt::format("oscillating points {} -> {} of {} on the lattice ({})", ob, oh,
                           lattice_points(b), pct(ob, oh));
  judge(whole, region_shrinks(ob, oh));
  return {ss, chaos, full, whole};
}

std::vector<Claim> load(const ClaimInputs& in) {
  Claim grows{"fig6_stick_slip_grows", kFig6, "Section 4.2, Fig. 6",
              "doubling the total moving mass (1.5 -> 3.0 kg) enlarges the stick-slip region",
              "the stick-slip region (points stick-slip in at least half of their runs) gains "
              "at least one point",
              "fig6_map_ps025_m30"};
  Claim few{"fig6_few_always_chaotic", kFig6, "Section 4.2, Fig. 6",
            "at 3.0 kg a few points are chaotic in every run",
            "between 1 and max(3, 1.3 % of the points) points chaotic in all runs (10 of the "
            "paper's 780)",
            "fig6_map_ps025_m30"};
  Claim none{"fig6_triple_no_chaos", "A tripled load completely prevents chaotic behavior.",
             "Section 4.2",
             "at 4.5 kg total no run is chaotic, beyond what the verdict's own false positives "
             "give",
             fmt::format("chaotic runs at most the 95 % quantile of a binomial count at the "
                         "verdict's false-positive rate per judged run ({:.1f} %, measured on "
                         "the default rig against the model's exponent), over the map's judged "
                         "runs (verdict neither steady nor undetermined)",
                         100 * kVerdictFalsePositiveRate),
             "fig6b_map_ps025_m45"};
  if (in.base && in.double_m) {
    grows.ours = fmt::format("stick-slip {} -> {} points", in.base->stick_slip_points,
                             in.double_m->stick_slip_points);
    judge(grows, region_grows(in.base->stick_slip_points, in.double_m->stick_slip_points));
    few.ours = fmt::format("{} points chaotic in every run", in.double_m->chaos_full_points);
    judge(few, a_few_points(in.double_m->chaos_full_points, in.double_m->points));
    few.cells = points_where(
        *in.double_m, [](const PointSummary& p) { return chaos_class(p) == ChaosClass::kAll; });
  } else {
    grows = not_reproduced(grows, "maps missing");
    few = not_reproduced(few, "maps missing");
  }
  if (in.triple_m) {
    none.ours = beyond_false_positives(*in.triple_m) +
                fmt::format("; {} points chaotic at least once", in.triple_m->chaos_any_points);
    judge(none, no_chaos_beyond_false_positives(chaotic_runs(*in.triple_m),
                                                judged_runs(*in.triple_m)));
    none.cells = points_where(
        *in.triple_m, [](const PointSummary& p) { return chaos_class(p) != ChaosClass::kNone; });
  } else {
    none = not_reproduced(none, "map missing");
  }
  return {grows, few, none};
}

}  // namespace

void judge(Claim& c, const RuleResult& r) {
  c.margin = r.margin;
  if (!r.evaluated()) {
    c.verdict = kNotReproduced;
    c.why = r.why;
  } else {
    c.verdict = r.passes() ? kAgrees : kDisagrees;
    c.why = r.passes() ? std::string() : r.why;
  }
}

std::vector<Claim> map_claims(const ClaimInputs& in) {
  std::vector<Claim> out = location(in);
  for (auto* part : {&supply_pressure, &load})
    for (Claim& c : part(in)) out.push_back(std::move(c));
  return out;
}

std::vector<Claim> evaluate_claims(const ClaimInputs& in) {
  std::vector<Claim> out = map_claims(in);
  for (Claim& c : example_claims(in)) out.push_back(std::move(c));
  return out;
}

ClaimCount count_claims(const std::vector<Claim>& claims) {
  ClaimCount n;
  for (const Claim& c : claims) {
    const std::string& v = c.verdict;
    ++(v == kAgrees           ? n.agrees
       : v == kDisagrees      ? n.disagrees
       : v == kNotReproduced  ? n.not_reproduced
       : v == kIdentity       ? n.identity
                              : n.contradictory);
  }
  return n;
}

std::string claims_headline(const ClaimCount& c) {
  return fmt::format("{} of {} claims agree ({} disagree, {} not reproduced); {} not scored "
                     "({} identity, {} where the paper contradicts itself)",
                     c.agrees, c.scored(), c.disagrees, c.not_reproduced,
                     c.identity + c.contradictory, c.identity, c.contradictory);
}

}  // namespace pneumachaos
