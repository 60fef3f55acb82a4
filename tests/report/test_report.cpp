// The report: every figure rendered, every link of the page resolving, claims computed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/claim_test_maps.hpp"
#include "support/variant_scenarios.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/claims/claim_rules.hpp"
#include "report/figures.hpp"
#include "pneumachaos/report/reproduce.hpp"
#include "pneumachaos/stability/stability_map.hpp"

namespace pneumachaos {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Report, QuickReproduceWritesEveryFigureAndAPageWhoseLinksResolve) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("pneumachaos_report_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ReproduceOptions o;
  o.out_dir = dir.string();
  o.quick = true;
  o.progress = false;
  const ReproduceResult r = reproduce(o);
  // Figs. 2, 3, 4, 5, 6 (and 4.5 kg) under each judge, 7a-d and the stability map.
  ASSERT_EQ(r.figures.size(), 15u);
  for (const FigureFiles& f : r.figures) {
    const std::string png = slurp(dir / "figures" / f.png);
    ASSERT_GT(png.size(), 1000u) << f.png;
    EXPECT_EQ(png.substr(1, 3), "PNG") << f.png;  // the PNG signature
    const std::string svg = slurp(dir / "figures" / f.svg);
    EXPECT_NE(svg.find("<svg"), std::string::npos) << f.svg;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << f.svg;
    EXPECT_TRUE(std::filesystem::exists(dir / "figures" / f.script));
    EXPECT_FALSE(slurp(dir / "figures" / f.plot_script).empty());
    ASSERT_FALSE(f.data.empty());
    for (const auto& d : f.data)
      EXPECT_GT(std::filesystem::file_size(dir / "figures" / d), 10u) << d;
  }
  const std::string html = slurp(r.index_html);
  const std::regex link(R"((src|href)="([^"#]+)\")");
  std::size_t links = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), link); it != std::sregex_iterator();
       ++it) {
    EXPECT_TRUE(std::filesystem::exists(dir / (*it)[2].str())) << (*it)[2].str();
    ++links;
  }
  EXPECT_GE(links, 15u * 4);  // image, SVG, script and data of each figure
  EXPECT_EQ(r.claims.size(), 22u);
  EXPECT_NE(html.find("<th>figure</th>"), std::string::npos);
  for (const Claim& c : r.claims) EXPECT_NE(html.find(c.verdict), std::string::npos);
  // The page says where it stands, first: the headline in the title and the first paragraph.
  const std::string headline = claims_headline(count_claims(r.claims));
  const auto title = html.find("<title>"), first = html.find(headline);
  EXPECT_NE(html.find(headline.substr(0, headline.find(" ("))), std::string::npos);
  EXPECT_LT(title, first);
  EXPECT_LT(first, html.find("<table>"));
  // The scenario block shows what the maps ran with: the seal scatter and bore texture.
  EXPECT_NE(html.find("friction_rel_sd = 0.03"), std::string::npos);
  EXPECT_NE(html.find("texture_rel = 0.02"), std::string::npos);
  // Fig. 3 labels the example's record by the page's own verdict, not as "chaotic".
  EXPECT_NE(slurp(dir / "figures" / "fig3_record1.dat").find("judged"), std::string::npos);
  // claims.json holds the same rows.
  const auto j = nlohmann::json::parse(slurp(dir / "claims.json"));
  ASSERT_EQ(j["claims"].size(), r.claims.size());
  for (std::size_t i = 0; i < r.claims.size(); ++i)
    EXPECT_EQ(j["claims"][i]["verdict"], r.claims[i].verdict);
  // Both judges: the headline gives both counts, claims.json the paper's outcome of each chaos
  // row, each map a second figure.
  ASSERT_EQ(r.paper_claims.size(), r.claims.size());
  const std::string both =
      both_judges_headline(count_claims(r.claims), count_claims(r.paper_claims));
  EXPECT_LT(html.find(both), html.find("<table>"));
  EXPECT_EQ(j["paper_judge"]["headline"], both);
  EXPECT_EQ(j["paper_judge"]["claims"].size(), 8u);
  EXPECT_TRUE(std::filesystem::exists(dir / "figures" / "fig4_map_ps025_m15_paper_judge.png"));
  std::filesystem::remove_all(dir);
}

SweepSummary map_with(std::size_t stick_slip, std::size_t full, std::size_t chaotic_runs) {
  // Every run judged (stick-slip), the chaotic runs spread over points of five runs each.
  SweepSummary s =
      spread_map(chaotic_runs, {0, 0, 0, 1, 0, 0, 0}, &PointSummary::chaos_incidence);
  s.stick_slip_points = stick_slip;
  s.chaos_full_points = full;
  return s;
}

TEST(Claims, FollowTheSweepResults) {
  ClaimInputs in;
  in.base = map_with(320, 30, 400);
  in.high_ps = map_with(260, 10, 300);
  in.double_m = map_with(370, 8, 500);
  in.triple_m = map_with(520, 0, 100);
  auto claims = evaluate_claims(in);
  EXPECT_EQ(row(claims, "fig5_chaos_reduced").verdict, kAgrees);      // 400 -> 300 runs
  EXPECT_EQ(row(claims, "fig5_full_chaos_halved").verdict, kAgrees);  // 30 -> 10
  EXPECT_EQ(row(claims, "fig6_stick_slip_grows").verdict, kAgrees);   // 320 -> 370
  EXPECT_EQ(row(claims, "fig6_few_always_chaotic").verdict, kAgrees);  // 8
  EXPECT_EQ(row(claims, "fig6_triple_no_chaos").verdict, kAgrees);     // 100 <= allowance
  // Change the inputs: the table changes with them.
  in.high_ps = map_with(330, 20, 420);
  in.double_m = map_with(300, 12, 500);
  in.triple_m = map_with(520, 0, 900);
  claims = evaluate_claims(in);
  EXPECT_EQ(row(claims, "fig5_chaos_reduced").verdict, kDisagrees);
  EXPECT_EQ(row(claims, "fig5_full_chaos_halved").verdict, kDisagrees);
  EXPECT_EQ(row(claims, "fig6_stick_slip_grows").verdict, kDisagrees);
  EXPECT_EQ(row(claims, "fig6_few_always_chaotic").verdict, kDisagrees);
  const Claim& none = row(claims, "fig6_triple_no_chaos");
  EXPECT_EQ(none.verdict, kDisagrees);
  EXPECT_LT(none.margin, 0.0);
  EXPECT_NE(none.why.find("900 runs are chaotic"), std::string::npos);
  in.high_ps.reset();
  EXPECT_EQ(row(evaluate_claims(in), "fig5_chaos_reduced").verdict, kNotReproduced);
}

// Misreading: the paper says both that Ps 0.30 shrinks the stick-slip region by about 20 % and
// that it extends it; scoring one reading silently would hide that.
TEST(Claims, TheContradictionIsShownAndNotScored) {
  ClaimInputs in;
  in.base = map_with(320, 30, 400);
  for (std::size_t after : {256u, 400u}) {
    in.high_ps = map_with(after, 10, 300);
    const auto claims = evaluate_claims(in);
    const Claim& c = row(claims, "fig5_stick_slip");
    EXPECT_EQ(c.verdict, kContradictory);
    EXPECT_FALSE(c.scored());
    EXPECT_NE(c.quote.find("decreases by about 20%"), std::string::npos);
    EXPECT_NE(c.quote.find("extends the stick-slip region"), std::string::npos);
    EXPECT_EQ(count_claims(claims).contradictory, 1u);
  }
}

// The paper's claim is that the exponent is positive, not the whole regime verdict: the two
// are separate rows.
TEST(Claims, ExponentAndVerdictAreSeparateRows) {
  ClaimInputs in;
  in.example_lambda = 3.0;
  in.example_uncertainty = 0.3;
  in.example_chaotic = false;
  in.example_regime = "stick-slip";
  auto claims = evaluate_claims(in);
  const Claim& e = row(claims, "fig7_exponent");
  EXPECT_EQ(e.verdict, kAgrees);
  EXPECT_NE(e.ours.find("4.33 +- 0.43 bits/s"), std::string::npos);  // 3 / ln 2
  EXPECT_EQ(row(claims, "fig7_verdict").verdict, kDisagrees);
  in.example_uncertainty = 2.0;
  in.example_chaotic = true;
  claims = evaluate_claims(in);
  EXPECT_EQ(row(claims, "fig7_exponent").verdict, kDisagrees);
  EXPECT_EQ(row(claims, "fig7_verdict").verdict, kAgrees);
}

// Misreading: at a choked equilibrium the mass multiplies a term that is 0 (eq. 9) or positive
// by construction (eq. 11), so "load increases a damping coefficient" passed on every model.
TEST(Claims, TheLoadsDampingCoefficientIsAnIdentityNotAScore) {
  ClaimInputs in;
  in.heavier = LoadCoefficients{-98.8, -98.8, -95.5, -92.1};
  const auto claims = evaluate_claims(in);
  const Claim& c = row(claims, "eq9_eq11_load_identity");
  EXPECT_EQ(c.verdict, kIdentity);
  EXPECT_FALSE(c.scored());
  EXPECT_EQ(count_claims(claims).identity, 1u);
}

TEST(Claims, EveryRowQuotesThePaperAndCarriesItsMargin) {
  ClaimInputs in;
  in.base = map_with(320, 30, 400);
  in.high_ps = map_with(260, 10, 300);
  in.example_peak_share = 0.67;
  in.example_acf_after_1s = 0.1;
  in.sign_rule = SignRuleCounts{18, 14, 24, 24, 3};
  in.meter_in_ps = {{19.6, 28.4, -7.1, -9.9}};
  const auto claims = evaluate_claims(in);
  ASSERT_EQ(claims.size(), 22u);
  for (const Claim& c : claims) {
    EXPECT_FALSE(c.id.empty());
    EXPECT_FALSE(c.quote.empty()) << c.id;
    EXPECT_FALSE(c.where.empty()) << c.id;
    EXPECT_FALSE(c.reading.empty()) << c.id;
    EXPECT_FALSE(c.rule.empty()) << c.id;
    if (c.verdict == kAgrees) EXPECT_GE(c.margin, 0.0) << c.id;
    if (c.verdict == kDisagrees) {
      EXPECT_LT(c.margin, 0.0) << c.id;
      EXPECT_FALSE(c.why.empty()) << c.id;
    }
    if (c.verdict == kNotReproduced) EXPECT_FALSE(c.why.empty()) << c.id;
  }
  EXPECT_EQ(row(claims, "fig7_spectrum").verdict, kDisagrees);
  EXPECT_NEAR(row(claims, "fig7_spectrum").margin, (0.25 - 0.67) / 0.25, 1e-12);
  EXPECT_EQ(row(claims, "sec32_sign_rule").verdict, kDisagrees);  // 14 of 18 < 80 %
  EXPECT_EQ(row(claims, "eq11_supply_pressure").verdict, kAgrees);
  const ClaimCount n = count_claims(claims);
  EXPECT_EQ(n.scored() + n.identity + n.contradictory, claims.size());
  const auto j = nlohmann::json::parse(claims_json(claims));
  EXPECT_EQ(j["claims"].size(), claims.size());
  EXPECT_EQ(j["count"]["agrees"], n.agrees);
  for (const auto& c : j["claims"]) {
    for (const char* key : {"id", "paper", "reading", "rule", "ours", "margin", "verdict", "why"})
      EXPECT_TRUE(c.contains(key)) << key;
    if (c["verdict"] == kNotReproduced) EXPECT_TRUE(c["margin"].is_null());
  }
}

// The paper's m is the total moving mass: the load levels are set on it, not added to the
// 1.05 kg piston + rod (which would make "doubled" x1.59) of the compliant-mount rig.
TEST(Claims, LoadLevelsAreTotalMovingMass) {
  Scenario s = compliant_mount();
  s.set_total_moving_mass(1.5);
  EXPECT_DOUBLE_EQ(s.total_moving_mass_kg(), 1.5);
  EXPECT_NEAR(s.load.mass_kg, 1.5 - s.load.piston_mass_kg, 1e-12);
  Scenario doubled = s;
  doubled.set_total_moving_mass(3.0);
  EXPECT_DOUBLE_EQ(doubled.total_moving_mass_kg() / s.total_moving_mass_kg(), 2.0);
  EXPECT_THROW(s.set_total_moving_mass(0.5), Error);  // below the piston + rod
  Scenario rigid = simple_rig_scenario();
  rigid.set_total_moving_mass(4.5);
  EXPECT_DOUBLE_EQ(rigid.load.mass_kg, 4.5);
}

// Misreading: the figure labelled (a) meter-in and (b) meter-out; the paper's (a) is meter-out.
TEST(Claims, Fig2PanelsAreLabelledAsThePapers) {
  TimeSeries t(1000.0);
  t.add_channel("v", "m/s", std::vector<double>(10, 0.05));
  const FigureSpec f = time_responses_figure({{"S2", t}}, {{"S1", t}});
  const auto a = f.plot.find("(a) meter-out"), b = f.plot.find("(b) meter-in");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_LT(a, b);
}

// Fig. 2: a record that stops before the 3 s asked says why (the stroke end); a full one says
// nothing.
TEST(Report, TimeResponsesSayWhichLineStopsShort) {
  const auto record = [](double seconds) {
    TimeSeries t(100.0);
    t.add_channel("v", "m/s",
                  std::vector<double>(static_cast<std::size_t>(100 * seconds) + 1, 0.1));
    return t;
  };
  const FigureSpec f =
      time_responses_figure({{"S2 = 0.2 mm^2", record(3.0)}}, {{"S1 = 0.6 mm^2", record(1.9)}});
  EXPECT_NE(f.caption.find("In (b), S1 = 0.6 mm^2 ends at 1.9 s: the piston reached the stroke "
                           "end."),
            std::string::npos)
      << f.caption;
  EXPECT_EQ(f.caption.find("In (a)"), std::string::npos) << f.caption;
}

// An adaptive map's figure marks its inferred points; a full map's figure has no such marks.
TEST(Report, IncidenceMapMarksInferredPoints) {
  SweepSpec spec;
  spec.axes = {parse_grid_axis("circuit.S1_mm2=2.45:2.50:0.05"),
               parse_grid_axis("circuit.S2_mm2=0.05:0.20:0.15")};
  SweepSummary s;
  for (std::size_t p = 0; p < 4; ++p) {
    PointSummary ps;
    ps.coordinates = {spec.axes[0].values[p / 2], spec.axes[1].values[p % 2]};
    s.per_point.push_back(ps);
  }
  const FigureSpec full = incidence_map_figure("m", "t", spec, s);
  EXPECT_EQ(full.data.size(), 3u);
  EXPECT_EQ(full.plot.find("inferred"), std::string::npos);
  s.per_point[3].inferred = true;
  s.inferred_points = 1;
  const FigureSpec adaptive = incidence_map_figure("m", "t", spec, s);
  ASSERT_EQ(adaptive.data.size(), 4u);
  EXPECT_EQ(adaptive.data[3].first, "m_inferred.dat");
  EXPECT_NE(adaptive.data[3].second.find("\n2.5 0.2\n"), std::string::npos)
      << adaptive.data[3].second;
  EXPECT_NE(adaptive.plot.find("'m_inferred.dat' using 1:2 with points"), std::string::npos);
  // The legend names every mark; the points run without chaos are marked, the inferred not.
  EXPECT_NE(adaptive.plot.find("set key below"), std::string::npos);
  EXPECT_NE(adaptive.plot.find("title 'inferred, not run'"), std::string::npos);
  EXPECT_NE(adaptive.plot.find("title 'run, no chaos'"), std::string::npos);
  EXPECT_EQ(adaptive.data[2].first, "m_calm.dat");
  EXPECT_NE(adaptive.data[2].second.find("\n2.5 0.05\n"), std::string::npos);
  EXPECT_EQ(adaptive.data[2].second.find("2.5 0.2"), std::string::npos);
  EXPECT_NE(adaptive.caption.find("1 of the 4 points were not run"), std::string::npos);
}

// Figures a person reads: the stability map's colour scale is set by the bulk of its values,
// not by one extreme that would leave most points near-white; the extremes are marked.
TEST(Figures, StabilityMapScaleFollowsTheBulkAndMarksTheExtremes) {
  StabilityMap m;
  m.axes = {parse_grid_axis("circuit.S1_mm2=2.45:2.5:0.05"),
            parse_grid_axis("circuit.S2_mm2=0.05:2.9:0.15")};
  for (std::size_t i = 0; i < 40; ++i) {
    StabilityMapPoint p;
    p.coordinates = {i < 20 ? 2.45 : 2.5, 0.05 + 0.15 * static_cast<double>(i % 20)};
    p.result.verdict_full = StabilityVerdict::kDamped;
    p.result.max_real_part_per_s = i % 20 == 0 ? 265.0 : -3.0 + 0.1 * static_cast<double>(i % 20);
    m.points.push_back(p);
  }
  const double scale = stability_colour_scale(m);
  EXPECT_LT(scale, 10.0);  // the extreme's own scale: 265
  EXPECT_GE(scale, 3.0);
  const FigureSpec f = stability_map_figure(m);
  EXPECT_NE(f.plot.find(fmt::format("set cbrange [-{0}:{0}]", scale)), std::string::npos);
  EXPECT_NE(f.plot.find("pt 6"), std::string::npos);  // the extremes, marked
  EXPECT_NE(f.caption.find("the 2 points beyond it"), std::string::npos) << f.caption;
}

// Fig. 7b's exponent panel holds where both running estimates settle (Wolf's is not clipped at
// a multiple of the model's last value), and Figs. 3 and 7b keep their legends off the curves.
TEST(Figures, ExponentPanelHoldsBothEstimatesAndLegendsStayOffTheCurves) {
  const std::vector<double> wolf = {40, 9, 6, 5, 4.8, 4.6, 4.5, 4.4};
  const std::vector<double> model = {30, 3, 1.5, 1.2, 1.1, 1.0, 0.9, 1.0};
  const auto range = lyapunov_panel_range(wolf, model);
  EXPECT_GT(range[1], 4.8);
  EXPECT_LT(range[1], 10.0);
  EXPECT_EQ(range[0], 0.0);
  EXPECT_LT(lyapunov_panel_range({-1, -2, -2}, {})[0], -2.0);
  TimeSeries t(1000.0);
  t.add_channel("v", "m/s", std::vector<double>(10, 0.05));
  t.add_channel("F_friction", "N", std::vector<double>(10, 20.0));
  EXPECT_NE(friction_loops_figure({{"a", t}}, 0.01, {}).plot.find("set key below"),
            std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
