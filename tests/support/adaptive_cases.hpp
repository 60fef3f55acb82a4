#pragma once
// The maps on which adaptive sweeps are validated against the full grid (the long test
// AdaptiveSweep.PaperGridAgreesWithTheFullGrid and bench/bench_adaptive; docs/sweep.md
// "Adaptive maps"): the paper's four maps of the default rig, the simple rig's Fig. 4 map,
// and the default rig on a grid of small S1 whose borders cross S1.
#include <string>
#include <vector>

#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

struct AdaptiveCase {
  std::string name;
  SweepSpec spec;         ///< the full grid's (adaptive.enabled false), coarse step the default
  double min_runs_ratio;  ///< full-grid runs per adaptive run at least this (4 on the paper's maps)
};

/// `variants_dir`: scenarios/variants. Each map as reproduce runs it: the paper's Ps and total moving
/// mass, 5 runs per point, 3 % friction variation and a 2 % bore texture per run.
inline std::vector<AdaptiveCase> adaptive_cases(const std::string& variants_dir) {
  const auto spec = [](Scenario base, std::vector<GridAxis> axes) {
    SweepSpec s;
    s.base = std::move(base);
    s.base.variation.friction_rel_sd = 0.03;
    s.base.variation.texture_rel = 0.02;
    s.axes = std::move(axes);
    s.repeats = 5;
    return s;
  };
  // The report's conditions (src/report/reproduce.cpp): Ps and the total moving mass m.
  const auto fig = [&](const std::string& Ps_MPa, double m_kg) {
    Scenario base = build_scenario("", {"supply.pressure_MPa=" + Ps_MPa});
    base.set_total_moving_mass(m_kg);
    return spec(std::move(base), paper_valve_grid());
  };
  return {
      {"fig4 (Ps 0.25 MPa, m 1.5 kg)", fig("0.25", 1.5), 4.0},
      {"fig5 (Ps 0.30 MPa, m 1.5 kg)", fig("0.30", 1.5), 4.0},
      {"fig6 (Ps 0.25 MPa, m 3.0 kg)", fig("0.25", 3.0), 4.0},
      {"fig6b (Ps 0.25 MPa, m 4.5 kg)", fig("0.25", 4.5), 4.0},
      {"simple rig, fig4 grid",
       spec(build_scenario(variants_dir + "/simple_rig.toml", {}), paper_valve_grid()), 1.0},
      {"default rig, S1 0.10-1.35 mm^2",
       spec(build_scenario("", {}),
            {parse_grid_axis("circuit.S1_mm2=0.10:1.35:0.05"), paper_valve_grid()[1]}),
       1.0},
  };
}

}  // namespace pneumachaos
