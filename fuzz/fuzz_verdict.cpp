// libFuzzer harness: the regime verdict on fuzzed evidence and thresholds. Every number the
// verdict reads comes from the bytes (a 16-bit value times a power of ten; a threshold is
// now and then an infinity or a NaN, which validate() must refuse by name). Only pneumachaos::Error may come
// out, and only from validate(); the verdict's flags agree with its regime, and a steady
// record with enough samples and no rests is called steady.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "fuzz_input.hpp"
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/core/error.hpp"

namespace {

using pneumachaos::fuzz::FuzzInput;
using pneumachaos::fuzz::require;

// Evidence is computed from a finite record and is finite; a threshold may be anything.
double number(FuzzInput& in, bool special = false) {
  const std::uint8_t kind = in.byte();
  if (special && kind == 255) return std::numeric_limits<double>::quiet_NaN();
  if (special && kind == 254) return std::numeric_limits<double>::infinity();
  const auto raw = static_cast<std::int16_t>(in.byte() | (in.byte() << 8));
  return raw * std::pow(10.0, static_cast<int>(kind % 13) - 6);
}

pneumachaos::RegimeEvidence evidence(FuzzInput& in) {
  pneumachaos::RegimeEvidence e;
  e.samples = in.in_range(0, 255) * 40;
  e.mean = number(in), e.range = number(in);
  e.last_half_std = number(in), e.last_half_mean = number(in);
  e.rest_intervals = in.in_range(0, 5), e.rest_share = number(in);
  e.lyapunov_found = (in.byte() & 1) != 0;
  e.lyapunov_per_s = number(in), e.lyapunov_uncertainty_per_s = number(in);
  e.lyapunov_slope_uncertainty_per_s = number(in);
  e.broadband_share = number(in), e.late_acf = number(in), e.determinism = number(in);
  e.zero_one_run = (in.byte() & 1) != 0;
  e.zero_one_K = number(in), e.zero_one_q25 = number(in), e.zero_one_q75 = number(in);
  e.prediction_computed = (in.byte() & 1) != 0;
  e.prediction_nonlinear = number(in), e.prediction_linear = number(in);
  e.surrogate_run = (in.byte() & 1) != 0;
  e.surrogate_count = in.in_range(0, 60), e.surrogate_rank = in.in_range(0, 60);
  e.surrogate_p = number(in);
  e.surrogate_rejected = (in.byte() & 1) != 0, e.surrogate_more_predictable = (in.byte() & 1) != 0;
  e.second_line_power = number(in), e.second_line_ratio = number(in);
  e.second_line_incommensurate = (in.byte() & 1) != 0;
  e.repetition.run = (in.byte() & 1) != 0, e.repetition.repeats = (in.byte() & 1) != 0;
  e.repetition.share = number(in), e.repetition.growth_per_s = number(in);
  e.repetition.stretch_max_mismatch = number(in), e.repetition.mismatch = number(in);
  return e;
}

// Half the inputs keep the defaults; the others perturb thresholds validate() must check.
pneumachaos::VerdictOptions options(FuzzInput& in) {
  pneumachaos::VerdictOptions o;
  if ((in.byte() & 1) == 0) return o;
  o.min_samples = in.in_range(0, 255) * 10;
  o.rest_fraction = number(in, true), o.min_rest_share = number(in, true);
  o.steady_variation = number(in, true), o.lyapunov_sigmas = number(in, true);
  o.zero_one_split = number(in, true), o.max_prediction_ratio = number(in, true);
  o.surrogate_max_prediction_ratio = number(in, true), o.periodic_min_late_acf = number(in, true);
  o.periodic_max_broadband = number(in, true), o.second_line_min_power = number(in, true);
  o.repetition.max_mismatch = number(in, true), o.repetition.min_share = number(in, true);
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzInput in(data, size);
  const auto o = options(in);
  const auto e = evidence(in);
  try {
    o.validate();
  } catch (const pneumachaos::Error&) {
    return 0;
  }
  const auto v = pneumachaos::decide_regime(e, o);
  require(v.chaotic == (v.regime == pneumachaos::Regime::kChaotic));
  require(!v.evidence.empty() && !pneumachaos::verdict_rule(o).empty());
  if (e.samples >= o.min_samples && !v.stick_slip && pneumachaos::is_steady(e, o)) {
    require(v.regime == pneumachaos::Regime::kSteady);
  }
  return 0;
}
