#pragma once
// The dysts validation (docs/notes/exponent_validation.md): each flow of tests/support/dysts_flows.hpp
// integrated here, its largest exponent from the equations by the two-trajectory method
// (Benettin et al. 1980), and the analysis's exponent and verdict on its first coordinate.
// Shared by tests/analysis/test_dysts.cpp and bench/bench_dysts.cpp.

#include <fmt/format.h>

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "dysts_flows.hpp"
#include "analysis/jacobian_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"

namespace pneumachaos::testing::dysts {

/// Samples per characteristic period: dysts's own default resampling is 100; 50 keeps 10^4
/// samples at 200 orbits while still resolving every flow here.
inline constexpr double kPointsPerPeriod = 50.0;

/// The first coordinate, sampled every period / points_per_period after `transient_periods`
/// (dysts's initial conditions already lie on the attractor; the transient only forgets them).
inline std::vector<double> record(const System& s, std::size_t n,
                                  double points_per_period = kPointsPerPeriod,
                                  double transient_periods = 20.0) {
  namespace odeint = boost::numeric::odeint;
  const Rhs f = vector_field(s);
  const double h = s.period / points_per_period;
  State x = s.initial;
  auto stepper = odeint::make_dense_output(1e-10, 1e-10, odeint::runge_kutta_dopri5<State>());
  const auto skip = static_cast<std::size_t>(std::lround(transient_periods * points_per_period));
  std::vector<double> out;
  out.reserve(n);
  std::size_t k = 0;
  odeint::integrate_const(stepper, f, x, 0.0, h * static_cast<double>(n + skip - 1), h,
                          [&](const State& st, double) {
                            if (k++ >= skip) out.push_back(st[0]);
                          });
  return out;
}

struct Benettin {
  double lambda = 0.0;  ///< 1 / time unit, over the whole run
  double spread = 0.0;  ///< |first half - second half| / 2: how far it has converged
};

/// Largest exponent from the equations: a second trajectory d0 away, renormalised every
/// period / 10 (Benettin, Galgani, Giorgilli & Strelcyn 1980, Meccanica 15), over `periods`
/// after the same 20-period transient as record(): with periods = the record's length it is
/// the exponent of the very stretch of trajectory the record samples.
inline Benettin benettin(const System& s, double periods = 2000.0) {
  namespace odeint = boost::numeric::odeint;
  const Rhs f = vector_field(s);
  const std::size_t n = s.initial.size();
  const auto pair = [&](const State& z, State& dz, double t) {
    State a(z.begin(), z.begin() + n), b(z.begin() + n, z.end()), da(n), db(n);
    f(a, da, t);
    f(b, db, t);
    dz.assign(da.begin(), da.end());
    dz.insert(dz.end(), db.begin(), db.end());
  };
  State z = s.initial;
  auto stepper = odeint::make_controlled(1e-12, 1e-12, odeint::runge_kutta_dopri5<State>());
  const double tau = s.period / 10.0;
  odeint::integrate_adaptive(stepper, f, z, 0.0, 20.0 * s.period, tau);  // onto the attractor
  // The separation: 1e-8 of the state's size, far above the integration error (1e-12).
  double norm2 = 0.0;
  for (double v : z) norm2 += v * v;
  const double d0 = 1e-8 * std::max(1.0, std::sqrt(norm2));
  z.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) z[n + i] = z[i] + d0 / std::sqrt(static_cast<double>(n));
  const auto steps = static_cast<std::size_t>(periods * 10.0);
  double sum = 0.0, first_half = 0.0;
  for (std::size_t k = 0; k < steps; ++k) {
    odeint::integrate_adaptive(stepper, pair, z, 0.0, tau, tau / 10.0);
    double d2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) d2 += (z[n + i] - z[i]) * (z[n + i] - z[i]);
    const double d = std::sqrt(d2);
    sum += std::log(d / d0);
    for (std::size_t i = 0; i < n; ++i) z[n + i] = z[i] + (z[n + i] - z[i]) * d0 / d;
    // dopri5 reuses its last derivative (first same as last): stale after the state moved.
    stepper.reset();
    if (k + 1 == steps / 2) first_half = sum;
  }
  const double half_time = tau * static_cast<double>(steps / 2);
  const double a = first_half / half_time, b = (sum - first_half) / (tau * steps - half_time);
  return {sum / (tau * static_cast<double>(steps)), 0.5 * std::abs(a - b)};
}

struct Row {
  std::string name;
  std::size_t samples = 0;
  double truth = 0.0;  ///< two trajectories over 2000 periods: the flow's exponent
  double span = 0.0;   ///< two trajectories over the record's own stretch (finite-time value)
  double truth_spread = 0.0;
  double period = 0.0;       ///< dysts's characteristic period
  double lambda_dysts = 0.0;
  bool found = false;
  double lambda = 0.0;             ///< 1 / time unit
  double low = 0.0, high = 0.0;    ///< the interval: +-1.96 u, or the local slopes' 10-90 %
  bool from_slopes = false;        ///< no linear region: the local-slope estimate
  Regime regime = Regime::kUndetermined;
  double orbits = 0.0;  ///< orbits in the record (maxima spacing)
  /// The local-Jacobian estimate (analyse(..., jacobian = true)): value, 95 % half-width
  /// (1.96 u), and whether its fits call it reliable.
  bool jacobian_found = false, jacobian_reliable = false;
  double jacobian = 0.0, jacobian_half = 0.0;
  /// The two combined (combined_exponent): value and 95 % half-width; where it is not
  /// defined, the divergence estimate's.
  bool combined_defined = false;
  double combined = 0.0, combined_half = 0.0;
  [[nodiscard]] double error() const { return found ? lambda / truth - 1.0 : -1.0; }
  [[nodiscard]] bool within10() const { return found && std::abs(error()) <= 0.10; }
  [[nodiscard]] bool covered() const {
    return found && low <= truth && truth <= high;
  }
};

/// The analysis of one record, as `analyze` runs it (39 surrogates).
inline Row analyse(const System& s, std::size_t n, const Benettin& long_run,
                   std::uint64_t seed = 1, bool jacobian = false) {
  const std::vector<double> x = record(s, n);
  const double rate = kPointsPerPeriod / s.period;
  AnalysisOptions o;
  o.surrogates.count = 39;
  o.seed = seed;
  o.wolf = false;
  o.embedding_spread = true;  // as `analyze` runs it
  o.jacobian = jacobian;
  const AnalysisResult r = analyze_series(x, rate, o);
  const Benettin span = benettin(s, static_cast<double>(n) / kPointsPerPeriod);
  Row row{s.name, n, long_run.lambda, span.lambda, long_run.spread, s.period,
          s.lambda_dysts};
  const DivergenceResult& d = r.divergence;
  row.found = d.found_linear_region || r.divergence_estimate;
  row.from_slopes = !d.found_linear_region && r.divergence_estimate;
  row.lambda = row.from_slopes ? d.local_slopes.median * rate : d.lambda_per_s;
  row.low = row.from_slopes ? d.local_slopes.low * rate : row.lambda - 1.96 * d.uncertainty_per_s;
  row.high = row.from_slopes ? d.local_slopes.high * rate : row.lambda + 1.96 * d.uncertainty_per_s;
  row.regime = r.verdict.regime;
  row.orbits = r.maxima_spacing_samples > 0 ? n / r.maxima_spacing_samples : 0.0;
  row.jacobian_found = r.jacobian_run;
  row.jacobian_reliable = r.jacobian_run && r.jacobian.reliable;
  row.jacobian = r.jacobian.lambda_per_s;
  row.jacobian_half = 1.96 * r.jacobian.uncertainty_per_s;
  const CombinedExponent c = combined_exponent(r);
  row.combined_defined = c.defined;
  row.combined = c.defined ? c.value_per_s : row.lambda;
  row.combined_half = c.defined ? 1.96 * c.uncertainty_per_s : 0.5 * (row.high - row.low);
  return row;
}

/// Which question a record answers (docs/notes/exponent_validation.md "Classes").
/// Chaotic: the flow's exponent (2000 periods) is clearly positive (>= 1 % per period, five
/// times its convergence spread) and the record's own stretch agrees with it within 30 %:
/// scored for the exponent and for "chaotic". Regular: the flow's exponent is below 1 % per
/// period and the record's own stretch separates two trajectories by fewer than 10 e-folds over
/// the whole record (a regular orbit's separation grows like a power of time): scored for
/// "never chaotic". Anything else (a chaotic transient that dies, a stretch far from the long
/// run): "unsettled", listed, not scored.
enum class Truth { kChaotic, kRegular, kUnsettled };

inline Truth truth_class(const Row& r) {
  const bool flow_chaotic = r.truth * r.period >= 0.01 && r.truth > 5.0 * r.truth_spread;
  if (flow_chaotic && std::abs(r.span / r.truth - 1.0) <= 0.3) return Truth::kChaotic;
  const double efolds = r.span * r.period * static_cast<double>(r.samples) / kPointsPerPeriod;
  if (r.truth * r.period < 0.01 && efolds < 10.0) return Truth::kRegular;
  return Truth::kUnsettled;
}

inline const char* truth_name(Truth t) {
  return t == Truth::kChaotic ? "chaotic" : t == Truth::kRegular ? "regular" : "unsettled";
}

inline std::string format_row(const Row& r) {
  return fmt::format("{:<20} {:>6} {:>9} {:>9.4f} {:>9.4f} {:>9.4f} {:>9} {:>8} {:>7} {:>5} {:>6.0f}  {}",
                     r.name, r.samples, truth_name(truth_class(r)), r.truth, r.span, r.lambda_dysts,
                     r.found ? fmt::format("{}{:.4f}", r.from_slopes ? "~" : "", r.lambda) : "-",
                     r.found ? fmt::format("{:.4f}", 0.5 * (r.high - r.low)) : "-",
                     r.found ? fmt::format("{:+.0f}%", 100.0 * r.error()) : "-",
                     r.covered() ? "yes" : "no", r.orbits, regime_name(r.regime));
}

inline std::string table_header() {
  return fmt::format("{:<20} {:>6} {:>9} {:>9} {:>9} {:>9} {:>9} {:>8} {:>7} {:>5} {:>6}  {}",
                     "system", "N", "class", "truth", "span", "dysts", "ours", "95%half", "error", "cov", "orbits",
                     "verdict");
}

}  // namespace pneumachaos::testing::dysts

namespace pneumachaos::testing::dysts {

struct Summary {
  std::size_t records = 0, found = 0, within10 = 0, covered = 0, chaotic = 0;
  [[nodiscard]] std::string text() const {
    return fmt::format("{} records: a value on {}, within 10 % on {}, the truth inside the 95 % "
                       "interval on {}, called chaotic {}",
                       records, found, within10, covered, chaotic);
  }
};

inline Summary summarise(const std::vector<Row>& rows) {
  Summary s;
  for (const Row& r : rows) {
    ++s.records;
    s.found += r.found ? 1 : 0;
    s.within10 += r.within10() ? 1 : 0;
    s.covered += r.covered() ? 1 : 0;
    s.chaotic += r.regime == Regime::kChaotic ? 1 : 0;
  }
  return s;
}

/// Both estimators against both references (docs/validation.md, "Two estimators"): within
/// 10 % of the long-run truth and of the record's own stretch, and the truth inside the 95 %
/// interval; `jacobian_*` counts only reliable local-Jacobian values as found.
struct EstimatorScores {
  std::size_t records = 0;
  std::size_t divergence_truth10 = 0, divergence_span10 = 0, divergence_covered = 0;
  std::size_t jacobian_found = 0, jacobian_truth10 = 0, jacobian_span10 = 0,
              jacobian_covered = 0;
  std::vector<double> jacobian_half_share;  ///< 95 % half-width / value, reliable values
  /// The combined value where defined, else the divergence's (records with a value).
  std::size_t combined_defined = 0, combined_truth10 = 0, combined_span10 = 0,
              combined_covered = 0;
  std::vector<double> divergence_half_share, combined_half_share, combined_error;
  static double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  }
  [[nodiscard]] std::string text() const {
    const double median = median_of(jacobian_half_share);
    return fmt::format("{} records; divergence: within 10 % of the truth {}, of the span {}, "
                       "truth covered {}, median 95 % half-width {:.0f} % of the value; local "
                       "Jacobians: reliable value {}, within 10 % of the truth {}, of the span "
                       "{}, truth covered {}, median 95 % half-width {:.0f} % of the value; "
                       "combined (defined on {}): within 10 % of the truth {}, of the span {}, "
                       "truth covered {}, median 95 % half-width {:.0f} % of the value, median "
                       "error {:.1f} %",
                       records, divergence_truth10, divergence_span10, divergence_covered,
                       100.0 * median_of(divergence_half_share), jacobian_found,
                       jacobian_truth10, jacobian_span10, jacobian_covered, 100.0 * median,
                       combined_defined, combined_truth10, combined_span10, combined_covered,
                       100.0 * median_of(combined_half_share), 100.0 * median_of(combined_error));
  }
};

inline EstimatorScores score_estimators(const std::vector<Row>& rows) {
  const auto near = [](double v, double ref) { return std::abs(v / ref - 1.0) <= 0.10; };
  EstimatorScores s;
  for (const Row& r : rows) {
    ++s.records;
    s.divergence_truth10 += r.within10() ? 1 : 0;
    s.divergence_span10 += r.found && near(r.lambda, r.span) ? 1 : 0;
    s.divergence_covered += r.covered() ? 1 : 0;
    if (r.found) {
      s.divergence_half_share.push_back(0.5 * (r.high - r.low) / std::abs(r.lambda));
      s.combined_defined += r.combined_defined ? 1 : 0;
      s.combined_truth10 += near(r.combined, r.truth) ? 1 : 0;
      s.combined_span10 += near(r.combined, r.span) ? 1 : 0;
      s.combined_covered += std::abs(r.combined - r.truth) <= r.combined_half ? 1 : 0;
      s.combined_half_share.push_back(r.combined_half / std::abs(r.combined));
      s.combined_error.push_back(std::abs(r.combined / r.truth - 1.0));
    }
    if (!r.jacobian_reliable) continue;
    ++s.jacobian_found;
    s.jacobian_truth10 += near(r.jacobian, r.truth) ? 1 : 0;
    s.jacobian_span10 += near(r.jacobian, r.span) ? 1 : 0;
    s.jacobian_covered += std::abs(r.jacobian - r.truth) <= r.jacobian_half ? 1 : 0;
    s.jacobian_half_share.push_back(r.jacobian_half / std::abs(r.jacobian));
  }
  return s;
}

}  // namespace pneumachaos::testing::dysts
