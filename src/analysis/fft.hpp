#pragma once
// Discrete Fourier transforms of real series through KissFFT (BSD licensed, mixed radix).

#include <complex>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace pneumachaos {

/// Smallest n >= min_size whose only prime factors are 2, 3 and 5 (fast for KissFFT).
std::size_t fast_fft_size(std::size_t min_size);

/// Forward DFT of x zero-padded to n points: X[k] = sum_j x[j] exp(-2 pi i j k / n).
std::vector<std::complex<double>> forward_dft(std::span<const double> x, std::size_t n);

/// Real part of the inverse DFT without the 1/n factor: sum_k X[k] exp(+2 pi i j k / n).
std::vector<double> inverse_dft_real(const std::vector<std::complex<double>>& X);

/// A forward and an inverse transform of one fixed size n, set up once and reused: the
/// surrogate iteration transforms the same length hundreds of times.
class DftPlan {
 public:
  explicit DftPlan(std::size_t n);
  ~DftPlan();
  DftPlan(const DftPlan&) = delete;
  DftPlan& operator=(const DftPlan&) = delete;
  [[nodiscard]] std::size_t size() const { return n_; }
  /// X = forward DFT of x (x.size() == size()).
  void forward(std::span<const double> x, std::vector<std::complex<double>>& X) const;
  /// x = real part of the inverse DFT of X, without the 1/n factor.
  void inverse_real(const std::vector<std::complex<double>>& X, std::vector<double>& x) const;
  /// Complex input: out = forward (or inverse, without 1/n) DFT of in; both of size().
  void transform(const std::vector<std::complex<double>>& in, std::vector<std::complex<double>>& out,
                 bool inverse) const;

 private:
  struct Impl;
  std::size_t n_;
  std::unique_ptr<Impl> impl_;
  mutable std::vector<std::complex<double>> buffer_;
};

}  // namespace pneumachaos
