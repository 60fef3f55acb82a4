#include "analysis/continuous_alignment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

namespace {

// Samples a cubic interpolation reads: base - 1 .. base + 2.
constexpr std::size_t kCubicStencil = 4;

// Newton steps towards the closest approach: the first from the sample itself, the second
// from the interpolated point it reaches.
constexpr int kNewtonSteps = 2;

[[noreturn, gnu::noinline]] void too_short(std::size_t n, std::size_t needed) {
  throw Error("interpolation", fmt::format("{} samples: at least {} are needed", n, needed));
}

// The first sample of the stencil for fractional index t (`needed` samples read from there
// on), kept inside the record: near either end the cubic through the four end samples is
// used (still exact at the samples), so no caller's margin can make it read outside.
std::size_t stencil_start(double t, std::size_t n, std::size_t needed) {
  if (n < needed) too_short(n, needed);
  const double first = std::floor(t) - 1.0;
  const double last = static_cast<double>(n - needed);
  return static_cast<std::size_t>(std::clamp(first, 0.0, last));
}

// interpolate_series, inlined into closest_offset: Wolf's program aligns 40 candidates per
// replacement, 18 interpolations each, and the calls cost a sixth of a 1e6-sample analysis
// (docs/notes/performance.md). The arithmetic is the same.
inline double cubic_at(std::span<const double> x, double t) {
  const std::size_t s = stencil_start(t, x.size(), kCubicStencil);
  const double u = t - static_cast<double>(s + 1);
  const double p0 = x[s], p1 = x[s + 1], p2 = x[s + 2], p3 = x[s + 3];
  return p1 + 0.5 * u *
                  (p2 - p0 +
                   u * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + u * (3.0 * (p1 - p2) + p3 - p0)));
}

double coordinate_at(const DelayEmbedding& e, double t, std::size_t d) {
  return cubic_at(e.series(), t + static_cast<double>(d * e.delay()));
}

}  // namespace

double interpolate_series(std::span<const double> x, double t) { return cubic_at(x, t); }

std::span<const double> shifted_series(std::span<const double> x, std::size_t j, double s,
                                       std::size_t count, std::vector<double>& buffer) {
  // t = j + s = base + u; Lagrange weights of the cubic through base-1..base+2, the stencil
  // kept inside the record (u then lies in [-1, 2), still interpolating or exact at a node).
  const double t = static_cast<double>(j) + s;
  const std::size_t start = stencil_start(t, x.size(), count + kCubicStencil - 1);
  const double u = t - static_cast<double>(start + 1);
  const double w0 = -u * (u - 1.0) * (u - 2.0) / 6.0;
  const double w1 = (u + 1.0) * (u - 1.0) * (u - 2.0) / 2.0;
  const double w2 = -(u + 1.0) * u * (u - 2.0) / 2.0;
  const double w3 = (u + 1.0) * u * (u - 1.0) / 6.0;
  buffer.resize(count);
  const double* p = x.data() + start;
  for (std::size_t k = 0; k < count; ++k) {
    buffer[k] = w0 * p[k] + w1 * p[k + 1] + w2 * p[k + 2] + w3 * p[k + 3];
  }
  return buffer;
}

namespace {

// One Newton step's sums at the neighbour's time t: the offset moves by -num / den.
struct NewtonSums {
  double num = 0.0, den = 0.0;
};

NewtonSums newton_sums(const DelayEmbedding& e, std::size_t i, double t) {
  NewtonSums n;
  for (std::size_t d = 0; d < e.dimension(); ++d) {
    const double here = coordinate_at(e, t, d);
    const double tangent = 0.5 * (coordinate_at(e, t + 1.0, d) - coordinate_at(e, t - 1.0, d));
    n.num += (here - e.coordinate(i, d)) * tangent;
    n.den += tangent * tangent;
  }
  return n;
}

// The same sums at a whole sample j whose stencils (at j - 1, j, j + 1 in every coordinate)
// lie inside the record: there the cubic's fractional part is exactly 0 and it returns the
// sample itself (at most the sign of a zero differs, which no sum below can carry: s starts
// at +0 and 0 - (+-0) is +0), so the samples are read directly. This is the first of the two
// steps of every alignment, half of Wolf's candidate placement (docs/notes/performance.md,
// "Wolf's candidate placement").
NewtonSums newton_sums_at_sample(const DelayEmbedding& e, std::size_t i, std::size_t j) {
  NewtonSums n;
  const double* x = e.series().data();
  for (std::size_t d = 0; d < e.dimension(); ++d) {
    const std::size_t k = j + d * e.delay();
    const double tangent = 0.5 * (x[k + 1] - x[k - 1]);
    n.num += (x[k] - e.coordinate(i, d)) * tangent;
    n.den += tangent * tangent;
  }
  return n;
}

}  // namespace

double closest_offset(const DelayEmbedding& e, std::size_t i, std::size_t j) {
  const std::size_t last = j + (e.dimension() - 1) * e.delay();
  const bool inside = j >= 2 && last + kCubicStencil <= e.series().size();
  double s = 0.0;
  for (int iteration = 0; iteration < kNewtonSteps; ++iteration) {
    const NewtonSums n = iteration == 0 && inside ? newton_sums_at_sample(e, i, j)
                                                  : newton_sums(e, i, static_cast<double>(j) + s);
    if (n.den <= 0.0) break;
    s = std::clamp(s - n.num / n.den, -1.0, 1.0);
  }
  return s;
}

double distance2_to(const DelayEmbedding& e, std::size_t i, double j_plus_s) {
  double d2 = 0.0;
  for (std::size_t d = 0; d < e.dimension(); ++d) {
    const double diff = e.coordinate(i, d) - coordinate_at(e, j_plus_s, d);
    d2 += diff * diff;
  }
  return d2;
}

}  // namespace pneumachaos
