#include "pneumachaos/model/transducer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// The keys' own ranges, again for scenarios built in code; `value` in the key's unit.
void refuse_negative(double value, const std::string& key, const char* unit) {
  if (std::isfinite(value) && value >= 0.0) return;
  throw Error(key, fmt::format("{} {} is out of range: expected >= 0", value, unit));
}

// A converter quantises over its full scale, so bits > 0 needs a range.
void check_converter(int bits, double range, const std::string& prefix, const char* range_key) {
  const std::string bits_key = prefix + "bits";
  if (bits < 0 || bits > kMaxTransducerBits) {
    throw Error(bits_key, fmt::format("{} is out of range: expected >= 0 and <= {}", bits,
                                      kMaxTransducerBits));
  }
  if (bits > 0 && !(range > 0.0)) {
    throw Error(
        prefix + range_key,
        fmt::format("a {}-bit converter ({}) needs its full scale: expected > 0", bits, bits_key));
  }
}

}  // namespace

bool TransducerParams::ideal() const {
  const VelocityTransducer& v = velocity;
  const PressureTransducer& p = pressure;
  return v.noise_m_per_s == 0.0 && v.bandwidth_Hz == 0.0 && v.bits == 0 && v.range_m_per_s == 0.0 &&
         p.noise_Pa == 0.0 && p.bandwidth_Hz == 0.0 && p.bits == 0 && p.range_Pa == 0.0;
}

void TransducerParams::validate() const {
  const VelocityTransducer& v = velocity;
  refuse_negative(v.noise_m_per_s * 1e3, "transducer.velocity_noise_mm_per_s", "mm/s");
  refuse_negative(v.bandwidth_Hz, "transducer.velocity_bandwidth_Hz", "Hz");
  refuse_negative(v.range_m_per_s * 1e3, "transducer.velocity_range_mm_per_s", "mm/s");
  check_converter(v.bits, v.range_m_per_s, "transducer.velocity_", "range_mm_per_s");
  const PressureTransducer& p = pressure;
  refuse_negative(p.noise_Pa * 1e-3, "transducer.pressure_noise_kPa", "kPa");
  refuse_negative(p.bandwidth_Hz, "transducer.pressure_bandwidth_Hz", "Hz");
  refuse_negative(p.range_Pa * 1e-6, "transducer.pressure_range_MPa", "MPa");
  check_converter(p.bits, p.range_Pa, "transducer.pressure_", "range_MPa");
}

}  // namespace pneumachaos
