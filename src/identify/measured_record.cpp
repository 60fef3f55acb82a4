#include "pneumachaos/identify/measured_record.hpp"

#include <cmath>
#include <fmt/format.h>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos::identify {
namespace {

void check_column(const MeasuredRecord& r, const std::vector<double>& column, const char* name) {
  if (column.size() != r.t_s.size())
    throw Error(r.source, fmt::format("column {} has {} samples but t has {}", name, column.size(),
                                      r.t_s.size()));
  for (std::size_t i = 0; i < column.size(); ++i)
    if (!std::isfinite(column[i]))
      throw Error(r.source, fmt::format("column {}, sample {}: value is not finite", name, i + 1));
}

}  // namespace

void check_measured_record(const MeasuredRecord& r, std::size_t min_samples) {
  if (r.size() < min_samples)
    throw Error(r.source, fmt::format("{} samples; at least {} are needed", r.size(), min_samples));
  check_column(r, r.t_s, "t");
  check_column(r, r.v_m_per_s, "v");
  check_column(r, r.p1_Pa, "P1");
  check_column(r, r.p2_Pa, "P2");
  if (r.x_m) check_column(r, *r.x_m, "x");
  if (r.a_m_per_s2) check_column(r, *r.a_m_per_s2, "a");
  const double dt = r.dt_s();
  if (!(dt > 0.0)) throw Error(r.source, "time column does not increase");
  // A rig's A/D clock is uniform; a gap or a repeated stamp means samples were lost, and every
  // derivative and fit below assumes a fixed step.
  for (std::size_t i = 1; i < r.size(); ++i)
    if (std::abs(r.t_s[i] - r.t_s[i - 1] - dt) > 1e-2 * dt)
      throw Error(r.source, fmt::format("time is not uniform at sample {} (t = {} s): step {} s, "
                                        "expected {} s", i + 1, r.t_s[i], r.t_s[i] - r.t_s[i - 1], dt));
}

}  // namespace pneumachaos::identify
