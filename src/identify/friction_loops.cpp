// The friction-velocity picture of an estimate: the binned steady curve, the excursions
// between sticks and reversals, and the paper's Fig. 3 marks A-D on each (docs/friction.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "friction_steps.hpp"

namespace pneumachaos::identify {
namespace {

using detail::sign_of;

// Point B of one excursion: where the accelerating branch (begin..peak) and the decelerating
// one (peak..end) cross in the F-v plane, compared on a grid of speeds over both branches.
std::optional<LoopMark> branch_crossing(const FrictionEstimate& e, const std::vector<double>& Fs,
                                        std::size_t begin, std::size_t peak, std::size_t end,
                                        int dir) {
  const double top = dir * e.v_smooth_m_per_s[peak];
  const double lo = e.stick_threshold_m_per_s;
  if (!(top > 2.0 * lo) || peak - begin < 4 || end - peak < 4) return std::nullopt;
  constexpr int kGrid = 24;
  const double half = 0.5 * (0.95 * top - lo) / kGrid;
  const auto branch_mean = [&](std::size_t from, std::size_t to, double u, std::size_t& nearest) {
    double s = 0.0, best = std::numeric_limits<double>::infinity();
    std::size_t c = 0;
    for (std::size_t i = from; i < to; ++i) {
      const double d = std::abs(dir * e.v_smooth_m_per_s[i] - u);
      if (d <= half) {
        s += Fs[i];
        ++c;
      }
      if (d < best) {
        best = d;
        nearest = i;
      }
    }
    return c ? s / double(c) : std::numeric_limits<double>::quiet_NaN();
  };
  double prev_diff = std::numeric_limits<double>::quiet_NaN(), prev_u = 0.0, prev_f = 0.0;
  for (int g = 0; g < kGrid; ++g) {
    const double u = lo + (2 * g + 1) * half;
    std::size_t ia = begin, id = peak;
    const double fa = branch_mean(begin, peak + 1, u, ia);
    const double fd = branch_mean(peak, end, u, id);
    if (std::isnan(fa) || std::isnan(fd)) continue;
    const double diff = fa - fd;
    if (!std::isnan(prev_diff) && sign_of(diff) != sign_of(prev_diff) && diff != 0.0) {
      const double w = prev_diff / (prev_diff - diff);
      LoopMark b;
      b.label = 'B';
      b.v_m_per_s = dir * (prev_u + w * (u - prev_u));
      b.F_N = prev_f + w * (0.5 * (fa + fd) - prev_f);
      b.index = ia;
      return b;
    }
    prev_diff = diff;
    prev_u = u;
    prev_f = 0.5 * (fa + fd);
  }
  return std::nullopt;
}

// The sliding samples moving in direction `dir`, binned by speed from the stick threshold to
// the largest speed: mean velocity, mean force and its spread per non-empty bin, slowest first.
std::vector<CurveBin> direction_bins(const FrictionEstimate& e, int dir, std::size_t count) {
  const std::size_t n = e.v_m_per_s.size();
  const double thr = e.stick_threshold_m_per_s;
  double top = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (e.sliding[i] && dir * e.v_m_per_s[i] > 0) top = std::max(top, dir * e.v_m_per_s[i]);
  if (!(top > thr) || count == 0) return {};
  const double width = (top - thr) / double(count);
  std::vector<CurveBin> bins(count);
  std::vector<double> sum_v(count, 0.0), sum_f(count, 0.0), sum_f2(count, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = dir * e.v_m_per_s[i];
    if (!e.sliding[i] || u < thr) continue;
    const auto b = std::min(count - 1, static_cast<std::size_t>((u - thr) / width));
    ++bins[b].count;
    sum_v[b] += e.v_m_per_s[i];
    sum_f[b] += e.F_N[i];
    sum_f2[b] += e.F_N[i] * e.F_N[i];
  }
  std::vector<CurveBin> kept;
  for (std::size_t b = 0; b < count; ++b) {
    const double a = thr + double(b) * width, c = a + width;
    bins[b].v_lo_m_per_s = dir > 0 ? a : -c;
    bins[b].v_hi_m_per_s = dir > 0 ? c : -a;
    if (bins[b].count == 0) continue;
    const double m = double(bins[b].count);
    bins[b].v_mean_m_per_s = sum_v[b] / m;
    bins[b].F_mean_N = sum_f[b] / m;
    bins[b].F_sd_N = bins[b].count > 1
                         ? std::sqrt(std::max(0.0, (sum_f2[b] - sum_f[b] * sum_f[b] / m) / (m - 1.0)))
                         : 0.0;
    kept.push_back(bins[b]);
  }
  return kept;
}

Excursion excursion(std::size_t begin, std::size_t end, int dir, bool from_stick, bool to_stick) {
  Excursion ex;
  ex.begin = begin;
  ex.end = end;
  ex.direction = dir;
  ex.from_stick = from_stick;
  ex.to_stick = to_stick;
  return ex;
}

// The moving run [i, j) split at every reversal (a crossing of the threshold in the opposite
// direction; the split at the last sample of the old sign).
void split_run(FrictionEstimate& e, std::size_t i, std::size_t j) {
  const double thr = e.stick_threshold_m_per_s;
  std::size_t begin = i;
  int dir = 0;
  bool begins_at_stick = i > 0;
  for (std::size_t k = i; k < j; ++k) {
    const double v = e.v_smooth_m_per_s[k];
    if (dir == 0) {
      if (std::abs(v) > thr) dir = sign_of(v);
      continue;
    }
    if (-dir * v > thr) {
      std::size_t split = k;
      while (split > begin && sign_of(e.v_smooth_m_per_s[split - 1]) != dir) --split;
      e.excursions.push_back(excursion(begin, split, dir, begins_at_stick, false));
      begin = split;
      begins_at_stick = false;
      dir = -dir;
    }
  }
  if (dir != 0) e.excursions.push_back(excursion(begin, j, dir, begins_at_stick, j < e.stuck.size()));
}

}  // namespace

namespace detail {

void add_steady_curve(FrictionEstimate& e, std::size_t bins) {
  for (int dir : {-1, 1}) {
    std::vector<CurveBin> kept = direction_bins(e, dir, bins);
    if (dir < 0) std::reverse(kept.begin(), kept.end());  // negative velocities first
    e.curve.insert(e.curve.end(), kept.begin(), kept.end());
  }
}

void add_excursions(FrictionEstimate& e) {
  const std::size_t n = e.stuck.size();
  for (std::size_t i = 0; i < n;) {
    if (e.stuck[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && !e.stuck[j]) ++j;
    split_run(e, i, j);
    i = j;
  }
}

void add_loop_marks(FrictionEstimate& e, const std::vector<double>& F_smooth) {
  for (Excursion& ex : e.excursions) {
    if (ex.end - ex.begin < 3) continue;
    const int dir = ex.direction;
    std::size_t peak = ex.begin;
    for (std::size_t k = ex.begin; k < ex.end; ++k)
      if (dir * e.v_smooth_m_per_s[k] > dir * e.v_smooth_m_per_s[peak]) peak = k;
    if (ex.from_stick) {
      const auto st = std::find_if(e.sticks.begin(), e.sticks.end(),
                                   [&](const StickInterval& s2) { return s2.end == ex.begin; });
      ex.marks.push_back({'A', ex.begin, e.v_m_per_s[ex.begin],
                          st != e.sticks.end() ? st->breakaway_N : F_smooth[ex.begin]});
    }
    if (auto b = branch_crossing(e, F_smooth, ex.begin, peak, ex.end, dir)) ex.marks.push_back(*b);
    ex.marks.push_back({'C', peak, e.v_m_per_s[peak], F_smooth[peak]});
    if (ex.to_stick) ex.marks.push_back({'D', ex.end - 1, e.v_m_per_s[ex.end - 1], F_smooth[ex.end - 1]});
  }
}

}  // namespace detail
}  // namespace pneumachaos::identify
