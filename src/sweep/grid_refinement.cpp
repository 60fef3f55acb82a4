#include "sweep/grid_refinement.hpp"

#include <algorithm>
#include <limits>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Every step-th index of an axis of n values, and its last.
std::vector<std::size_t> lattice(std::size_t n, std::size_t step) {
  std::vector<std::size_t> lines;
  for (std::size_t i = 0; i < n; i += step) lines.push_back(i);
  if (lines.back() != n - 1) lines.push_back(n - 1);
  return lines;
}

// Neighbouring lattice lines; a single line is a degenerate interval (an axis of one value).
std::vector<std::pair<std::size_t, std::size_t>> intervals(const std::vector<std::size_t>& l) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t k = 0; k + 1 < l.size(); ++k) out.emplace_back(l[k], l[k + 1]);
  if (l.size() == 1) out.emplace_back(l[0], l[0]);
  return out;
}

}  // namespace

GridRefinement::GridRefinement(std::size_t n0, std::size_t n1, std::size_t coarse_step)
    : n0_(n0), n1_(n1), step_(coarse_step), evaluated_(n0 * n1, 0) {
  if (n0 == 0 || n1 == 0) throw Error("grid refinement", "the grid has no points");
  if (coarse_step == 0) throw Error("grid refinement", "the coarse step must be at least 1");
}

std::size_t GridRefinement::evaluated_count() const {
  return static_cast<std::size_t>(std::count(evaluated_.begin(), evaluated_.end(), 1));
}

bool GridRefinement::uniform(const Cell& c, const std::vector<int>& classes) const {
  bool seen = false;
  int first = 0;
  for (std::size_t i = c.i0; i <= c.i1; ++i) {
    for (std::size_t j = c.j0; j <= c.j1; ++j) {
      const std::size_t p = i * n1_ + j;
      if (evaluated_[p] == 0) continue;
      if (!seen) {
        first = classes[p];
        seen = true;
      } else if (classes[p] != first) {
        return false;
      }
    }
  }
  return true;
}

// Halves the cell along each axis it spans more than one step of; marks the children's
// corners in `asked`.
void GridRefinement::split(const Cell& c, std::vector<Cell>& into, std::vector<char>& asked) const {
  std::vector<std::pair<std::size_t, std::size_t>> a{{c.i0, c.i1}}, b{{c.j0, c.j1}};
  if (c.i1 - c.i0 > 1) a = {{c.i0, (c.i0 + c.i1) / 2}, {(c.i0 + c.i1) / 2, c.i1}};
  if (c.j1 - c.j0 > 1) b = {{c.j0, (c.j0 + c.j1) / 2}, {(c.j0 + c.j1) / 2, c.j1}};
  for (const auto& [i0, i1] : a) {
    for (const auto& [j0, j1] : b) {
      into.push_back({i0, i1, j0, j1});
      for (std::size_t i : {i0, i1})
        for (std::size_t j : {j0, j1}) asked[i * n1_ + j] = 1;
    }
  }
}

std::vector<std::size_t> GridRefinement::next(const std::vector<int>& classes) {
  if (classes.size() != points()) throw Error("grid refinement", "one class per grid point");
  std::vector<char> asked(points(), 0);
  if (!started_) {
    started_ = true;
    for (const auto& [i0, i1] : intervals(lattice(n0_, step_)))
      for (const auto& [j0, j1] : intervals(lattice(n1_, step_)))
        cells_.push_back({i0, i1, j0, j1});
    asked = coarse_lattice(n0_, n1_, step_);
  } else {
    // A split whose new corners a neighbour has already evaluated asks for nothing; its
    // children are judged at once, until some point is asked for or no cell splits.
    bool split_any = true;
    while (split_any && std::count(asked.begin(), asked.end(), 1) == 0) {
      split_any = false;
      std::vector<Cell> kept;
      for (const Cell& c : cells_) {
        const bool splittable = c.i1 - c.i0 > 1 || c.j1 - c.j0 > 1;
        if (!splittable || uniform(c, classes)) {
          kept.push_back(c);
          continue;
        }
        split(c, kept, asked);
        split_any = true;
      }
      cells_ = std::move(kept);
      for (std::size_t p = 0; p < points(); ++p) asked[p] = asked[p] != 0 && evaluated_[p] == 0;
    }
  }
  std::vector<std::size_t> batch;
  for (std::size_t p = 0; p < points(); ++p) {
    if (asked[p] == 0 || evaluated_[p] != 0) continue;
    batch.push_back(p);
    evaluated_[p] = 1;
  }
  return batch;
}

std::vector<std::size_t> GridRefinement::sources() const {
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> source(points(), kNone);
  for (std::size_t p = 0; p < points(); ++p)
    if (evaluated_[p] != 0) source[p] = p;
  for (const Cell& c : cells_) {
    for (std::size_t i = c.i0; i <= c.i1; ++i) {
      for (std::size_t j = c.j0; j <= c.j1; ++j) {
        const std::size_t p = i * n1_ + j;
        if (source[p] != kNone) continue;
        // A cell's corners are evaluated: the nearest one (the lowest index among equals).
        std::size_t best = kNone, best_d = kNone;
        for (std::size_t a : {c.i0, c.i1}) {
          for (std::size_t b : {c.j0, c.j1}) {
            const std::size_t di = a > i ? a - i : i - a, dj = b > j ? b - j : j - b;
            const std::size_t q = a * n1_ + b, d = di * di + dj * dj;
            if (d < best_d || (d == best_d && q < best)) best = q, best_d = d;
          }
        }
        source[p] = best;
      }
    }
  }
  return source;
}

std::size_t RefinementResult::evaluated_count() const {
  return static_cast<std::size_t>(std::count(evaluated.begin(), evaluated.end(), 1));
}

RefinementResult refine_grid(std::size_t n0, std::size_t n1, std::size_t coarse_step,
                             const std::function<int(std::size_t)>& class_of) {
  GridRefinement g(n0, n1, coarse_step);
  std::vector<int> classes(n0 * n1, 0);
  RefinementResult r;
  for (auto batch = g.next(classes); !batch.empty(); batch = g.next(classes)) {
    for (std::size_t p : batch) classes[p] = class_of(p);
    ++r.rounds;
  }
  r.evaluated.resize(g.points());
  for (std::size_t p = 0; p < g.points(); ++p) r.evaluated[p] = g.evaluated(p) ? 1 : 0;
  r.source = g.sources();
  return r;
}

std::vector<char> coarse_lattice(std::size_t n0, std::size_t n1, std::size_t coarse_step) {
  if (n0 == 0 || n1 == 0) throw Error("grid refinement", "the grid has no points");
  if (coarse_step == 0) throw Error("grid refinement", "the coarse step must be at least 1");
  std::vector<char> on(n0 * n1, 0);
  for (std::size_t i : lattice(n0, coarse_step))
    for (std::size_t j : lattice(n1, coarse_step)) on[i * n1 + j] = 1;
  return on;
}

}  // namespace pneumachaos
