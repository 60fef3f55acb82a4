#include "pneumachaos/identify/friction_fits.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "model/friction_laws.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos::identify {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The members friction_laws.hpp reads, in the fitted scalar T (double or ceres::Jet), so
/// that the fitted laws are the plant's laws, written once: FrictionParams' own parameter
/// structs on T, and no texture (the fits take the bore as uniform).
template <typename T>
struct FitParams {
  FrictionKind kind = FrictionKind::kStribeck;
  BasicStribeckCurve<T> curve;
  BasicPressureGains<T> pressure_gain;
  BasicLuGreBristles<T> lugre;
  std::array<TextureMode, 0> texture{};
};

// The static models' parameter block: q = Fc [N], Fs [N], vs [mm/s], delta, B [N s/m],
// Fc gain [N/MPa], Fs gain [N/MPa]; the scales keep the block well conditioned.
enum Q { kFc, kFs, kVs, kDelta, kB, kGc, kGs, kQ };

template <typename T>
BasicStribeckCurve<T> curve_of(const T* q) {
  return {.coulomb_N = q[kFc],
          .static_N = q[kFs],
          .viscous_Ns_per_m = q[kB],
          .stribeck_velocity_m_per_s = q[kVs] * 1e-3,
          .stribeck_exponent = q[kDelta]};
}

template <typename T>
BasicPressureGains<T> pressure_gain_of(const T* q) {
  return {.coulomb_N_per_Pa = q[kGc] * 1e-6, .static_N_per_Pa = q[kGs] * 1e-6};
}

template <typename T>
FitParams<T> params_of(FrictionKind kind, const T* q) {
  FitParams<T> p;
  p.kind = kind;
  p.curve = curve_of(q);
  p.pressure_gain = pressure_gain_of(q);
  return p;
}

FrictionParams to_friction(FrictionKind kind, const double* q) {
  FrictionParams f;
  f.kind = kind;
  f.curve = curve_of(q);
  f.pressure_gain = pressure_gain_of(q);
  return f;
}

// The comparison set (docs/friction.md, "Fits"): the equation of motion integrated over
// blocks of kBlock sample intervals inside sliding runs, m (v_end - v_begin) / T =
// mean(drive) - mean(F), so that the fitted force needs no differentiated velocity (whose
// bias at breakaways and stops would bias vs and B); plus one point per breakaway.
constexpr std::size_t kBlock = 5;

struct Sample {
  double v = 0.0, gauge = 0.0, w = 0.0;  // w: trapezoid weight / sum of the block's weights
  int dir = 0;
};
struct Block {
  std::size_t first = 0, count = 0;  // into FitData::samples
  std::size_t begin = 0;             // record sample of the block's start
  double target_N = 0.0;             // mean friction over the block from the motion
};
struct Breakaway {
  double gauge = 0.0, F = 0.0;
  int dir = 0;
};
struct FitData {
  std::vector<Sample> samples;
  std::vector<Block> blocks;
  std::vector<Breakaway> breakaways;
  [[nodiscard]] std::size_t size() const { return blocks.size() + breakaways.size(); }
};

FitData fit_data(const FrictionEstimate& e) {
  FitData d;
  const std::size_t n = e.F_N.size();
  const double dt = n > 1 ? e.t_s[1] - e.t_s[0] : 1e-3;
  for (std::size_t i = 0; i < n;) {
    if (!e.sliding[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    const int dir = e.v_m_per_s[i] > 0.0 ? 1 : -1;
    while (j < n && e.sliding[j] && (e.v_m_per_s[j] > 0.0 ? 1 : -1) == dir) ++j;
    // Blocks of kBlock intervals over samples i .. j-1 (a shorter last block if >= 2).
    for (std::size_t b = i; b + 1 < j; b += kBlock) {
      const std::size_t last = std::min(b + kBlock, j - 1);
      Block blk;
      blk.first = d.samples.size();
      blk.count = last - b + 1;
      blk.begin = b;
      const double intervals = double(last - b);
      double drive = 0.0;
      for (std::size_t k = b; k <= last; ++k) {
        const double w = (k == b || k == last ? 0.5 : 1.0) / intervals;
        drive += w * e.drive_N[k];
        d.samples.push_back({e.v_m_per_s[k], e.gauge_sum_Pa[k], w, dir});
      }
      blk.target_N = drive - e.mass_kg * (e.v_m_per_s[last] - e.v_m_per_s[b]) / (intervals * dt);
      d.blocks.push_back(blk);
    }
    i = j;
  }
  for (const StickInterval& s : e.sticks) {
    if (s.direction == 0 || !std::isfinite(s.breakaway_N)) continue;
    d.breakaways.push_back({e.gauge_sum_Pa[s.end - 1], s.breakaway_N, s.direction});
  }
  return d;
}

template <typename T, typename P>
T sliding_force(const P& p, const Sample& s) {
  BasicFrictionInput<T> in;
  in.v_m_per_s = T(s.v);
  in.gauge_sum_Pa = T(s.gauge);
  in.position_m = T(0.0);
  return friction_law::stiction_sliding_N(p, in, s.dir);
}

template <typename T, typename P>
T breakaway_force(const P& p, const Breakaway& b) {
  BasicFrictionInput<T> in;
  in.v_m_per_s = T(0.0);
  in.gauge_sum_Pa = T(b.gauge);
  in.position_m = T(0.0);
  return double(b.dir) * friction_law::static_N(p, in);
}

struct StaticResidual {
  const FitData* data;
  FrictionKind kind;
  template <typename T>
  bool operator()(const T* const q, T* residual) const {
    const FitParams<T> p = params_of(kind, q);
    std::size_t r = 0;
    for (const Block& b : data->blocks) {
      T mean(0.0);
      for (std::size_t k = b.first; k < b.first + b.count; ++k)
        mean += data->samples[k].w * sliding_force<T>(p, data->samples[k]);
      residual[r++] = mean - b.target_N;
    }
    for (const Breakaway& b : data->breakaways) residual[r++] = breakaway_force<T>(p, b) - b.F;
    return true;
  }
};

// LuGre along the measured velocity: q = ln sigma0, ln sigma1, Fc, Fs, vs [mm/s], B (delta and
// the pressure gains held at the Stribeck fit's). While
// stuck, the bristles hold the measured force (z = F / sigma0, within the static level);
// elsewhere z follows dz/dt = v - sigma0 |v| z / g(v), stepped exactly for v held over a
// sample. Residuals on the comparison set's blocks and breakaways, as the static models'.
struct LuGreResidual {
  static constexpr int kSub = 4;
  // A speed of exactly 0 (quantised records have them at reversals) makes pow(|v|/vs, delta)
  // non-differentiable for delta < 1; a nanometre per second is zero for the force.
  static double off_zero(double v) { return v != 0.0 ? v : 1e-9; }
  const FrictionEstimate* e;
  const FitData* data;
  std::vector<std::size_t> block_samples;  // record index of each of data->samples
  FrictionParams levels;
  template <typename T>
  bool operator()(const T* const q, T* residual) const {
    using std::abs;
    using std::exp;
    FitParams<T> p;
    p.kind = FrictionKind::kLuGre;
    p.curve = {.coulomb_N = q[2],
               .static_N = q[3],
               .viscous_Ns_per_m = q[5],
               .stribeck_velocity_m_per_s = q[4] * 1e-3,
               .stribeck_exponent = T(levels.curve.stribeck_exponent)};
    p.pressure_gain = {.coulomb_N_per_Pa = T(levels.pressure_gain.coulomb_N_per_Pa),
                       .static_N_per_Pa = T(levels.pressure_gain.static_N_per_Pa)};
    p.lugre.sigma0_N_per_m = exp(q[0]);
    p.lugre.sigma1_Ns_per_m = exp(q[1]);
    const std::size_t n = e->F_N.size();
    const double dt = n > 1 ? e->t_s[1] - e->t_s[0] : 1e-3;
    std::vector<T> force(n, T(0.0));
    T z(0.0);
    for (std::size_t i = 0; i < n; ++i) {
      BasicFrictionInput<T> in;
      in.v_m_per_s = T(off_zero(e->v_m_per_s[i]));
      in.gauge_sum_Pa = T(e->gauge_sum_Pa[i]);
      in.position_m = T(0.0);
      if (e->stuck[i]) {
        const T zmax = friction_law::static_N(p, in) / p.lugre.sigma0_N_per_m;
        z = T(e->F_N[i]) / p.lugre.sigma0_N_per_m;
        if (z > zmax) z = zmax;
        if (z < -zmax) z = -zmax;
        force[i] = p.lugre.sigma0_N_per_m * z;
        continue;
      }
      T dz;
      force[i] = friction_law::lugre_N(p, in, z, dz);
      // To the next sample in kSub steps, v linear between the samples, each step exact
      // for v held at its midpoint (the bristles' time constant g / (sigma0 |v|) can be
      // shorter than a sample).
      const double v0 = e->v_m_per_s[i], v1 = i + 1 < n ? e->v_m_per_s[i + 1] : v0;
      for (int k = 0; k < kSub; ++k) {
        const double v = off_zero(v0 + (v1 - v0) * (k + 0.5) / kSub);
        BasicFrictionInput<T> mid = in;
        mid.v_m_per_s = T(v);
        const T g = friction_law::stribeck_level_N(p, mid, mid.v_m_per_s);
        const T zss = (v >= 0.0 ? g : -g) / p.lugre.sigma0_N_per_m;
        z = zss + (z - zss) * exp(-p.lugre.sigma0_N_per_m * std::abs(v) * (dt / kSub) / g);
      }
    }
    std::size_t r = 0;
    for (const Block& b : data->blocks) {
      T mean(0.0);
      for (std::size_t k = b.first; k < b.first + b.count; ++k)
        mean += data->samples[k].w * force[block_samples[k]];
      residual[r++] = mean - b.target_N;
    }
    std::size_t s = 0;
    for (const StickInterval& st : e->sticks) {
      if (st.direction == 0 || !std::isfinite(st.breakaway_N)) continue;
      residual[r++] = force[st.end - 1] - data->breakaways[s++].F;
    }
    return true;
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

// Starting values: classic by linear least squares on the blocks; Stribeck by a grid over vs
// with the levels and B linear at each vs.
std::array<double, kQ> start_values(const FitData& d, bool stribeck, double delta) {
  std::array<double, kQ> q{};
  q[kDelta] = delta;
  q[kVs] = 10.0;
  double break_sum = 0.0;
  for (const Breakaway& b : d.breakaways) break_sum += b.dir * b.F;
  std::vector<std::vector<double>> rows;
  std::vector<double> y;
  for (const Block& b : d.blocks) {
    double dir = 0.0, v = 0.0;
    for (std::size_t k = b.first; k < b.first + b.count; ++k) {
      dir += d.samples[k].w * d.samples[k].dir;
      v += d.samples[k].w * d.samples[k].v;
    }
    rows.push_back({dir, v});
    y.push_back(b.target_N);
  }
  const auto c = linear_lsq(rows, y, nullptr);
  q[kFc] = std::max(0.0, c.size() > 0 ? c[0] : 0.0);
  q[kB] = std::max(0.0, c.size() > 1 ? c[1] : 0.0);
  q[kFs] = d.breakaways.empty() ? q[kFc]
                                : std::max(q[kFc], break_sum / double(d.breakaways.size()));
  if (!stribeck) return q;
  double best = std::numeric_limits<double>::infinity();
  for (int g = 0; g <= 60; ++g) {
    const double vs_mm = 0.1 * std::pow(10.0, g / 15.0);  // 0.1 mm/s .. 1 m/s
    std::vector<std::vector<double>> sr;
    std::vector<double> sy;
    for (const Block& b : d.blocks) {
      double c0 = 0.0, c1 = 0.0, c2 = 0.0;
      for (std::size_t k = b.first; k < b.first + b.count; ++k) {
        const Sample& s = d.samples[k];
        const double w = std::exp(-std::pow(std::abs(s.v) / (vs_mm * 1e-3), delta));
        c0 += s.w * s.dir * (1.0 - w);
        c1 += s.w * s.dir * w;
        c2 += s.w * s.v;
      }
      sr.push_back({c0, c1, c2});
      sy.push_back(b.target_N);
    }
    for (const Breakaway& b : d.breakaways) {
      sr.push_back({0.0, double(b.dir), 0.0});
      sy.push_back(b.F);
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
  o.function_tolerance = 1e-9;
  o.parameter_tolerance = 1e-9;
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

std::vector<double> static_residuals(const FitData& pts, FrictionKind kind, const double* q) {
  std::vector<double> r(pts.size());
  StaticResidual{&pts, kind}(q, r.data());
  return r;
}

ModelFit fit_static(FrictionFitModel model, const FitData& pts, std::size_t sliding,
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
  if (sliding < needed || pts.blocks.size() < 2 * f.free_params) {
    f.skipped = fmt::format("too few sliding samples to fit: {} (at least {} needed for {} "
                            "parameters)", sliding, needed, f.free_params);
    return f;
  }
  std::array<double, kQ> q = start_values(pts, stribeck, o.fixed_exponent);
  if (free_delta) {
    // The shortcuts for delta = 0.5, 1, 2 in stribeck_weight carry no derivative in delta:
    // start off them (the optimum lands on one exactly with probability zero).
    if (q[kDelta] == 2.0 || q[kDelta] == 1.0 || q[kDelta] == 0.5) q[kDelta] *= 1.05;
  }
  ceres::Problem problem;
  auto* cost = new ceres::AutoDiffCostFunction<StaticResidual, ceres::DYNAMIC, kQ>(
      new StaticResidual{&pts, kind}, static_cast<int>(pts.size()));
  problem.AddResidualBlock(cost, nullptr, q.data());
  if (!constant.empty()) problem.SetManifold(q.data(), new ceres::SubsetManifold(kQ, constant));
  for (int i : {kFc, kFs, kB, kGc, kGs}) problem.SetParameterLowerBound(q.data(), i, 0.0);
  problem.SetParameterLowerBound(q.data(), kVs, 0.01);
  problem.SetParameterUpperBound(q.data(), kVs, 1e4);
  // Bounds that always contain the start (the scenario's delta may lie outside 0.3..5).
  problem.SetParameterLowerBound(q.data(), kDelta, std::min(0.3, q[kDelta]));
  problem.SetParameterUpperBound(q.data(), kDelta, std::max(5.0, q[kDelta]));
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

ModelFit fit_lugre(const FrictionEstimate& e, const FitData& data, std::size_t sliding,
                   const ModelFit* stribeck, const FrictionFitOptions& o) {
  ModelFit f;
  f.model = FrictionFitModel::kLuGre;
  f.name = fit_model_name(f.model);
  f.free_params = 6;
  const std::size_t needed = 10 * f.free_params;
  if (sliding < needed || data.blocks.size() < 2 * f.free_params) {
    f.skipped = fmt::format("too few sliding samples to fit: {} (at least {} needed for {} "
                            "parameters)", sliding, needed, f.free_params);
    return f;
  }
  // Start from the Stribeck fit's levels (or the scenario's), all refitted with sigma0, sigma1.
  FrictionParams levels = stribeck ? stribeck->friction : o.start;
  if (!stribeck) levels.curve.stribeck_exponent = o.fixed_exponent;
  levels.kind = FrictionKind::kLuGre;
  levels.texture.clear();
  levels.memory = FrictionMemory::kNone;
  std::vector<std::size_t> index;
  for (const Block& b : data.blocks)
    for (std::size_t k = 0; k < b.count; ++k) index.push_back(b.begin + k);
  std::array<double, 6> q{std::log(std::clamp(o.start.lugre.sigma0_N_per_m, 1e3, 1e8)),
                          std::log(std::clamp(o.start.lugre.sigma1_Ns_per_m, 1e-2, 1e5)),
                          std::max(1e-3, levels.curve.coulomb_N),
                          std::max({1e-3, levels.curve.static_N, levels.curve.coulomb_N}),
                          std::max(0.02, levels.curve.stribeck_velocity_m_per_s * 1e3),
                          levels.curve.viscous_Ns_per_m};
  ceres::Problem problem;
  auto* functor = new LuGreResidual{&e, &data, index, levels};
  const LuGreResidual copy = *functor;
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LuGreResidual, ceres::DYNAMIC, 6>(
                               functor, static_cast<int>(data.size())),
                           nullptr, q.data());
  problem.SetParameterLowerBound(q.data(), 0, std::log(1e2));
  problem.SetParameterUpperBound(q.data(), 0, std::log(1e9));
  problem.SetParameterLowerBound(q.data(), 1, std::log(1e-3));
  problem.SetParameterUpperBound(q.data(), 1, std::log(1e6));
  for (int i : {2, 3, 5}) problem.SetParameterLowerBound(q.data(), i, 0.0);
  problem.SetParameterLowerBound(q.data(), 2, 1e-3);  // g(v) >= min(Fc, Fs) > 0 divides
  problem.SetParameterLowerBound(q.data(), 3, 1e-3);
  problem.SetParameterLowerBound(q.data(), 4, 0.01);
  problem.SetParameterUpperBound(q.data(), 4, 1e4);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(o.max_iterations), &problem, &summary);
  f.fitted = true;
  f.converged = converged(summary);
  f.summary = termination(summary);
  std::vector<double> res(data.size());
  copy(q.data(), res.data());
  score(f, res);
  const double dof = std::max(1.0, double(data.size()) - double(f.free_params));
  const auto se = standard_errors(problem, q.data(), 6, f.rms_N * f.rms_N * double(data.size()) / dof);
  levels.lugre.sigma0_N_per_m = std::exp(q[0]);
  levels.lugre.sigma1_Ns_per_m = std::exp(q[1]);
  levels.curve.coulomb_N = q[2];
  levels.curve.static_N = q[3];
  levels.curve.stribeck_velocity_m_per_s = q[4] * 1e-3;
  levels.curve.viscous_Ns_per_m = q[5];
  f.friction = levels;
  f.params.push_back({"Fc_N", q[2], se[2], "N", false});
  f.params.push_back({"Fs_N", q[3], se[3], "N", false});
  f.params.push_back({"vs_mm_per_s", q[4], se[4], "mm/s", false});
  f.params.push_back({"stribeck_exponent", levels.curve.stribeck_exponent, 0.0, "-", true});
  f.params.push_back({"B_Ns_per_m", q[5], se[5], "N*s/m", false});
  if (o.pressure_dependent) {
    f.params.push_back(
        {"Fc_gain_N_per_MPa", levels.pressure_gain.coulomb_N_per_Pa * 1e6, 0.0, "N/MPa", true});
    f.params.push_back(
        {"Fs_gain_N_per_MPa", levels.pressure_gain.static_N_per_Pa * 1e6, 0.0, "N/MPa", true});
  }
  f.params.push_back({"sigma0_N_per_m", levels.lugre.sigma0_N_per_m,
                      levels.lugre.sigma0_N_per_m * se[0], "N/m", false});
  f.params.push_back({"sigma1_Ns_per_m", levels.lugre.sigma1_Ns_per_m,
                      levels.lugre.sigma1_Ns_per_m * se[1], "N*s/m", false});
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

const ModelFit* FrictionFits::preferred() const {
  for (const auto& f : fits)
    if (f.name == preferred_model) return &f;
  return nullptr;
}

bool FrictionFits::any_converged() const {
  return std::any_of(fits.begin(), fits.end(),
                     [](const ModelFit& f) { return f.fitted && f.converged; });
}

namespace {

// Fc above Fs: a fit no scenario accepts (the seal's breakaway is at least its sliding level).
bool unphysical_levels(const ModelFit& f) {
  const FittedParameter* fc = f.param("Fc_N");
  const FittedParameter* fs = f.param("Fs_N");
  return fc != nullptr && fs != nullptr && fc->value > fs->value;
}

// The warnings of fit_friction: a model that did not converge is kept, marked and never
// preferred; a kinetic level above the static one is no breakaway peak and is said so.
std::vector<std::string> fit_warnings(const std::vector<ModelFit>& fits) {
  std::vector<std::string> w;
  for (const auto& f : fits) {
    if (!f.fitted) continue;
    if (!f.converged) {
      w.push_back(fmt::format("the {} fit did not converge ({}): its parameters are shown, "
                              "marked, and not used; the other models stand",
                              f.name, f.summary));
      continue;
    }
    if (unphysical_levels(f)) {
      const FittedParameter* fc = f.param("Fc_N");
      const FittedParameter* fs = f.param("Fs_N");
      w.push_back(fmt::format("the {} fit has Fc {:.3g} N above Fs {:.3g} N, which no seal has "
                              "(breakaway is at least the sliding level): its levels are not "
                              "identified by this record, and it is not preferred",
                              f.name, fc->value, fs->value));
    }
  }
  return w;
}

}  // namespace

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
  o.validate();
  const FitData pts = fit_data(e);
  const std::size_t sliding = e.sliding_count();
  const bool breakaways = !pts.breakaways.empty();
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
    if (f.fitted && f.converged && !unphysical_levels(f) && f.bic < best) {
      best = f.bic;
      out.preferred_model = f.name;
    }
  out.warnings = fit_warnings(out.fits);
  return out;
}

FrictionFitOptions fit_options_for(const Scenario& scenario, const std::vector<std::string>& models,
                                   bool pressure_dependent, const std::string& where) {
  FrictionFitOptions fit;
  if (!models.empty()) fit.models.clear();
  for (const auto& m : models) {
    const FrictionFitModel model = parse_fit_model(m, where);
    if (std::find(fit.models.begin(), fit.models.end(), model) == fit.models.end())
      fit.models.push_back(model);
  }
  fit.pressure_dependent = pressure_dependent;
  fit.fixed_exponent = scenario.friction.curve.stribeck_exponent;
  fit.start = scenario.friction;
  return fit;
}

void require_converged(const FrictionFits& fits) {
  const ModelFit* failed = fits.failed();
  if (failed != nullptr && !fits.any_converged())
    throw RunError("friction fit " + failed->name,
                   "did not converge (" + failed->summary +
                       "), nor did any other model; no output written");
}

}  // namespace pneumachaos::identify
