// The adaptive map's refinement on synthetic class fields of the paper's grid shape: what it
// finds exactly, what it evaluates, and the honest limit (a region thinner than the coarse
// step between the lattice's points is missed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "sweep/grid_refinement.hpp"

namespace pneumachaos {
namespace {

constexpr std::size_t kN0 = 26, kN1 = 30;  // the paper's S1 x S2 grid
constexpr std::size_t kStep = 4;           // the default coarse step

using Field = std::function<int(std::size_t, std::size_t)>;

struct Outcome {
  std::size_t wrong = 0, evaluated = 0;
};

// Refines `field`, then counts the points whose inferred class is not their own.
Outcome refine(const Field& field, std::size_t step = kStep) {
  const auto class_of = [&](std::size_t p) { return field(p / kN1, p % kN1); };
  const RefinementResult r = refine_grid(kN0, kN1, step, class_of);
  Outcome o;
  o.evaluated = r.evaluated_count();
  for (std::size_t p = 0; p < kN0 * kN1; ++p) {
    EXPECT_EQ(r.evaluated[p] != 0, r.source[p] == p) << p;
    if (class_of(r.source[p]) != class_of(p)) ++o.wrong;
  }
  return o;
}

TEST(GridRefinement, AUniformFieldCostsOnlyTheCoarseLattice) {
  const Outcome o = refine([](std::size_t, std::size_t) { return 0; });
  EXPECT_EQ(o.wrong, 0u);
  // Lines 0, 4, ..., 24 and 25 of S1; 0, 4, ..., 28 and 29 of S2.
  EXPECT_EQ(o.evaluated, 8u * 9u);
}

TEST(GridRefinement, ADiskIsFoundAndItsBorderFollowed) {
  const Outcome o = refine(
      [](std::size_t i, std::size_t j) { return std::hypot(i - 11.3, j - 16.6) < 6.2 ? 1 : 0; });
  EXPECT_EQ(o.wrong, 0u);
  EXPECT_LT(o.evaluated, kN0 * kN1 / 2);
}

TEST(GridRefinement, ADiagonalBandOfThreeClassesIsExact) {
  const Outcome o = refine([](std::size_t i, std::size_t j) {
    const double d = static_cast<double>(j) - 1.1 * static_cast<double>(i) - 2.0;
    return d < 0.0 ? 0 : d < 5.0 ? 1 : 2;
  });
  EXPECT_EQ(o.wrong, 0u);
  EXPECT_LT(o.evaluated, kN0 * kN1 / 2);
}

TEST(GridRefinement, AOneCellStripeThroughTheLatticesPointsIsFollowed) {
  // The diagonal i == j passes through lattice points (0,0), (4,4), ...
  const Outcome diagonal = refine([](std::size_t i, std::size_t j) { return i == j ? 1 : 0; });
  EXPECT_EQ(diagonal.wrong, 0u);
  // A row of S2 on a lattice line.
  const Outcome row = refine([](std::size_t, std::size_t j) { return j == 12 ? 1 : 0; });
  EXPECT_EQ(row.wrong, 0u);
}

TEST(GridRefinement, AOneCellStripeBetweenTheLatticesPointsIsMissed) {
  // The documented limit: a region thinner than the coarse step that holds no lattice point is
  // not seen at all; the whole stripe is inferred as its surroundings.
  const Outcome row = refine([](std::size_t, std::size_t j) { return j == 13 ? 1 : 0; });
  EXPECT_EQ(row.wrong, kN0);
  EXPECT_EQ(row.evaluated, 8u * 9u);
  // i == j + 2 meets no lattice point ((25, 23) is not one; (25, 24) would be, and i == j + 1
  // is found through it and followed).
  const Outcome diagonal = refine([](std::size_t i, std::size_t j) { return i == j + 2 ? 1 : 0; });
  EXPECT_EQ(diagonal.wrong, kN0 - 2);
  EXPECT_EQ(refine([](std::size_t i, std::size_t j) { return i == j + 1 ? 1 : 0; }).wrong, 0u);
  // A coarse step of 1 is the full grid: nothing is missed, nothing saved.
  const Outcome full = refine([](std::size_t, std::size_t j) { return j == 13 ? 1 : 0; }, 1);
  EXPECT_EQ(full.wrong, 0u);
  EXPECT_EQ(full.evaluated, kN0 * kN1);
}

TEST(GridRefinement, BatchesAreNewAscendingPointsAndTheFirstIsTheLattice) {
  GridRefinement g(5, 7, 2);
  std::vector<int> classes(35, 0);
  const auto lattice = g.next(classes);
  EXPECT_EQ(lattice, (std::vector<std::size_t>{0, 2, 4, 6, 14, 16, 18, 20, 28, 30, 32, 34}));
  classes[16] = 1;  // point (2, 2): its four cells are refined
  const auto second = g.next(classes);
  ASSERT_FALSE(second.empty());
  for (std::size_t k = 0; k < second.size(); ++k) {
    EXPECT_FALSE(std::count(lattice.begin(), lattice.end(), second[k])) << second[k];
    if (k > 0) EXPECT_LT(second[k - 1], second[k]);
  }
  // The four cells around (2, 2) halved: every point of (0..4) x (0..4) not on the lattice.
  EXPECT_EQ(second.size(), 16u);
  for (auto batch = g.next(classes); !batch.empty(); batch = g.next(classes)) {
  }
  const auto source = g.sources();
  for (std::size_t p = 0; p < 35; ++p) EXPECT_EQ(classes[source[p]], p == 16 ? 1 : 0) << p;
}

// The lattice the report counts motion on (PointSummary::on_lattice) is exactly round 0, so
// every adaptive map runs it, whatever the classes do afterwards.
TEST(GridRefinement, TheCoarseLatticeIsRoundZero) {
  GridRefinement g(5, 7, 2);
  const auto first = g.next(std::vector<int>(35, 0));
  const std::vector<char> mask = coarse_lattice(5, 7, 2);
  std::vector<std::size_t> on;
  for (std::size_t p = 0; p < mask.size(); ++p)
    if (mask[p] != 0) on.push_back(p);
  EXPECT_EQ(on, first);
  const std::vector<char> paper = coarse_lattice(kN0, kN1, kStep);
  EXPECT_EQ(std::count(paper.begin(), paper.end(), 1), 8 * 9);
  EXPECT_THROW(coarse_lattice(3, 3, 0), Error);
}

TEST(GridRefinement, AnAxisOfOneValueIsALine) {
  const RefinementResult r = refine_grid(1, 9, 4, [](std::size_t p) { return p >= 3 ? 1 : 0; });
  for (std::size_t p = 0; p < 9; ++p) EXPECT_EQ(r.source[p] >= 3, p >= 3) << p;
  EXPECT_THROW(GridRefinement(0, 3, 1), Error);
  EXPECT_THROW(GridRefinement(3, 3, 0), Error);
}

}  // namespace
}  // namespace pneumachaos
