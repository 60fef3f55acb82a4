#include "log_array.hpp"

#include <bit>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstdint>

namespace pneumachaos {
namespace {

// x = 2^e * m with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(s) with s = (m - 1) / (m + 1),
// |s| <= 0.1716, summed as 2 (s + s^3/3 + ... + s^21/21): the first omitted term is below
// 1e-18 of the sum. ln 2 is split in a part with trailing zero bits (e * kLn2Hi is exact for
// every exponent) and the rest. Only for normal positive x; the caller handles the others.
inline double log_normal(double x) {
  constexpr double kLn2Hi = 0x1.62e42fee00000p-1;
  constexpr double kLn2Lo = 0x1.a39ef35793c76p-33;
  constexpr std::uint64_t kMantissa = 0x000FFFFFFFFFFFFFull;
  constexpr std::uint64_t kOne = 0x3FF0000000000000ull;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  // m above sqrt(2) is halved and e raised by one, in integer form so the loop stays free of
  // branches (and vectorises): 0x6A09E667F3BCD is the mantissa of sqrt(2).
  const std::uint64_t high = (bits & kMantissa) > 0x6A09E667F3BCDull ? 1 : 0;
  const double m = std::bit_cast<double>(((bits & kMantissa) | kOne) - (high << 52));
  // The biased exponent as a double without an integer conversion (2^52 + e, exactly).
  const double e =
      std::bit_cast<double>(((bits >> 52) + high) | 0x4330000000000000ull) - 0x1p52 - 1023.0;
  const double s = (m - 1.0) / (m + 1.0);
  const double z = s * s;
  double p = 2.0 / 21.0;
  for (const double c : {2.0 / 19.0, 2.0 / 17.0, 2.0 / 15.0, 2.0 / 13.0, 2.0 / 11.0, 2.0 / 9.0,
                         2.0 / 7.0, 2.0 / 5.0, 2.0 / 3.0}) {
    p = p * z + c;
  }
  // 2s + s z p', with 2s kept apart so that its rounding is the only one at full size.
  const double tail = s * (z * p);
  return e * kLn2Hi + ((2.0 * s + tail) + e * kLn2Lo);
}

}  // namespace

// Two clones, chosen once at load time: the same arithmetic, wider vectors where available.
__attribute__((target_clones("avx2", "default"))) void log_array(std::span<const double> x,
                                                                 std::span<double> out) {
  assert(out.size() >= x.size());
  const std::size_t n = x.size();
  const double* __restrict in = x.data();
  double* __restrict o = out.data();
  // Positive normal numbers are the bit patterns 0x0010... to 0x7FEF...: one unsigned
  // comparison per element, or-ed so the loop stays vectorised.
  std::uint64_t others = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(in[k]);
    others |= (bits - 0x0010000000000000ull) >= 0x7FE0000000000000ull ? 1 : 0;
    o[k] = log_normal(in[k]);
  }
  if (others == 0) return;
  // Zero, subnormal, negative, infinite and NaN inputs: rare; the library's answer.
  for (std::size_t k = 0; k < n; ++k) {
    if (!(in[k] >= DBL_MIN && in[k] <= DBL_MAX)) o[k] = std::log(in[k]);
  }
}

}  // namespace pneumachaos
