#include "report/run_traces.hpp"

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/parallel_indices.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/spectrum.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

using Json = nlohmann::ordered_json;

// Points per chart: enough for a chart a few hundred pixels wide, few enough that the paper's
// full report (about 3,300 runs) stays within its 20 MB (docs/notes/explorable_report.md).
constexpr std::size_t kRecordBuckets = 400;
constexpr std::size_t kAcfBuckets = 250;
constexpr std::size_t kSpectrumPoints = 256;
constexpr int kLevels = 4095;
constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

Json series_json(const std::vector<double>& values, double x0, double dx) {
  double lo = 0.0, hi = 0.0;
  std::string q = quantise_series(values, lo, hi);
  return {{"n", values.size()}, {"x0", x0}, {"dx", dx}, {"lo", lo}, {"hi", hi}, {"q", q}};
}

// The spectrum above DC in log10, each group of bins as its strongest (a peak survives).
Json spectrum_json(const Spectrum& s) {
  const std::size_t bins = s.psd.size() - 1;
  const std::size_t group = (bins + kSpectrumPoints - 1) / kSpectrumPoints;
  double floor = HUGE_VAL;
  for (double p : s.psd)
    if (p > 0.0) floor = std::min(floor, p);
  std::vector<double> log_psd;
  for (std::size_t b = 1; b <= bins; b += group) {
    const auto last = s.psd.begin() + static_cast<std::ptrdiff_t>(std::min(b + group, bins + 1));
    log_psd.push_back(std::log10(std::max(*std::max_element(s.psd.begin() + b, last), floor)));
  }
  const double res = s.frequency_Hz[1] - s.frequency_Hz[0];
  Json j = series_json(log_psd, s.frequency_Hz[1] + 0.5 * (group - 1) * res, group * res);
  j["peak_Hz"] = s.peak_frequency_Hz;
  j["broadband_share"] = s.broadband_share;
  return j;
}

Json acf_json(const Autocorrelation& a) {
  const std::vector<double> r = min_max_decimate(a.r, kAcfBuckets);
  const double lags = static_cast<double>(a.r.size() - 1) / a.rate_Hz;
  Json j = series_json(r, 0.0, r.size() > 1 ? lags / static_cast<double>(r.size() - 1) : 0.0);
  j["late_acf"] = a.late_envelope;
  return j;
}

// One run's traces, or why it has none. The spectrum and autocorrelation are those the
// sweep's verdict read (analyze_series with the sweep's default spectrum options).
Json trace_json(const SweepRun& run) {
  try {
    if (!run.sim.summary.ok()) return {{"error", run.sim.summary.message}};
    const std::vector<double>& v = run.measured_v;
    const double rate = run.sim.series.rate_Hz();
    const std::vector<double> shown = min_max_decimate(v, kRecordBuckets);
    const double span = static_cast<double>(v.size() - 1) / rate;
    Json j = {
        {"samples", v.size()},
        {"rate_Hz", rate},
        {"v", series_json(shown, 0.0,
                          shown.size() > 1 ? span / static_cast<double>(shown.size() - 1) : 0.0)}};
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    if (*lo == *hi) {
      j["note"] = "a constant record: no spectrum or autocorrelation";
      return j;
    }
    j["spectrum"] = spectrum_json(welch_spectrum(v, rate, AnalysisOptions{}.spectrum));
    j["acf"] = acf_json(autocorrelation(v, rate));
    return j;
  } catch (const std::exception& e) {
    return {{"error", e.what()}};
  }
}

// As JSON text; a message that is not UTF-8 is kept with its bad bytes replaced.
std::string text_of(const Json& j) {
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

Json simulated_trace(const SweepSpec& spec, const RunKey& k) {
  try {
    return trace_json(simulate_run(spec, k.point, k.repeat));
  } catch (const std::exception& e) {
    return {{"error", e.what()}};
  }
}

}  // namespace

std::string quantise_series(const std::vector<double>& values, double& lo, double& hi) {
  lo = HUGE_VAL;
  hi = -HUGE_VAL;
  for (double x : values)
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  if (!(lo <= hi)) lo = hi = 0.0;
  const double range = hi > lo ? hi - lo : 1.0;
  std::string q;
  q.reserve(2 * values.size());
  for (double x : values) {
    const int code =
        std::isfinite(x) ? static_cast<int>(std::lround((x - lo) / range * kLevels)) : 0;
    q += kAlphabet[code / 64];
    q += kAlphabet[code % 64];
  }
  return q;
}

std::vector<double> min_max_decimate(const std::vector<double>& x, std::size_t buckets) {
  if (x.size() <= 2 * buckets) return x;
  std::vector<double> out;
  out.reserve(2 * buckets);
  for (std::size_t b = 0; b < buckets; ++b) {
    const auto first = x.begin() + static_cast<std::ptrdiff_t>(b * x.size() / buckets);
    const auto last = x.begin() + static_cast<std::ptrdiff_t>((b + 1) * x.size() / buckets);
    const auto [lo, hi] = std::minmax_element(first, last);
    out.push_back(lo < hi ? *lo : *hi);
    out.push_back(lo < hi ? *hi : *lo);
  }
  return out;
}

void RunTraces::keep(const SweepRun& run) {
  std::string text = text_of(trace_json(run));
  const std::lock_guard<std::mutex> lock(mutex_);
  traces_[{run.point, run.repeat}] = std::move(text);
}

std::string RunTraces::js(const MapData& map, const std::vector<RunKey>& runs,
                          std::size_t threads) {
  std::vector<RunKey> missing;
  for (const RunKey& k : runs)
    if (traces_.count({k.point, k.repeat}) == 0) missing.push_back(k);
  auto one = [&](std::size_t i) {
    std::string text = text_of(simulated_trace(map.spec, missing[i]));
    const std::lock_guard<std::mutex> lock(mutex_);
    traces_[{missing[i].point, missing[i].repeat}] = std::move(text);
  };
  tbb::task_arena arena(threads > 0 ? static_cast<int>(threads) : tbb::task_arena::automatic);
  arena.execute([&] { detail::parallel_indices(missing.size(), one); });
  std::string all;
  for (const RunKey& k : runs)
    all += fmt::format("{}\"{}:{}\":{}", all.empty() ? "{" : ",", k.point, k.repeat,
                       traces_.at({k.point, k.repeat}));
  return fmt::format(
      "(window.PNEUMACHAOS_RUNS = window.PNEUMACHAOS_RUNS || {{}})[\"{}\"] = {}}};\n", map.figure,
      all.empty() ? "{" : all);
}

}  // namespace pneumachaos
