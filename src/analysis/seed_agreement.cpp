#include "seed_agreement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pneumachaos/analysis/series_statistics.hpp"

namespace pneumachaos {
namespace {

// Constants of the normal distribution: its interquartile range is kIqrToSd standard
// deviations (2 x 0.6745); from the large-sample variance of a sample q-quantile,
// q (1 - q) / (n f(x_q)^2), the median's standard error is kMedianSe sd / sqrt(n)
// (sqrt(pi / 2)) and a quartile's kQuartileSe sd / sqrt(n) (sqrt(0.75 x 0.25) / phi(0.6745)).
constexpr double kIqrToSd = 1.349;
constexpr double kMedianSe = 1.2533;
constexpr double kQuartileSe = 1.3626;

}  // namespace

void note_zero_one(const ZeroOneResult& z, RegimeEvidence& e) {
  e.zero_one_run = z.run;
  e.zero_one_note = z.reason;
  e.zero_one_K = z.K;
  e.zero_one_q25 = z.K_q25;
  e.zero_one_q75 = z.K_q75;
}

void note_surrogates(const SurrogateTest& s, RegimeEvidence& e) {
  e.surrogate_run = s.run;
  e.surrogate_note = s.reason;
  e.surrogate_count = s.surrogate_statistics.size();
  e.surrogate_rank = s.rank;
  e.surrogate_p = s.p_value;
  e.surrogate_rejected = s.rejected;
  e.surrogate_more_predictable = s.more_predictable;
}

double surrogate_flip_probability(const SurrogateTest& s) {
  const std::vector<double>& v = s.surrogate_statistics;
  if (!s.run || v.size() < 2) return 0.0;
  const auto n = static_cast<double>(v.size());
  const double sd = standard_deviation(v) * std::sqrt(n / (n - 1.0));  // the sample's estimate
  if (!(sd > 0.0)) return 0.0;
  // P(a new surrogate's error is below the record's), then P(all n of them lie above it).
  const double below = 0.5 * std::erfc(-(s.statistic - mean_of(v)) / (sd * std::sqrt(2.0)));
  const double log_all_above = n * std::log1p(-below);
  return s.more_predictable ? -std::expm1(log_all_above) : std::exp(log_all_above);
}

double zero_one_flip_probability(const ZeroOneResult& z, std::size_t frequencies, double split) {
  if (!z.run || frequencies < 2) return 0.0;
  // The spread of K over the frequencies as a normal's (IQR / kIqrToSd), and the large-sample
  // standard errors of the median and of the upper quartile.
  const double sd = (z.K_q75 - z.K_q25) / kIqrToSd;
  if (!(sd > 0.0)) return 0.0;
  const double root_n = std::sqrt(static_cast<double>(frequencies));
  const auto tail = [](double distance, double se) {
    return 0.5 * std::erfc(std::abs(distance) / (se * std::sqrt(2.0)));
  };
  return std::max(tail(z.K - split, kMedianSe * sd / root_n),
                  tail(z.K_q75 - split, kQuartileSe * sd / root_n));
}

namespace {

// Chances of a flip below this are not chased: the surrogates cost more than the rest of
// the analysis together, and five 0-1 tests a quarter of a chaotic record's analysis.
constexpr double kWorthRerunning = 0.01;

// Would the regime differ with the 0-1 test's outcome forced to each of its three readings
// (regular, diffusive, neither clearly)?
bool zero_one_pivotal(const RegimeEvidence& e, const VerdictOptions& o, Regime first) {
  if (!e.zero_one_run) return false;
  for (const auto& [K, q75] : {std::pair{0.0, 0.0}, std::pair{1.0, 1.0}, std::pair{0.0, 1.0}}) {
    RegimeEvidence f = e;
    f.zero_one_K = f.zero_one_q25 = K;
    f.zero_one_q75 = q75;
    if (decide_regime(f, o).regime != first) return true;
  }
  return false;
}

// Would it differ with the surrogate test's outcome the other way?
bool surrogates_pivotal(const RegimeEvidence& e, const VerdictOptions& o, Regime first) {
  if (!e.surrogate_run) return false;
  RegimeEvidence f = e;
  f.surrogate_more_predictable = !e.surrogate_more_predictable;
  f.surrogate_rejected =
      f.surrogate_more_predictable || (e.surrogate_rejected && !e.surrogate_more_predictable);
  return decide_regime(f, o).regime != first;
}

struct Trial {
  ZeroOneResult zero_one;
  SurrogateTest surrogate;
  RegimeEvidence evidence;
  Verdict verdict;
};

std::string tally_line(const std::vector<Trial>& trials, std::uint64_t seed, Regime reported,
                       bool majority) {
  std::vector<std::pair<Regime, std::size_t>> tally;
  for (const Trial& t : trials) {
    auto it = std::find_if(tally.begin(), tally.end(),
                           [&](const auto& p) { return p.first == t.verdict.regime; });
    if (it == tally.end()) {
      tally.emplace_back(t.verdict.regime, 1);
    } else {
      ++it->second;
    }
  }
  const std::string seeds = fmt::format("seeds {}..{}", seed, seed + trials.size() - 1);
  if (tally.size() == 1) {
    return fmt::format("seed agreement: {} on all {} {} of the random tests", regime_name(reported),
                       trials.size(), seeds);
  }
  std::string parts;
  for (const auto& [regime, count] : tally) {
    parts += fmt::format("{}{} on {}", parts.empty() ? "" : ", ", regime_name(regime), count);
  }
  return fmt::format("seed agreement: the verdict flips with the seed of the random tests ({} of "
                     "{} {}); reported: {}",
                     parts, trials.size(), seeds,
                     majority ? "the majority" : "undetermined, no regime has a majority");
}

}  // namespace

void check_seed_agreement(std::span<const double> x, const AnalysisOptions& o,
                          const SeededTestSetup& setup, AnalysisResult& r) {
  SeedAgreement& a = r.seed_agreement;
  const Regime first = r.verdict.regime;
  a = SeedAgreement{};
  a.regimes = {first};
  a.surrogate_flip_probability = surrogate_flip_probability(r.surrogate);
  if (o.verdict_seeds <= 1) return;
  a.zero_one_flip_probability =
      zero_one_flip_probability(r.zero_one, o.zero_one.frequencies, o.verdict.zero_one_split);
  a.zero_one_rerun = zero_one_pivotal(r.evidence, o.verdict, first) &&
                     a.zero_one_flip_probability >= kWorthRerunning;
  a.surrogates_rerun = surrogates_pivotal(r.evidence, o.verdict, first) &&
                       a.surrogate_flip_probability >= kWorthRerunning;
  if (!a.zero_one_rerun && !a.surrogates_rerun) return;
  std::vector<Trial> trials{{r.zero_one, r.surrogate, r.evidence, r.verdict}};
  for (std::size_t k = 1; k < o.verdict_seeds; ++k) {
    Trial t = trials.front();
    const std::uint64_t seed = o.seed + k;
    if (a.zero_one_rerun) {
      ZeroOneOptions z = o.zero_one;
      z.seed = seed;
      t.zero_one = zero_one_test(x, setup.zero_one_step, z);
      note_zero_one(t.zero_one, t.evidence);
    }
    if (a.surrogates_rerun) {
      SurrogateOptions s = o.surrogates;
      s.seed = seed;
      t.surrogate = surrogate_test(x, setup.prediction, s);
      note_surrogates(t.surrogate, t.evidence);
    }
    t.verdict = decide_regime(t.evidence, o.verdict);
    trials.push_back(std::move(t));
  }
  a.seeds = trials.size();
  a.regimes.clear();
  for (const Trial& t : trials) a.regimes.push_back(t.verdict.regime);
  // The first seed giving the majority's regime supplies the numbers, so they match it.
  const auto count = [&](Regime g) {
    return static_cast<std::size_t>(std::count(a.regimes.begin(), a.regimes.end(), g));
  };
  const auto chosen = std::find_if(trials.begin(), trials.end(), [&](const Trial& t) {
    return 2 * count(t.verdict.regime) > trials.size();
  });
  const bool majority = chosen != trials.end();
  const Trial& use = majority ? *chosen : trials.front();
  r.zero_one = use.zero_one;
  r.surrogate = use.surrogate;
  r.evidence = use.evidence;
  r.verdict = use.verdict;
  if (!majority) {
    r.verdict.regime = Regime::kUndetermined;
    r.verdict.chaotic = false;
  }
  a.agreeing = count(r.verdict.regime);
  r.verdict.evidence.push_back(tally_line(trials, o.seed, r.verdict.regime, majority));
}

}  // namespace pneumachaos
