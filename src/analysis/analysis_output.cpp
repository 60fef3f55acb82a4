#include "pneumachaos/analysis/analysis_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>

#include "analysis/jacobian_output.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/analysis/paper_judge.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "io/json_quantity.hpp"

namespace pneumachaos {
namespace {

nlohmann::json number(double v) { return json_number(v); }
nlohmann::json quantity(double v, const std::string& unit) { return json_quantity(v, unit); }
double bits(double per_s) { return per_s / std::numbers::ln2; }

// The 0-1 test and the surrogate test: when not run, "run": false and the reason; numbers
// are null, never NaN.
nlohmann::json zero_one_json(const AnalysisResult& r) {
  const ZeroOneResult& z = r.zero_one;
  return {{"run", z.run},
          {"reason", z.reason},
          {"K", quantity(z.run ? z.K : NAN, "-")},
          {"K_q25", quantity(z.run ? z.K_q25 : NAN, "-")},
          {"K_q75", quantity(z.run ? z.K_q75 : NAN, "-")},
          {"step", quantity(z.step / r.rate_Hz, "s")},
          {"step_samples", z.step},
          {"points", z.points},
          {"method", "Gottwald & Melbourne 2004/2009, correlation method, median over c"}};
}

nlohmann::json surrogate_json(const AnalysisResult& r) {
  const SurrogateTest& t = r.surrogate;
  return {{"run", t.run},
          {"reason", t.reason},
          {"count", t.surrogate_statistics.size()},
          {"samples", t.samples},
          {"statistic", quantity(t.run ? t.statistic : NAN, "-")},
          {"surrogate_statistics", t.surrogate_statistics},
          {"rank", t.rank},
          {"p_value", quantity(t.run ? t.p_value : NAN, "-")},
          {"null_rejected", t.rejected},
          {"more_predictable", t.more_predictable},
          {"method", "IAAFT (Schreiber & Schmitz 1996), local-constant prediction error, "
                     "two-sided rank test"}};
}

nlohmann::json prediction_json(const AnalysisResult& r) {
  const PredictionErrors& p = r.prediction;
  return {{"computed", p.computed},
          {"horizon_samples", p.horizon},
          {"nonlinear", quantity(p.computed ? p.nonlinear : NAN, "-")},
          {"linear", quantity(p.computed ? p.linear : NAN, "-")},
          {"ratio", quantity(p.computed ? p.ratio() : NAN, "-")}};
}

// Numbers are null when not run (too short a record, no period), never NaN.
nlohmann::json repetition_json(const AnalysisResult& r) {
  const SelfRepetition& s = r.evidence.repetition;
  const auto value = [&](double v, const char* unit) { return quantity(s.run ? v : NAN, unit); };
  return {{"run", s.run},
          {"reason", s.reason},
          {"lag", value(s.lag_s, "s")},
          {"lag_samples", s.lag},
          {"lag_drift", value(s.lag_drift_s, "s")},
          {"mismatch", value(s.mismatch, "-")},
          {"stretch", value(s.stretch_s, "s")},
          {"share", value(s.share, "-")},
          {"stretch_max_mismatch", value(s.stretch_max_mismatch, "-")},
          {"growth", value(s.growth_per_s, "1/s")},
          {"repeats", s.repeats},
          {"method", "RMS of x(t + L) - x(t) relative to sqrt(2) std, per one-period window"}};
}

// The paper's three indices (pneumachaos/analysis/paper_judge.hpp); null where one is missing
// (Wolf's exponent, where the other two already refuse).
nlohmann::json paper_judge_json(const PaperJudgement& p) {
  if (!p.evaluated) return {{"chaotic", nullptr}, {"status", p.why}};
  return {{"chaotic", p.chaotic},
          {"no_dominant_line", p.flat_spectrum},
          {"peak_share", quantity(p.peak_share, "-")},
          {"acf_converges", p.acf_converges},
          {"acf_envelope_after_1s", quantity(*p.acf_envelope, "-")},
          {"wolf_positive", p.wolf_computed ? nlohmann::json(p.wolf_positive) : nullptr},
          {"wolf", p.wolf_computed ? quantity(p.wolf_per_s, "1/s") : nullptr},
          {"wolf_uncertainty", p.wolf_computed ? quantity(p.wolf_uncertainty_per_s, "1/s") : nullptr},
          {"thresholds", {{"peak_share", kPaperPeakShare},
                          {"acf_envelope", kPaperAcfEnvelope},
                          {"acf_after", quantity(kPaperAcfAfter_s, "s")},
                          {"wolf_sigmas", kPaperExponentSigmas}}}};
}

std::string evidence_summary(const AnalysisResult& r) {
  const ZeroOneResult& z = r.zero_one;
  std::string out = z.run ? fmt::format("0-1 test: K = {:.3f} (quartiles {:.3f} .. {:.3f}), "
                                        "every {} samples, {} points\n",
                                        z.K, z.K_q25, z.K_q75, z.step, z.points)
                          : fmt::format("0-1 test: {}\n", z.reason);
  if (r.prediction.computed) {
    out += fmt::format("prediction error ({} samples ahead, / std): local-constant {:.3g}, "
                       "linear {:.3g}\n",
                       r.prediction.horizon, r.prediction.nonlinear, r.prediction.linear);
  }
  const SurrogateTest& t = r.surrogate;
  out += t.run ? fmt::format("surrogate test: prediction error {:.3g}, {} of {} IAAFT surrogates "
                             "lower, p = {:.3f}, linear-stochastic null {}\n",
                             t.statistic, t.rank, t.surrogate_statistics.size(), t.p_value,
                             t.rejected ? "rejected" : "kept")
               : fmt::format("surrogate test: {}\n", t.reason);
  const SelfRepetition& s = r.evidence.repetition;
  out += s.run ? fmt::format("self-repetition: lag {:.4g} s, mismatch {:.3g} of the attractor's "
                             "size (whole overlap), small over {:.0f} % of the record\n",
                             s.lag_s, s.mismatch, 100.0 * s.share)
               : fmt::format("self-repetition: {}\n", s.reason);
  return out;
}

std::string noise_floor_line(const AnalysisResult& r) {
  const NoiseFloor& f = r.noise;
  if (f.resolved) {
    return fmt::format("noise floor: white noise of sd {:.3g} ({:.2g} % of the std){}\n", f.sd,
                       100.0 * f.sd / r.standard_deviation,
                       r.evidence.rest_noise_sd > 0.0
                           ? "; rests are judged above it"
                           : "; too small to change how rests are judged");
  }
  if (f.dominates) {
    return fmt::format("noise floor: none separated (the smallest scales are white, at {:.3g}, "
                       "but that is most of the record)\n",
                       f.bound);
  }
  return fmt::format(
      "noise floor: none resolved (the smallest scales are the signal's; any "
      "white noise is below {:.3g})\n",
      f.bound);
}

nlohmann::json noise_floor_json(const AnalysisResult& r, const std::string& unit) {
  const NoiseFloor& f = r.noise;
  return {{"sd", number(f.sd)},
          {"bound", number(f.bound)},
          {"resolved", f.resolved},
          {"dominates", f.dominates},
          {"by_order", f.by_order},
          {"unit", unit},
          {"method",
           "1.4826 MAD of the k-th differences / sqrt(C(2k, k)), k = 1 .. 5; resolved "
           "where the last two agree"}};
}

// The tally over seeds: `seeds` 1 when no random test could turn the verdict.
nlohmann::json seed_agreement_json(const SeedAgreement& a) {
  std::vector<std::string> regimes;
  for (const Regime g : a.regimes) regimes.emplace_back(regime_name(g));
  return {{"seeds", a.seeds},
          {"agreeing", a.agreeing},
          {"share", static_cast<double>(a.agreeing) / static_cast<double>(a.seeds)},
          {"regimes", regimes},
          {"zero_one_rerun", a.zero_one_rerun},
          {"surrogates_rerun", a.surrogates_rerun},
          {"zero_one_flip_probability", a.zero_one_flip_probability},
          {"surrogate_flip_probability", a.surrogate_flip_probability}};
}

}  // namespace

namespace {

// Words of `text` in lines of at most `width` characters, each line indented by `indent`.
std::string wrapped(const std::string& text, std::size_t width, const std::string& indent) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return line.empty() ? out : out + indent + line + "\n";
}

// One line of the verdict's evidence; the verdict's whole rule (a paragraph) only when asked,
// wrapped, else a pointer to it.
std::string evidence_line(const std::string& line, bool explain) {
  // Characters per line of the wrapped rule before its six-space indent: 98 in all, so the
  // paragraph fits a 100-column terminal.
  constexpr std::size_t kRuleWidth = 92;
  static const std::string rule = "[--] rule: ";
  if (!line.starts_with(rule)) return "  " + line + "\n";
  if (!explain)
    return "  [--] rule: the rule that combines these lines is printed by --explain (and held "
           "in the JSON's verdict evidence)\n";
  return "  [--] rule:\n" + wrapped(line.substr(rule.size()), kRuleWidth, "      ");
}

}  // namespace

std::string analysis_summary(const AnalysisResult& r, const std::string& name,
                             const std::string& unit, bool explain) {
  // The answer first: the verdict and the exponent, then how they were reached.
  std::string out = fmt::format("verdict: {} (chaotic: {}, stick-slip: {})\n",
                                regime_name(r.verdict.regime), r.verdict.chaotic ? "yes" : "no",
                                r.verdict.stick_slip ? "yes" : "no");
  if (r.seed_agreement.agreeing < r.seed_agreement.seeds) {
    out += fmt::format("  the verdict flips with the seed: {} on {} of {} seeds (see the evidence)\n",
                       regime_name(r.verdict.regime), r.seed_agreement.agreeing,
                       r.seed_agreement.seeds);
  }
  if (r.divergence.found_linear_region) {
    out += fmt::format("maximum Lyapunov exponent: {:.4g} +- {:.2g} 1/s (divergence curve)\n",
                       r.divergence.lambda_per_s, r.divergence.uncertainty_per_s);
  } else {
    out += fmt::format("maximum Lyapunov exponent: none ({})\n",
                       r.divergence_status.empty() ? "not computed" : r.divergence_status);
  }
  out += fmt::format("{} samples of {} [{}] at {} Hz ({:.4g} s); mean {:.4g}, std {:.4g}\n",
                     r.samples, name, unit, r.rate_Hz, r.samples / r.rate_Hz, r.mean,
                     r.standard_deviation);
  if (r.standard_deviation > 0.0) {
    out += noise_floor_line(r);
    out += fmt::format(
        "spectrum: peak {:.4g} Hz ({:.1f} % of power), broadband share {:.3f}, flatness {:.3f}\n",
        r.spectrum.peak_frequency_Hz, 100.0 * r.spectrum.peak_share, r.spectrum.broadband_share,
        r.spectrum.spectral_flatness);
    out += fmt::format("autocorrelation: first zero {:.4g} s, 1/e {:.4g} s, late envelope {:.3f}\n",
                       r.acf.first_zero_s, r.acf.one_over_e_s, r.acf.late_envelope);
    out += fmt::format(
        "embedding: delay {} samples ({:.4g} s, {}), dimension {} (Cao), Theiler {} samples\n",
        r.delay.delay, r.delay.delay / r.rate_Hz, r.delay.method, r.dimension.dimension, r.theiler);
    out += fmt::format("orbital period: {:.4g} s (maxima spacing {:.4g} s{})\n",
                       r.period_samples / r.rate_Hz, r.maxima_spacing_samples / r.rate_Hz,
                       r.period_samples != r.maxima_spacing_samples
                           ? "; the maxima follow a faster mode, the period is the slower line's"
                           : "");
    out += fmt::format("maximum Lyapunov exponent (1/s = nats/s):\n");
    if (r.divergence.found_linear_region) {
      const auto& seg = r.divergence.segment_slopes_per_step;
      const double segment_min = seg.empty() ? 0.0 : *std::min_element(seg.begin(), seg.end());
      const double segment_max = seg.empty() ? 0.0 : *std::max_element(seg.begin(), seg.end());
      out += fmt::format(
          "  divergence curve: {:.4g} +- {:.2g} 1/s ({:.4g} bits/s), fit {:.4g}..{:.4g} s (slope "
          "alone +- {:.2g}); on {} segments {:.3g} .. {:.3g} 1/s\n",
          r.divergence.lambda_per_s, r.divergence.uncertainty_per_s,
          bits(r.divergence.lambda_per_s), r.divergence.fit_first / r.rate_Hz,
          r.divergence.fit_last / r.rate_Hz, r.divergence.slope_uncertainty_per_s,
          r.divergence.segment_slopes_per_step.size(), segment_min * r.rate_Hz,
          segment_max * r.rate_Hz);
    } else {
      out += "  divergence curve: no rising linear region\n";
    }
    if (r.wolf_run) {
      out +=
          fmt::format("  Wolf et al. 1985: {:.4g} +- {:.2g} 1/s ({:.4g} bits/s), {} replacements\n",
                      r.wolf.lambda_per_s, r.wolf.uncertainty_per_s, bits(r.wolf.lambda_per_s),
                      r.wolf.replacements);
    }
    if (!r.wolf_status.empty()) out += "  Wolf: " + r.wolf_status + "\n";
    out += jacobian_text(r);
    out += fmt::format("Poincare section: {} points; successive maxima: {} pairs\n",
                       r.poincare.points.size(), r.maxima_map.size());
    out += evidence_summary(r);
  }
  out += "the paper's judge (its three indices, beside the verdict): " +
         describe(paper_judge(r)) + "\n";
  out += fmt::format("evidence for the verdict ({}):\n", regime_name(r.verdict.regime));
  for (const auto& line : r.verdict.evidence) out += evidence_line(line, explain);
  return out;
}

namespace {

// The divergence exponent with its fit, its segments and, without a linear region, the wide
// estimate.
nlohmann::json divergence_json(const AnalysisResult& r) {
  nlohmann::json d = {
      {"value", r.divergence.found_linear_region ? number(r.divergence.lambda_per_s) : nullptr},
      // Without a linear region there is no exponent, so no uncertainty of it either (the
      // spread of placeholder zeros is no measurement).
      {"uncertainty",
       r.divergence.found_linear_region ? number(r.divergence.uncertainty_per_s) : nullptr},
      {"slope_uncertainty",
       r.divergence.found_linear_region ? number(r.divergence.slope_uncertainty_per_s) : nullptr},
      {"unit", "1/s"},
      {"value_bits",
       r.divergence.found_linear_region ? number(bits(r.divergence.lambda_per_s)) : nullptr},
      {"unit_bits", "bits/s"},
      {"found_linear_region", r.divergence.found_linear_region},
      {"fit", r.divergence.found_linear_region
                  ? nlohmann::json{{"from", quantity(r.divergence.fit_first / r.rate_Hz, "s")},
                                   {"to", quantity(r.divergence.fit_last / r.rate_Hz, "s")}}
                  : nlohmann::json(nullptr)},
      {"aligned_in_time", r.divergence.aligned},
      {"method",
       "Rosenstein/Kantz divergence, automatic linear region; uncertainty: jackknife, "
       "fit window, segments, each half of the window, embedding dimensions m - 1 and m + 1"}};
  d["status"] = r.divergence_status;
  // Without a linear region, a deterministic record's wide estimate (analyze.hpp
  // divergence_estimate): a value always with its range, never a range alone.
  const SlopeSpread& ls = r.divergence.local_slopes;
  d["without_linear_region"] =
      r.divergence_estimate
          ? nlohmann::json{{"value", number(ls.median * r.rate_Hz)},
                           {"low", number(ls.low * r.rate_Hz)},
                           {"high", number(ls.high * r.rate_Hz)},
                           {"unit", "1/s"},
                           {"method", "median and 10-90 % range of the one-orbit local slopes "
                                      "over the curve's rise"}}
          : nlohmann::json(nullptr);
  // The exponent fitted on each contiguous segment of the record (docs/notes/analysis.md
  // "Divergence exponent's uncertainty"): their spread is part of the uncertainty.
  // A segment without a linear region of its own or the record's has no value: null.
  nlohmann::json segments = nlohmann::json::array();
  for (double s : r.divergence.segment_slopes_per_step) segments.push_back(number(s * r.rate_Hz));
  d["segments"] = {
      {"values", segments},
      {"unit", "1/s"},
      {"without_own_linear_region", r.divergence.segments_without_region}};
  // The choices behind the value, which its uncertainty covers (exponent_spread.hpp).
  const ExponentSpread& s = r.exponent_spread;
  d["spread"] = r.divergence.found_linear_region
                    ? nlohmann::json{{"window", number(s.window_per_s)},
                                     {"window_choice", number(s.window_choice_per_s)},
                                     {"other_windows", s.other_windows_per_s},
                                     {"embedding", number(s.embedding_per_s)},
                                     {"dimensions", s.dimensions},
                                     {"values", s.lambda_per_s},
                                     {"unit", "1/s"}}
                    : nlohmann::json(nullptr);
  return d;
}

}  // namespace

std::string analysis_json(const AnalysisResult& r, const std::string& source,
                          const std::string& name, const std::string& unit) {
  nlohmann::json j;
  j["source"] = source;
  j["series"] = {{"name", name},
                 {"unit", unit},
                 {"samples", r.samples},
                 {"rate", quantity(r.rate_Hz, "Hz")},
                 {"mean", quantity(r.mean, unit)},
                 {"std", quantity(r.standard_deviation, unit)}};
  j["noise_floor"] = noise_floor_json(r, unit);
  j["spectrum"] = {{"peak_frequency", quantity(r.spectrum.peak_frequency_Hz, "Hz")},
                   {"peak_share", quantity(r.spectrum.peak_share, "-")},
                   {"broadband_share", quantity(r.spectrum.broadband_share, "-")},
                   {"flatness", quantity(r.spectrum.spectral_flatness, "-")},
                   {"resolution", quantity(r.spectrum.resolution_Hz, "Hz")},
                   {"segments", r.spectrum.segments}};
  j["autocorrelation"] = {{"first_zero", quantity(r.acf.first_zero_s, "s")},
                          {"one_over_e", quantity(r.acf.one_over_e_s, "s")},
                          {"envelope_decay", quantity(r.acf.envelope_decay_per_s, "1/s")},
                          {"late_envelope", quantity(r.acf.late_envelope, "-")}};
  j["embedding"] = {{"delay", quantity(r.delay.delay / r.rate_Hz, "s")},
                    {"delay_samples", r.delay.delay},
                    {"delay_method", r.delay.method},
                    {"dimension", r.dimension.dimension},
                    {"theiler_samples", r.theiler},
                    {"cao_E1", r.dimension.E1},
                    {"cao_E2", r.dimension.E2},
                    {"period", quantity(r.period_samples / r.rate_Hz, "s")},
                    {"maxima_spacing", quantity(r.maxima_spacing_samples / r.rate_Hz, "s")}};
  j["lyapunov"]["divergence"] = divergence_json(r);
  if (!r.wolf_status.empty()) {
    j["lyapunov"]["wolf"] = {{"value", r.wolf_run ? number(r.wolf.lambda_per_s) : nullptr},
                             {"status", r.wolf_status},
                             {"uncertainty", r.wolf_run ? number(r.wolf.uncertainty_per_s) : nullptr},
                             {"unit", "1/s"},
                             {"value_bits", r.wolf_run ? number(bits(r.wolf.lambda_per_s)) : nullptr},
                             {"unit_bits", "bits/s"},
                             {"replacements", r.wolf.replacements},
                             {"method", "Wolf, Swift, Swinney & Vastano 1985"}};
  }
  j["paper_judge"] = paper_judge_json(paper_judge(r));
  if (!r.jacobian_status.empty()) j["lyapunov"]["jacobian"] = jacobian_json(r);
  j["poincare"] = {{"points", r.poincare.points.size()},
                   {"level", quantity(r.poincare.level, unit)}};
  j["zero_one"] = zero_one_json(r);
  j["surrogate"] = surrogate_json(r);
  j["prediction"] = prediction_json(r);
  j["self_repetition"] = repetition_json(r);
  j["verdict"] = {{"regime", regime_name(r.verdict.regime)},
                  {"chaotic", r.verdict.chaotic},
                  {"stick_slip", r.verdict.stick_slip},
                  {"rests_judged", r.evidence.rests_judged},
                  {"rests_above_noise", r.evidence.rests_above_noise},
                  {"rest_level", quantity(r.evidence.rest_level, unit)},
                  {"seed_agreement", seed_agreement_json(r.seed_agreement)},
                  {"evidence", r.verdict.evidence}};
  return j.dump(2);
}

void write_analysis_series(const AnalysisResult& r, std::span<const double> x,
                           const std::string& dir, const std::string& unit, OutputSet& out) {
  const auto write = [&](const std::string& file, const std::string& header, auto&& rows) {
    std::ofstream& f = out.add((std::filesystem::path(dir) / file).string());
    f << header << '\n';
    rows(f);
  };
  const double dt = 1.0 / r.rate_Hz;
  write("spectrum.csv", fmt::format("f[Hz],psd[({})^2/Hz]", unit), [&](std::ostream& o) {
    for (std::size_t k = 0; k < r.spectrum.psd.size(); ++k) {
      o << fmt::format("{},{}\n", r.spectrum.frequency_Hz[k], r.spectrum.psd[k]);
    }
  });
  write("autocorrelation.csv", "lag[s],r[-]", [&](std::ostream& o) {
    for (std::size_t k = 0; k < r.acf.r.size(); ++k)
      o << fmt::format("{},{}\n", k * dt, r.acf.r[k]);
  });
  write("divergence.csv", "t[s],mean_ln_distance[-],fit[-]", [&](std::ostream& o) {
    for (std::size_t k = 0; k < r.divergence.curve.size(); ++k) {
      const bool in = r.divergence.found_linear_region && k >= r.divergence.fit_first &&
                      k <= r.divergence.fit_last;
      o << fmt::format(
          "{},{},{}\n", k * dt, r.divergence.curve[k],
          in ? fmt::format("{}", r.divergence.intercept + r.divergence.slope_per_step * k)
             : std::string());
    }
  });
  write("wolf_running.csv", "t[s],lambda[1/s]", [&](std::ostream& o) {
    for (std::size_t k = 0; k < r.wolf.running_per_s.size(); ++k) {
      o << fmt::format("{},{}\n", r.wolf.running_time_s[k], r.wolf.running_per_s[k]);
    }
  });
  // The delay-embedded 3-D trajectory of the paper's Fig. 7c.
  write("embedding.csv", fmt::format("t[s],x_t[{0}],x_t+tau[{0}],x_t+2tau[{0}]", unit),
        [&](std::ostream& o) {
          const std::size_t tau = r.delay.delay;
          for (std::size_t i = 0; i + 2 * tau < x.size(); ++i) {
            o << fmt::format("{},{},{},{}\n", i * dt, x[i], x[i + tau], x[i + 2 * tau]);
          }
        });
  write("poincare.csv", fmt::format("x_t+tau[{0}],x_t+2tau[{0}],t[s]", unit), [&](std::ostream& o) {
    for (std::size_t k = 0; k < r.poincare.points.size(); ++k) {
      o << fmt::format("{},{},{}\n", r.poincare.points[k][0], r.poincare.points[k][1],
                       r.poincare.time_s[k]);
    }
  });
  write("maxima_map.csv", fmt::format("max_k[{0}],max_k+1[{0}]", unit), [&](std::ostream& o) {
    for (const auto& p : r.maxima_map) o << fmt::format("{},{}\n", p[0], p[1]);
  });
}

}  // namespace pneumachaos
