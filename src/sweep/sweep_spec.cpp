#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/surrogates.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

ModelLyapunovOptions ModelExponentSpec::options(double duration_s) const {
  ModelLyapunovOptions o;
  o.transient_s = transient_s;
  o.measure_s = measure_s > 0.0 ? measure_s : duration_s - transient_s;
  o.renormalize_s = renormalize_s;
  o.until_terminal_event = true;  // volumes following the piston: the rest of the stroke
  return o;
}

std::vector<std::string> SweepSpec::warnings() const {
  std::vector<std::string> w;
  const VariationParams& v = base.variation;
  // What differs from repeat to repeat: the variation and the analysed velocity's noise.
  const char* const noise_key = "transducer.velocity_noise_mm_per_s";
  const bool gridded = std::any_of(axes.begin(), axes.end(), [&](const GridAxis& a) {
    return a.key.starts_with("variation.") || a.key == noise_key;
  });
  if (repeats > 1 && v.friction_rel_sd == 0.0 && v.texture_rel == 0.0 &&
      base.transducer.velocity.noise_m_per_s == 0.0 && !gridded) {
    w.push_back(fmt::format(
        "the {} repeats of each point are identical copies: variation.friction_rel_sd, "
        "variation.texture_rel and {} are all 0, so every "
        "incidence is 0 or 1. The report's maps (reproduce) use --set "
        "variation.friction_rel_sd=0.03 --set variation.texture_rel=0.02; or use --repeats 1",
        repeats, noise_key));
  }
  for (const auto& n : scenario_notes(base)) w.push_back(n);
  return w;
}

void ModelExponentSpec::validate(double duration_s) const {
  if (!enabled) return;
  using namespace validation;
  require(std::isfinite(transient_s) && transient_s >= 0.0 && transient_s < duration_s,
          kTransientField, transient_s,
          fmt::format(">= 0 and < {} s (shorter than the run)", duration_s));
  require_finite_ge(kMeasureField, measure_s, 0, "s; 0: the rest of the run");
  require_finite_gt(kRenormalizeField, renormalize_s, 0, "s");
  const ModelLyapunovOptions o = options(duration_s);
  // The uncertainty is the spread between blocks: each needs at least one renormalisation.
  const double fewest_s = o.renormalize_s * static_cast<double>(o.blocks);
  if (o.measure_s < fewest_s) {
    if (measure_s > 0.0) {
      require(false, kMeasureField, measure_s,
              fmt::format(">= {} s ({} renormalisations of {} s, one per block)", fewest_s,
                          o.blocks, o.renormalize_s));
    }
    require(false, kTransientField, transient_s,
            fmt::format("<= {} s (the rest of the run must hold {} renormalisations of {} s, "
                        "one per block)",
                        duration_s - fewest_s, o.blocks, o.renormalize_s));
  }
  o.validate();
}

void SweepSpec::validate() const {
  validate_grid(axes);
  validation::require_ge(kRepeatsField, static_cast<double>(repeats), 1);
  if (runs() > 10'000'000)
    throw Error(kGridField, fmt::format("{} runs is more than 10 million", runs()));
  base.validate();
  check_surrogate_count(surrogates, "surrogates");  // up front, not as every run's failure
  model_exponent.validate(base.run.duration_s);
  adaptive.validate(axes.size());
}

void AdaptiveSpec::validate(std::size_t axes) const {
  if (!enabled) return;
  if (axes != 2) {
    throw Error(kEnabledField,
                fmt::format("refines a map over exactly two grid axes; this sweep has {}", axes));
  }
  validation::require_ge(kCoarseStepField, static_cast<double>(coarse_step), 1);
}

std::string SweepSpec::fingerprint() const {
  // FNV-1a over everything that decides the results; the text form of the scenario covers
  // every key.
  std::string text = "pneumachaos sweep v1\n" + scenario_to_toml(base);
  for (const auto& a : axes) {
    text += a.key + "=";
    for (double v : a.values) text += fmt::format("{};", v);
    text += "\n";
  }
  text += fmt::format("repeats={} seed={} wolf={}\n", repeats, seed, wolf);
  // Only when on, so that a sweep without it keeps its fingerprint.
  if (paper_judge) text += "judge=paper\n";
  // Only when on, so that the journals of sweeps from before the option still resume.
  if (surrogates > 0) text += fmt::format("surrogates={}\n", surrogates);
  const ModelExponentSpec& m = model_exponent;
  text += fmt::format("model_exponent={} transient={} measure={} renormalize={}\n", m.enabled,
                      m.transient_s, m.measure_s, m.renormalize_s);
  // Only when on, so that full sweeps keep their fingerprint.
  if (adaptive.enabled) text += fmt::format("adaptive coarse_step={}\n", adaptive.coarse_step);
  if (adaptive.enabled && adaptive.follow_motion) text += "adaptive follow_motion\n";
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return fmt::format("{:016x}", h);
}

}  // namespace pneumachaos
