#pragma once
// A record measured on a rig (or simulated and degraded like one): the signals the paper's
// apparatus recorded at 1 kHz. All quantities in SI units, pressures absolute; the reader
// (read_measured_record) converts from the units named in the CSV header.

#include <optional>
#include <string>
#include <vector>

namespace pneumachaos::identify {

struct MeasuredRecord {
  std::vector<double> t_s;
  std::vector<double> v_m_per_s;
  std::vector<double> p1_Pa;  ///< chamber 1 (the driving chamber), absolute
  std::vector<double> p2_Pa;  ///< chamber 2 (the rod side), absolute
  std::optional<std::vector<double>> x_m;          ///< piston position, when recorded
  std::optional<std::vector<double>> a_m_per_s2;   ///< acceleration, when recorded
  std::string source = "record";                   ///< file name, for messages

  std::size_t size() const { return t_s.size(); }
  /// Uniform sample interval (s); valid after check_measured_record().
  double dt_s() const { return t_s.size() > 1 ? (t_s.back() - t_s.front()) / double(t_s.size() - 1) : 0.0; }
};

/// Throws Error naming `source` when the columns differ in length, a value is not finite,
/// the record has fewer than `min_samples` samples, or the time column is not uniform
/// (a step more than 1 % from the mean step).
void check_measured_record(const MeasuredRecord& record, std::size_t min_samples = 100);

}  // namespace pneumachaos::identify
