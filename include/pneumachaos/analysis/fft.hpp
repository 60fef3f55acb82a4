#pragma once
// Discrete Fourier transforms of real series through KissFFT (BSD licensed, mixed radix).

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

/// Smallest n >= min_size whose only prime factors are 2, 3 and 5 (fast for KissFFT).
std::size_t fast_fft_size(std::size_t min_size);

/// Forward DFT of x zero-padded to n points: X[k] = sum_j x[j] exp(-2 pi i j k / n).
std::vector<std::complex<double>> forward_dft(std::span<const double> x, std::size_t n);

/// Real part of the inverse DFT without the 1/n factor: sum_k X[k] exp(+2 pi i j k / n).
std::vector<double> inverse_dft_real(const std::vector<std::complex<double>>& X);

}  // namespace pneumachaos
