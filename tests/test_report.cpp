// The report: every figure rendered, every link of the page resolving, claims computed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

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
  EXPECT_EQ(r.claims.size(), 6u);
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
  auto claims = evaluate_claims(in);
  ASSERT_EQ(claims.size(), 6u);
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
  in.high_ps.reset();
  EXPECT_EQ(evaluate_claims(in)[1].verdict, "not reproduced");
}

}  // namespace
}  // namespace pneumachaos
