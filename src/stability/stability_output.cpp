#include "pneumachaos/stability/stability_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/json_quantity.hpp"

namespace pneumachaos {
namespace {

nlohmann::json quantity(double value, const char* unit) { return json_quantity(value, unit); }

const char* circuit_name(const Scenario& s) {
  return s.circuit.kind == CircuitKind::kMeterOut ? "meter-out" : "meter-in";
}

}  // namespace

namespace {

// Why the equilibrium sits where it does: the scenario's frozen volumes, mid-stroke (the
// default), or a position the caller chose.
std::string position_reason(const Scenario& s, double position_m) {
  const CylinderGeometry& c = s.cylinder;
  if (c.volumes_frozen() && std::abs(position_m - c.frozen_position_m) < 1e-9)
    return "the scenario's cylinder.frozen_position_mm";
  if (!c.volumes_frozen() && std::abs(position_m - 0.5 * c.stroke_m) < 1e-9)
    return "mid-stroke, the default; --position-mm sets another";
  return "--position-mm";
}

}  // namespace

std::string stability_table(const Scenario& s, const StabilityResult& r) {
  const double Pa = s.ambient_pressure_Pa;
  std::string out = fmt::format(
      "circuit {}, S1 = {:.3g} mm^2, S2 = {:.3g} mm^2, Ps = {:.3g} MPa gauge, m = {:.3g} kg\n",
      circuit_name(s), s.circuit.S1() * 1e6, s.circuit.S2() * 1e6, s.supply_gauge_Pa * 1e-6,
      s.load.mass_kg);
  if (!r.has_equilibrium()) return out + "no steady motion: " + r.reason + "\n";
  const Equilibrium& e = r.equilibrium;
  const bool meter_out = s.circuit.kind == CircuitKind::kMeterOut;
  out += fmt::format(
      "equilibrium at x = {:.1f} mm ({}): v0 = {:.3f} mm/s, P10 = {:.4f} MPa, P20 = {:.4f} MPa "
      "(gauge), friction {:.3f} N, slope B = {:.4g} N*s/m\n",
      e.position_m * 1e3, position_reason(s, e.position_m), e.v0_m_per_s * 1e3,
      (e.P10_Pa - Pa) * 1e-6, (e.P20_Pa - Pa) * 1e-6, e.friction_N, e.slope_Ns_per_m);
  out +=
      fmt::format("paper ({}): {} = {:.4g} N*s/m, {} = {:.4g} N/m, zeta = {:.4g} -> {}\n",
                  meter_out ? "eqs. 6-9" : "eqs. 10-11", meter_out ? "a1" : "b1",
                  meter_out ? r.paper.a1 : r.paper.b1, meter_out ? "a2" : "b2",
                  meter_out ? r.paper.a2 : r.paper.b2, r.paper.zeta, verdict_name(r.paper.verdict));
  out += fmt::format("full model ({} states: ", r.state_names.size());
  for (std::size_t i = 0; i < r.state_names.size(); ++i) out += (i ? ", " : "") + r.state_names[i];
  out += "): eigenvalues [1/s]\n";
  for (const auto& ev : r.eigenvalues) {
    out += fmt::format("  {:>12.5g} {:+.5g}i\n", ev.real(), ev.imag());
  }
  out += fmt::format("  largest real part {:.4g} 1/s -> {}\n", r.max_real_part_per_s,
                     verdict_name(r.verdict_full));
  if (r.oscillatory_frequency_Hz > 0.0) {
    out += fmt::format("  oscillatory pair: {:.4g} Hz, damping ratio {:.4g}\n",
                       r.oscillatory_frequency_Hz, r.oscillatory_damping_ratio);
  }
  out += r.agree() ? "the paper's approximation and the full model agree\n"
                   : "the paper's approximation and the full model DISAGREE\n";
  return out;
}

std::string stability_json(const Scenario& s, const StabilityResult& r) {
  const double Pa = s.ambient_pressure_Pa;
  nlohmann::json j;
  j["circuit"] = circuit_name(s);
  j["S1"] = quantity(s.circuit.S1() * 1e6, "mm^2");
  j["S2"] = quantity(s.circuit.S2() * 1e6, "mm^2");
  j["supply_pressure"] = quantity(s.supply_gauge_Pa * 1e-6, "MPa gauge");
  j["mass"] = quantity(s.load.mass_kg, "kg");
  j["equilibrium_exists"] = r.has_equilibrium();
  if (!r.has_equilibrium()) {
    j["reason"] = r.reason;
    return j.dump(2);
  }
  const Equilibrium& e = r.equilibrium;
  j["equilibrium"] = {{"position", quantity(e.position_m * 1e3, "mm")},
                      {"v0", quantity(e.v0_m_per_s * 1e3, "mm/s")},
                      {"P10", quantity((e.P10_Pa - Pa) * 1e-6, "MPa gauge")},
                      {"P20", quantity((e.P20_Pa - Pa) * 1e-6, "MPa gauge")},
                      {"friction", quantity(e.friction_N, "N")},
                      {"B", quantity(e.slope_Ns_per_m, "N*s/m")}};
  j["paper"] = {{"Cd1", quantity(r.paper.Cd1_kg_per_sPa, "kg/(s*Pa)")},
                {"Cd2", quantity(r.paper.Cd2_kg_per_sPa, "kg/(s*Pa)")},
                {"a1", quantity(r.paper.a1, "N*s/m")},
                {"a2", quantity(r.paper.a2, "N/m")},
                {"a", quantity(r.paper.a, "1/s")},
                {"b1", quantity(r.paper.b1, "N*s/m")},
                {"b2", quantity(r.paper.b2, "N/m")},
                {"b", quantity(r.paper.b, "1/s")},
                {"zeta", quantity(r.paper.zeta, "-")},
                {"verdict", verdict_name(r.paper.verdict)}};
  nlohmann::json eig = nlohmann::json::array();
  for (const auto& ev : r.eigenvalues) eig.push_back({{"re", ev.real()}, {"im", ev.imag()}});
  j["full_model"] = {{"states", r.state_names},
                     {"eigenvalues", {{"values", eig}, {"unit", "1/s"}}},
                     {"max_real_part", quantity(r.max_real_part_per_s, "1/s")},
                     {"dominant_frequency", quantity(r.dominant_frequency_Hz, "Hz")},
                     {"dominant_damping_ratio", quantity(r.dominant_damping_ratio, "-")},
                     {"oscillatory_frequency", quantity(r.oscillatory_frequency_Hz, "Hz")},
                     {"oscillatory_damping_ratio", quantity(r.oscillatory_damping_ratio, "-")},
                     {"verdict", verdict_name(r.verdict_full)}};
  j["agree"] = r.agree();
  return j.dump(2);
}

void write_stability_map_csv(std::ostream& out, const StabilityMap& map, double ambient_Pa) {
  for (const auto& a : map.axes) out << a.key << ',';
  out << "v0_mm_per_s,P10_MPa_gauge,P20_MPa_gauge,B_Ns_per_m,a1_Ns_per_m,b1_Ns_per_m,"
         "zeta_paper,verdict_paper,max_real_part_per_s,osc_frequency_Hz,osc_damping_ratio,"
         "verdict_full,agree,error\n";
  for (const auto& p : map.points) {
    for (double c : p.coordinates) out << fmt::format("{},", c);
    const StabilityResult& r = p.result;
    if (!r.has_equilibrium()) {
      std::string why = p.error.empty() ? r.reason : p.error;
      for (char& c : why) c = (c == ',' || c == '"') ? ';' : c;
      out << ",,,,,,,,"
          << ",,,no-equilibrium,," << '"' << why << '"' << '\n';
      continue;
    }
    const Equilibrium& e = r.equilibrium;
    out << fmt::format(
        "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{:.6g},{:.6g},{:.6g},{},{},\n",
        e.v0_m_per_s * 1e3, (e.P10_Pa - ambient_Pa) * 1e-6, (e.P20_Pa - ambient_Pa) * 1e-6,
        e.slope_Ns_per_m, r.paper.a1, r.paper.b1, r.paper.zeta, verdict_name(r.paper.verdict),
        r.max_real_part_per_s, r.oscillatory_frequency_Hz, r.oscillatory_damping_ratio,
        verdict_name(r.verdict_full), r.agree() ? 1 : 0);
  }
}

}  // namespace pneumachaos
