// The verdict's thresholds checked before a record is judged: each out-of-range value is named
// with its field, as every options struct of the library does (regime.hpp).
#include <fmt/format.h>

#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

void check(bool ok, const char* field, double value, const char* range) {
  if (!ok) throw Error(std::string("verdict ") + field, fmt::format("{}: must be {}", value, range));
}

}  // namespace

void VerdictOptions::validate() const {
  check(min_samples >= 1, "min_samples", static_cast<double>(min_samples), ">= 1");
  check(rest_fraction >= 0.0 && rest_fraction < 1.0, "rest_fraction", rest_fraction,
        ">= 0 and < 1");
  check(min_rest_samples >= 1, "min_rest_samples", static_cast<double>(min_rest_samples), ">= 1");
  check(min_rest_intervals >= 1, "min_rest_intervals", static_cast<double>(min_rest_intervals),
        ">= 1");
  check(min_rest_share >= 0.0 && min_rest_share <= 1.0, "min_rest_share", min_rest_share,
        "between 0 and 1");
  check(rest_noise_sigmas >= 0.0, "rest_noise_sigmas", rest_noise_sigmas, ">= 0");
  check(rest_trend_sigmas > 0.0, "rest_trend_sigmas", rest_trend_sigmas, "> 0");
  check(min_rest_samples_in_noise >= 1, "min_rest_samples_in_noise",
        static_cast<double>(min_rest_samples_in_noise), ">= 1");
  check(rest_max_rms > 0.0, "rest_max_rms", rest_max_rms, "> 0");
  check(max_rest_band > 0.0 && max_rest_band <= 1.0, "max_rest_band", max_rest_band,
        "> 0 and <= 1 (a fraction of max|x|)");
  check(steady_variation >= 0.0 && steady_variation < 1.0, "steady_variation", steady_variation,
        ">= 0 and < 1");
  check(lyapunov_sigmas > 0.0, "lyapunov_sigmas", lyapunov_sigmas, "> 0");
  check(zero_one_split > 0.0 && zero_one_split < 1.0, "zero_one_split", zero_one_split,
        "between 0 and 1 (the 0-1 test's K lies there)");
  check(max_prediction_ratio > 0.0, "max_prediction_ratio", max_prediction_ratio, "> 0");
  check(surrogate_max_prediction_ratio > 0.0, "surrogate_max_prediction_ratio",
        surrogate_max_prediction_ratio, "> 0");
  check(periodic_min_late_acf >= 0.0 && periodic_min_late_acf <= 1.0, "periodic_min_late_acf",
        periodic_min_late_acf, "between 0 and 1 (an autocorrelation envelope)");
  check(periodic_max_broadband >= 0.0 && periodic_max_broadband <= 1.0, "periodic_max_broadband",
        periodic_max_broadband, "between 0 and 1 (a share of the power)");
  check(second_line_min_power >= 0.0 && second_line_min_power <= 1.0, "second_line_min_power",
        second_line_min_power, "between 0 and 1 (a share of the first line's power)");
  repetition.validate();
}

}  // namespace pneumachaos
