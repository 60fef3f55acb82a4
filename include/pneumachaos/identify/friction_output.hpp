#pragma once
// The friction command's outputs (docs/friction.md, "Outputs"): the summary, the JSON, the
// curves for plotting and the scenario fragment.

#include <string>

#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/io/atomic_file.hpp"

namespace pneumachaos::identify {

/// Human-readable account: the method's settings, sticks, breakaways, each fit.
std::string friction_summary(const FrictionEstimate& e, const FrictionFits& fits);

/// fits.<model>.<param>.{value,stderr,unit}, fits.<model>.rms_N, breakaway_N,
/// stick_intervals, rms_N (per model), preferred_model, steady_curve, loops, ...
std::string friction_json(const FrictionEstimate& e, const FrictionFits& fits,
                          const EstimateSpec& settings, const std::string& source);

/// A [friction] table that plugs `fit` into `simulate` (model, Fc_N, Fs_N, ...).
std::string friction_scenario_toml(const ModelFit& fit, const std::string& source);

/// force.csv (F(t) and the F(v) points), steady_curve.csv, model_<name>.csv per fit,
/// loop_marks.csv, added to `outputs` under `dir`.
void write_friction_series(const FrictionEstimate& e, const FrictionFits& fits,
                           const std::string& dir, OutputSet& outputs);

}  // namespace pneumachaos::identify
