#include "sweep/map_agreement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

using Member = std::function<bool(const PointSummary&)>;

RegionAgreement region(const std::string& name, const Member& in, std::size_t n1,
                       const SweepSummary& full, const SweepSummary& adaptive) {
  RegionAgreement r;
  r.region = name;
  const auto& f = full.per_point;
  for (std::size_t p = 0; p < f.size(); ++p) {
    r.full_points += in(f[p]) ? 1 : 0;
    r.adaptive_points += in(adaptive.per_point[p]) ? 1 : 0;
    const bool last_in_row = (p + 1) % n1 == 0;
    if (!last_in_row && in(f[p]) != in(f[p + 1])) ++r.border_steps;
    if (p + n1 < f.size() && in(f[p]) != in(f[p + n1])) ++r.border_steps;
  }
  return r;
}

// The regime of most of a point's runs (the first of equals); -1 for a point never judged.
long dominant_regime(const PointSummary& p) {
  if (p.runs <= p.failed && !p.inferred) return -1;
  const auto& r = p.regime_incidence;
  return std::max_element(r.begin(), r.end()) - r.begin();
}

}  // namespace

std::size_t RegionAgreement::area_error() const {
  return full_points > adaptive_points ? full_points - adaptive_points
                                       : adaptive_points - full_points;
}

double MapAgreement::runs_ratio() const {
  return adaptive_runs == 0 ? 0.0 : static_cast<double>(full_runs) / adaptive_runs;
}

bool MapAgreement::areas_within_borders() const {
  for (const RegionAgreement& r : regions)
    if (r.area_error() > r.border_steps) return false;
  return true;
}

std::string MapAgreement::describe() const {
  std::string s = fmt::format(
      "{} points, {} inferred; stick-slip class agrees at {:.2f} %, chaos class at {:.2f} % "
      "(most frequent regime, not followed: {:.2f} %); {} of {} runs ({:.2f}x fewer)",
      points, inferred_points, 100.0 * stick_slip_agreement, 100.0 * chaos_agreement,
      100.0 * regime_agreement, adaptive_runs, full_runs, runs_ratio());
  for (const RegionAgreement& r : regions) {
    s += fmt::format("; {} area {} vs {} points (error {}, border {} steps)", r.region,
                     r.adaptive_points, r.full_points, r.area_error(), r.border_steps);
  }
  return s;
}

MapAgreement compare_maps(const SweepSpec& spec, const SweepSummary& full,
                          const SweepSummary& adaptive) {
  if (spec.axes.size() != 2 || full.per_point.size() != spec.points() ||
      adaptive.per_point.size() != spec.points()) {
    throw Error("compare maps", "two summaries of one two-axis sweep are needed");
  }
  MapAgreement m;
  m.points = spec.points();
  m.inferred_points = adaptive.inferred_points;
  m.full_runs = full.runs;
  m.adaptive_runs = adaptive.runs;
  std::size_t same_ss = 0, same_chaos = 0, same_regime = 0;
  for (std::size_t p = 0; p < m.points; ++p) {
    same_regime += dominant_regime(full.per_point[p]) == dominant_regime(adaptive.per_point[p]);
    same_ss +=
        in_stick_slip_region(full.per_point[p]) == in_stick_slip_region(adaptive.per_point[p]);
    same_chaos += chaos_class(full.per_point[p]) == chaos_class(adaptive.per_point[p]);
  }
  m.stick_slip_agreement = static_cast<double>(same_ss) / m.points;
  m.chaos_agreement = static_cast<double>(same_chaos) / m.points;
  m.regime_agreement = static_cast<double>(same_regime) / m.points;
  const std::size_t n1 = spec.axes[1].values.size();
  m.regions.push_back(region("stick-slip", in_stick_slip_region, n1, full, adaptive));
  m.regions.push_back(region(
      "chaos in every run",
      [](const PointSummary& p) { return chaos_class(p) == ChaosClass::kAll; }, n1, full,
      adaptive));
  m.regions.push_back(region(
      "chaos in some run",
      [](const PointSummary& p) { return chaos_class(p) != ChaosClass::kNone; }, n1, full,
      adaptive));
  return m;
}

AdaptiveValidation validate_adaptive(SweepSpec spec, const SweepOptions& options) {
  AdaptiveValidation v;
  const auto timed = [&](bool adaptive, double& wall_s) {
    spec.adaptive.enabled = adaptive;
    SweepOptions o = options;
    o.out_dir = options.out_dir + (adaptive ? "/adaptive" : "/full");
    const auto t0 = std::chrono::steady_clock::now();
    SweepSummary s = run_sweep(spec, o);
    wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
  };
  v.full = timed(false, v.full_wall_s);
  v.adaptive = timed(true, v.adaptive_wall_s);
  v.agreement = compare_maps(spec, v.full, v.adaptive);
  return v;
}

}  // namespace pneumachaos
