// Model identification by segment-wise simulation (multiple shooting) and Ceres least squares;
// the method and its limits: docs/notes/model_fit.md.

#include "pneumachaos/identify/fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <optional>
#include <span>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/event_integrator.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos::identify {
namespace {

// The parameters Ceres sees: q = kOffset + ln(value / start). The offset keeps q near 10 so
// that Ceres's relative difference step (|q| * relative_step_size) is a constant step in
// ln(value): the same relative change of every parameter whatever its unit or size.
constexpr double kOffset = 10.0;

std::string key_unit(const std::string& key) {
  for (const KeyInfo& info : scenario_key_infos()) {
    if (info.key == key) return info.unit;
  }
  return {};
}

double key_value(const Scenario& scenario, const std::string& key) {
  return std::stod(setting_text(scenario, key));
}

// A least-squares straight line through samples [lo, hi] of y, evaluated at index k.
double local_line(const std::vector<double>& y, std::size_t k, std::size_t half) {
  const std::size_t lo = k >= half ? k - half : 0;
  const std::size_t hi = std::min(y.size() - 1, k + half);
  const double n = static_cast<double>(hi - lo + 1);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = lo; i <= hi; ++i) {
    const double u = static_cast<double>(i) - static_cast<double>(k);
    sx += u;
    sy += y[i];
    sxx += u * u;
    sxy += u * y[i];
  }
  const double det = n * sxx - sx * sx;
  if (n < 2 || det <= 0) return y[k];
  // Value of the line at u = 0.
  return (sy * sxx - sx * sxy) / det;
}

// What the segments need of the record, independent of the parameters.
struct Prepared {
  const MeasuredRecord* record = nullptr;
  double rate_Hz = 1000.0;
  std::vector<double> x_m;  // measured or integrated position
  struct Segment {
    std::size_t k0 = 0, n = 0;
    double x = 0, v = 0, P1 = 0, P2 = 0;  // smoothed starting values
  };
  std::vector<Segment> segments;
};

Prepared prepare(const MeasuredRecord& record, const FitOptions& o) {
  check_measured_record(record);
  o.validate();
  Prepared p;
  p.record = &record;
  const std::size_t N = record.size();
  const double dt = record.dt_s();
  p.rate_Hz = 1.0 / dt;
  if (record.x_m) {
    p.x_m = *record.x_m;
  } else {
    p.x_m.resize(N);
    p.x_m[0] = o.x0_m;
    for (std::size_t k = 1; k < N; ++k) {
      p.x_m[k] = p.x_m[k - 1] + 0.5 * dt * (record.v_m_per_s[k - 1] + record.v_m_per_s[k]);
    }
  }
  const auto L = std::max<std::size_t>(10, static_cast<std::size_t>(std::lround(o.segment_length_s / dt)));
  for (std::size_t k0 = 0; k0 < N - 1; k0 += L) {
    std::size_t n = std::min(L + 1, N - k0);  // segments share their boundary sample
    // A short tail joins the previous segment.
    if (N - k0 - n < L / 2 && N - k0 - n > 0) n = N - k0;
    Prepared::Segment s;
    s.k0 = k0;
    s.n = n;
    const std::size_t h = o.start_half_window;
    // Each segment starts from the local straight line through its neighbourhood (the
    // integrated position needs no smoothing).
    s.x = local_line(p.x_m, k0, record.x_m ? h : 0);
    s.v = local_line(record.v_m_per_s, k0, h);
    s.P1 = local_line(record.p1_Pa, k0, h);
    s.P2 = local_line(record.p2_Pa, k0, h);
    if (std::abs(s.v) < o.rest_speed_m_per_s) s.v = 0.0;
    p.segments.push_back(s);
    if (k0 + n >= N) break;
  }
  return p;
}

// Simulates segment `seg` of `prep` on `plant` from the pressures P1_0, P2_0; writes P1, P2,
// v, for its samples into the record-length arrays. False when the integration fails.
bool simulate_one(const Plant& plant, const Scenario& scenario, const Prepared& prep,
                  const Prepared::Segment& seg, double P1_0, double P2_0, const FitOptions& o,
                  double* P1, double* P2, double* v, std::string* why, std::size_t base = 0) {
  const StateLayout& L = plant.layout();
  const double stroke = plant.geometry().stroke_m;
  // Segments start after the valve switched, from the record's own motion.
  const double x0 = plant.geometry().volumes_frozen() ? seg.x : std::clamp(seg.x, 0.0, stroke * (1 - 1e-9));
  std::vector<double> state = plant.state_at({x0, seg.v, P1_0, P2_0});

  // The scenario's run settings (stepper, step bound, step budget) with the fit's tolerances,
  // as every simulation builds them (integrator_options).
  RunParams run = scenario.run;
  run.duration_s = static_cast<double>(seg.n - 1) / prep.rate_Hz;
  run.relative_tolerance = o.relative_tolerance;
  run.absolute_tolerance = o.absolute_tolerance;
  run.sample_rate_Hz = prep.rate_Hz;
  IntegratorOptions io = integrator_options(run);
  io.record_events = false;
  std::size_t count = 0;
  const auto observer = [&](double, std::span<const double> s, const Mode&) {
    if (count >= seg.n) return;
    const std::size_t k = seg.k0 - base + count++;
    P1[k] = s[L.P1];
    P2[k] = s[L.P2];
    v[k] = s[L.v];
  };
  Mode mode = plant.initial_mode(state, 0.0);
  const IntegrationSummary summary = integrate_hybrid(plant, state, mode, io, observer);
  if (!summary.ok()) {
    if (why) *why = fmt::format("segment at t = {:.3f} s: {}", prep.record->t_s[seg.k0], summary.message);
    return false;
  }
  // A run that ended early (end of stroke) holds its last state.
  for (; count < seg.n && count > 0; ++count) {
    const std::size_t k = seg.k0 - base + count;
    P1[k] = P1[k - 1];
    P2[k] = P2[k - 1];
    v[k] = v[k - 1];
  }
  return true;
}

// Simulates every segment of `prep` with `scenario`, from the smoothed measured pressures or,
// when given, from starts[2 i], starts[2 i + 1] (Pa) for segment i; writes P1, P2, v per
// sample (the boundary sample of two segments holds the later segment's start). False when
// the plant rejects the scenario or a segment's integration fails.
bool simulate_segments(const Prepared& prep, const Scenario& scenario, const FitOptions& o,
                       std::vector<double>& P1, std::vector<double>& P2, std::vector<double>& v,
                       std::string* why = nullptr, const std::vector<double>* starts = nullptr) {
  const std::size_t N = prep.record->size();
  P1.assign(N, 0.0);
  P2.assign(N, 0.0);
  v.assign(N, 0.0);
  std::optional<Plant> plant;
  try {
    plant.emplace(scenario);
  } catch (const Error& e) {
    if (why) *why = e.what();
    return false;
  }
  for (std::size_t i = 0; i < prep.segments.size(); ++i) {
    const auto& seg = prep.segments[i];
    const double P1_0 = starts ? (*starts)[2 * i] : seg.P1;
    const double P2_0 = starts ? (*starts)[2 * i + 1] : seg.P2;
    if (!simulate_one(*plant, scenario, prep, seg, P1_0, P2_0, o, P1.data(), P2.data(), v.data(), why)) {
      return false;
    }
  }
  return true;
}

struct FreeParam {
  std::string key, unit;
  double start = 0;
};

Scenario with_values(const Scenario& start, const std::vector<FreeParam>& free,
                     const double* q) {
  Scenario s = start;
  for (std::size_t j = 0; j < free.size(); ++j) {
    apply_setting(s, free[j].key, free[j].start * std::exp(q[j] - kOffset), "fit");
  }
  return s;
}

class SegmentCost {
 public:
  SegmentCost(const Prepared& prep, const Scenario& start, std::vector<FreeParam> free,
              const FitOptions& o)
      : prep_(prep), start_(start), free_(std::move(free)), o_(o) {}

  bool operator()(double const* const* q, double* residuals) const {
    Scenario s;
    try {
      s = with_values(start_, free_, q[0]);
    } catch (const Error&) {
      return false;  // outside a key's range: Ceres shrinks the step
    }
    if (!simulate_segments(prep_, s, o_, P1_, P2_, v_)) return false;
    const MeasuredRecord& r = *prep_.record;
    const std::size_t N = r.size();
    for (std::size_t k = 0; k < N; ++k) {
      residuals[3 * k] = (P1_[k] - r.p1_Pa[k]) / o_.pressure_scale_Pa;
      residuals[3 * k + 1] = (P2_[k] - r.p2_Pa[k]) / o_.pressure_scale_Pa;
      residuals[3 * k + 2] = (v_[k] - r.v_m_per_s[k]) / o_.velocity_scale_m_per_s;
    }
    return true;
  }

 private:
  const Prepared& prep_;
  const Scenario& start_;
  std::vector<FreeParam> free_;
  const FitOptions& o_;
  mutable std::vector<double> P1_, P2_, v_;
};

// Multiple shooting proper: one residual block per segment, with the segment's starting
// pressures as parameters of their own, p = kOffset + (P_0 - P_smoothed) / pressure scale.
// The block's residuals are the samples the segment owns: its first up to the next segment's
// first (the last segment: to the end).
class SegmentBlockCost {
 public:
  SegmentBlockCost(const Prepared& prep, std::size_t i, const Scenario& start,
                   const std::vector<FreeParam>& free, const FitOptions& o)
      : prep_(prep), i_(i), start_(start), free_(free), o_(o) {
    const auto& seg = prep.segments[i];
    owned_ = i + 1 == prep.segments.size() ? seg.n : seg.n - 1;
    P1_.resize(seg.n);
    P2_.resize(seg.n);
    v_.resize(seg.n);
  }
  [[nodiscard]] std::size_t owned() const { return owned_; }

  bool operator()(double const* const* p, double* residuals) const {
    std::optional<Plant> plant;
    Scenario s;
    try {
      s = with_values(start_, free_, p[0]);
      plant.emplace(s);
    } catch (const Error&) {
      return false;  // outside a key's range or rejected by the plant: a shorter step
    }
    const auto& seg = prep_.segments[i_];
    const double P1_0 = seg.P1 + (p[1][0] - kOffset) * o_.pressure_scale_Pa;
    const double P2_0 = seg.P2 + (p[1][1] - kOffset) * o_.pressure_scale_Pa;
    if (!simulate_one(*plant, s, prep_, seg, P1_0, P2_0, o_, P1_.data(), P2_.data(), v_.data(),
                      nullptr, seg.k0)) {
      return false;
    }
    const MeasuredRecord& r = *prep_.record;
    for (std::size_t j = 0; j < owned_; ++j) {
      const std::size_t k = seg.k0 + j;
      residuals[3 * j] = (P1_[j] - r.p1_Pa[k]) / o_.pressure_scale_Pa;
      residuals[3 * j + 1] = (P2_[j] - r.p2_Pa[k]) / o_.pressure_scale_Pa;
      residuals[3 * j + 2] = (v_[j] - r.v_m_per_s[k]) / o_.velocity_scale_m_per_s;
    }
    return true;
  }

 private:
  const Prepared& prep_;
  std::size_t i_;
  const Scenario& start_;
  const std::vector<FreeParam>& free_;
  const FitOptions& o_;
  std::size_t owned_ = 0;
  mutable std::vector<double> P1_, P2_, v_;
};

class Progress : public ceres::IterationCallback {
 public:
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    std::fprintf(stderr, "fit: iteration %d cost %.6g step %s\n", s.iteration, s.cost,
                 s.step_is_successful ? "accepted" : "rejected");
    return ceres::SOLVER_CONTINUE;
  }
};

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return a.empty() ? 0.0 : std::sqrt(s / static_cast<double>(a.size()));
}

ValidationSeries validation_of(const Prepared& prep, const Scenario& scenario,
                               const FitOptions& o,
                               const std::vector<double>* starts = nullptr) {
  ValidationSeries vs;
  std::string why;
  if (!simulate_segments(prep, scenario, o, vs.p1_sim, vs.p2_sim, vs.v_sim, &why, starts)) {
    throw RunError("fit", "the segment simulation failed: " + why);
  }
  const MeasuredRecord& r = *prep.record;
  vs.t_s = r.t_s;
  vs.v_meas = r.v_m_per_s;
  vs.p1_meas = r.p1_Pa;
  vs.p2_meas = r.p2_Pa;
  for (const auto& s : prep.segments) vs.segment_starts.push_back(s.k0);
  return vs;
}

}  // namespace

std::vector<std::string> default_free_keys(const Scenario& /*start*/) {
  // The valve areas set the pressure rates, Fc the sliding force balance and Fs the
  // breakaways; all four shape P1, P2 and v. vs, B, sigma0/1 are weakly seen (docs/notes/model_fit.md).
  return {"circuit.S1_mm2", "circuit.S2_mm2", "friction.Fc_N", "friction.Fs_N"};
}

void check_free_keys(const Scenario& start, const std::vector<std::string>& free_keys) {
  if (free_keys.empty()) throw Error(kFreeKeysField, "no free parameter to fit");
  std::set<std::string> seen;
  const auto infos = scenario_key_infos();
  for (const std::string& key : free_keys) {
    const auto it = std::find_if(infos.begin(), infos.end(),
                                 [&](const KeyInfo& i) { return i.key == key; });
    if (it == infos.end()) {
      throw Error(kFreeKeysField, fmt::format("unknown scenario key '{}' (see `pneumachaos scenario --keys`)", key));
    }
    if (!it->choices.empty()) {
      throw Error(kFreeKeysField, fmt::format("'{}' is a word ({}), not a number that can be fitted",
                                        key, it->choices));
    }
    if (!seen.insert(key).second) throw Error(kFreeKeysField, fmt::format("'{}' named twice", key));
    double value = 0;
    try {
      value = key_value(start, key);
    } catch (const std::exception&) {
      throw Error(kFreeKeysField, fmt::format("'{}' has no numeric value to start from", key));
    }
    if (!(value > 0) || !std::isfinite(value)) {
      throw Error(kFreeKeysField, fmt::format(
          "'{}' starts at {}: a fitted parameter must start from a positive value (it is "
          "fitted in log form); set a start with --set {}=...", key, value, key));
    }
  }
}

ValidationSeries segment_simulation(const MeasuredRecord& record, const Scenario& scenario,
                                    const FitOptions& options) {
  const Prepared prep = prepare(record, options);
  return validation_of(prep, scenario, options);
}

namespace {

// One Ceres fit of the free parameters q (in place) with the segments of `prep`.
struct StageOutcome {
  ceres::Solver::Summary summary;
  std::vector<double> covariance;  // of q, when asked for and computed
};

StageOutcome solve_stage(const Prepared& prep, const Scenario& start,
                         const std::vector<FreeParam>& free, const FitOptions& options,
                         std::vector<double>& q, bool with_covariance,
                         std::vector<double>* starts = nullptr) {
  const int np = static_cast<int>(free.size());
  const int nr = static_cast<int>(3 * prep.record->size());
  ceres::NumericDiffOptions nd;
  nd.relative_step_size = options.difference_step / kOffset;
  ceres::Problem problem;
  // The segments' starting pressures (multiple shooting), one block of two per segment.
  std::vector<std::array<double, 2>> state(prep.segments.size(), {kOffset, kOffset});
  if (options.fit_start_pressures) {
    for (std::size_t i = 0; i < prep.segments.size(); ++i) {
      auto* functor = new SegmentBlockCost(prep, i, start, free, options);
      const auto owned = static_cast<int>(functor->owned());
      auto* cost = new ceres::DynamicNumericDiffCostFunction<SegmentBlockCost, ceres::CENTRAL>(
          functor, ceres::TAKE_OWNERSHIP, nd);
      cost->AddParameterBlock(np);
      cost->AddParameterBlock(2);
      cost->SetNumResiduals(3 * owned);
      problem.AddResidualBlock(cost, nullptr, q.data(), state[i].data());
    }
  } else {
    auto* cost = new ceres::DynamicNumericDiffCostFunction<SegmentCost, ceres::CENTRAL>(
        new SegmentCost(prep, start, free, options), ceres::TAKE_OWNERSHIP, nd);
    cost->AddParameterBlock(np);
    cost->SetNumResiduals(nr);
    problem.AddResidualBlock(cost, nullptr, q.data());
  }
  const double span = std::log(options.max_factor);
  for (int j = 0; j < np; ++j) {
    problem.SetParameterLowerBound(q.data(), j, kOffset - span);
    problem.SetParameterUpperBound(q.data(), j, kOffset + span);
  }
  ceres::Solver::Options so;
  // With the starting pressures free, the Schur complement eliminates them segment by segment.
  so.linear_solver_type = options.fit_start_pressures ? ceres::DENSE_SCHUR : ceres::DENSE_QR;
  so.max_num_iterations = options.max_iterations;
  so.function_tolerance = options.function_tolerance;
  so.parameter_tolerance = options.parameter_tolerance;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  Progress progress;
  if (options.verbose) so.callbacks.push_back(&progress);
  StageOutcome out;
  ceres::Solve(so, &problem, &out.summary);
  const ceres::Solver::Summary& summary = out.summary;
  if (!summary.IsSolutionUsable() || summary.termination_type != ceres::CONVERGENCE) {
    throw RunError("fit", fmt::format(
        "the fit did not converge with {:g} s segments ({}): {}", options.segment_length_s,
        ceres::TerminationTypeToString(summary.termination_type), summary.message));
  }
  if (starts) {
    starts->resize(2 * prep.segments.size());
    for (std::size_t i = 0; i < prep.segments.size(); ++i) {
      (*starts)[2 * i] = prep.segments[i].P1 + (state[i][0] - kOffset) * options.pressure_scale_Pa;
      (*starts)[2 * i + 1] = prep.segments[i].P2 + (state[i][1] - kOffset) * options.pressure_scale_Pa;
    }
  }
  if (!with_covariance) return out;
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = 0;  // rank deficiency is a failure, not a pseudo-inverse
  co.num_threads = 1;
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double*, const double*>> blocks{{q.data(), q.data()}};
  if (!covariance.Compute(blocks, &problem)) {
    throw RunError("fit", fmt::format(
        "the fit's covariance is rank-deficient: the record does not determine all of the "
        "free parameters (fix some with --set and drop them from --free); Ceres: {}",
        summary.BriefReport()));
  }
  out.covariance.resize(static_cast<std::size_t>(np * np));
  covariance.GetCovarianceBlock(q.data(), q.data(), out.covariance.data());
  return out;
}

// The start must simulate over the record, or there is nothing to fit from.
void require_start_simulates(const Prepared& prep, const Scenario& start, const FitOptions& options) {
  std::vector<double> a, b, c;
  std::string why;
  if (!simulate_segments(prep, start, options, a, b, c, &why))
    throw RunError("fit", "the start scenario does not simulate over the record: " + why);
}

// The global stage: a fit from the start with each candidate segment length, each judged by
// the cost with the final segments; q becomes the best candidate's parameters (or stays at the
// start when none beats it). cost_of is that final cost (NaN when it fails).
template <typename Cost>
void global_stage(const MeasuredRecord& record, const Scenario& start,
                  const std::vector<FreeParam>& free, const FitOptions& options,
                  const Cost& cost_of, std::vector<double>& q, FitResult& result) {
  double best = cost_of(q);
  result.initial_cost = best;
  std::vector<double> lengths = options.first_segment_lengths_s;
  if (std::find(lengths.begin(), lengths.end(), options.segment_length_s) == lengths.end())
    lengths.push_back(options.segment_length_s);
  for (double length : lengths) {
    if (!(length > 0)) continue;
    FitOptions o = options;
    o.segment_length_s = length;
    std::vector<double> qc(free.size(), kOffset);
    double c = std::numeric_limits<double>::quiet_NaN();
    try {
      const StageOutcome out = solve_stage(prepare(record, o), start, free, o, qc, false);
      result.iterations += static_cast<int>(out.summary.iterations.size());
      c = cost_of(qc);
    } catch (const RunError&) {
      // a candidate that does not converge is dropped; the final fit reports its own failure
    }
    result.candidate_segment_lengths_s.push_back(length);
    result.candidate_costs.push_back(c);
    if (std::isfinite(c) && !(c >= best)) {
      best = c;
      q = qc;
      result.chosen_candidate = static_cast<int>(result.candidate_costs.size()) - 1;
    }
  }
}

// The fitted values with standard errors: the covariance of log(value / start), scaled by the
// reduced chi-square, carried to the value.
void add_parameters(const std::vector<FreeParam>& free, const std::vector<double>& C,
                    FitResult& result) {
  const std::size_t np = free.size();
  for (std::size_t j = 0; j < np; ++j) {
    FittedKey p;
    p.key = free[j].key;
    p.unit = free[j].unit;
    p.start = free[j].start;
    p.value = key_value(result.scenario, p.key);
    const double var_log = C[j * np + j] * result.reduced_chi2;
    p.standard_error = p.value * std::sqrt(std::max(0.0, var_log));
    result.parameters.push_back(p);
  }
}

void add_validation(const Prepared& prep, const FitOptions& options,
                    const std::vector<double>& starts, FitResult& result) {
  result.validation = validation_of(prep, result.scenario, options,
                                    options.fit_start_pressures ? &starts : nullptr);
  const ValidationSeries& vs = result.validation;
  result.rms_P1_Pa = rms(vs.p1_sim, vs.p1_meas);
  result.rms_P2_Pa = rms(vs.p2_sim, vs.p2_meas);
  result.rms_v_m_per_s = rms(vs.v_sim, vs.v_meas);
}

}  // namespace

FitResult fit_model(const MeasuredRecord& record, const Scenario& start,
                    const std::vector<std::string>& free_keys, const FitOptions& options) {
  // Ceres reports failed evaluations and rank deficiency through glog too; the RunErrors
  // and the result say it, so glog stays quiet while fitting.
  struct QuietGlog {
    int level = FLAGS_minloglevel;
    QuietGlog() { FLAGS_minloglevel = google::GLOG_FATAL; }
    ~QuietGlog() { FLAGS_minloglevel = level; }
  } quiet;
  const auto t0 = std::chrono::steady_clock::now();
  check_free_keys(start, free_keys);
  start.validate();
  std::vector<FreeParam> free;
  for (const auto& key : free_keys) free.push_back({key, key_unit(key), key_value(start, key)});
  const Prepared final_prep = prepare(record, options);
  require_start_simulates(final_prep, start, options);

  const SegmentCost final_cost(final_prep, start, free, options);
  std::vector<double> residuals(3 * record.size());
  const auto cost_of = [&](const std::vector<double>& q) {
    const double* blocks[] = {q.data()};
    if (!final_cost(blocks, residuals.data())) return std::numeric_limits<double>::quiet_NaN();
    double c = 0;
    for (double r : residuals) c += r * r;
    return 0.5 * c;
  };
  FitResult result;
  std::vector<double> q(free.size(), kOffset);
  global_stage(record, start, free, options, cost_of, q, result);

  std::vector<double> starts;
  const StageOutcome outcome = solve_stage(final_prep, start, free, options, q, true, &starts);
  result.iterations += static_cast<int>(outcome.summary.iterations.size());
  const ceres::Solver::Summary& summary = outcome.summary;
  const int nr = static_cast<int>(3 * record.size());
  const int fitted = static_cast<int>(free.size()) +
                     (options.fit_start_pressures ? 2 * static_cast<int>(final_prep.segments.size()) : 0);
  result.scenario = with_values(start, free, q.data());
  result.segments = final_prep.segments.size();
  result.residuals = static_cast<std::size_t>(nr);
  result.final_cost = summary.final_cost;
  result.reduced_chi2 = 2.0 * summary.final_cost / std::max(1, nr - fitted);
  result.summary = summary.BriefReport();
  add_parameters(free, outcome.covariance, result);
  add_validation(final_prep, options, starts, result);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace pneumachaos::identify
