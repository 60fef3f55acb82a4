#include "pneumachaos/report/claims.hpp"

#include <fmt/format.h>

#include <cmath>

#include "pneumachaos/report/claim_rules.hpp"

namespace pneumachaos {
namespace {

const char* kAgrees = "agrees";
const char* kDisagrees = "disagrees";
const char* kNotReproduced = "not reproduced";

double change(std::size_t from, std::size_t to) {
  return from == 0 ? 0.0 : 100.0 * (static_cast<double>(to) - static_cast<double>(from)) / from;
}

// "chaotic oscillation occurs in the limited region in which S1 and S2 are relatively small
// ... in the vicinity of the border between the stick-slip and non-stick-slip regions".
// S1 > S2 holds on every point of the paper's grid (S1 >= 2.45 mm^2), so it is not tested.
Claim location(const ClaimInputs& in) {
  Claim c{"chaos in a limited region near the border of the stick-slip region", "Fig. 4", "", "",
          "agrees if >= 75 % of the chaos incidence lies within one S2 step of a change between "
          "stick-slip and non-stick-slip (same S1) and <= 25 % of the map's points are ever "
          "chaotic",
          "fig4_map_ps025_m15"};
  if (!in.base || in.spec.axes.size() < 2) {
    c.ours = "no map";
    c.verdict = kNotReproduced;
    return c;
  }
  const ChaosLocation loc = chaos_location(in.base->per_point, in.spec.axes[1].values.size());
  if (loc.total == 0.0) {
    c.ours = "no chaotic run on the map";
    c.verdict = kNotReproduced;
    return c;
  }
  c.ours = fmt::format("{:.0f} % of the incidence near the border; {:.0f} % of the points chaotic",
                       100 * loc.near_border, 100 * loc.map_share);
  c.verdict = chaos_near_border(loc) ? kAgrees : kDisagrees;
  return c;
}

}  // namespace

std::vector<Claim> evaluate_claims(const ClaimInputs& in) {
  std::vector<Claim> out;
  out.push_back(location(in));

  Claim ss{"Ps 0.25 -> 0.30 MPa shrinks the stick-slip region", "about -20 %", "", "",
           "agrees if the region shrinks by 10-30 %", "fig5_map_ps030_m15"};
  Claim full{"Ps 0.25 -> 0.30 MPa contracts the 100 %-chaos region", "by more than half", "", "",
             "agrees if it keeps less than half of its points", "fig5_map_ps030_m15"};
  if (in.base && in.high_ps) {
    const double d = change(in.base->stick_slip_points, in.high_ps->stick_slip_points);
    ss.ours = fmt::format("{} -> {} points ({:+.0f} %)", in.base->stick_slip_points,
                          in.high_ps->stick_slip_points, d);
    ss.verdict = d <= -10.0 && d >= -30.0 ? kAgrees : kDisagrees;
    full.ours =
        fmt::format("{} -> {} points", in.base->chaos_full_points, in.high_ps->chaos_full_points);
    full.verdict = in.base->chaos_full_points == 0                                  ? kNotReproduced
                   : 2 * in.high_ps->chaos_full_points < in.base->chaos_full_points ? kAgrees
                                                                                    : kDisagrees;
  } else {
    ss.ours = full.ours = "maps missing";
    ss.verdict = full.verdict = kNotReproduced;
  }
  out.push_back(ss);
  out.push_back(full);

  Claim dbl{"doubling the load promotes stick-slip and leaves a few always-chaotic points",
            "Fig. 6", "", "",
            "agrees if the stick-slip region grows and 1-10 points stay 100 % chaotic",
            "fig6_map_ps025_m30"};
  if (in.base && in.double_m) {
    dbl.ours =
        fmt::format("stick-slip {} -> {} points; 100 %-chaos {} points", in.base->stick_slip_points,
                    in.double_m->stick_slip_points, in.double_m->chaos_full_points);
    dbl.verdict = in.double_m->stick_slip_points > in.base->stick_slip_points &&
                          in.double_m->chaos_full_points >= 1 &&
                          in.double_m->chaos_full_points <= 10
                      ? kAgrees
                      : kDisagrees;
  } else {
    dbl.ours = "maps missing";
    dbl.verdict = kNotReproduced;
  }
  out.push_back(dbl);

  Claim tri{"tripling the load prevents chaos completely", "no chaotic point", "", "",
            "agrees if no run of the map is chaotic",
            "fig6b_map_ps025_m45"};
  if (in.triple_m) {
    tri.ours = fmt::format("{} points chaotic at least once, {} always",
                           in.triple_m->chaos_any_points, in.triple_m->chaos_full_points);
    tri.verdict = in.triple_m->chaos_any_points == 0 ? kAgrees : kDisagrees;
  } else {
    tri.ours = "map missing";
    tri.verdict = kNotReproduced;
  }
  out.push_back(tri);

  for (Claim& c : example_claims(in)) out.push_back(std::move(c));
  return out;
}

}  // namespace pneumachaos
