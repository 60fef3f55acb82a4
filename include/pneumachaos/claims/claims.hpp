#pragma once
// The paper's claims against our numbers. Each row quotes the paper's sentence, says how we
// read it, states the rule, gives our numbers, a signed margin and the verdict, and for a row
// that does not agree one sentence saying why (docs/report.md lists every rule).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pneumachaos/claims/claim_rules.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

/// The verdicts a row can carry. Only the first three are scored: an identity is a rule no
/// plausible model can fail, and a contradictory row is one where the paper's own sentences
/// disagree, so there is nothing to score.
inline constexpr const char* kAgrees = "agrees";
inline constexpr const char* kDisagrees = "disagrees";
inline constexpr const char* kNotReproduced = "not reproduced";
inline constexpr const char* kIdentity = "identity";
inline constexpr const char* kContradictory = "contradictory";

struct Claim {
  Claim() = default;
  /// The row's text; its numbers and verdict are filled in when it is judged.
  Claim(std::string id_, std::string quote_, std::string where_, std::string reading_,
        std::string rule_, std::string figure_)
      : id(std::move(id_)),
        quote(std::move(quote_)),
        where(std::move(where_)),
        reading(std::move(reading_)),
        rule(std::move(rule_)),
        figure(std::move(figure_)) {}
  std::string id;       ///< stable key (claims.json), e.g. "fig7_spectrum"
  std::string quote;    ///< the paper's sentence(s), verbatim
  std::string where;    ///< its section or figure
  std::string reading;  ///< what we take it to say, in one line
  std::string rule;     ///< how the verdict is decided
  std::string figure;   ///< the report figure that shows it (FigureSpec name), or empty
  std::string ours;     ///< our numbers
  std::string verdict;  ///< one of the names above
  double margin = kNaN;  ///< signed, dimensionless; >= 0 passes; NaN: not evaluated
  std::string why;       ///< for a row that does not agree: one sentence
  /// The grid points of `figure`'s map the rule read (its border cells), where it names any.
  std::vector<std::size_t> cells;
  [[nodiscard]] bool scored() const { return verdict != kIdentity && verdict != kContradictory; }
};

/// How many rows carry each verdict.
struct ClaimCount {
  std::size_t agrees = 0, disagrees = 0, not_reproduced = 0, identity = 0, contradictory = 0;
  [[nodiscard]] std::size_t scored() const { return agrees + disagrees + not_reproduced; }
};
ClaimCount count_claims(const std::vector<Claim>& claims);
/// "N of M claims agree (...)": the report's headline.
std::string claims_headline(const ClaimCount& c);
/// The table as JSON (claims.json): the count and every row with its fields.
std::string claims_json(const std::vector<Claim>& claims);
/// The same, followed by "paper_judge": the count and the rows that read the chaos judge
/// (reads_chaos_judge) as `paper` evaluates them; the strict table before it is unchanged.
std::string claims_json(const std::vector<Claim>& claims, const std::vector<Claim>& paper);

/// Fig. 2 reduced: each circuit's step responses at the same openings, under the paper's own
/// assumptions (meter-out with P1 = Ps, meter-in with the rod side at atmosphere).
struct CircuitTransients {
  std::vector<double> areas_mm2;
  std::vector<Settling> meter_out, meter_in;
};

/// The paper's a1 (eq. 9) and b1 (eq. 11) at the example point before and after a load change.
struct LoadCoefficients {
  double a1_before = 0.0, a1_after = 0.0, b1_before = 0.0, b1_after = 0.0;  ///< [N s/m]
};

struct ClaimInputs {
  MapGrid grid;                          ///< the maps' S1 x S2 axes
  std::optional<SweepSummary> base;      ///< Ps 0.25 MPa, m 1.5 kg (total moving mass)
  std::optional<SweepSummary> high_ps;   ///< Ps 0.30 MPa
  std::optional<SweepSummary> double_m;  ///< m 3.0 kg
  std::optional<SweepSummary> triple_m;  ///< m 4.5 kg
  // The chaotic example (Fig. 7), its settled record.
  std::optional<double> example_lambda;       ///< divergence exponent [1/s]
  std::optional<double> example_uncertainty;  ///< its slope's uncertainty [1/s]
  std::optional<double> example_wolf;         ///< Wolf's estimate [1/s]
  std::optional<double> example_model_lambda;       ///< the model's own exponent [1/s]
  std::optional<double> example_model_uncertainty;  ///< its standard error [1/s]
  std::optional<bool> example_chaotic;        ///< the regime verdict says chaotic
  std::optional<bool> example_paper_chaotic;  ///< the paper's three indices say chaotic
  std::string example_regime;                 ///< the verdict's regime name
  std::optional<double> example_peak_share;   ///< spectral peak (+-1 bin) / total power
  std::optional<double> example_spectrum_resolution_Hz;  ///< that spectrum's bin width
  std::optional<double> example_settled_s;  ///< the length of the record the example's rules read
  std::optional<double> example_acf_after_1s;  ///< largest |ACF| at lags >= 1 s
  std::optional<FoldStretch> fold_stretch;
  std::optional<FrictionLoop> friction_loop;
  std::optional<LineFit> friction_line;  ///< friction against low speed, example record
  double friction_slope_vmax = 0.0;      ///< its upper speed [m/s]
  std::optional<CircuitTransients> fig2;
  std::vector<DampingPair> meter_in_ps;  ///< eq. (11): Ps 0.25 -> 0.30 at each meter-in opening
  std::optional<LoadCoefficients> heavier;  ///< 1.5 -> 3.0 kg at the example point
  std::optional<SignRuleCounts> sign_rule;
};

/// The claims about the maps (Figs. 4-6; claims.cpp).
std::vector<Claim> map_claims(const ClaimInputs& in);
/// The claims of the chaotic example, Figs. 2 and 3 and the linear analysis (claims_example.cpp).
std::vector<Claim> example_claims(const ClaimInputs& in);
/// Every row, maps first.
std::vector<Claim> evaluate_claims(const ClaimInputs& in);

/// The claims whose rule reads which runs are chaotic (a map's chaos incidence or the Fig. 7
/// example's verdict): the ones the paper's judge can decide otherwise than the verdict.
bool reads_chaos_judge(const std::string& claim_id);
/// The same inputs with the paper's judge in the verdict's place: each map under_paper_judge
/// and the example's paper judgement as its verdict. The rules are not changed; only which
/// runs count as chaotic. Throws Error when a map was swept without the paper's judge.
ClaimInputs under_paper_judge(const ClaimInputs& in);
/// "K of M claims agree by the strict verdict; N of M by the paper's criterion" (the strict
/// count first, where the page's single count stood).
std::string both_judges_headline(const ClaimCount& strict, const ClaimCount& paper);

/// Fills a row's verdict, margin and why from its rule's result.
void judge(Claim& c, const RuleResult& r);

}  // namespace pneumachaos
