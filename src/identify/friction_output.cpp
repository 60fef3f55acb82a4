#include "pneumachaos/identify/friction_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace pneumachaos::identify {
namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

double median_gauge(const FrictionEstimate& e) {
  std::vector<double> g;
  for (std::size_t i = 0; i < e.gauge_sum_Pa.size(); ++i)
    if (e.sliding[i]) g.push_back(e.gauge_sum_Pa[i]);
  if (g.empty()) g = e.gauge_sum_Pa;
  if (g.empty()) return 0.0;
  std::nth_element(g.begin(), g.begin() + static_cast<std::ptrdiff_t>(g.size() / 2), g.end());
  return g[g.size() / 2];
}

std::vector<double> breakaways(const FrictionEstimate& e) {
  std::vector<double> b;
  for (const auto& s : e.sticks)
    if (s.direction != 0 && std::isfinite(s.breakaway_N)) b.push_back(s.breakaway_N);
  return b;
}

}  // namespace

std::string friction_summary(const FrictionEstimate& e, const FrictionFits& fits) {
  std::string s;
  const double dt = e.t_s.size() > 1 ? e.t_s[1] - e.t_s[0] : 0.0;
  s += fmt::format("samples          {} at {:g} Hz\n", e.t_s.size(), dt > 0 ? 1.0 / dt : 0.0);
  if (e.acceleration_given)
    s += "acceleration     from the record's a column\n";
  else
    s += fmt::format("acceleration     Savitzky-Golay derivative, window {} samples ({:g} ms) median, "
                     "{}-{} by the noise/bias rule\n",
                     2 * e.sg_half_width + 1, (2 * e.sg_half_width + 1) * dt * 1e3,
                     2 * e.sg_half_width_min + 1, 2 * e.sg_half_width_max + 1);
  s += fmt::format("velocity noise   {:.3g} mm/s; at rest below {:.3g} mm/s\n",
                   e.velocity_noise_m_per_s * 1e3, e.stick_threshold_m_per_s * 1e3);
  s += fmt::format("force noise      {:.3g} N\n", e.force_noise_N);
  s += fmt::format("sliding samples  {}\n", e.sliding_count());
  s += fmt::format("stick intervals  {}\n", e.sticks.size());
  const auto b = breakaways(e);
  if (!b.empty()) {
    std::string list;
    for (double x : b) list += fmt::format("{}{:.1f}", list.empty() ? "" : ", ", x);
    s += fmt::format("breakaway [N]    {}\n", list);
  }
  s += fmt::format("excursions       {}\n", e.excursions.size());
  for (const auto& f : fits.fits) {
    if (!f.fitted) {
      s += fmt::format("\n{}: not fitted: {}\n", f.name, f.skipped);
      continue;
    }
    s += fmt::format("\n{}: rms {:.3g} N over {} points, BIC {:.1f}{}\n", f.name, f.rms_N,
                     f.points, f.bic, f.converged ? "" : " (did NOT converge: " + f.summary + ")");
    for (const auto& p : f.params)
      s += fmt::format("  {:<20} {:>12.5g} +- {:<10.3g} {}{}\n", p.name, p.value, p.stderr_value,
                       p.unit, p.fixed ? " (fixed)" : "");
  }
  s += fmt::format("\npreferred model  {} ({})\n",
                   fits.preferred_model.empty() ? "none" : fits.preferred_model, fits.criterion);
  return s;
}

namespace {

using nlohmann::json;

json sticks_json(const FrictionEstimate& e) {
  json sticks = json::array();
  for (const auto& s : e.sticks)
    sticks.push_back({{"t_begin_s", s.t_begin_s},
                      {"t_end_s", s.t_end_s},
                      {"breakaway_N", number(s.breakaway_N)},
                      {"direction", s.direction}});
  return sticks;
}

json curve_json(const FrictionEstimate& e) {
  json curve = json::array();
  for (const auto& c : e.curve)
    curve.push_back({{"v_mm_per_s", c.v_mean_m_per_s * 1e3},
                     {"v_lo_mm_per_s", c.v_lo_m_per_s * 1e3},
                     {"v_hi_mm_per_s", c.v_hi_m_per_s * 1e3},
                     {"F_N", c.F_mean_N},
                     {"F_sd_N", c.F_sd_N},
                     {"count", c.count}});
  return curve;
}

json loops_json(const FrictionEstimate& e) {
  json loops = json::array();
  for (const auto& x : e.excursions) {
    json marks = json::object();
    for (const auto& m : x.marks)
      marks[std::string(1, m.label)] = {{"t_s", e.t_s[m.index]},
                                        {"v_mm_per_s", m.v_m_per_s * 1e3},
                                        {"F_N", m.F_N}};
    loops.push_back({{"t_begin_s", e.t_s[x.begin]},
                     {"t_end_s", e.t_s[x.end - 1]},
                     {"direction", x.direction},
                     {"from_stick", x.from_stick},
                     {"to_stick", x.to_stick},
                     {"marks", marks}});
  }
  return loops;
}

json fit_json_of(const ModelFit& f) {
  json m = json::object();
  if (!f.fitted) {
    m["skipped"] = f.skipped;
    return m;
  }
  for (const auto& p : f.params)
    m[p.name] = {{"value", number(p.value)},
                 {"stderr", number(p.stderr_value)},
                 {"unit", p.unit},
                 {"fixed", p.fixed}};
  m["rms_N"] = number(f.rms_N);
  m["points"] = f.points;
  m["free_parameters"] = f.free_params;
  m["bic"] = number(f.bic);
  m["aic"] = number(f.aic);
  m["converged"] = f.converged;
  m["summary"] = f.summary;
  return m;
}

}  // namespace

std::string friction_json(const FrictionEstimate& e, const FrictionFits& fits,
                          const EstimateSpec& st, const std::string& source) {
  json j;
  j["file"] = source;
  j["samples"] = e.t_s.size();
  j["settings"] = {{"A1_m2", st.area_head_m2},
                   {"A2_m2", st.area_rod_m2},
                   {"mass_kg", st.mass_kg},
                   {"ambient_Pa", st.ambient_Pa},
                   {"external_force_N", st.external_force_N}};
  const auto window = [&](std::size_t h) { return e.acceleration_given ? 0 : 2 * h + 1; };
  j["acceleration"] = {{"source", e.acceleration_given ? "column" : "savitzky-golay"},
                       {"window_samples", window(e.sg_half_width)},
                       {"window_min_samples", window(e.sg_half_width_min)},
                       {"window_max_samples", window(e.sg_half_width_max)},
                       {"polynomial_order", 2}};
  j["velocity_noise_mm_per_s"] = number(e.velocity_noise_m_per_s * 1e3);
  j["stick_threshold_mm_per_s"] = number(e.stick_threshold_m_per_s * 1e3);
  j["force_noise_N"] = number(e.force_noise_N);
  j["sliding_samples"] = e.sliding_count();
  j["stick_intervals"] = sticks_json(e);
  j["breakaway_N"] = breakaways(e);
  j["steady_curve"] = curve_json(e);
  j["loops"] = loops_json(e);
  json fj = json::object(), rms = json::object();
  for (const auto& f : fits.fits) {
    fj[f.name] = fit_json_of(f);
    if (f.fitted) rms[f.name] = number(f.rms_N);
  }
  j["fits"] = fj;
  j["rms_N"] = rms;
  j["preferred_model"] = fits.preferred_model.empty() ? json(nullptr) : json(fits.preferred_model);
  j["criterion"] = fits.criterion;
  j["warnings"] = fits.warnings;
  return j.dump(2);
}

std::string friction_scenario_toml(const ModelFit& f, const std::string& source) {
  const FrictionParams& p = f.friction;
  std::string s = fmt::format(
      "# Seal friction fitted by `pneumachaos friction` to {}\n# model {} (rms {:.3g} N); merge into a "
      "scenario or pass as --set friction.KEY=VALUE\n[friction]\n",
      source, f.name, f.rms_N);
  const char* model = p.kind == FrictionKind::kClassic ? "classic"
                      : p.kind == FrictionKind::kLuGre ? "lugre"
                                                       : "stribeck";
  s += fmt::format("model = \"{}\"\n", model);
  s += fmt::format("Fc_N = {:.6g}\n", p.curve.coulomb_N);
  s += fmt::format("Fs_N = {:.6g}\n", std::max(p.curve.static_N, p.curve.coulomb_N));
  s += fmt::format("B_Ns_per_m = {:.6g}\n", p.curve.viscous_Ns_per_m);
  if (p.kind != FrictionKind::kClassic) {
    s += fmt::format("vs_mm_per_s = {:.6g}\n", p.curve.stribeck_velocity_m_per_s * 1e3);
    s += fmt::format("stribeck_exponent = {:.6g}\n", p.curve.stribeck_exponent);
  }
  if (p.kind == FrictionKind::kLuGre) {
    s += fmt::format("sigma0_N_per_m = {:.6g}\n", p.lugre.sigma0_N_per_m);
    s += fmt::format("sigma1_Ns_per_m = {:.6g}\n", p.lugre.sigma1_Ns_per_m);
  }
  s += fmt::format("Fc_gain_N_per_MPa = {:.6g}\n", p.pressure_gain.coulomb_N_per_Pa * 1e6);
  s += fmt::format("Fs_gain_N_per_MPa = {:.6g}\n", p.pressure_gain.static_N_per_Pa * 1e6);
  return s;
}

void write_friction_series(const FrictionEstimate& e, const FrictionFits& fits,
                           const std::string& dir, OutputSet& outputs) {
  const auto path = [&](const std::string& name) {
    return (std::filesystem::path(dir) / name).string();
  };
  {
    auto& out = outputs.add(path("force.csv"));
    out << "t[s],v[m/s],a[m/s^2],F[N],stuck[-],sliding[-]\n";
    for (std::size_t i = 0; i < e.t_s.size(); ++i)
      out << fmt::format("{},{},{},{},{},{}\n", e.t_s[i], e.v_m_per_s[i], e.a_m_per_s2[i], e.F_N[i],
                         int(e.stuck[i]), int(e.sliding[i]));
  }
  {
    auto& out = outputs.add(path("steady_curve.csv"));
    out << "v[m/s],F[N],F_sd[N],count[-],v_lo[m/s],v_hi[m/s]\n";
    for (const auto& c : e.curve)
      out << fmt::format("{},{},{},{},{},{}\n", c.v_mean_m_per_s, c.F_mean_N, c.F_sd_N, c.count,
                         c.v_lo_m_per_s, c.v_hi_m_per_s);
  }
  {
    auto& out = outputs.add(path("loop_marks.csv"));
    out << "excursion[-],label[-],t[s],v[m/s],F[N]\n";
    for (std::size_t k = 0; k < e.excursions.size(); ++k)
      for (const auto& m : e.excursions[k].marks)
        out << fmt::format("{},{},{},{},{}\n", k + 1, m.label, e.t_s[m.index], m.v_m_per_s, m.F_N);
  }
  double top = e.stick_threshold_m_per_s;
  for (double v : e.v_m_per_s) top = std::max(top, std::abs(v));
  const double g = median_gauge(e);
  for (const auto& f : fits.fits) {
    if (!f.fitted) continue;
    auto& out = outputs.add(path("model_" + f.name + ".csv"));
    out << "v[m/s],F[N]\n";
    constexpr int kPoints = 200;
    for (int k = -kPoints; k <= kPoints; ++k) {
      if (k == 0) continue;
      const double v = top * double(k) / kPoints;
      out << fmt::format("{},{}\n", v, steady_friction_N(f.friction, v, g));
    }
  }
}

}  // namespace pneumachaos::identify
