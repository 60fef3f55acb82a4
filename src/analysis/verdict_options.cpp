// The verdict's thresholds checked before a record is judged: each out-of-range value is named
// with its field, as every options struct of the library does (core/validation.hpp).
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {

void VerdictOptions::validate() const {
  using namespace validation;
  require_ge(field("verdict.min_samples"), static_cast<double>(min_samples), 1);
  require_ge_lt(field("verdict.rest_fraction"), rest_fraction, 0, 1);
  require_ge(field("verdict.min_rest_samples"), static_cast<double>(min_rest_samples), 1);
  require_ge(field("verdict.min_rest_intervals"), static_cast<double>(min_rest_intervals), 1);
  require_between(field("verdict.min_rest_share"), min_rest_share, 0, 1);
  require_ge(field("verdict.rest_noise_sigmas"), rest_noise_sigmas, 0);
  require_gt(field("verdict.rest_trend_sigmas"), rest_trend_sigmas, 0);
  require_ge(field("verdict.rest_window_in_noise"), static_cast<double>(rest_window_in_noise),
             1);
  require_gt(field("verdict.rest_max_rms"), rest_max_rms, 0);
  require_gt_le(field("verdict.max_rest_band"), max_rest_band, 0, 1, "a fraction of max|x|");
  require_ge_lt(field("verdict.steady_variation"), steady_variation, 0, 1);
  require_gt(field("verdict.lyapunov_sigmas"), lyapunov_sigmas, 0);
  require_gt_lt(field("verdict.zero_one_split"), zero_one_split, 0, 1,
                "the 0-1 test's K lies there");
  require_gt(field("verdict.max_prediction_ratio"), max_prediction_ratio, 0);
  require_gt(field("verdict.surrogate_max_prediction_ratio"), surrogate_max_prediction_ratio, 0);
  require_between(field("verdict.periodic_min_late_acf"), periodic_min_late_acf, 0, 1,
                  "an autocorrelation envelope");
  require_between(field("verdict.periodic_max_broadband"), periodic_max_broadband, 0, 1,
                  "a share of the power");
  require_between(field("verdict.second_line_min_power"), second_line_min_power, 0, 1,
                  "a share of the first line's power");
  repetition.validate();
}

}  // namespace pneumachaos
