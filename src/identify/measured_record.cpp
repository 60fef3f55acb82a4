#include "pneumachaos/identify/measured_record.hpp"

#include <fmt/format.h>

#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/column_units.hpp"

namespace pneumachaos::identify {
namespace {

// `quantity`: what the column holds in SI units (absolute pressures), checked to be physical
// as every record reader checks it (a record built from arrays has no header to say more).
void check_column(const MeasuredRecord& r, const std::vector<double>& column, const char* name,
                  Quantity quantity = Quantity::kOther) {
  if (column.size() != r.t_s.size())
    throw Error(r.source, fmt::format("column {} has {} samples but t has {}", name, column.size(),
                                      r.t_s.size()));
  ColumnUnit si;
  si.quantity = quantity;
  for (std::size_t i = 0; i < column.size(); ++i) {
    const std::string problem = std::isfinite(column[i])
                                    ? implausible_value(column[i], si, name, PlausibleRange{})
                                    : "value is not finite";
    if (!problem.empty())
      throw Error(fmt::format("{}: column {}, sample {}", r.source, name, i + 1), problem);
  }
}

}  // namespace

void check_measured_record(const MeasuredRecord& r, std::size_t min_samples) {
  if (r.size() < min_samples)
    throw Error(r.source, fmt::format("{} samples; at least {} are needed", r.size(), min_samples));
  check_column(r, r.t_s, "t");
  check_column(r, r.v_m_per_s, "v", Quantity::kVelocity);
  check_column(r, r.p1_Pa, "P1", Quantity::kPressure);
  check_column(r, r.p2_Pa, "P2", Quantity::kPressure);
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
