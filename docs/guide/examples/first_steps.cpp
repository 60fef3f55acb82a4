// The guide's C++ example (docs/guide/cpp.md): one scenario set through its typed fields, its
// linear stability, a simulation and the chaos analysis of the piston velocity, and a small
// S1 x S2 sweep, through the installed library and its one public header.
// Built and run by the test docs.cpp_example (tests/consumer/run.sh).
#include <cstdio>
#include <exception>
#include <filesystem>

#include "pneumachaos/pneumachaos.hpp"

namespace pc = pneumachaos;

int main() {
  try {
    // The built-in virtual rig with a narrow exhaust and a short record; SI units throughout.
    pc::Scenario scenario = pc::default_scenario();
    scenario.circuit.S2_m2 = 0.05e-6;  // 0.05 mm^2
    scenario.run.duration_s = 5.0;
    scenario.validate();  // throws pc::Error naming the key of a value out of range
    const pc::Plant plant(scenario);

    const pc::StabilityResult stability = pc::analyze_stability(plant);
    std::printf("steady motion: %s (largest real part %.2f 1/s)\n",
                pc::verdict_name(stability.verdict_full), stability.max_real_part_per_s);

    const pc::SimulationResult run = pc::simulate(plant, scenario.run);
    if (!run.summary.ok()) {
      std::fprintf(stderr, "%s\n", pc::describe(run.summary).c_str());
      return 3;
    }
    const auto& v = run.series.channel("v").values;  // piston velocity [m/s]
    const pc::AnalysisResult analysis = pc::analyze_series(v, run.series.rate_Hz());
    std::printf("%zu samples at %.0f Hz: %s (stick-slip: %s)\n", analysis.samples,
                analysis.rate_Hz, pc::regime_name(analysis.verdict.regime),
                analysis.verdict.stick_slip ? "yes" : "no");

    // A 2 x 2 map over S1 x S2 (in mm^2, as the command line's --grid), one run per point.
    pc::SweepSpec sweep;
    sweep.base = scenario;
    sweep.axes = {pc::parse_grid_axis("circuit.S1_mm2=2.45:2.70:0.25"),
                  pc::parse_grid_axis("circuit.S2_mm2=0.05:0.35:0.30")};
    sweep.repeats = 1;
    pc::SweepOptions where;
    where.out_dir = (std::filesystem::temp_directory_path() / "first_steps_sweep").string();
    std::filesystem::remove_all(where.out_dir);
    const pc::SweepSummary map = pc::run_sweep(sweep, where);
    std::printf("map: %zu points, %zu with stick-slip, %zu failed runs\n", map.points,
                map.stick_slip_points, map.failed);
    return map.failed == 0 ? 0 : 3;
  } catch (const std::exception& e) {  // bad keys, values out of range: the message names them
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
