#include "pneumachaos/report/claims.hpp"

#include <fmt/format.h>

#include <cmath>

namespace pneumachaos {
namespace {

const char* kAgrees = "agrees";
const char* kDisagrees = "disagrees";
const char* kNotReproduced = "not reproduced";

double change(std::size_t from, std::size_t to) {
  return from == 0 ? 0.0 : 100.0 * (static_cast<double>(to) - static_cast<double>(from)) / from;
}

// Chaos located where S1 > S2 and near the stick-slip region: chaos-weighted share of
// points with S1 > S2, and of points within two S2 steps of a stick-slip point at the same S1.
Claim location(const ClaimInputs& in) {
  Claim c{"chaos where S1 > S2, near the border of the stick-slip region", "Fig. 4", "", "",
          "agrees if >= 90 % of the chaos incidence lies at S1 > S2 and >= 75 % within two "
          "S2 steps of a stick-slip point of the same S1"};
  if (!in.base || in.spec.axes.size() < 2) {
    c.ours = "no map";
    c.verdict = kNotReproduced;
    return c;
  }
  const auto& pts = in.base->per_point;
  const std::size_t n2 = in.spec.axes[1].values.size();
  double total = 0.0, above = 0.0, near = 0.0;
  for (const auto& p : pts) {
    if (p.chaos_incidence <= 0.0) continue;
    total += p.chaos_incidence;
    if (p.coordinates[0] > p.coordinates[1]) above += p.chaos_incidence;
    const std::size_t j = p.point % n2;
    bool close = false;
    for (std::size_t k = (j >= 2 ? j - 2 : 0); k <= std::min(n2 - 1, j + 2); ++k) {
      if (pts[p.point - j + k].stick_slip_incidence >= 0.5) close = true;
    }
    if (close) near += p.chaos_incidence;
  }
  if (total == 0.0) {
    c.ours = "no chaotic run on the map";
    c.verdict = kNotReproduced;
    return c;
  }
  c.ours = fmt::format("{:.0f} % at S1 > S2, {:.0f} % within two S2 steps of stick-slip",
                       100 * above / total, 100 * near / total);
  c.verdict = above >= 0.9 * total && near >= 0.75 * total ? kAgrees : kDisagrees;
  return c;
}

}  // namespace

std::vector<Claim> evaluate_claims(const ClaimInputs& in) {
  std::vector<Claim> out;
  out.push_back(location(in));

  Claim ss{"Ps 0.25 -> 0.30 MPa shrinks the stick-slip region", "about -20 %", "", "",
           "agrees if the region shrinks by 10-30 %"};
  Claim full{"Ps 0.25 -> 0.30 MPa contracts the 100 %-chaos region", "by more than half", "", "",
             "agrees if it keeps less than half of its points"};
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
            "agrees if the stick-slip region grows and 1-10 points stay 100 % chaotic"};
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
            "agrees if no run of the map is chaotic"};
  if (in.triple_m) {
    tri.ours = fmt::format("{} points chaotic at least once, {} always",
                           in.triple_m->chaos_any_points, in.triple_m->chaos_full_points);
    tri.verdict = in.triple_m->chaos_any_points == 0 ? kAgrees : kDisagrees;
  } else {
    tri.ours = "map missing";
    tri.verdict = kNotReproduced;
  }
  out.push_back(tri);

  Claim ex{"the chaotic example (S1 2.70, S2 0.35 mm^2) has a positive maximum Lyapunov exponent",
           "3.41 (unit not stated)", "", "",
           "agrees if the record's exponent exceeds 3 times its uncertainty"};
  if (in.example_lambda && in.example_uncertainty) {
    ex.ours = fmt::format(
        "record: {:.2f} +- {:.2f} 1/s{}", *in.example_lambda, *in.example_uncertainty,
        in.example_model_lambda ? fmt::format("; model: {:.2f} 1/s", *in.example_model_lambda)
                                : std::string());
    ex.verdict = *in.example_lambda > 3.0 * *in.example_uncertainty ? kAgrees : kDisagrees;
  } else {
    ex.ours = "no rising divergence curve";
    ex.verdict = kNotReproduced;
  }
  out.push_back(ex);
  return out;
}

}  // namespace pneumachaos
