#pragma once
// Adaptive refinement of a two-axis map (docs/sweep.md "Adaptive maps"): a coarse
// lattice of the grid first, then every cell whose evaluated points differ in what the map
// shows is split, down to single grid steps. Pure: it knows points and classes, not runs.

#include <cstddef>
#include <functional>
#include <vector>

namespace pneumachaos {

/// Which points of an n0 x n1 grid (point = i0 * n1 + i1, the last axis fastest, as
/// grid_index) to evaluate, round by round.
///
/// Round 0 is the coarse lattice: every `coarse_step`-th line of each axis plus its last line.
/// Each later round splits every cell (a rectangle between neighbouring lattice lines) whose
/// evaluated points — its corners and any point on its edges that a neighbour's refinement
/// evaluated — do not all share one class, at its midlines, and asks for the new corners.
/// When no cell needs splitting, every point not evaluated lies in a cell whose evaluated
/// points all share one class, and takes that class (source()).
///
/// The guarantee and its limit: a region of one class is found when it holds a point of the
/// coarse lattice (any region at least `coarse_step` points wide along both axes does), and
/// its border with its neighbours is then followed to single grid steps; a region narrower
/// than the coarse step that slips between the lattice's points can be missed entirely, and
/// so can a bump of a border that enters a uniform cell without touching an evaluated point.
class GridRefinement {
 public:
  /// Throws Error for an empty grid or a coarse step of 0.
  GridRefinement(std::size_t n0, std::size_t n1, std::size_t coarse_step);

  /// The points to evaluate next, ascending and none evaluated before; empty when the
  /// refinement is complete. `classes[p]` is read for the evaluated points only (what the
  /// map shows at p: equal values look alike); it has one entry per grid point.
  std::vector<std::size_t> next(const std::vector<int>& classes);

  [[nodiscard]] bool evaluated(std::size_t point) const { return evaluated_.at(point) != 0; }
  [[nodiscard]] std::size_t evaluated_count() const;
  [[nodiscard]] std::size_t points() const { return n0_ * n1_; }

  /// Once next() has returned empty: for every point, the evaluated point whose class and
  /// values it takes — itself when evaluated, else the nearest corner of its cell (the lowest
  /// index among equally near ones), whose evaluated points all share one class.
  [[nodiscard]] std::vector<std::size_t> sources() const;

 private:
  struct Cell {
    std::size_t i0, i1, j0, j1;  ///< closed index ranges
  };
  [[nodiscard]] bool uniform(const Cell& c, const std::vector<int>& classes) const;
  void split(const Cell& c, std::vector<Cell>& into, std::vector<char>& asked) const;
  std::size_t n0_, n1_, step_;
  std::vector<Cell> cells_;
  std::vector<char> evaluated_;
  bool started_ = false;
};

/// A refinement run to its end with a known class per point (synthetic fields, or a full
/// map's classes): which points it evaluated and where every point takes its class from.
struct RefinementResult {
  std::vector<char> evaluated;
  std::vector<std::size_t> source;
  std::size_t rounds = 0;
  [[nodiscard]] std::size_t evaluated_count() const;
};
RefinementResult refine_grid(std::size_t n0, std::size_t n1, std::size_t coarse_step,
                             const std::function<int(std::size_t)>& class_of);

/// The refinement's round 0 as a mask over the n0 x n1 grid: 1 on every `coarse_step`-th line
/// of each axis and on its last. Every adaptive map of the grid runs these points, and they
/// sample the whole grid evenly (the refined points crowd at the borders): what a map does
/// not follow can be read on them, the same with and without refinement.
std::vector<char> coarse_lattice(std::size_t n0, std::size_t n1, std::size_t coarse_step);

}  // namespace pneumachaos
