#include "pneumachaos/model/transducer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// A converter quantises over its full scale, so bits > 0 needs a range; `range` in the range
// key's unit.
void check_converter(int bits, double range, ErrorField bits_key, ErrorField range_key) {
  validation::require_between(bits_key, bits, 0, kMaxTransducerBits);
  validation::require(
      bits == 0 || range > 0.0, range_key, range,
      fmt::format("> 0 when {} = {} (a converter's full scale)", bits_key.id, bits));
}

}  // namespace

bool TransducerParams::ideal() const {
  const VelocityTransducer& v = velocity;
  const PressureTransducer& p = pressure;
  return v.noise_m_per_s == 0.0 && v.bandwidth_Hz == 0.0 && v.bits == 0 && v.range_m_per_s == 0.0 &&
         p.noise_Pa == 0.0 && p.bandwidth_Hz == 0.0 && p.bits == 0 && p.range_Pa == 0.0;
}

void TransducerParams::validate() const {
  // The keys' own ranges, again for scenarios built in code; each value in its key's unit.
  using namespace validation;
  const VelocityTransducer& v = velocity;
  require_finite_ge(field("transducer.velocity_noise_mm_per_s"), v.noise_m_per_s * 1e3, 0);
  require_finite_ge(field("transducer.velocity_bandwidth_Hz"), v.bandwidth_Hz, 0);
  require_finite_ge(field("transducer.velocity_range_mm_per_s"), v.range_m_per_s * 1e3, 0);
  check_converter(v.bits, v.range_m_per_s * 1e3, field("transducer.velocity_bits"),
                  field("transducer.velocity_range_mm_per_s"));
  const PressureTransducer& p = pressure;
  require_finite_ge(field("transducer.pressure_noise_kPa"), p.noise_Pa * 1e-3, 0);
  require_finite_ge(field("transducer.pressure_bandwidth_Hz"), p.bandwidth_Hz, 0);
  require_finite_ge(field("transducer.pressure_range_MPa"), p.range_Pa * 1e-6, 0);
  check_converter(p.bits, p.range_Pa * 1e-6, field("transducer.pressure_bits"),
                  field("transducer.pressure_range_MPa"));
}

}  // namespace pneumachaos
