// The outputs of `pneumachaos fit`: JSON, validation CSV and its plot commands (docs/reference/outputs.md).

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "pneumachaos/identify/fit.hpp"

namespace pneumachaos::identify {
namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

std::string fit_json(const FitResult& r, const FitOptions& o, const MeasuredRecord& record) {
  nlohmann::json j;
  j["record"] = {{"source", record.source},
                 {"samples", record.size()},
                 {"duration_s", number(record.size() > 1 ? record.t_s.back() - record.t_s.front() : 0.0)},
                 {"position", record.x_m ? "recorded" : "integrated from v"}};
  nlohmann::json params = nlohmann::json::object();
  nlohmann::json order = nlohmann::json::array();
  for (const auto& p : r.parameters) {
    params[p.key] = {{"value", number(p.value)},
                     {"stderr", number(p.standard_error)},
                     {"unit", p.unit},
                     {"start", number(p.start)}};
    order.push_back(p.key);
  }
  j["free"] = order;
  j["parameters"] = params;
  j["rms"] = {{"P1", {{"value", number(r.rms_P1_Pa)}, {"unit", "Pa"}}},
              {"P2", {{"value", number(r.rms_P2_Pa)}, {"unit", "Pa"}}},
              {"v", {{"value", number(r.rms_v_m_per_s)}, {"unit", "m/s"}}}};
  nlohmann::json candidates = nlohmann::json::array();
  for (std::size_t i = 0; i < r.candidate_costs.size(); ++i) {
    candidates.push_back({{"segment_length_s", r.candidate_segment_lengths_s[i]},
                          {"cost", number(r.candidate_costs[i])}});
  }
  j["method"] = {{"segment_length_s", o.segment_length_s},
                 {"segments", r.segments},
                 {"residuals", r.residuals},
                 {"pressure_scale_Pa", o.pressure_scale_Pa},
                 {"velocity_scale_m_per_s", o.velocity_scale_m_per_s},
                 {"difference_step_log", o.difference_step},
                 {"fit_start_pressures", o.fit_start_pressures},
                 {"candidates", candidates},
                 {"chosen_candidate", r.chosen_candidate}};
  j["cost"] = {{"initial", number(r.initial_cost)}, {"final", number(r.final_cost)}};
  j["reduced_chi2"] = number(r.reduced_chi2);
  j["iterations"] = r.iterations;
  j["wall_time_s"] = number(r.wall_time_s);
  j["converged"] = true;
  j["summary"] = r.summary;
  return j.dump(2) + "\n";
}

std::string validation_csv(const ValidationSeries& s) {
  std::string out =
      "t[s],v_meas[m/s],v_sim[m/s],P1_meas[Pa],P1_sim[Pa],P2_meas[Pa],P2_sim[Pa],segment[-]\n";
  std::size_t seg = 0;
  for (std::size_t k = 0; k < s.t_s.size(); ++k) {
    while (seg + 1 < s.segment_starts.size() && s.segment_starts[seg + 1] <= k) ++seg;
    out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", s.t_s[k],
                       s.v_meas[k], s.v_sim[k], s.p1_meas[k], s.p1_sim[k], s.p2_meas[k],
                       s.p2_sim[k], seg);
  }
  return out;
}

std::string validation_plot_commands(const std::string& csv) {
  return fmt::format(
      "set datafile separator ','\n"
      "set key autotitle columnhead top right\n"
      "set grid\n"
      "set multiplot layout 3,1 title 'fit: measured (grey) and segment-wise simulated (red)'\n"
      "set ylabel 'v [mm/s]'\n"
      "plot '{0}' using 1:($2*1000) with lines lc rgb '#999999' title 'measured', \\\n"
      "     '' using 1:($3*1000) with lines lc rgb '#cc0000' title 'simulated'\n"
      "set ylabel 'P1 [kPa abs]'\n"
      "plot '{0}' using 1:($4/1000) with lines lc rgb '#999999' title 'measured', \\\n"
      "     '' using 1:($5/1000) with lines lc rgb '#cc0000' title 'simulated'\n"
      "set ylabel 'P2 [kPa abs]'\n"
      "set xlabel 't [s]'\n"
      "plot '{0}' using 1:($6/1000) with lines lc rgb '#999999' title 'measured', \\\n"
      "     '' using 1:($7/1000) with lines lc rgb '#cc0000' title 'simulated'\n"
      "unset multiplot\n",
      csv);
}

}  // namespace pneumachaos::identify
