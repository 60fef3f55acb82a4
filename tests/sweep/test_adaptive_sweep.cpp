// Adaptive sweeps (sweep --adaptive): the runs they evaluate are the full sweep's records bit
// for bit, their files do not depend on threads or resumes, and (label long) their maps agree
// with the full grid's on the paper's grid.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "support/adaptive_cases.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "sweep/map_agreement.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"
#include "support/sweep_test_files.hpp"

namespace pneumachaos {
namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::istringstream in(slurp(path));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// 6 x 7 points of 2 s runs with varied friction: stick-slip at the lowest S2, not above.
SweepSpec small_map(bool adaptive) {
  SweepSpec spec;
  spec.base = build_scenario("", {"run.duration_s=2", "variation.friction_rel_sd=0.05"});
  spec.axes = {parse_grid_axis("circuit.S1_mm2=2.45:3.70:0.25"),
               parse_grid_axis("circuit.S2_mm2=0.05:0.95:0.15")};
  spec.repeats = 2;
  spec.adaptive.enabled = adaptive;
  spec.adaptive.coarse_step = 2;
  return spec;
}

SweepSummary run_into(const SweepSpec& spec, const std::string& dir, std::size_t threads = 0) {
  SweepOptions o;
  o.progress = false;
  o.out_dir = dir;
  o.threads = threads;
  return run_sweep(spec, o);
}

TEST(AdaptiveSweep, EvaluatedRunsAreTheFullSweepsRecordsAndTheRestIsInferred) {
  const std::string full_dir = temp_dir("adaptive_full"), adaptive_dir = temp_dir("adaptive_map");
  const SweepSummary full = run_into(small_map(false), full_dir);
  const SweepSummary adaptive = run_into(small_map(true), adaptive_dir);
  ASSERT_GT(adaptive.inferred_points, 0u);
  ASSERT_LT(adaptive.inferred_points, 42u - 20u);  // more than the 4 x 4 lattice is evaluated
  EXPECT_EQ(adaptive.runs, 2 * (42 - adaptive.inferred_points));
  // runs.csv: every line of the adaptive sweep is the full sweep's line of that run.
  const auto full_runs = lines_of(full_dir + "/runs.csv");
  const std::set<std::string> full_lines(full_runs.begin(), full_runs.end());
  const auto adaptive_runs = lines_of(adaptive_dir + "/runs.csv");
  ASSERT_EQ(adaptive_runs.size(), adaptive.runs + 1);
  for (const std::string& line : adaptive_runs) EXPECT_TRUE(full_lines.count(line)) << line;
  // points.csv: the evaluated points' rows are the full sweep's with inferred = 0.
  const auto full_points = lines_of(full_dir + "/points.csv");
  const auto adaptive_points = lines_of(adaptive_dir + "/points.csv");
  ASSERT_EQ(full_points.size(), adaptive_points.size());
  EXPECT_EQ(full_points[0], adaptive_points[0]);
  // `inferred`, then the paper's judge's incidence (NaN: this sweep ran the verdict only).
  EXPECT_EQ(full_points[0].substr(full_points[0].rfind(",inferred")),
            ",inferred,paper_chaos_incidence");
  for (std::size_t p = 0; p < 42; ++p) {
    const bool inferred = adaptive.per_point[p].inferred;
    EXPECT_EQ(adaptive_points[p + 1].substr(adaptive_points[p + 1].rfind(',') - 2),
              inferred ? ",1,nan" : ",0,nan");
    if (!inferred) EXPECT_EQ(adaptive_points[p + 1], full_points[p + 1]);
    if (inferred) EXPECT_EQ(adaptive.per_point[p].runs, 0u);
    // The lattice the report counts motion on: the same in both, and never inferred.
    EXPECT_EQ(adaptive.per_point[p].on_lattice, full.per_point[p].on_lattice) << p;
    if (adaptive.per_point[p].on_lattice) EXPECT_FALSE(inferred) << p;
  }
  // On this small map the border is followed exactly.
  const MapAgreement m = compare_maps(small_map(true), full, adaptive);
  EXPECT_EQ(m.stick_slip_agreement, 1.0) << m.describe();
  EXPECT_EQ(m.chaos_agreement, 1.0) << m.describe();
  EXPECT_GT(full.stick_slip_points, 0u);
  EXPECT_LT(full.stick_slip_points, 42u);
  EXPECT_EQ(adaptive.stick_slip_points, full.stick_slip_points);
  std::filesystem::remove_all(full_dir);
  std::filesystem::remove_all(adaptive_dir);
}

TEST(AdaptiveSweep, FilesDoNotDependOnThreadsOrAResumeAndItsIdentityIsItsOwn) {
  const SweepSpec spec = small_map(true);
  const std::string one = temp_dir("adaptive_t1"), two = temp_dir("adaptive_t2");
  const std::string part = temp_dir("adaptive_part");
  run_into(spec, one, 1);
  run_into(spec, two, 2);
  // A kill after the lattice and a few refined runs, with a torn line.
  const std::string journal = slurp(one + "/journal.csv");
  std::size_t cut = 0;
  for (int lines = 0; lines < 1 + 16 * 2 + 3; ++lines) cut = journal.find('\n', cut) + 1;
  std::filesystem::create_directories(part);
  std::ofstream(part + "/journal.csv", std::ios::binary) << journal.substr(0, cut) << "9,0,12";
  SweepOptions o;
  o.progress = false;
  o.out_dir = part;
  o.resume = true;
  run_sweep(spec, o);
  for (const char* f : {"/runs.csv", "/points.csv", "/summary.json"}) {
    EXPECT_EQ(slurp(one + f), slurp(two + f)) << f;
    EXPECT_EQ(slurp(one + f), slurp(part + f)) << f;
  }
  EXPECT_NE(slurp(one + "/summary.json").find("\"inferred_points\""), std::string::npos);
  // The full sweep, and another coarse step, are other sweeps.
  EXPECT_NE(small_map(false).fingerprint(), spec.fingerprint());
  SweepSpec coarser = spec;
  coarser.adaptive.coarse_step = 3;
  EXPECT_NE(coarser.fingerprint(), spec.fingerprint());
  EXPECT_THROW(run_sweep(coarser, o), Error);
  for (const auto& d : {one, two, part}) std::filesystem::remove_all(d);
}

// compare_maps on a 2 x 3 map whose stick-slip region (points 0 and 1) lost point 1.
TEST(AdaptiveSweep, CompareMapsCountsAgreementAreasAndBorders) {
  SweepSpec spec;
  spec.axes = {parse_grid_axis("circuit.S1_mm2=1:2:1"), parse_grid_axis("circuit.S2_mm2=1:3:1")};
  SweepSummary full, adaptive;
  for (std::size_t p = 0; p < 6; ++p) {
    PointSummary ps;
    ps.runs = 5;
    ps.stick_slip_incidence = p < 2 ? 1.0 : 0.0;
    ps.chaos_incidence = p == 5 ? 0.4 : 0.0;
    ps.regime_incidence = {1.0, 0.0};
    full.per_point.push_back(ps);
  }
  full.runs = 30;
  adaptive = full;
  adaptive.per_point[1].stick_slip_incidence = 0.0;
  adaptive.per_point[1].runs = 0;
  adaptive.per_point[1].inferred = true;
  adaptive.inferred_points = 1;
  adaptive.runs = 25;
  const MapAgreement m = compare_maps(spec, full, adaptive);
  EXPECT_DOUBLE_EQ(m.stick_slip_agreement, 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(m.chaos_agreement, 1.0);
  EXPECT_DOUBLE_EQ(m.regime_agreement, 1.0);
  EXPECT_DOUBLE_EQ(m.runs_ratio(), 30.0 / 25.0);
  ASSERT_EQ(m.regions.size(), 3u);
  EXPECT_EQ(m.regions[0].full_points, 2u);
  EXPECT_EQ(m.regions[0].adaptive_points, 1u);
  EXPECT_EQ(m.regions[0].area_error(), 1u);
  EXPECT_EQ(m.regions[0].border_steps, 3u);  // 1-2 along S2; 0-3 and 1-4 along S1
  EXPECT_EQ(m.regions[2].full_points, 1u);   // chaos in some run: point 5
  EXPECT_EQ(m.regions[2].border_steps, 2u);
  EXPECT_TRUE(m.areas_within_borders());
  SweepSpec one_axis = spec;
  one_axis.axes.pop_back();
  EXPECT_THROW(compare_maps(one_axis, full, adaptive), Error);
}

TEST(AdaptiveSweep, NeedsExactlyTwoAxesAndACoarseStep) {
  SweepSpec spec = small_map(true);
  spec.axes.pop_back();
  try {
    spec.validate();
    ADD_FAILURE() << "one axis accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "adaptive: refines a map over exactly two grid axes; this sweep has 1");
  }
  spec = small_map(true);
  spec.adaptive.coarse_step = 0;
  EXPECT_THROW(spec.validate(), Error);
  // Off, the sweep's identity is the full sweep's: the option's other fields change nothing.
  SweepSpec off = small_map(false);
  off.adaptive.coarse_step = 7;
  EXPECT_EQ(off.fingerprint(), small_map(false).fingerprint());
  // Following the motion evaluates other points: another sweep, refused as such on resume.
  SweepSpec motion = small_map(true);
  motion.adaptive.follow_motion = true;
  EXPECT_NE(motion.fingerprint(), small_map(true).fingerprint());
}

// Following the motion refines where a point's regime turns from settling to oscillating, so
// an inferred point's motion is its cell's: no inferred point's motion differs from the full
// sweep's on a small map with both (S2 0.05-1.85 mm^2: stick-slip rows, steady rows).
TEST(AdaptiveSweep, FollowingTheMotionInfersNoMotionWrongly) {
  SweepSpec full = small_map(false);
  full.axes[1] = parse_grid_axis("circuit.S2_mm2=0.05:1.85:0.2");
  SweepSpec adaptive = full;
  adaptive.adaptive = {true, 2, true};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("pneumachaos_adaptive_motion_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const SweepSummary f = run_into(full, (dir / "full").string(), 2);
  const SweepSummary a = run_into(adaptive, (dir / "adaptive").string(), 2);
  ASSERT_GT(a.inferred_points, 0u);
  for (std::size_t p = 0; p < f.per_point.size(); ++p)
    EXPECT_EQ(point_motion(a.per_point[p]), point_motion(f.per_point[p])) << p;
  std::filesystem::remove_all(dir);
}

// The adaptive sweep's validation (label long; docs/sweep.md "Adaptive maps"): the paper's grid, 5
// runs per point, full against adaptive in the same process. Goals: >= 99 % of points in the
// same stick-slip class, >= 98 % in the same chaos class, each region's area within its
// border's length in grid steps, and on the paper's maps >= 4x fewer runs. The Fig. 4 map,
// the simple rig and the default rig at small S1 here; all six maps: bench/bench_adaptive.
TEST(AdaptiveSweep, PaperGridAgreesWithTheFullGrid) {
  if (std::getenv("PNEUMACHAOS_LONG_TESTS") == nullptr) {
    GTEST_SKIP() << "a long check: ctest --test-dir build -L long";
  }
  for (const AdaptiveCase& c : adaptive_cases(PNEUMACHAOS_VARIANTS_DIR)) {
    if (c.name.rfind("fig4", 0) != 0 && c.name.rfind("simple", 0) != 0 &&
        c.name.rfind("default", 0) != 0) {
      continue;
    }
    SweepOptions o;
    o.progress = false;
    o.out_dir = temp_dir("adaptive_validation");
    const AdaptiveValidation v = validate_adaptive(c.spec, o);
    const MapAgreement& m = v.agreement;
    std::cout << c.name << ": " << m.describe() << "; wall " << v.full_wall_s << " s full, "
              << v.adaptive_wall_s << " s adaptive" << std::endl;  // shown as each map ends
    EXPECT_GE(m.stick_slip_agreement, 0.99) << c.name;
    EXPECT_GE(m.chaos_agreement, 0.98) << c.name;
    EXPECT_TRUE(m.areas_within_borders()) << c.name;
    EXPECT_GE(m.runs_ratio(), c.min_runs_ratio) << c.name;
    std::filesystem::remove_all(o.out_dir);
  }
}

}  // namespace
}  // namespace pneumachaos
