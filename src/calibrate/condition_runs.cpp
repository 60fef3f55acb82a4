#include "condition_runs.hpp"

#include "pneumachaos/sweep/distribution.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/claims/example_run.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

namespace pneumachaos::detail {
namespace {

std::optional<SweepSummary>& slot(ClaimInputs& in, const std::string& role) {
  if (role == "base") return in.base;
  if (role == "high_ps") return in.high_ps;
  if (role == "double_m") return in.double_m;
  return in.triple_m;
}

}  // namespace

void clear_role(ClaimInputs& inputs, const std::string& role) { slot(inputs, role).reset(); }

bool is_writer_rank() { return Distribution::instance().rank() == 0; }

SweepSpec map_sweep_spec(const ObjectiveSpec& o, Scenario scenario, const MapCondition& c) {
  apply_setting(scenario, "supply.pressure_MPa", c.Ps_MPa, c.where);
  scenario.set_total_moving_mass(c.m_kg);
  SweepSpec spec;
  spec.base = std::move(scenario);
  spec.base.run.duration_s = o.maps.duration_s;
  spec.axes = o.maps.axes;
  spec.repeats = o.maps.repeats;
  spec.adaptive.enabled = o.maps.adaptive;
  spec.paper_judge = o.paper_judge;
  // The damping claims read a point's motion on the coarse lattice, which every map runs.
  return spec;
}

SweepSummary run_map(const SweepSpec& spec, const std::string& dir, const ConditionRunOptions& settings) {
  SweepSpec s = spec;
  s.seed = settings.sweep_seed;
  SweepOptions so;
  so.out_dir = dir;
  so.threads = settings.threads;
  so.progress = false;
  so.resume = true;
  return run_sweep(s, so);
}

void run_conditions(const ObjectiveSpec& o, const Scenario& scenario,
                    const ConditionSet& conditions, const std::string& dir,
                    const ConditionRunOptions& settings, ClaimInputs& inputs) {
  if (!o.maps.axes.empty()) inputs.grid = {o.maps.axes[0].values, o.maps.axes[1].values};
  for (const MapCondition& c : conditions.maps) {
    SweepSpec spec;
    try {
      spec = map_sweep_spec(o, scenario, c);
      spec.validate();
    } catch (const RunError&) {
      throw;
    } catch (const Error&) {
      continue;  // the model refuses this scenario at this condition: the map is missing
    }
    slot(inputs, c.role) = run_map(spec, dir + "/" + c.role, settings);
  }
  if (conditions.example) add_example(o, scenario, inputs);
  if (o.paper_judge) inputs = under_paper_judge(inputs);
}

void add_example(const ObjectiveSpec& o, const Scenario& scenario, ClaimInputs& inputs) {
  try {
    // The example runs without the maps' scatter and texture, as reproduce's does
    // (run_example keeps only the seal's random level).
    add_example_inputs(inputs,
                       run_example(scenario, o.example_record_s, o.example_model_exponent));
  } catch (const RunError&) {
    throw;
  } catch (const Error&) {
    // A failed simulation or an invalid scenario: the example's claims are not reproduced.
  }
}

}  // namespace pneumachaos::detail
