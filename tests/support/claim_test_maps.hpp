#pragma once
// Maps and lookups for the claims' tests: the paper's 780-point grid with chaotic runs placed
// where a test wants them.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {

/// 780 points of five runs, every run given `regimes` (shares in sweep_regime_names() order);
/// `chaotic` runs fill the first points five at a time, counted in `incidence` (the verdict's
/// chaos_incidence or the paper's judge's paper_chaos_incidence).
inline SweepSummary spread_map(std::size_t chaotic, const std::vector<double>& regimes,
                               double PointSummary::*incidence) {
  SweepSummary s;
  s.points = 780;
  s.runs = 3900;
  for (std::size_t i = 0; i < 780; ++i) {
    PointSummary p;
    p.point = i;
    p.runs = 5;
    p.regime_incidence = regimes;
    const std::size_t here = std::min<std::size_t>(5, chaotic > 5 * i ? chaotic - 5 * i : 0);
    p.*incidence = static_cast<double>(here) / 5.0;
    s.per_point.push_back(p);
  }
  return s;
}

inline const Claim& row(const std::vector<Claim>& claims, const std::string& id) {
  for (const Claim& c : claims)
    if (c.id == id) return c;
  throw std::runtime_error("no row " + id);
}

}  // namespace pneumachaos
