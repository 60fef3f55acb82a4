// The report: every figure rendered, every link of the page resolving, claims computed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "pneumachaos/report/claim_rules.hpp"
#include "pneumachaos/report/figures.hpp"
#include "pneumachaos/report/reproduce.hpp"

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
  // Figs. 2, 3, 4, 5, 6 (and 4.5 kg), 7a-d and the stability map.
  ASSERT_EQ(r.figures.size(), 11u);
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
  EXPECT_GE(links, 11u * 4);  // image, SVG, script and data of each figure
  EXPECT_EQ(r.claims.size(), 15u);
  EXPECT_NE(html.find("<th>figure</th>"), std::string::npos);
  for (const Claim& c : r.claims) EXPECT_NE(html.find(c.verdict), std::string::npos);
  std::filesystem::remove_all(dir);
}

SweepSummary map_with(std::size_t stick_slip, std::size_t full, std::size_t any) {
  SweepSummary s;
  s.stick_slip_points = stick_slip;
  s.chaos_full_points = full;
  s.chaos_any_points = any;
  return s;
}

TEST(Claims, FollowTheSweepResults) {
  ClaimInputs in;
  in.base = map_with(32, 11, 43);
  in.high_ps = map_with(26, 0, 39);
  in.double_m = map_with(37, 8, 56);
  in.triple_m = map_with(52, 5, 49);
  in.example_lambda = 2.7;
  in.example_uncertainty = 0.3;
  in.example_chaotic = true;
  auto claims = evaluate_claims(in);
  ASSERT_EQ(claims.size(), 15u);
  EXPECT_EQ(claims[1].verdict, "agrees");     // 32 -> 26: -19 %
  EXPECT_EQ(claims[2].verdict, "agrees");     // 11 -> 0
  EXPECT_EQ(claims[3].verdict, "agrees");     // 32 -> 37, 8 always chaotic
  EXPECT_EQ(claims[4].verdict, "disagrees");  // chaos at 4.5 kg
  EXPECT_EQ(claims[5].verdict, "agrees");
  // Change the inputs: the table changes with them.
  in.high_ps = map_with(31, 9, 40);
  in.triple_m = map_with(60, 0, 0);
  in.example_uncertainty = 2.0;
  claims = evaluate_claims(in);
  EXPECT_EQ(claims[1].verdict, "disagrees");
  EXPECT_EQ(claims[1].ours, "32 -> 31 points (-3 %)");
  EXPECT_EQ(claims[2].verdict, "disagrees");
  EXPECT_EQ(claims[4].verdict, "agrees");
  EXPECT_EQ(claims[5].verdict, "disagrees");
  in.example_uncertainty = 0.3;
  in.example_chaotic = false;  // a periodic record's curve can rise too
  EXPECT_EQ(evaluate_claims(in)[5].verdict, "disagrees");
  in.high_ps.reset();
  EXPECT_EQ(evaluate_claims(in)[1].verdict, "not reproduced");
}

// A column of a map (S2 fastest) from stick-slip and chaos incidences.
std::vector<PointSummary> column(const std::vector<double>& stick, const std::vector<double>& chaos) {
  std::vector<PointSummary> pts(stick.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts[i].point = i;
    pts[i].stick_slip_incidence = stick[i];
    pts[i].chaos_incidence = chaos[i];
  }
  return pts;
}

TEST(ClaimRules, ChaosNearTheBorderFailsForChaosFarFromIt) {
  // Stick-slip in the first two S2 rows; chaos right above them: near the border.
  const std::vector<double> stick = {1, 1, 0, 0, 0, 0, 0, 0, 0, 0};
  auto near = chaos_location(column(stick, {0, 0, 1, 0, 0, 0, 0, 0, 0, 0}), 10);
  EXPECT_DOUBLE_EQ(near.near_border, 1.0);
  EXPECT_TRUE(chaos_near_border(near));
  // The same amount of chaos high up the S2 axis (every S1 > S2 still): far from the border.
  auto far = chaos_location(column(stick, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0}), 10);
  EXPECT_DOUBLE_EQ(far.near_border, 0.0);
  EXPECT_FALSE(chaos_near_border(far));
  // Chaos near the border but over most of the map: not a limited region.
  auto wide = chaos_location(column(stick, {1, 1, 1, 1, 1, 1, 0, 0, 0, 0}), 10);
  EXPECT_FALSE(chaos_near_border(wide));
}

TEST(ClaimRules, ExponentNeedsAChaoticRecord) {
  EXPECT_TRUE(positive_exponent_of_chaos(3.0, 0.5, true));
  EXPECT_FALSE(positive_exponent_of_chaos(3.0, 0.5, false));  // periodic, curve rising anyway
  EXPECT_FALSE(positive_exponent_of_chaos(3.0, 1.5, true));
}

TEST(ClaimRules, AcfOfASineDoesNotConvergeButNoiseDoes) {
  const double rate = 100.0;
  std::vector<double> sine(500), decaying(500);
  for (std::size_t k = 0; k < sine.size(); ++k) {
    sine[k] = std::cos(2 * M_PI * 6.3 * k / rate);
    decaying[k] = std::exp(-5.0 * k / rate) * std::cos(2 * M_PI * 6.3 * k / rate);
  }
  EXPECT_FALSE(acf_converged(acf_envelope_after(sine, rate, 1.0)));
  EXPECT_TRUE(acf_converged(acf_envelope_after(decaying, rate, 1.0)));
  EXPECT_FALSE(spectrum_without_dominant_peak(0.31));
  EXPECT_TRUE(spectrum_without_dominant_peak(0.08));
}

TEST(ClaimRules, CircuitContrastAndSpeedOrder) {
  EXPECT_TRUE(fluctuates_much_more({0.3, 0.4}, {0.01, 0.05}));
  EXPECT_FALSE(fluctuates_much_more({0.3, 0.1}, {0.01, 0.05}));  // 0.1 < 3 x 0.05
  EXPECT_TRUE(strictly_increasing({38, 66, 110}));
  EXPECT_FALSE(strictly_increasing({38, 66, 60}));
  std::vector<double> steady(100, 2.0), wobbly(100, 2.0);
  for (std::size_t k = 0; k < wobbly.size(); ++k) wobbly[k] += (k % 2 ? 1.0 : -1.0);
  EXPECT_DOUBLE_EQ(relative_fluctuation(steady, 10), 0.0);
  EXPECT_NEAR(relative_fluctuation(wobbly, 10), 0.5, 1e-12);
}

TEST(ClaimRules, LowSpeedSlopeSeesAStribeckDip) {
  std::vector<double> v, falling, rising;
  for (int k = 1; k <= 50; ++k) {
    v.push_back(1e-3 * k);
    falling.push_back(20.0 - 100.0 * 1e-3 * k);  // Stribeck: friction falls with speed
    rising.push_back(10.0 + 100.0 * 1e-3 * k);   // viscous only
  }
  EXPECT_NEAR(low_speed_slope(v, falling, 0.05), -100.0, 1e-9);
  EXPECT_NEAR(low_speed_slope(v, rising, 0.05), 100.0, 1e-9);
}

// A memoryless friction curve F(v) traces no loop; a lagging one does; a record that rests
// at zero speed is a standstill, not "without a standstill".
TEST(ClaimRules, FrictionLoopNeedsHysteresisAndMotion) {
  std::vector<double> v, memoryless, lagging, resting;
  const double dt = 1e-3;
  for (int k = 0; k < 4000; ++k) {
    const double t = k * dt, w = 2 * M_PI * 4.0;
    v.push_back(0.09 + 0.08 * std::sin(w * t));
    memoryless.push_back(20.0 - 50.0 * v.back());
    lagging.push_back(20.0 - 50.0 * (0.09 + 0.08 * std::sin(w * (t - 0.01))));
    resting.push_back(std::max(0.0, 0.08 * std::sin(w * t)));
  }
  EXPECT_FALSE(loops_without_standstill(measure_friction_loop(v, memoryless)));
  const FrictionLoop l = measure_friction_loop(v, lagging);
  EXPECT_TRUE(loops_without_standstill(l));
  EXPECT_EQ(l.hysteretic_bins, l.bins);
  const FrictionLoop r = measure_friction_loop(resting, lagging);
  EXPECT_GT(r.standstill_share, 0.4);
  EXPECT_FALSE(loops_without_standstill(r));
}

TEST(ClaimRules, FoldAndStretchBands) {
  FoldStretch f{0.8, 40, 12.0, 1.0, -5.0, 2.0};
  EXPECT_TRUE(folded_and_stretched(f));
  f.maxima_in_fold_band = 0.3;  // the trajectory turns back elsewhere
  EXPECT_FALSE(folded_and_stretched(f));
  f = FoldStretch{0.8, 40, 2.0, 1.0, -5.0, 2.0};  // stretching not significant
  EXPECT_FALSE(folded_and_stretched(f));
  f = FoldStretch{0.8, 40, 12.0, 1.0, 10.0, 2.0};  // the fold band stretches as much
  EXPECT_FALSE(folded_and_stretched(f));
  // A sine of amplitude 160 mm/s around 0 turns back at 160 mm/s, in the fold band, but
  // nearby trajectories of a periodic orbit do not separate anywhere.
  std::vector<double> sine(6000);
  for (std::size_t k = 0; k < sine.size(); ++k) sine[k] = 0.16 * std::sin(2 * M_PI * 3.0 * k / 1000.0);
  const FoldStretch s = measure_fold_stretch(sine, 1000.0, 3, 40, 80);
  EXPECT_GT(s.maxima_in_fold_band, 0.9);
  EXPECT_FALSE(folded_and_stretched(s));
}

TEST(Claims, DampingAndSignRuleFollowTheirInputs) {
  ClaimInputs in;
  in.higher_ps = DampingChange{-99, -98, -96, -95, 35.0, 30.0};
  in.heavier = DampingChange{-99, -98, -96, -95, 35.0, 40.0};
  in.sign_rule = SignRuleCounts{18, 15, 24, 24};
  auto claims = evaluate_claims(in);
  EXPECT_EQ(claims[11].verdict, "agrees");
  EXPECT_EQ(claims[12].verdict, "agrees");
  EXPECT_EQ(claims[10].verdict, "agrees");
  in.higher_ps = DampingChange{-99, -98, -96, -96, 35.0, 36.0};  // b1 unchanged, less damped
  in.heavier = DampingChange{-99, -100, -96, -95, 35.0, 40.0};   // a1 falls
  in.sign_rule = SignRuleCounts{18, 10, 24, 24};                 // damped points oscillate
  claims = evaluate_claims(in);
  EXPECT_EQ(claims[11].verdict, "disagrees");
  EXPECT_EQ(claims[12].verdict, "disagrees");
  EXPECT_EQ(claims[10].verdict, "disagrees");
  EXPECT_EQ(claims[7].verdict, "not reproduced");  // no ACF given
  ASSERT_EQ(claims.size(), 15u);
  EXPECT_EQ(claims[13].verdict, "not reproduced");  // no fold/stretch measurement
  in.friction_loop = FrictionLoop{0.3, 10, 10};      // loops, but rests 30 % of the time
  EXPECT_EQ(evaluate_claims(in)[14].verdict, "disagrees");
}

// An adaptive map's figure marks its inferred points; a full map's figure is as before.
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
  EXPECT_EQ(full.data.size(), 2u);
  EXPECT_EQ(full.plot.find("inferred"), std::string::npos);
  s.per_point[3].inferred = true;
  s.inferred_points = 1;
  const FigureSpec adaptive = incidence_map_figure("m", "t", spec, s);
  ASSERT_EQ(adaptive.data.size(), 3u);
  EXPECT_EQ(adaptive.data[2].first, "m_inferred.dat");
  EXPECT_NE(adaptive.data[2].second.find("\n2.5 0.2\n"), std::string::npos)
      << adaptive.data[2].second;
  EXPECT_NE(adaptive.plot.find("'m_inferred.dat' using 1:2 with points"), std::string::npos);
  EXPECT_NE(adaptive.caption.find("1 of the 4 points were not run"), std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
