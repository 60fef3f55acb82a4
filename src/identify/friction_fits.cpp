#include "pneumachaos/identify/friction_fits.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../model/friction_laws.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos::identify {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The members friction_laws.hpp reads, in the fitted scalar T (double or ceres::Jet), so
/// that the fitted laws are the plant's laws, written once.
template <typename T>
struct FitParams {
  FrictionKind kind = FrictionKind::kStribeck;
  T coulomb_N, static_N, viscous_Ns_per_m, stribeck_velocity_m_per_s, stribeck_exponent;
  T sigma0_N_per_m, sigma1_Ns_per_m, coulomb_gain_N_per_Pa, static_gain_N_per_Pa;
  std::array<TextureMode, 0> texture{};
  FrictionMemory memory = FrictionMemory::kNone;
  double lag_time_s = 0.005;
  [[nodiscard]] bool lagged() const { return false; }
};

// The static models' parameter block: q = Fc [N], Fs [N], vs [mm/s], delta, B [N s/m],
// Fc gain [N/MPa], Fs gain [N/MPa]; the scales keep the block well conditioned.
enum Q { kFc, kFs, kVs, kDelta, kB, kGc, kGs, kQ };

template <typename T>
FitParams<T> params_of(FrictionKind kind, const T* q) {
  FitParams<T> p;
  p.kind = kind;
  p.coulomb_N = q[kFc];
  p.static_N = q[kFs];
  p.stribeck_velocity_m_per_s = q[kVs] * 1e-3;
  p.stribeck_exponent = q[kDelta];
  p.viscous_Ns_per_m = q[kB];
  p.coulomb_gain_N_per_Pa = q[kGc] * 1e-6;
  p.static_gain_N_per_Pa = q[kGs] * 1e-6;
  p.sigma0_N_per_m = T(0.0);
  p.sigma1_Ns_per_m = T(0.0);
  return p;
}

FrictionParams to_friction(FrictionKind kind, const double* q) {
  FrictionParams f;
  f.kind = kind;
  f.coulomb_N = q[kFc];
  f.static_N = q[kFs];
  f.stribeck_velocity_m_per_s = q[kVs] * 1e-3;
  f.stribeck_exponent = q[kDelta];
  f.viscous_Ns_per_m = q[kB];
  f.coulomb_gain_N_per_Pa = q[kGc] * 1e-6;
  f.static_gain_N_per_Pa = q[kGs] * 1e-6;
  return f;
}

// A point of the comparison set: a sliding sample, or a breakaway (v = 0+ in `dir`).
struct Point {
  double v = 0.0, gauge = 0.0, F = 0.0;
  int dir = 0;
  bool breakaway = false;
};

std::vector<Point> comparison_points(const FrictionEstimate& e) {
  std::vector<Point> pts;
  for (std::size_t i = 0; i < e.F_N.size(); ++i) {
    if (!e.sliding[i]) continue;
    const int dir = e.v_smooth_m_per_s[i] > 0.0 ? 1 : -1;
    if (dir * e.v_m_per_s[i] <= 0.0) continue;  // noise across zero: no direction to fit
    pts.push_back({e.v_m_per_s[i], e.gauge_sum_Pa[i], e.F_N[i], dir, false});
  }
  for (const StickInterval& s : e.sticks) {
    if (s.direction == 0 || !std::isfinite(s.breakaway_N)) continue;
    pts.push_back({0.0, e.gauge_sum_Pa[s.end - 1], s.breakaway_N, s.direction, true});
  }
  return pts;
}

template <typename T, typename P>
T static_prediction(const P& p, const Point& pt) {
  BasicFrictionInput<T> in;
  in.v_m_per_s = T(pt.v);
  in.gauge_sum_Pa = T(pt.gauge);
  in.position_m = T(0.0);
  if (pt.breakaway) return double(pt.dir) * friction_law::static_N(p, in);
  return friction_law::stiction_sliding_N(p, in, pt.dir);
}

struct StaticResidual {
  const std::vector<Point>* points;
  FrictionKind kind;
  template <typename T>
  bool operator()(const T* const q, T* residual) const {
    const FitParams<T> p = params_of(kind, q);
    for (std::size_t i = 0; i < points->size(); ++i)
      residual[i] = static_prediction<T>(p, (*points)[i]) - (*points)[i].F;
    return true;
  }
};

// LuGre along the measured velocity: q = ln sigma0, ln sigma1, the levels fixed. While
// stuck, the bristles hold the measured force (z = F / sigma0, within the static level);
// elsewhere z follows dz/dt = v - sigma0 |v| z / g(v), stepped exactly for v held over a
// sample. Residuals on the samples outside sticks.
struct LuGreResidual {
  const FrictionEstimate* e;
  FrictionParams levels;
  template <typename T>
  bool operator()(const T* const q, T* residual) const {
    using std::abs;
    using std::exp;
    FitParams<T> p;
    p.kind = FrictionKind::kLuGre;
    p.coulomb_N = T(levels.coulomb_N);
    p.static_N = T(levels.static_N);
    p.stribeck_velocity_m_per_s = T(levels.stribeck_velocity_m_per_s);
    p.stribeck_exponent = T(levels.stribeck_exponent);
    p.viscous_Ns_per_m = T(levels.viscous_Ns_per_m);
    p.coulomb_gain_N_per_Pa = T(levels.coulomb_gain_N_per_Pa);
    p.static_gain_N_per_Pa = T(levels.static_gain_N_per_Pa);
    p.sigma0_N_per_m = exp(q[0]);
    p.sigma1_Ns_per_m = exp(q[1]);
    const double dt = e->t_s.size() > 1 ? e->t_s[1] - e->t_s[0] : 1e-3;
    T z(0.0);
    std::size_t r = 0;
    for (std::size_t i = 0; i < e->F_N.size(); ++i) {
      BasicFrictionInput<T> in;
      in.v_m_per_s = T(e->v_m_per_s[i]);
      in.gauge_sum_Pa = T(e->gauge_sum_Pa[i]);
      in.position_m = T(0.0);
      if (e->stuck[i]) {
        const T zmax = friction_law::static_N(p, in) / p.sigma0_N_per_m;
        z = T(e->F_N[i]) / p.sigma0_N_per_m;
        if (z > zmax) z = zmax;
        if (z < -zmax) z = -zmax;
        continue;
      }
      T dz;
      residual[r++] = friction_law::lugre_N(p, in, z, dz) - e->F_N[i];
      const T g = friction_law::stribeck_level_N(p, in, in.v_m_per_s);
      const double v = e->v_m_per_s[i];
      const T zss = (v >= 0.0 ? g : -g) / p.sigma0_N_per_m;
      z = zss + (z - zss) * exp(-p.sigma0_N_per_m * std::abs(v) * dt / g);
    }
    return true;
  }
  // The force it predicts at each sample (stuck samples: the held force), in double.
  std::vector<double> prediction(const double* q) const {
    std::vector<double> out(e->F_N.size(), 0.0);
    std::vector<double> res(e->F_N.size());
    (*this)(q, res.data());
    std::size_t r = 0;
    const double s0 = std::exp(q[0]);
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (e->stuck[i]) {
        const double smax = levels.static_N + levels.static_gain_N_per_Pa * e->gauge_sum_Pa[i];
        out[i] = std::clamp(e->F_N[i], -smax, smax);
        (void)s0;
      } else {
        out[i] = res[r++] + e->F_N[i];
      }
    }
    return out;
  }
};

// Small dense least squares by the normal equations (a handful of columns).
std::vector<double> linear_lsq(const std::vector<std::vector<double>>& rows,
                               const std::vector<double>& y, double* rss) {
  const std::size_t k = rows.empty() ? 0 : rows.front().size();
  std::vector<double> A(k * k, 0.0), b(k, 0.0);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t i = 0; i < k; ++i) {
      b[i] += rows[r][i] * y[r];
      for (std::size_t j = 0; j < k; ++j) A[i * k + j] += rows[r][i] * rows[r][j];
    }
  for (std::size_t i = 0; i < k; ++i) A[i * k + i] += 1e-9 * (1.0 + A[i * k + i]);
  // Gaussian elimination with partial pivoting.
  std::vector<double> x(k, 0.0);
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < k; ++r)
      if (std::abs(A[r * k + c]) > std::abs(A[piv * k + c])) piv = r;
    for (std::size_t j = 0; j < k; ++j) std::swap(A[c * k + j], A[piv * k + j]);
    std::swap(b[c], b[piv]);
    if (A[c * k + c] == 0.0) continue;
    for (std::size_t r = c + 1; r < k; ++r) {
      const double f = A[r * k + c] / A[c * k + c];
      for (std::size_t j = c; j < k; ++j) A[r * k + j] -= f * A[c * k + j];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = k; c-- > 0;) {
    double s = b[c];
    for (std::size_t j = c + 1; j < k; ++j) s -= A[c * k + j] * x[j];
    x[c] = A[c * k + c] != 0.0 ? s / A[c * k + c] : 0.0;
  }
  if (rss) {
    *rss = 0.0;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      double p = 0.0;
      for (std::size_t i = 0; i < k; ++i) p += rows[r][i] * x[i];
      *rss += (p - y[r]) * (p - y[r]);
    }
  }
  return x;
}

// Starting values: classic by linear least squares; Stribeck by a grid over vs with the
// levels and B linear at each vs.
std::array<double, kQ> start_values(const std::vector<Point>& pts, bool stribeck, double delta) {
  std::array<double, kQ> q{};
  q[kDelta] = delta;
  q[kVs] = 10.0;
  double break_sum = 0.0;
  std::size_t breaks = 0;
  std::vector<std::vector<double>> rows;
  std::vector<double> y;
  for (const Point& p : pts) {
    if (p.breakaway) {
      break_sum += p.dir * p.F;
      ++breaks;
      continue;
    }
    rows.push_back({1.0, std::abs(p.v)});
    y.push_back(p.dir * p.F);
  }
  const auto c = linear_lsq(rows, y, nullptr);
  q[kFc] = std::max(0.0, c.size() > 0 ? c[0] : 0.0);
  q[kB] = std::max(0.0, c.size() > 1 ? c[1] : 0.0);
  q[kFs] = breaks ? std::max(q[kFc], break_sum / double(breaks)) : q[kFc];
  if (!stribeck) return q;
  double best = std::numeric_limits<double>::infinity();
  for (int g = 0; g <= 60; ++g) {
    const double vs_mm = 0.1 * std::pow(10.0, g / 15.0);  // 0.1 mm/s .. 1 m/s
    std::vector<std::vector<double>> sr;
    std::vector<double> sy;
    for (const Point& p : pts) {
      const double w = p.breakaway ? 1.0 : std::exp(-std::pow(std::abs(p.v) / (vs_mm * 1e-3), delta));
      sr.push_back({1.0 - w, w, p.breakaway ? 0.0 : std::abs(p.v)});
      sy.push_back(p.dir * p.F);
    }
    double rss = 0.0;
    const auto x = linear_lsq(sr, sy, &rss);
    if (rss < best && x[0] >= 0.0 && x[1] >= 0.0 && x[2] >= 0.0) {
      best = rss;
      q[kFc] = x[0];
      q[kFs] = x[1];
      q[kB] = x[2];
      q[kVs] = vs_mm;
    }
  }
  return q;
}

std::string termination(const ceres::Solver::Summary& s) {
  return fmt::format("{} after {} iterations: {}", ceres::TerminationTypeToString(s.termination_type),
                     s.iterations.size(), s.message);
}

bool converged(const ceres::Solver::Summary& s) {
  return s.termination_type == ceres::CONVERGENCE || s.termination_type == ceres::USER_SUCCESS;
}

ceres::Solver::Options solver_options(int max_iterations) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = max_iterations;
  o.function_tolerance = 1e-10;
  o.parameter_tolerance = 1e-10;
  o.gradient_tolerance = 1e-12;
  o.num_threads = 1;
  o.logging_type = ceres::SILENT;
  return o;
}

// Standard errors of a block from the Ceres covariance, scaled by the residual variance
// (Ceres assumes unit-variance residuals). NaN when the Jacobian is rank deficient.
std::vector<double> standard_errors(ceres::Problem& problem, double* block, int size,
                                    double residual_variance) {
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = -1;
  co.min_reciprocal_condition_number = 1e-14;
  ceres::Covariance cov(co);
  std::vector<double> se(static_cast<std::size_t>(size), kNaN);
  std::vector<std::pair<const double*, const double*>> blocks{{block, block}};
  if (!cov.Compute(blocks, &problem)) return se;
  std::vector<double> c(static_cast<std::size_t>(size * size));
  if (!cov.GetCovarianceBlock(block, block, c.data())) return se;
  for (int i = 0; i < size; ++i)
    se[static_cast<std::size_t>(i)] = std::sqrt(std::max(0.0, c[static_cast<std::size_t>(i * size + i)] * residual_variance));
  return se;
}

void score(ModelFit& f, const std::vector<double>& residuals) {
  double rss = 0.0;
  for (double r : residuals) rss += r * r;
  const double n = double(residuals.size());
  f.points = residuals.size();
  f.rms_N = n > 0 ? std::sqrt(rss / n) : kNaN;
  const double k = double(f.free_params);
  const double ll = n * std::log(std::max(rss, 1e-300) / n);
  f.bic = ll + k * std::log(n);
  f.aic = ll + 2.0 * k;
}

std::vector<double> static_residuals(const std::vector<Point>& pts, FrictionKind kind,
                                     const double* q) {
  std::vector<double> r(pts.size());
  StaticResidual{&pts, kind}(q, r.data());
  return r;
}

ModelFit fit_static(FrictionFitModel model, const std::vector<Point>& pts, std::size_t sliding,
                    bool breakaways, const FrictionFitOptions& o) {
  ModelFit f;
  f.model = model;
  f.name = fit_model_name(model);
  const bool stribeck = model != FrictionFitModel::kClassic;
  const bool free_delta = model == FrictionFitModel::kStribeckDelta;
  const FrictionKind kind = stribeck ? FrictionKind::kStribeck : FrictionKind::kClassic;
  // Held constant: vs and delta of classic; delta of "stribeck"; the gains unless asked for;
  // classic's Fs without a breakaway to measure it.
  std::vector<int> constant;
  if (!stribeck) constant = {kVs, kDelta};
  if (stribeck && !free_delta) constant.push_back(kDelta);
  if (!o.pressure_dependent) {
    constant.push_back(kGc);
    constant.push_back(kGs);
  }
  const bool fs_fixed = !stribeck && !breakaways;
  if (fs_fixed) constant.push_back(kFs);
  f.free_params = kQ - constant.size();
  const std::size_t needed = 10 * f.free_params;
  if (sliding < needed) {
    f.skipped = fmt::format("too few sliding samples to fit: {} (at least {} needed for {} "
                            "parameters)", sliding, needed, f.free_params);
    return f;
  }
  std::array<double, kQ> q = start_values(pts, stribeck, o.fixed_exponent);
  if (free_delta) {
    // The shortcut for delta = 2 in stribeck_weight carries no derivative in delta: start off it.
    if (q[kDelta] == 2.0) q[kDelta] = 1.9;
  }
  ceres::Problem problem;
  auto* cost = new ceres::AutoDiffCostFunction<StaticResidual, ceres::DYNAMIC, kQ>(
      new StaticResidual{&pts, kind}, static_cast<int>(pts.size()));
  problem.AddResidualBlock(cost, nullptr, q.data());
  if (!constant.empty()) problem.SetManifold(q.data(), new ceres::SubsetManifold(kQ, constant));
  for (int i : {kFc, kFs, kB, kGc, kGs}) problem.SetParameterLowerBound(q.data(), i, 0.0);
  problem.SetParameterLowerBound(q.data(), kVs, 0.01);
  problem.SetParameterUpperBound(q.data(), kVs, 1e4);
  problem.SetParameterLowerBound(q.data(), kDelta, 0.3);
  problem.SetParameterUpperBound(q.data(), kDelta, 5.0);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(o.max_iterations), &problem, &summary);
  f.fitted = true;
  f.converged = converged(summary);
  f.summary = termination(summary);
  const auto res = static_residuals(pts, kind, q.data());
  score(f, res);
  const double dof = std::max(1.0, double(pts.size()) - double(f.free_params));
  const auto se = standard_errors(problem, q.data(), kQ, f.rms_N * f.rms_N * double(pts.size()) / dof);
  f.friction = to_friction(kind, q.data());
  const auto is_const = [&](int i) { return std::find(constant.begin(), constant.end(), i) != constant.end(); };
  const auto add = [&](const char* name, int i, double scale, const char* unit) {
    f.params.push_back({name, q[static_cast<std::size_t>(i)] * scale,
                        is_const(i) ? 0.0 : se[static_cast<std::size_t>(i)] * scale, unit, is_const(i)});
  };
  add("Fc_N", kFc, 1.0, "N");
  add("Fs_N", kFs, 1.0, "N");
  if (stribeck) {
    add("vs_mm_per_s", kVs, 1.0, "mm/s");
    add("stribeck_exponent", kDelta, 1.0, "-");
  }
  add("B_Ns_per_m", kB, 1.0, "N*s/m");
  if (o.pressure_dependent) {
    add("Fc_gain_N_per_MPa", kGc, 1.0, "N/MPa");
    add("Fs_gain_N_per_MPa", kGs, 1.0, "N/MPa");
  }
  return f;
}

ModelFit fit_lugre(const FrictionEstimate& e, const std::vector<Point>& pts, std::size_t sliding,
                   const ModelFit* stribeck, const FrictionFitOptions& o) {
  ModelFit f;
  f.model = FrictionFitModel::kLuGre;
  f.name = fit_model_name(f.model);
  f.free_params = 2 + (stribeck ? stribeck->free_params : 0);
  const std::size_t needed = 10 * f.free_params;
  if (sliding < needed) {
    f.skipped = fmt::format("too few sliding samples to fit: {} (at least {} needed for {} "
                            "parameters)", sliding, needed, f.free_params);
    return f;
  }
  FrictionParams levels = stribeck ? stribeck->friction : o.start;
  levels.kind = FrictionKind::kLuGre;
  levels.texture.clear();
  levels.memory = FrictionMemory::kNone;
  std::size_t moving = 0;
  for (char s : e.stuck) moving += s ? 0 : 1;
  std::array<double, 2> q{std::log(std::max(1.0, o.start.sigma0_N_per_m)),
                          std::log(std::max(1e-3, o.start.sigma1_Ns_per_m))};
  ceres::Problem problem;
  auto* functor = new LuGreResidual{&e, levels};
  const LuGreResidual copy = *functor;
  problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<LuGreResidual, ceres::DYNAMIC, 2>(functor, static_cast<int>(moving)),
      nullptr, q.data());
  problem.SetParameterLowerBound(q.data(), 0, std::log(1e2));
  problem.SetParameterUpperBound(q.data(), 0, std::log(1e9));
  problem.SetParameterLowerBound(q.data(), 1, std::log(1e-3));
  problem.SetParameterUpperBound(q.data(), 1, std::log(1e6));
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(o.max_iterations), &problem, &summary);
  f.fitted = true;
  f.converged = converged(summary);
  f.summary = termination(summary);
  // The comparison set: the sliding samples and breakaways, as for the static models.
  const auto pred = copy.prediction(q.data());
  std::vector<double> res;
  for (std::size_t i = 0; i < e.F_N.size(); ++i)
    if (e.sliding[i] && (e.v_smooth_m_per_s[i] > 0.0 ? 1.0 : -1.0) * e.v_m_per_s[i] > 0.0)
      res.push_back(pred[i] - e.F_N[i]);
  for (const StickInterval& s : e.sticks)
    if (s.direction != 0 && std::isfinite(s.breakaway_N))
      res.push_back(pred[s.end - 1] - s.breakaway_N);
  (void)pts;
  score(f, res);
  double rss_moving = 0.0;
  {
    std::vector<double> r(moving);
    copy(q.data(), r.data());
    for (double x : r) rss_moving += x * x;
  }
  const auto se = standard_errors(problem, q.data(), 2,
                                  rss_moving / std::max(1.0, double(moving) - 2.0));
  levels.sigma0_N_per_m = std::exp(q[0]);
  levels.sigma1_Ns_per_m = std::exp(q[1]);
  f.friction = levels;
  if (stribeck) {
    for (const auto& p : stribeck->params) {
      FittedParameter c = p;
      c.fixed = true;  // from the Stribeck fit
      f.params.push_back(c);
    }
  }
  f.params.push_back({"sigma0_N_per_m", levels.sigma0_N_per_m, levels.sigma0_N_per_m * se[0], "N/m", false});
  f.params.push_back({"sigma1_Ns_per_m", levels.sigma1_Ns_per_m, levels.sigma1_Ns_per_m * se[1], "N*s/m", false});
  return f;
}

}  // namespace

const char* fit_model_name(FrictionFitModel m) {
  switch (m) {
    case FrictionFitModel::kClassic: return "classic";
    case FrictionFitModel::kStribeck: return "stribeck";
    case FrictionFitModel::kStribeckDelta: return "stribeck_delta";
    case FrictionFitModel::kLuGre: return "lugre";
  }
  return "?";
}

FrictionFitModel parse_fit_model(const std::string& name, const std::string& where) {
  for (FrictionFitModel m : all_fit_models())
    if (name == fit_model_name(m)) return m;
  throw Error(where, fmt::format("unknown friction model \"{}\"; expected one of classic | "
                                 "stribeck | stribeck_delta | lugre", name));
}

std::vector<FrictionFitModel> all_fit_models() {
  return {FrictionFitModel::kClassic, FrictionFitModel::kStribeck, FrictionFitModel::kStribeckDelta,
          FrictionFitModel::kLuGre};
}

const FittedParameter* ModelFit::param(const std::string& n) const {
  for (const auto& p : params)
    if (p.name == n) return &p;
  return nullptr;
}

const ModelFit* FrictionFits::failed() const {
  for (const auto& f : fits)
    if (f.fitted && !f.converged) return &f;
  return nullptr;
}

double steady_friction_N(const FrictionParams& p, double v, double gauge_sum_Pa) {
  FrictionParams q = p;
  if (q.kind == FrictionKind::kLuGre) q.kind = FrictionKind::kStribeck;
  q.texture.clear();
  q.memory = FrictionMemory::kNone;
  FrictionInput in;
  in.v_m_per_s = v;
  in.gauge_sum_Pa = gauge_sum_Pa;
  if (v == 0.0) return 0.0;
  return friction_law::stiction_sliding_N(q, in, v > 0.0 ? 1 : -1);
}

FrictionFits fit_friction(const FrictionEstimate& e, const FrictionFitOptions& o) {
  const std::vector<Point> pts = comparison_points(e);
  std::size_t sliding = 0;
  bool breakaways = false;
  for (const Point& p : pts) {
    if (p.breakaway) breakaways = true;
    else ++sliding;
  }
  FrictionFits out;
  const auto wants = [&](FrictionFitModel m) {
    return std::find(o.models.begin(), o.models.end(), m) != o.models.end();
  };
  std::optional<ModelFit> stribeck_fixed;
  for (FrictionFitModel m : all_fit_models()) {
    if (m == FrictionFitModel::kLuGre) continue;
    const bool needed_for_lugre = m == FrictionFitModel::kStribeck && wants(FrictionFitModel::kLuGre);
    if (!wants(m) && !needed_for_lugre) continue;
    ModelFit f = fit_static(m, pts, sliding, breakaways, o);
    if (m == FrictionFitModel::kStribeck) stribeck_fixed = f;
    if (wants(m)) out.fits.push_back(std::move(f));
  }
  if (wants(FrictionFitModel::kLuGre)) {
    const ModelFit* levels = stribeck_fixed && stribeck_fixed->fitted && stribeck_fixed->converged
                                 ? &*stribeck_fixed
                                 : nullptr;
    out.fits.push_back(fit_lugre(e, pts, sliding, levels, o));
  }
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : out.fits)
    if (f.fitted && f.converged && f.bic < best) {
      best = f.bic;
      out.preferred_model = f.name;
    }
  return out;
}

}  // namespace pneumachaos::identify
