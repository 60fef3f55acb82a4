#pragma once
// Natural logarithms of a block of numbers at once: the divergence curve takes ~1.7 million
// of them on a 1e4 record, and the C library's scalar log takes half the curve's time
// (docs/notes/performance.md, "Logarithms in blocks").

#include <span>

namespace pneumachaos {

/// out[k] = ln(x[k]) for every k, within 2 ulp of the correctly rounded value (checked in
/// tests/analysis/test_lyapunov.cpp). Any positive finite, zero, infinite or NaN x gives what std::log
/// gives. The result is the same bit for bit on every x86-64 machine: the loop is vectorised
/// for the processor at hand (AVX2 or the baseline) but performs the same IEEE operations in
/// the same order per element (no fused multiply-add).
void log_array(std::span<const double> x, std::span<double> out);

}  // namespace pneumachaos
