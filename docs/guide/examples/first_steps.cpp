// The guide's C++ example (docs/guide/cpp.md): one scenario, its linear stability, a
// simulation and the chaos analysis of the piston velocity, through the installed library.
// Built and run by the test docs.cpp_example (tests/docs_cpp_example.sh).
#include <cstdio>
#include <exception>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/stability_analysis.hpp"

int main() {
  namespace pc = pneumachaos;
  try {
    // The built-in virtual rig with two keys changed, as `--set` does on the command line
    // (the first argument is a TOML file; empty: the built-in scenario).
    const pc::Scenario scenario =
        pc::build_scenario("", {"circuit.S2_mm2=0.05", "run.duration_s=5"});
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
    return 0;
  } catch (const std::exception& e) {  // bad keys, values out of range: the message names them
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
